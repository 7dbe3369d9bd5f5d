// The search (search/search.hpp): reproducible on one thread with a step budget, reaches
// proven optima, stops at a target, continues from given packings, records as campaign units.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "constructors/catalogue.hpp"
#include "jobs/stored.hpp"
#include "pipeline/build.hpp"
#include "search/search.hpp"
#include "store/results_db.hpp"

namespace tripack {
namespace {

search::SearchRequest request(long long n, long long steps, std::uint64_t seed) {
  search::SearchRequest r;
  r.n = n;
  r.steps = steps;
  r.seconds = 600;  // the step budget decides
  r.seed = seed;
  return r;
}

// Two runs of one seed on one thread with a step budget: the same packings, digit for digit.
TEST(Search, SameSeedOneThreadGivesTheSameResult) {
  for (const auto method : {search::SearchMethod::BasinHopping, search::SearchMethod::Restarts}) {
    search::SearchRequest r = request(23, 25, 11);
    r.method = method;
    const search::SearchResult a = search::run_search(r);
    const search::SearchResult b = search::run_search(r);
    ASSERT_FALSE(a.packings.empty());
    ASSERT_EQ(a.packings.size(), b.packings.size());
    for (std::size_t i = 0; i < a.packings.size(); ++i) {
      EXPECT_EQ(a.packings[i].d.str(), b.packings[i].d.str());
      EXPECT_EQ(a.packings[i].label, b.packings[i].label);
      EXPECT_EQ(a.packings[i].graph_hash, b.packings[i].graph_hash);
    }
    EXPECT_EQ(a.steps(), 25);
    EXPECT_EQ(a.chains.at(0).analyses, b.chains.at(0).analyses);
  }
}

// Delta(4) = 10 disks: the optimum is the hexagonal packing, d = 1/3 (Oler's bound is attained;
// GL1995 sec. 1). Two chains on two threads both reach it, certified, and the best says when.
TEST(Search, ReachesTheProvenOptimumOfTen) {
  search::SearchRequest r = request(10, 20, 1);
  r.threads = 2;
  const search::SearchResult result = search::run_search(r);
  ASSERT_FALSE(result.packings.empty());
  const PackingRecord& best = result.packings.front();
  EXPECT_TRUE(best.certified);
  EXPECT_NEAR(static_cast<double>(best.d.value()), 1.0 / 3.0, 1e-15);
  EXPECT_EQ(best.label, "t10a");
  ASSERT_EQ(result.chains.size(), 2u);
  EXPECT_EQ(result.chains[0].seed, 1u);
  EXPECT_EQ(result.chains[1].seed, 2u);
  EXPECT_GE(result.seconds_to_best, 0);
  EXPECT_LE(result.seconds_to_best, result.seconds);
  for (const auto& chain : result.chains) ASSERT_TRUE(chain.best.has_value());
  // A packing's runs are the chains that reached it, however often each met it.
  for (const auto& p : result.packings) EXPECT_LE(p.runs(), 2) << p.label;
  EXPECT_EQ(best.runs(), 2);
}

// Delta(5) - 2 = 13 disks: GL1995's class Delta(k+2)-2 at k = 3, d(13) = 3/(6 + sqrt6 + 2 sqrt3)
// (docs/classes.md, "Closed forms"; GL1995 gives d(13) as a root of 4x^4 - 144x^3 + ...). A
// lattice start is Delta(5) with two vacancies; 20 steps of one chain reach it for every seed
// tried, certified.
TEST(Search, ReachesTheClosedFormOfThirteen) {
  const double d13 = 3 / (6 + std::sqrt(6.0) + 2 * std::sqrt(3.0));
  for (std::uint64_t seed : {1, 2, 3}) {
    const search::SearchResult result = search::run_search(request(13, 20, seed));
    ASSERT_FALSE(result.packings.empty());
    EXPECT_TRUE(result.packings.front().certified);
    EXPECT_NEAR(static_cast<double>(result.packings.front().d.value()), d13, 1e-15) << seed;
  }
}

// A target stops the chain at the step that reached it: the hexagonal 15 = Delta(5), d = 1/4.
TEST(Search, StopsOnceTheTargetIsReached) {
  search::SearchRequest r = request(15, 500, 3);
  r.target = 0.25L;
  const search::SearchResult result = search::run_search(r);
  const search::SearchChain& chain = result.chains.at(0);
  ASSERT_TRUE(chain.target_reached);
  EXPECT_LT(chain.steps, 500);
  EXPECT_NEAR(static_cast<double>(std::stold(chain.best_d)), 0.25, 1e-15);
  EXPECT_LE(chain.cpu_seconds_to_target, chain.cpu_seconds + 1e-9);
}

// Continuing from a packing: the first step analyses it, so the best is at least that good at
// once. The start here is the hexagonal Delta(4) itself (d = 1/3).
TEST(Search, ContinuesFromTheGivenPackings) {
  Packing hexagonal;
  hexagonal.d = 1.0L / 3;
  for (int row = 0; row < 4; ++row)
    for (int i = 0; i < 4 - row; ++i)
      hexagonal.points.push_back({(i + row / 2.0L) / 3, row * std::sqrt(3.0L) / 6});
  search::SearchRequest r = request(10, 1, 5);
  r.starts = {hexagonal};
  const search::SearchResult result = search::run_search(r);
  ASSERT_FALSE(result.packings.empty());
  EXPECT_NEAR(static_cast<double>(result.packings.front().d.value()), 1.0 / 3.0, 1e-15);
  EXPECT_EQ(search::search_method(r), "search 600 s, continued");
}

// Started from the builders, a search never returns less than `build --n N`, even with one step:
// at n = 48 the builder's vacancy-segment packing (docs/findings.md) is denser than any search
// has found from random. The builder's time is the chain's time to it, and the chains, started
// from it, confirm nothing independently.
TEST(Search, StartsFromTheBuilderAndNeverReturnsLess) {
  const Catalogue catalogue = Catalogue::load(Catalogue::default_path());
  const long double built = pipeline::build_best_for_n(catalogue, 48, {}).best.record.d.value();
  search::SearchRequest r = request(48, 1, 7);
  r.builders = &catalogue;
  r.target = built;
  const search::SearchResult result = search::run_search(r);
  ASSERT_TRUE(result.builder.has_value());
  EXPECT_TRUE(result.builder->certified);
  EXPECT_GE(result.builder->candidates, 1);
  ASSERT_FALSE(result.packings.empty());
  EXPECT_GE(result.packings.front().d.value(), built * (1 - 1e-15L));
  const search::SearchChain& chain = result.chains.at(0);
  ASSERT_TRUE(chain.target_reached);
  EXPECT_EQ(chain.steps, 0);
  EXPECT_DOUBLE_EQ(chain.cpu_seconds_to_target, result.builder->cpu_seconds);
  for (const auto& p : result.packings)
    for (const auto& source : p.sources)
      if (source.kind == PackingSource::Kind::Billiards) {
        EXPECT_EQ(source.independent_runs, 0);
      }
  EXPECT_EQ(search::search_method(result), "search 600 s, from builders");
  // Without a target the chain's own steps go on from the builder's packing.
  r.target.reset();
  r.steps = 3;
  const search::SearchResult longer = search::run_search(r);
  EXPECT_EQ(longer.chains.at(0).steps, 3);
  EXPECT_GE(longer.packings.front().d.value(), built * (1 - 1e-15L));
  // The switch off: no builder, and the method says so.
  r.builder_starts = false;
  EXPECT_EQ(search::search_method(r), "search 600 s");
  EXPECT_FALSE(search::run_search(r).builder.has_value());
}

// Where the builder's certificate declines (197's vacancy-segment packing is a degenerate
// maximum: docs/certified.md), the search still returns it, flagged uncertified, rather than
// less: with no step taken, the result is the builder's packing and nothing else.
TEST(Search, KeepsTheBuildersPackingWhenItsCertificateDeclines) {
  const Catalogue catalogue = Catalogue::load(Catalogue::default_path());
  search::SearchRequest r = request(197, 0, 1);
  r.seconds = 1e-3;  // spent by the build: no step
  r.builders = &catalogue;
  const search::SearchResult result = search::run_search(r);
  ASSERT_TRUE(result.builder.has_value());
  ASSERT_FALSE(result.builder->certified);
  ASSERT_EQ(result.packings.size(), 1u);
  // builder->d is printed to long double's 18 digits: equal to 1e-17 relative.
  const long double built = std::stold(result.builder->d);
  EXPECT_NEAR(static_cast<double>(result.packings.front().d.value() / built), 1.0, 1e-17);
  EXPECT_FALSE(result.packings.front().certified);
}

TEST(Search, RefusesBadRequests) {
  EXPECT_THROW(search::run_search(request(1, 5, 1)), std::invalid_argument);
  search::SearchRequest r = request(10, 5, 1);
  r.threads = 0;
  EXPECT_THROW(search::run_search(r), std::invalid_argument);
  r = request(10, 5, 1);
  r.seconds = 0;
  EXPECT_THROW(search::run_search(r), std::invalid_argument);
  r = request(10, 5, 1);
  r.starts = {Packing{{{0, 0}, {1, 0}}, 1}};
  EXPECT_THROW(search::run_search(r), std::invalid_argument);
}

// A chain as a database unit: (n, seed, "search S s") with its best packing; recorded once.
TEST(Search, AChainIsACampaignUnit) {
  // A name of this process's own; the WAL and shared-memory files beside it go with it.
  const auto path = std::filesystem::temp_directory_path() /
                    ("tripack-search-unit-" + std::to_string(::getpid()) + ".db");
  const auto remove_all = [&] {
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path.string() + suffix);
  };
  remove_all();
  const search::SearchResult result = search::run_search(request(10, 4, 2));
  const store::RunRecord run = jobs::run_record_of(result, 0, "test");
  EXPECT_EQ(run.method, "search 600 s");
  EXPECT_EQ(run.events, 4);
  ASSERT_TRUE(run.packing.has_value());
  {
    store::ResultsDb db = store::ResultsDb::open(path.string());
    EXPECT_TRUE(db.record(run));
    EXPECT_FALSE(db.record(run));
    EXPECT_TRUE(db.has_run(10, 2, "search 600 s"));
    EXPECT_FALSE(db.has_run(10, 2));  // no billiards run of seed 2
    const auto starts = jobs::stored_starts(db, 10, 3);
    ASSERT_EQ(starts.size(), 1u);
    EXPECT_NEAR(static_cast<double>(starts[0].d), 1.0 / 3.0, 1e-15);
  }
  remove_all();
}

}  // namespace
}  // namespace tripack
