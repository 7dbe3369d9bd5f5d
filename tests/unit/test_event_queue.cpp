// sim/event_queue.hpp: the billiards engine's indexed heap of per-disk events, on its own.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <queue>
#include <random>
#include <vector>

#include "sim/event_queue.hpp"

namespace tripack::sim_detail {
namespace {

// Pops every event (top, then erase its disk) and returns them in the order they came out.
std::vector<Event> drain(EventQueue& q) {
  std::vector<Event> out;
  while (!q.empty()) {
    out.push_back(q.top());
    q.erase(out.back().i);
  }
  return out;
}

TEST(EventQueue, ResetGivesAnEmptyQueue) {
  EventQueue q;
  q.reset(5);
  EXPECT_TRUE(q.empty());
  q.set({1.0, 2, 3, 7});
  EXPECT_FALSE(q.empty());
  q.reset(5);
  EXPECT_TRUE(q.empty());
  for (int i = 0; i < 5; ++i) q.erase(i);  // erasing absent disks changes nothing
  EXPECT_TRUE(q.empty());
}

TEST(EventQueue, TopIsTheEarliestAndCarriesItsEvent) {
  EventQueue q;
  q.reset(4);
  q.set({3.0, 0, 1, 11});
  q.set({1.0, 1, -2, 12});
  q.set({2.0, 2, kUpdate, 13});
  q.set({4.0, 3, 0, 14});
  const Event e = q.top();
  EXPECT_EQ(e.t, 1.0);
  EXPECT_EQ(e.i, 1);
  EXPECT_EQ(e.j, -2);
  EXPECT_EQ(e.traj, 12u);
  const std::vector<Event> out = drain(q);
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(out[0].i, 1);
  EXPECT_EQ(out[1].i, 2);
  EXPECT_EQ(out[1].j, kUpdate);
  EXPECT_EQ(out[2].i, 0);
  EXPECT_EQ(out[2].traj, 11u);
  EXPECT_EQ(out[3].i, 3);
}

TEST(EventQueue, SetReplacesTheDisksEventEarlierOrLater) {
  EventQueue q;
  const int n = 9;
  q.reset(n);
  for (int i = 0; i < n; ++i) q.set({double(10 + i), i, kUpdate, 0});
  q.set({99.0, 0, 4, 2});  // the first becomes the last (moves down)
  EXPECT_EQ(q.top().i, 1);
  q.set({0.5, 8, 3, 1});   // the last becomes the first (moves up)
  q.set({14.5, 4, 5, 3});  // a small move down
  const std::vector<Event> out = drain(q);
  ASSERT_EQ(out.size(), std::size_t(n));  // one slot per disk: no stale entries
  EXPECT_EQ(out.front().i, 8);
  EXPECT_EQ(out.front().t, 0.5);
  EXPECT_EQ(out.back().i, 0);
  EXPECT_EQ(out.back().t, 99.0);
  EXPECT_EQ(out.back().j, 4);
  for (std::size_t k = 1; k < out.size(); ++k) EXPECT_LE(out[k - 1].t, out[k].t);
  const auto four = std::find_if(out.begin(), out.end(), [](const Event& e) { return e.i == 4; });
  ASSERT_NE(four, out.end());
  EXPECT_EQ(four->t, 14.5);
  EXPECT_EQ(four->traj, 3u);
}

TEST(EventQueue, EraseRemovesOnlyThatDisk) {
  EventQueue q;
  const int n = 13;
  q.reset(n);
  for (int i = 0; i < n; ++i) q.set({double((i * 7) % n), i, kUpdate, 0});
  q.erase(5);
  q.erase(5);  // already gone
  q.erase(0);  // the earliest (time 0)
  q.erase(2);  // time 1
  const std::vector<Event> out = drain(q);
  ASSERT_EQ(out.size(), std::size_t(n - 3));
  for (std::size_t k = 0; k < out.size(); ++k) {
    EXPECT_NE(out[k].i, 5);
    EXPECT_NE(out[k].i, 0);
    EXPECT_NE(out[k].i, 2);
    if (k > 0) {
      EXPECT_LT(out[k - 1].t, out[k].t);  // distinct times here
    }
  }
  EXPECT_EQ(out.front().t, 2.0);  // (i = 4: 28 mod 13)
}

TEST(EventQueue, TiesAllComeOutOnceAtTheirTime) {
  EventQueue q;
  const int n = 23;
  q.reset(n);
  for (int i = 0; i < n; ++i) q.set({i % 3 == 0 ? 1.0 : 2.0, i, kUpdate, 0});
  const std::vector<Event> out = drain(q);
  ASSERT_EQ(out.size(), std::size_t(n));
  std::vector<int> seen(std::size_t(n), 0);
  const int ones = (n + 2) / 3;  // i = 0, 3, ..., 21
  for (std::size_t k = 0; k < out.size(); ++k) {
    ++seen[std::size_t(out[k].i)];
    EXPECT_EQ(out[k].t, k < std::size_t(ones) ? 1.0 : 2.0);
    EXPECT_EQ(out[k].t, out[k].i % 3 == 0 ? 1.0 : 2.0);
  }
  for (int c : seen) EXPECT_EQ(c, 1);
}

// The clock restart: every time minus dt, the order and the rest of each event kept.
TEST(EventQueue, ShiftMovesEveryTimeAndKeepsTheOrder) {
  EventQueue q;
  q.reset(6);
  const std::vector<double> t = {0.75, 0.25, 1.5, 0.5, 3.0, 2.0};
  for (int i = 0; i < 6; ++i) q.set({t[std::size_t(i)], i, i - 1, std::uint32_t(100 + i)});
  const double dt = 0.125;
  q.shift(dt);
  const std::vector<Event> out = drain(q);
  ASSERT_EQ(out.size(), 6u);
  std::vector<double> want = t;
  std::sort(want.begin(), want.end());
  for (std::size_t k = 0; k < out.size(); ++k) {
    EXPECT_EQ(out[k].t, want[k] - dt);
    EXPECT_EQ(out[k].t, t[std::size_t(out[k].i)] - dt);
    EXPECT_EQ(out[k].j, out[k].i - 1);
    EXPECT_EQ(out[k].traj, std::uint32_t(100 + out[k].i));
  }
}

// set compares the new time with the disk's stored one to move it up or down, so the stored
// event times must be shifted too: here the new time is later than the shifted old one but
// earlier than the unshifted one.
TEST(EventQueue, SetAfterShiftComparesShiftedTimes) {
  EventQueue q;
  q.reset(3);
  q.set({1.0, 0, kUpdate, 0});
  q.set({2.0, 1, kUpdate, 0});
  q.set({3.0, 2, kUpdate, 0});
  q.shift(10.0);  // -9, -8, -7
  q.set({-7.5, 0, kUpdate, 0});
  EXPECT_EQ(q.top().i, 1);
  EXPECT_EQ(q.top().t, -8.0);
  const std::vector<Event> out = drain(q);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[1].i, 0);
  EXPECT_EQ(out[2].i, 2);
}

// Insertions only, in random order with repeated times: the drained times are those of a
// std::priority_queue fed the same times.
TEST(EventQueue, RandomInsertsDrainLikeAPriorityQueue) {
  std::mt19937_64 rng(42);
  for (int n : {1, 2, 3, 4, 5, 6, 17, 64, 65, 1000}) {
    EventQueue q;
    q.reset(n);
    std::priority_queue<double, std::vector<double>, std::greater<>> ref;
    std::uniform_int_distribution<int> coarse(0, std::max(1, n / 4));  // many ties
    std::vector<int> order(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) order[std::size_t(i)] = i;
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<double> time(static_cast<std::size_t>(n));
    for (int i : order) {
      time[std::size_t(i)] = 0.5 * coarse(rng);
      q.set({time[std::size_t(i)], i, kUpdate, std::uint32_t(i)});
      ref.push(time[std::size_t(i)]);
    }
    const std::vector<Event> out = drain(q);
    ASSERT_EQ(out.size(), std::size_t(n)) << "n = " << n;
    for (const Event& e : out) {
      EXPECT_EQ(e.t, ref.top()) << "n = " << n;
      EXPECT_EQ(e.t, time[std::size_t(e.i)]);
      EXPECT_EQ(e.traj, std::uint32_t(e.i));
      ref.pop();
    }
  }
}

// Random sets (earlier, later, new), erases, pops and clock shifts against a plain array of each
// disk's current event: the top is always an earliest one, and the final drain is the sorted
// array.
TEST(EventQueue, RandomOperationsMatchAnArrayOfCurrentEvents) {
  std::mt19937_64 rng(7);
  for (int n : {1, 3, 4, 5, 16, 21, 200}) {
    EventQueue q;
    q.reset(n);
    std::vector<double> cur(std::size_t(n), kInf);  // kInf: no event
    std::vector<int> partner(std::size_t(n), kNoEvent);
    std::uniform_int_distribution<int> disk(0, n - 1), op(0, 99), coarse(0, 40);
    for (int step = 0; step < 20000; ++step) {
      const int o = op(rng);
      if (o < 60) {
        const int i = disk(rng);
        const double t = 0.25 * coarse(rng);
        const int j = o % 5 - 4;  // walls, updates, "disk" codes
        q.set({t, i, j, std::uint32_t(step)});
        cur[std::size_t(i)] = t;
        partner[std::size_t(i)] = j;
      } else if (o < 80) {
        const int i = disk(rng);
        q.erase(i);
        cur[std::size_t(i)] = kInf;
      } else if (o < 97) {
        if (q.empty()) continue;
        const int i = q.top().i;
        q.erase(i);
        cur[std::size_t(i)] = kInf;
      } else {
        const double dt = 0.25 * coarse(rng);  // exact in binary: the oracle shifts alike
        q.shift(dt);
        for (double& t : cur) t -= dt;
      }
      const double earliest = *std::min_element(cur.begin(), cur.end());
      ASSERT_EQ(q.empty(), earliest == kInf) << "n = " << n << " step " << step;
      if (q.empty()) continue;
      const Event& e = q.top();
      ASSERT_EQ(e.t, earliest) << "n = " << n << " step " << step;
      ASSERT_EQ(cur[std::size_t(e.i)], earliest);
      ASSERT_EQ(e.j, partner[std::size_t(e.i)]);
    }
    std::vector<double> want;
    for (double t : cur)
      if (t < kInf) want.push_back(t);
    std::sort(want.begin(), want.end());
    const std::vector<Event> out = drain(q);
    ASSERT_EQ(out.size(), want.size()) << "n = " << n;
    for (std::size_t k = 0; k < out.size(); ++k) {
      EXPECT_EQ(out[k].t, want[k]);
      EXPECT_EQ(out[k].t, cur[std::size_t(out[k].i)]);
    }
  }
}

}  // namespace
}  // namespace tripack::sim_detail
