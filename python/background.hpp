// A long call from Python (docs/python.md, "Long calls"): the job runs on a thread of its own
// while the calling thread waits with the GIL released, so other Python threads run. Every 50 ms
// the caller takes the GIL back to hand the job's progress to the Python callback and to let
// Python run its signal handlers: a KeyboardInterrupt (or an exception from the callback) stops
// and abandons the job through its CancelToken, waits for it to end, and propagates.
// The job never touches a Python object; only the calling thread does.
#pragma once

#include <pybind11/pybind11.h>

#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include "core/progress.hpp"

namespace tripack::python {

// Progress as the callback receives it: a dict of the fields that say where a job is.
pybind11::dict progress_dict(const Progress& p);

// Runs work(job) on a thread; returns its result or rethrows its exception in the caller.
template <class Work>
auto run_in_background(Work work, const pybind11::object& progress_callback)
    -> decltype(work(std::declval<const JobContext&>())) {
  namespace py = pybind11;
  using Result = decltype(work(std::declval<const JobContext&>()));
  struct Mailbox {
    std::mutex mutex;
    std::condition_variable changed;
    std::deque<Progress> reports;
    bool finished = false;
  } mailbox;
  // A slow callback must not let the reports pile up: the oldest are dropped past this many.
  constexpr std::size_t kMaxQueued = 1000;
  CancelToken token;
  JobContext job;
  job.cancel = &token;
  job.tool_version = "tripack python";
  if (!progress_callback.is_none())
    job.progress = [&mailbox](const Progress& p) {
      std::lock_guard<std::mutex> lock(mailbox.mutex);
      if (mailbox.reports.size() == kMaxQueued) mailbox.reports.pop_front();
      mailbox.reports.push_back(p);
      mailbox.changed.notify_one();
    };
  std::optional<Result> result;
  std::exception_ptr failure;
  std::thread worker([&] {
    try {
      result.emplace(work(job));
    } catch (...) {  // Abandoned and Cancelled too: the caller decides what they mean
      failure = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(mailbox.mutex);
    mailbox.finished = true;
    mailbox.changed.notify_one();
  });
  const auto stop_and_join = [&] {
    token.cancel();
    token.abandon();
    py::gil_scoped_release release;
    worker.join();
  };
  for (bool finished = false; !finished;) {
    std::deque<Progress> reports;
    {
      py::gil_scoped_release release;
      std::unique_lock<std::mutex> lock(mailbox.mutex);
      mailbox.changed.wait_for(lock, std::chrono::milliseconds(50),
                               [&] { return mailbox.finished || !mailbox.reports.empty(); });
      reports.swap(mailbox.reports);
      finished = mailbox.finished;
    }
    try {
      for (const auto& p : reports) progress_callback(progress_dict(p));
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    } catch (...) {
      stop_and_join();
      throw;
    }
  }
  worker.join();
  if (failure) std::rethrow_exception(failure);
  return std::move(*result);
}

}  // namespace tripack::python
