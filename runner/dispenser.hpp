// The runner's shared state (runner/runner.hpp): the next item, the finished count, the first
// failure. Both executors hand out items through it, so cancelling and failing behave the same
// on threads and on MPI ranks.
#pragma once

#include <exception>
#include <mutex>
#include <optional>

#include "runner/runner.hpp"

namespace tripack {

class Dispenser {
 public:
  Dispenser(const JobItems& items, const CancelToken* cancel);
  // The next item; none when every item is handed out, after a failure, or when cancelled.
  std::optional<std::size_t> take();
  // An item's result to the job (one at a time); an exception there becomes the failure.
  void finish(std::size_t index, const std::string& result);
  void fail(std::exception_ptr error);
  // A worker: take, run, finish until none is left. run() throwing stops the job.
  void work();
  // After every worker has stopped: the outcome, or the failure rethrown.
  JobOutcome close();

 private:
  const JobItems& items_;
  const CancelToken* cancel_;
  std::mutex mutex_;
  std::size_t next_ = 0, total_, finished_ = 0;
  std::exception_ptr failure_;
};

}  // namespace tripack
