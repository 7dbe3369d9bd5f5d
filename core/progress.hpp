// What every long computation says about itself while it runs, and how it is asked to stop.
// One Progress type for all of them (a billiards run, an analysis, a search, a campaign, the
// atlas, the explorer, the accuracy study, an import), rendered by one function
// (report/progress_line.hpp); one CancelToken that main() sets on Ctrl-C or SIGTERM. Neither is
// global: a job receives both, in its JobContext.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>

namespace tripack {

struct Progress {
  std::string stage;  // the kind of work: "billiards", "relax", "campaign", "atlas", ...
  std::string item;   // the item under way or just finished, in words
  long long done = 0, total = 0;  // items of the stage finished and to do (total 0: not counted)
  long long skipped = 0;          // items an earlier call finished (a resumed campaign)
  double fraction = -1;           // of the whole job when weighted by cost (-1: done / total)
  double elapsed = 0;             // seconds since the job (or the run) started
  bool item_finished = false;     // this report ends an item (else: a snapshot of one under way)
  long double d = 0;              // the d reached (0: none yet, or not certified)
  int step = 0;                   // an iterative stage's step (relax), 0 otherwise
  // A billiards run under way.
  std::uint64_t events = 0;
  double relative_gap = 0;  // estimate of 1 - diameter / jammed diameter (0: none)
  double events_per_second() const {
    return elapsed > 0 ? static_cast<double>(events) / elapsed : 0;
  }
};
using ProgressFn = std::function<void(const Progress&)>;

// A progress callback that may be called from several threads at once, one call at a time.
inline ProgressFn serialised(ProgressFn progress) {
  if (!progress) return {};
  auto lock = std::make_shared<std::mutex>();
  return [lock, progress = std::move(progress)](const Progress& p) {
    std::lock_guard<std::mutex> guard(*lock);
    progress(p);
  };
}

// Asked to stop, in two steps (docs/cli.md, "Ctrl-C"). Stop: the job starts no new item; items
// under way finish, and its result says it was cancelled and holds what finished. Abandon: items
// under way that check the token (a billiards run, every 4096 events) give up by throwing
// Abandoned, and the job reports and records what finished before them.
class CancelToken {
 public:
  void cancel() {
    int none = 0;  // never lowers an abandon
    level_.compare_exchange_strong(none, 1);
  }
  void abandon() { level_.store(2); }
  bool cancelled() const { return level_.load() >= 1; }
  bool abandoned() const { return level_.load() >= 2; }
  // A job that is one item (a build) may sit in one library call for minutes (a sparse QR of 10^6
  // disks) with no check: the signal thread ends it after a grace time (app/main.cpp). The job
  // and that thread claim the ending once; the job claims it when its computation ends, before it
  // writes anything, so it is never ended halfway through its output.
  bool claim_ending() const { return !ending_claimed_.exchange(true); }

 private:
  std::atomic<int> level_{0};
  mutable std::atomic<bool> ending_claimed_{false};  // claimable by the jobs, which hold it const
};

// Thrown by an item under way that gives up on an abandoned token; the runner drops the item (it
// did not finish). Not a std::exception, so that the handlers that turn an item's errors into
// its result do not take it for one.
struct Abandoned {};

inline void throw_if_abandoned(const CancelToken* token) {
  if (token && token->abandoned()) throw Abandoned{};
}

// A job that is one item (a build: nothing finished to keep until it ends) stops at the first
// request: its next check throws Cancelled, and the command reports the interruption.
struct Cancelled {};

inline void throw_if_cancelled(const CancelToken* token) {
  if (token && token->cancelled()) throw Cancelled{};
}

inline bool cancelled(const CancelToken* token) {
  return token && token->cancelled();
}

// What every long job is given, the one way it is given (docs/architecture.md, "Long jobs"): how
// it is asked to stop, where it reports its progress, and the tool's version it records with what
// it stores. A job's result says `cancelled` when the token stopped it before every item ran.
struct JobContext {
  const CancelToken* cancel = nullptr;
  ProgressFn progress;
  std::string tool_version;

  bool cancelled() const { return tripack::cancelled(cancel); }
  void report(const Progress& p) const {
    if (progress) progress(p);
  }
};

}  // namespace tripack
