// The job runner (runner/runner.hpp) on its own: every item once, cancelling, failing, the order
// given; and the one progress renderer's text.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "report/progress_line.hpp"
#include "runner/runner.hpp"

namespace tripack::jobs {
namespace {

TEST(Runner, EveryItemRunsOnceAndFinishesOnOneThreadAtATime) {
  for (int threads : {1, 2, 4}) {
    std::vector<std::atomic<int>> runs(200);
    std::atomic<int> inside_finished{0};
    std::set<std::size_t> finished;
    JobItems items;
    items.count = runs.size();
    items.run = [&](std::size_t i) {
      ++runs[i];
      return std::to_string(i * i);
    };
    items.finished = [&](std::size_t i, const std::string& result) {
      EXPECT_EQ(++inside_finished, 1);  // never two at once
      EXPECT_EQ(result, std::to_string(i * i));
      finished.insert(i);
      --inside_finished;
    };
    const JobOutcome outcome = ThreadExecutor(threads).run_items(items, nullptr);
    EXPECT_EQ(outcome.finished, runs.size());
    EXPECT_FALSE(outcome.cancelled);
    EXPECT_EQ(finished.size(), runs.size());
    for (const auto& r : runs) EXPECT_EQ(r.load(), 1);
  }
}

TEST(Runner, RunsOnlyTheGivenOrder) {
  std::vector<std::size_t> seen;
  JobItems items;
  items.count = 10;
  items.order = std::vector<std::size_t>{7, 2, 9};
  items.run = [&](std::size_t i) {
    seen.push_back(i);
    return std::string();
  };
  EXPECT_EQ(ThreadExecutor(1).run_items(items, nullptr).finished, 3u);
  EXPECT_EQ(seen, (std::vector<std::size_t>{7, 2, 9}));
}

TEST(Runner, ACancelStartsNothingNewAndLetsTheItemsUnderWayFinish) {
  CancelToken cancel;
  std::atomic<int> started{0}, ended{0};
  JobItems items;
  items.count = 100;
  items.run = [&](std::size_t) {
    ++started;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    ++ended;
    return std::string();
  };
  int finished = 0;
  items.finished = [&](std::size_t, const std::string&) {
    if (++finished == 5) cancel.cancel();
  };
  const JobOutcome outcome = ThreadExecutor(2).run_items(items, &cancel);
  EXPECT_TRUE(outcome.cancelled);
  EXPECT_EQ(started.load(), ended.load());  // none left half done
  EXPECT_EQ(outcome.finished, static_cast<std::size_t>(ended.load()));
  // Two workers: when the fifth finishes, at most the other worker's item is under way.
  EXPECT_GE(ended.load(), 5);
  EXPECT_LE(ended.load(), 6);
}

TEST(Runner, AFailureInFinishedStopsTheJobAndIsRethrown) {
  std::atomic<int> started{0};
  JobItems items;
  items.count = 100;
  items.run = [&](std::size_t) {
    ++started;
    return std::string();
  };
  items.finished = [&](std::size_t i, const std::string&) {
    if (i == 3) throw std::runtime_error("disk full");
  };
  EXPECT_THROW(
      {
        try {
          ThreadExecutor(1).run_items(items, nullptr);
        } catch (const std::runtime_error& e) {
          EXPECT_STREQ(e.what(), "disk full");
          throw;
        }
      },
      std::runtime_error);
  EXPECT_EQ(started.load(), 4);  // one thread: nothing after item 3
}

TEST(Runner, AFailureInRunStopsTheJob) {
  JobItems items;
  items.count = 50;
  std::atomic<int> started{0};
  items.run = [&](std::size_t i) -> std::string {
    ++started;
    if (i == 0) throw std::invalid_argument("bad file");
    return {};
  };
  EXPECT_THROW(ThreadExecutor(1).run_items(items, nullptr), std::invalid_argument);
  EXPECT_EQ(started.load(), 1);
}

TEST(Runner, ProgressCounterCountsFinishedItems) {
  ProgressCounter counter("import", 3);
  const Progress a = counter.finished("a.txt", 0.5L);
  const Progress b = counter.finished("b.txt");
  EXPECT_EQ(a.done, 1);
  EXPECT_EQ(b.done, 2);
  EXPECT_EQ(b.total, 3);
  EXPECT_TRUE(a.item_finished);
  EXPECT_EQ(a.d, 0.5L);
  EXPECT_EQ(a.stage, "import");
  EXPECT_FALSE(counter.snapshot("c.txt").item_finished);
}

TEST(ProgressLine, TextShowsCountsEtaStageAndLiveRun) {
  Progress p;
  p.stage = "billiards";
  p.item = "run 3";
  p.done = 1;
  p.total = 4;
  p.d = 0.1794;
  p.events = 2'000'000;
  p.elapsed = 1.0;  // the run's own seconds: 2 M events/s
  p.relative_gap = 1e-3;
  // A quarter done after 10 s: 30 s to go.
  EXPECT_EQ(
      report::progress_text("billiards n=22", p, 10.0),
      "billiards n=22: 1/4 10.0 s, ETA 30 s: run 3, d = 0.1794, 2.00 M events/s, gap ~1.0e-03");
  Progress stage;
  stage.stage = "relax";
  stage.step = 7;
  EXPECT_EQ(report::progress_text("analyze", stage, 2.5), "analyze: 2.5 s, relax step 7");
}

TEST(ProgressLine, ALogGetsOneLinePerFinishedItem) {
  std::ostringstream log;
  {
    report::ProgressLineOptions options;
    options.job = "campaign";
    options.log_every = 1;
    report::ProgressLine line(log, options);
    const ProgressFn report = line.callback();
    ProgressCounter counter("campaign", 2);
    report(counter.snapshot("under way"));  // a snapshot: no line
    report(counter.finished("recorded n = 5 seed = 1: d = 0.5"));
    report(counter.finished("recorded n = 5 seed = 2: not certified"));
  }
  const std::string text = log.str();
  EXPECT_EQ(text.find("campaign: recorded n = 5 seed = 1: d = 0.5 (1/2, "), 0u) << text;
  EXPECT_NE(text.find("\ncampaign: recorded n = 5 seed = 2: not certified (2/2, "),
            std::string::npos);
  EXPECT_EQ(text.find("under way"), std::string::npos);
}

}  // namespace
}  // namespace tripack::jobs
