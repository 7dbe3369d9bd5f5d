// The one way a long job runs its items: a cancellable pool that hands out item indices one at a
// time to workers and gives every finished item back to the job on one thread at a time. Where
// the workers are is the executor's business: threads of this process (ThreadExecutor) or other
// MPI ranks plus threads of rank 0 (RankExecutor, runner/ranks.hpp). The billiards runs, a
// campaign, the atlas, the explorer, the accuracy study and an import all run through it.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/progress.hpp"
#include "core/timing.hpp"

namespace tripack {

struct JobItems {
  std::size_t count = 0;  // items 0 .. count - 1, unless `order` says which
  // The items to run, in this order. Every process of an MPI launch must agree on what an index
  // means; only rank 0's order counts (a campaign skips what its database already holds).
  std::optional<std::vector<std::size_t>> order;
  // Runs item i on some worker. Its result, when it has to travel to rank 0 (RankExecutor), is
  // the returned text; a job run on threads only may store its result itself and return "".
  // Under MPI it must not throw on a worker rank (rank 0 would wait for its report): catch and
  // encode the error instead, as a campaign's unit does.
  std::function<std::string(std::size_t)> run;
  // Rank 0, one call at a time, as items finish: the index and what run() returned. An exception
  // thrown here (a database write failed, a worker's result is malformed) stops the job: no item
  // starts after it, and run_items rethrows it once the items under way are done.
  std::function<void(std::size_t, const std::string&)> finished;
};

struct JobOutcome {
  std::size_t finished = 0;  // items finished (on rank 0: reported back)
  bool cancelled = false;    // the token stopped it before every item ran
  int ranks = 1, rank = 0;   // of an MPI launch; only rank 0's outcome counts items
};

class Executor {
 public:
  virtual ~Executor() = default;
  virtual JobOutcome run_items(const JobItems& items, const CancelToken* cancel) const = 0;
  // Only rank 0 of an MPI launch calls `finished` and may use the database or print a result.
  virtual int rank() const { return 0; }
};

// `threads` workers, this thread among them.
class ThreadExecutor final : public Executor {
 public:
  explicit ThreadExecutor(int threads) : threads_(threads < 1 ? 1 : threads) {}
  JobOutcome run_items(const JobItems& items, const CancelToken* cancel) const override;

 private:
  int threads_;
};

// Resume, the runner's one way (docs/architecture.md, "Long jobs"): a resumable job names each item
// by a key, and `done` holds the keys of the items an earlier run finished, read from the store
// (a campaign's runs) or from a formats/ table (the exact atlas's rows), never parsed by hand.
// Leaves in items.order only the items still to run, in their order; returns how many it skipped.
long long skip_done(JobItems& items, const std::function<std::string(std::size_t)>& key,
                    const std::set<std::string>& done);

// Elapsed seconds and the item count for a job's Progress reports (done() may be read from any
// thread while finished() counts on the one that records).
class ProgressCounter {
 public:
  ProgressCounter(std::string stage, long long total);
  // The report of an item that just finished (done counts it).
  Progress finished(std::string item, long double d = 0);
  Progress snapshot(std::string item) const;
  long long done() const { return done_; }
  double elapsed() const;

 private:
  std::string stage_;
  long long total_;
  std::atomic<long long> done_{0};
  Clock::time_point start_ = Clock::now();
};

}  // namespace tripack
