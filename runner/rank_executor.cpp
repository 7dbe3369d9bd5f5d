// The MPI executor's logic, apart from the MPI calls (runner/ranks_mpi.cpp), so it is compiled and
// linked the same way with or without MPI.
#include <fmt/format.h>

#include <chrono>
#include <map>
#include <stdexcept>
#include <thread>
#include <vector>

#include "runner/dispenser.hpp"
#include "runner/ranks.hpp"

namespace tripack {

namespace {

// Rank 0's main thread: answer every worker rank's report with an item or, when none is left,
// stop; return once every worker has stopped. A result from a rank that was given no item stops
// the job (nothing of it reaches `finished`).
void serve_ranks(RankLink& link, Dispenser& dispenser) {
  std::map<int, std::size_t> given;
  int working = link.size() - 1;
  while (working > 0) {
    const auto report = link.poll_report();
    if (!report) {
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      continue;
    }
    const auto it = given.find(report->from);
    if (!report->result.empty() && it == given.end())
      dispenser.fail(std::make_exception_ptr(std::runtime_error(
          fmt::format("rank {} sent a result for no item it was given", report->from))));
    else if (it != given.end())
      dispenser.finish(it->second, report->result);
    given.erase(report->from);
    if (const auto index = dispenser.take()) {
      given[report->from] = *index;
      link.send_item(report->from, *index);
    } else {
      link.send_stop(report->from);
      --working;
    }
  }
}

}  // namespace

RankExecutor::RankExecutor(int threads)
    : link_(std::make_unique<RankLink>()), threads_(threads < 0 ? 0 : threads) {}

JobOutcome RankExecutor::run_items(const JobItems& items, const CancelToken* cancel) const {
  JobOutcome outcome;
  if (link_->rank() != 0) {
    std::string last;
    while (const auto index = link_->report_and_wait(last)) last = items.run(*index);
  } else {
    Dispenser dispenser(items, cancel);
    std::vector<std::thread> pool;
    for (int t = 0; t < threads_; ++t) pool.emplace_back([&] { dispenser.work(); });
    serve_ranks(*link_, dispenser);
    for (auto& thread : pool) thread.join();
    outcome = dispenser.close();
  }
  outcome.ranks = link_->size();
  outcome.rank = link_->rank();
  return outcome;
}

std::unique_ptr<Executor> executor_for_launch(int threads) {
  if (launched_ranks() > 1) return std::make_unique<RankExecutor>(threads);
  return std::make_unique<ThreadExecutor>(threads);
}

}  // namespace tripack
