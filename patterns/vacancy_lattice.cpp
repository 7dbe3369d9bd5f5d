#include "patterns/vacancy_lattice.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <exception>
#include <mutex>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>

#include "analysis/bonds.hpp"
#include "analysis/interior_relax.hpp"
#include "analysis/relax.hpp"
#include "core/neighbours.hpp"

namespace tripack::patterns {

namespace {

// The 6 symmetries act on a site's barycentric coordinates (i, j, l = rows - 1 - i - j) by
// permuting them.
Site permuted(long rows, const Site& s, int symmetry) {
  const std::array<long, 3> c{s.i, s.j, rows - 1 - s.i - s.j};
  static constexpr int kPerm[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1},
                                      {1, 0, 2}, {0, 2, 1}, {2, 1, 0}};
  return {c[static_cast<std::size_t>(kPerm[symmetry][0])],
          c[static_cast<std::size_t>(kPerm[symmetry][1])]};
}

// The interior-point relax, then the LP relax, which ends the interior relax's last 1e-13 and
// loads the contacts (its duals). From kLpRelaxLimit disks the LP relax is not run: CLP's simplex
// on these degenerate LPs took over 10 minutes for one segment of n = 2450, where the
// interior-point relax alone (run again while a stage ends it short) took 2 s; the certificate's
// analysis certified its results up to n = 4953, not at n = 9873, where no bonds were identified
// (docs/performance.md). The report is then empty.
constexpr std::size_t kLpRelaxLimit = 1000;
RelaxReport relax_near_lattice(Packing& p) {
  InteriorRelaxOptions options;
  options.supernodal = true;  // as the enumeration always relaxed (InteriorRelaxOptions)
  InteriorRelaxReport report = interior_relax(p, options);
  if (p.size() < kLpRelaxLimit) return relax_packing(p);
  for (int again = 0; again < 3 && !report.converged; ++again) report = interior_relax(p, options);
  return {};
}

}  // namespace

Packing lattice_with_vacancies(long rows, const std::vector<Site>& vacancies) {
  if (rows < 2) throw std::invalid_argument("a lattice with vacancies needs at least 2 rows");
  std::set<Site> empty;
  for (const Site& s : vacancies) {
    if (s.i < 0 || s.j < 0 || s.i + s.j >= rows)
      throw std::invalid_argument("vacancy (" + std::to_string(s.i) + ", " + std::to_string(s.j) +
                                  ") is not a site of the " + std::to_string(rows) +
                                  "-row lattice");
    empty.insert(s);
  }
  const long double spacing = 1.0L / static_cast<long double>(rows - 1);
  Packing p;
  for (long j = 0; j < rows; ++j)
    for (long i = 0; i + j < rows; ++i)
      if (!empty.count({i, j}))
        p.points.push_back(
            {(static_cast<long double>(i) + static_cast<long double>(j) / 2) * spacing,
             static_cast<long double>(j) * kSqrt3 / 2 * spacing});
  p.d = spacing;
  return p;
}

std::vector<Site> canonical_vacancies(long rows, std::vector<Site> vacancies) {
  std::vector<Site> best;
  for (int s = 0; s < 6; ++s) {
    std::vector<Site> image;
    for (const Site& v : vacancies) image.push_back(permuted(rows, v, s));
    std::sort(image.begin(), image.end());
    if (best.empty() || image < best) best = image;
  }
  return best;
}

std::vector<std::vector<Site>> straight_segments(long rows, long length) {
  std::vector<std::vector<Site>> out;
  if (length < 1 || length > rows) return out;
  std::set<std::vector<Site>> seen;
  // Along rows only: the rotations carry the other two line directions onto rows.
  for (long j = 0; j + length <= rows; ++j)
    for (long i = 0; i + j + length <= rows; ++i) {
      std::vector<Site> seg;
      for (long t = 0; t < length; ++t) seg.push_back({i + t, j});
      if (seen.insert(canonical_vacancies(rows, seg)).second) out.push_back(seg);
    }
  return out;
}

namespace {

// A copy of the lattice start shrunk towards the centroid by 2 * jitter spacings and each
// coordinate moved by up to jitter / 2 spacings: strictly inside, and no two disks closer than
// the lattice less 2 jitter. The draws are the generator's raw 53-bit words (the same on every
// platform, unlike std::uniform_real_distribution).
Packing jittered(const Packing& lattice, long rows, long double jitter, std::mt19937_64& rng) {
  const long double spacing = 1.0L / static_cast<long double>(rows - 1);
  const long double shrink = 1 - 2 * jitter * spacing;
  const Vec2L centre{0.5L, kSqrt3 / 6};
  auto uniform = [&] { return static_cast<long double>(rng() >> 11) * 0x1p-53L * 2 - 1; };
  Packing p = lattice;
  for (auto& q : p.points) {
    const long double dx = uniform() * jitter * spacing / 2;
    const long double dy = uniform() * jitter * spacing / 2;
    q = Vec2L{centre.x + (q.x - centre.x) * shrink + dx, centre.y + (q.y - centre.y) * shrink + dy};
  }
  p.d = min_pair_distance(p.points, 2 * spacing);
  return p;
}

// The atlas's order on packings of one n: d first (equal below 1e-15 relative), then more bonds.
bool better_pattern(const Pattern& a, const Pattern& b) {
  if (a.packing.d > b.packing.d * (1 + 1e-15L)) return true;
  if (b.packing.d > a.packing.d * (1 + 1e-15L)) return false;
  return a.bonds.size() > b.bonds.size();
}

}  // namespace

namespace {

// Runs work(i) for every i < count on `threads` threads (the calling one included). The first
// exception (Cancelled) stops the hand-out and is rethrown once every thread has returned.
template <class Work>
void for_each_index(std::size_t count, int threads, const Work& work) {
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex error_lock;
  auto run = [&] {
    for (std::size_t i; (i = next++) < count;) {
      try {
        work(i);
      } catch (...) {
        const std::lock_guard<std::mutex> hold(error_lock);
        if (!error) error = std::current_exception();
        next = count;
      }
    }
  };
  const std::size_t helpers = std::min<std::size_t>(
      count > 0 ? count - 1 : 0, static_cast<std::size_t>(std::max(1, threads) - 1));
  std::vector<std::thread> pool;
  for (std::size_t t = 0; t < helpers; ++t) pool.emplace_back(run);
  run();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

// The fast ranking's relax: the interior-point relax alone, with a first stage of up to 400
// Newton steps (a long segment's start: its disks travel several spacings at <= 0.1 diameter per
// step; n = 600 converged after 141-270 steps where 80 declined), called again while it still
// ends short there and raised d. A relax that ends short in a later stage is at the last 1e-12 of
// a slip, where the LP relax finishes faster (n = 208: 4 LP steps against 700 more Newton steps
// that did not converge).
void relax_interior(Packing& p) {
  InteriorRelaxOptions options;
  options.max_first_stage_steps = 400;
  options.max_newton_steps = 800;
  InteriorRelaxReport report = interior_relax(p, options);
  for (int again = 0; again < 3 && !report.converged && report.stages == 1 &&
                      report.d_end > report.d_start * (1 + 1e-15L);
       ++again)
    report = interior_relax(p, options);
}

// The LP relax from the interior relax's end (1 to 4 LP steps there) and the bonds.
constexpr std::size_t kFastLpRelaxLimit = 5000;
// A relaxed packing with its bonds, identified from the relax's loaded contacts.
Pattern with_bonds(Packing p, const RelaxReport& lp) {
  BondIdentification id = identify_bonds(p, lp.active);
  Pattern out;
  out.packing = std::move(p);
  out.bonds = std::move(id.bonds);
  out.rattlers = std::move(id.rattlers);
  return out;
}

Pattern finish_relaxed(Packing p) {
  RelaxReport lp;
  if (p.size() < kFastLpRelaxLimit)
    lp = relax_packing(p);
  else
    relax_interior(p);
  return with_bonds(std::move(p), lp);
}

// How many lattice lines lie between the segment and the nearest wall (0: it touches one).
long lines_from_a_wall(long rows, const std::vector<Site>& segment) {
  long nearest = rows;
  for (const Site& s : segment) nearest = std::min({nearest, s.i, s.j, rows - 1 - s.i - s.j});
  return nearest;
}

// The lattice with `segment` empty, relaxed from the exact lattice or (seed > 0) from a
// jittered copy, by the chosen ranking.
struct SegmentRelax {
  Packing packing;
  RelaxReport lp;  // the exhaustive relax's LP (its loaded contacts); empty in the fast ranking
};

}  // namespace

std::vector<std::vector<Site>> jogged_lines(long rows, long distance) {
  std::vector<std::vector<Site>> out;
  if (distance < 1 || rows - distance < 2) return out;
  // The line i = distance (parallel to the wall i = 0; the rotations carry the other two walls'
  // lines onto it), from the bottom wall to the right one.
  std::vector<Site> line;
  for (long j = 0; distance + j < rows; ++j) line.push_back({distance, j});
  // A site's neighbours off its line: two on the line further in, two on the line nearer the
  // wall (the wall's own line when distance = 1).
  static constexpr Site kOff[4] = {{1, 0}, {1, -1}, {-1, 0}, {-1, 1}};
  std::set<std::vector<Site>> seen;
  for (std::size_t a = 0; a < line.size(); ++a)
    for (const Site& step : kOff) {
      const Site moved{line[a].i + step.i, line[a].j + step.j};
      if (moved.j < 0 || moved.i + moved.j >= rows) continue;
      std::vector<Site> set = line;
      set[a] = moved;
      if (seen.insert(canonical_vacancies(rows, set)).second) out.push_back(set);
    }
  return out;
}

SegmentChoice best_vacancy_segment(long rows, long vacancies, const SegmentEnumeration& search) {
  if (vacancies < 1 || vacancies >= rows)
    throw std::invalid_argument("a vacancy segment of " + std::to_string(vacancies) +
                                " sites does not fit a lattice line of " + std::to_string(rows) +
                                " rows with a disk left on it");
  return best_vacancy_set(rows, straight_segments(rows, vacancies), search);
}

SegmentChoice best_jogged_line(long rows, long distance, const SegmentEnumeration& search) {
  if (distance < 1 || rows - distance < 2)
    throw std::invalid_argument("no lattice line of 2 or more sites lies " +
                                std::to_string(distance) + " lines from a wall of the " +
                                std::to_string(rows) + "-row lattice");
  return best_vacancy_set(rows, jogged_lines(rows, distance), search);
}

SegmentChoice best_vacancy_set(long rows, std::vector<std::vector<Site>> segments,
                               const SegmentEnumeration& search) {
  if (segments.empty()) throw std::invalid_argument("no vacancy set to relax");
  const long vacancies = static_cast<long>(segments.front().size());
  const long n = triangular(rows) - vacancies;
  // Up to all_segments_up_to disks every candidate is relaxed as the exhaustive enumeration
  // relaxes it (0.05-0.3 s each there): the fast relaxes ended elsewhere on the degenerate
  // maxima of n = 69, 109, 169, 188 and 197 (1e-15 to 7e-13 apart, 188 then not certified), and
  // ranking by the interior relax alone missed n = 118's best segment (22nd by it).
  const bool exhaustive = search.exhaustive || n <= search.all_segments_up_to;
  const bool few = !exhaustive && n > search.few_restarts_from;
  const std::size_t budget = few ? search.few_segments : search.segment_budget;
  if (!exhaustive && segments.size() > budget) {
    std::stable_sort(segments.begin(), segments.end(),
                     [rows](const std::vector<Site>& a, const std::vector<Site>& b) {
                       return lines_from_a_wall(rows, a) < lines_from_a_wall(rows, b);
                     });
    segments.resize(budget);
  }
  // Above all_segments_up_to disks the LP relax, slow from a restart's end (0.5-12 s per restart
  // at n = 777 against 0.3 s for its interior relax), runs only on the lp_finalists densest
  // segments and on a restart whose interior relax alone ends above the best by more than its
  // own 1e-13.
  const int restarts = few ? std::min(search.restarts, search.few_restarts) : search.restarts;
  const std::size_t top =
      std::min(segments.size(), few ? 1 : std::max<std::size_t>(1, search.top_segments));
  const std::size_t finalists =
      exhaustive ? top : std::min(segments.size(), std::max(top, search.lp_finalists));
  const long long relaxes = static_cast<long long>(segments.size() + top * restarts);
  long long done = 0;
  std::mutex progress_lock;
  auto relaxed_one = [&](const char* what) {
    throw_if_cancelled(search.cancel);
    if (!search.progress) return;
    const std::lock_guard<std::mutex> hold(progress_lock);
    Progress p;
    p.stage = "construct";
    p.item = fmt::format("{} of Delta({}) less {}", what, rows, vacancies);
    p.done = ++done;
    p.total = relaxes;
    search.progress(p);
  };
  // Every segment from its exact lattice.
  std::vector<SegmentRelax> relaxed(segments.size());
  for_each_index(segments.size(), search.threads, [&](std::size_t s) {
    throw_if_cancelled(search.cancel);
    Packing p = lattice_with_vacancies(rows, segments[s]);
    if (exhaustive)
      relaxed[s].lp = relax_near_lattice(p);
    else {
      // The first ranking: stages of 80 Newton steps, ended where one stalls (at most 80 steps
      // in all above few_restarts_from disks).
      InteriorRelaxOptions ranking;
      if (few) ranking.max_newton_steps = 80;
      interior_relax(p, ranking);
    }
    relaxed[s].packing = std::move(p);
    relaxed_one("segments relaxed");
  });
  // The densest first (stable: ties keep straight_segments' order).
  std::vector<std::size_t> order(segments.size());
  for (std::size_t s = 0; s < order.size(); ++s) order[s] = s;
  auto denser = [&](std::size_t a, std::size_t b) {
    return relaxed[a].packing.d > relaxed[b].packing.d * (1 + 1e-14L);
  };
  std::stable_sort(order.begin(), order.end(), denser);
  // The finalists' bonds (the fast ranking: after the LP relax, then ranked again).
  std::vector<Pattern> patterns(segments.size());
  for_each_index(finalists, search.threads, [&](std::size_t f) {
    throw_if_cancelled(search.cancel);
    SegmentRelax& r = relaxed[order[f]];
    if (exhaustive) {
      BondIdentification id = identify_bonds(r.packing, r.lp.active);
      patterns[order[f]] = {r.packing, std::move(id.bonds), std::move(id.rattlers), {}, {}};
    } else {
      relax_interior(r.packing);  // the finalists' relax to the end
      patterns[order[f]] = finish_relaxed(r.packing);
      r.packing = patterns[order[f]].packing;
    }
  });
  std::stable_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(finalists), denser);
  // The top segments from jittered copies of their lattice (seeds 1, 2, ...).
  const std::size_t jobs = top * static_cast<std::size_t>(std::max(0, restarts));
  std::vector<Pattern> restarted(jobs);
  std::vector<char> finished(jobs, 1);
  for_each_index(jobs, search.threads, [&](std::size_t job) {
    throw_if_cancelled(search.cancel);
    const std::size_t s = job / static_cast<std::size_t>(restarts);
    const int restart = static_cast<int>(job % static_cast<std::size_t>(restarts)) + 1;
    std::mt19937_64 rng(static_cast<std::uint64_t>(restart));
    Packing start =
        jittered(lattice_with_vacancies(rows, segments[order[s]]), rows, search.jitter, rng);
    if (exhaustive) {
      restarted[job] = relax_to_pattern(start, true);
    } else {
      relax_interior(start);
      restarted[job].packing = std::move(start);
      finished[job] = 0;
    }
    relaxed_one("restarts relaxed");
  });
  // The winner, scanned in a fixed order: each top segment, then its restarts.
  SegmentChoice best;
  best.segments = segments.size();
  best.restarts = jobs;
  for (std::size_t s = 0; s < top; ++s) {
    Pattern& candidate = patterns[order[s]];
    if (s == 0 || better_pattern(candidate, best.pattern)) {
      best.pattern = std::move(candidate);
      best.vacancies = segments[order[s]];
    }
    for (int restart = 1; restart <= restarts; ++restart) {
      const std::size_t job =
          s * static_cast<std::size_t>(restarts) + static_cast<std::size_t>(restart - 1);
      Pattern& moved = restarted[job];
      if (!finished[job]) {
        if (!(moved.packing.d > best.pattern.packing.d * (1 + 1e-13L))) continue;
        moved = finish_relaxed(std::move(moved.packing));
      }
      if (better_pattern(moved, best.pattern)) {
        best.pattern = std::move(moved);
        best.vacancies = segments[order[s]];
      }
    }
  }
  return best;
}

Pattern relax_to_pattern(const Packing& start, bool exhaustive) {
  if (!exhaustive) {
    Packing p = start;
    relax_interior(p);
    return finish_relaxed(std::move(p));
  }
  Packing p = start;
  const RelaxReport lp = relax_near_lattice(p);
  return with_bonds(std::move(p), lp);
}

}  // namespace tripack::patterns
