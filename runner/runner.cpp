#include "runner/runner.hpp"

#include <thread>

#include "runner/dispenser.hpp"

namespace tripack {

Dispenser::Dispenser(const JobItems& items, const CancelToken* cancel)
    : items_(items), cancel_(cancel), total_(items.order ? items.order->size() : items.count) {}

std::optional<std::size_t> Dispenser::take() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (next_ == total_ || failure_ || cancelled(cancel_)) return std::nullopt;
  const std::size_t at = next_++;
  return items_.order ? (*items_.order)[at] : at;
}

void Dispenser::finish(std::size_t index, const std::string& result) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (failure_) return;
  try {
    if (items_.finished) items_.finished(index, result);
    ++finished_;
  } catch (...) {
    failure_ = std::current_exception();
  }
}

void Dispenser::fail(std::exception_ptr error) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!failure_) failure_ = error;
}

void Dispenser::work() {
  while (const auto index = take()) {
    std::string result;
    try {
      result = items_.run(*index);
    } catch (const Abandoned&) {
      continue;  // the token was abandoned: the item did not finish, and take() hands out no more
    } catch (...) {
      fail(std::current_exception());
      return;
    }
    finish(*index, result);
  }
}

JobOutcome Dispenser::close() {
  if (failure_) std::rethrow_exception(failure_);
  JobOutcome outcome;
  outcome.finished = finished_;
  outcome.cancelled = finished_ < total_;
  return outcome;
}

JobOutcome ThreadExecutor::run_items(const JobItems& items, const CancelToken* cancel) const {
  Dispenser dispenser(items, cancel);
  std::vector<std::thread> pool;
  for (int t = 1; t < threads_; ++t) pool.emplace_back([&] { dispenser.work(); });
  dispenser.work();
  for (auto& thread : pool) thread.join();
  return dispenser.close();
}

long long skip_done(JobItems& items, const std::function<std::string(std::size_t)>& key,
                    const std::set<std::string>& done) {
  std::vector<std::size_t> all;
  if (items.order) {
    all = *items.order;
  } else {
    for (std::size_t i = 0; i < items.count; ++i) all.push_back(i);
  }
  std::vector<std::size_t> pending;
  for (std::size_t i : all)
    if (!done.count(key(i))) pending.push_back(i);
  const auto skipped = static_cast<long long>(all.size() - pending.size());
  items.order = std::move(pending);
  return skipped;
}

ProgressCounter::ProgressCounter(std::string stage, long long total)
    : stage_(std::move(stage)), total_(total) {}

double ProgressCounter::elapsed() const {
  return seconds_since(start_);
}

Progress ProgressCounter::snapshot(std::string item) const {
  Progress p;
  p.stage = stage_;
  p.item = std::move(item);
  p.done = done_;
  p.total = total_;
  p.elapsed = elapsed();
  return p;
}

Progress ProgressCounter::finished(std::string item, long double d) {
  ++done_;
  Progress p = snapshot(std::move(item));
  p.item_finished = true;
  p.d = d;
  return p;
}

}  // namespace tripack
