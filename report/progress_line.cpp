#include "report/progress_line.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

namespace tripack::report {

namespace {

// Of the whole job: the job's own (cost-weighted) fraction, else items done / items.
double fraction_of(const Progress& p) {
  if (p.fraction >= 0) return std::min(1.0, p.fraction);
  return p.total > 0 ? static_cast<double>(p.done) / static_cast<double>(p.total) : -1;
}

}  // namespace

std::string progress_text(const std::string& job, const Progress& p, double elapsed) {
  std::string line = fmt::format("{}:", job);
  const double fraction = fraction_of(p);
  if (p.fraction >= 0) {
    const int width = 30, filled = static_cast<int>(fraction * width + 0.5);
    line += fmt::format(" [{}{}] {:3.0f}%", std::string(static_cast<std::size_t>(filled), '#'),
                        std::string(static_cast<std::size_t>(width - filled), '.'), fraction * 100);
  }
  if (p.total > 0) line += fmt::format(" {}/{}", p.done, p.total);
  if (p.skipped > 0) line += fmt::format(" ({} already recorded)", p.skipped);
  line += fmt::format(" {:.1f} s", elapsed);
  if (fraction > 0.02 && fraction < 1)
    line += fmt::format(", ETA {:.0f} s", elapsed * (1 - fraction) / fraction);
  if (!p.stage.empty() && job.rfind(p.stage, 0) != 0) line += fmt::format(", {}", p.stage);
  if (!p.item.empty()) line += fmt::format(": {}", p.item);
  if (p.step > 0) line += fmt::format(" step {}", p.step);
  if (p.d > 0 && !p.item_finished) line += fmt::format(", d = {:.12Lg}", p.d);
  if (p.events > 0 && !p.item_finished)
    line += fmt::format(", {:.2f} M events/s", p.events_per_second() / 1e6);
  if (p.relative_gap > 0 && !p.item_finished) line += fmt::format(", gap ~{:.1e}", p.relative_gap);
  return line;
}

ProgressLine::ProgressLine(std::ostream& out, ProgressLineOptions options)
    : out_(out), options_(std::move(options)) {}

ProgressLine::~ProgressLine() {
  finish();
}

ProgressFn ProgressLine::callback() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (options_.terminal && !ticker_.joinable() && !stopped_)
    ticker_ = std::thread([this] { tick(); });
  return [this](const Progress& p) { receive(p); };
}

void ProgressLine::receive(const Progress& p) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (stopped_) return;
  latest_ = p;
  has_report_ = true;
  if (options_.terminal) return;  // the ticker draws
  const double elapsed = seconds_since(start_);
  if (options_.log_stages && p.stage != last_stage_)
    out_ << fmt::format("{}: {} ({:.0f} s)\n", options_.job, p.stage, elapsed) << std::flush;
  last_stage_ = p.stage;
  if (options_.log_every > 0 && p.item_finished &&
      (p.done % options_.log_every == 0 || p.done == p.total)) {
    std::string line = fmt::format("{}: {} (", options_.job, p.item);
    if (p.total > 0) line += fmt::format("{}/{}, ", p.done, p.total);
    out_ << line << fmt::format("{:.0f} s)\n", elapsed) << std::flush;
  }
}

void ProgressLine::draw() {
  const double elapsed = seconds_since(start_);
  if (!has_report_ || elapsed < options_.quiet_seconds) return;
  std::string line = fmt::format("\r{}", progress_text(options_.job, latest_, elapsed));
  const std::size_t length = line.size();
  line.append(width_ > length ? width_ - length : 0, ' ');  // clear what a longer line left
  width_ = length;
  out_ << line << std::flush;
}

void ProgressLine::tick() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, std::chrono::milliseconds(200), [this] { return stopped_; })) draw();
}

void ProgressLine::finish() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopped_) return;
    stopped_ = true;
    if (options_.terminal) draw();  // the last state, so a short job's line is complete
  }
  wake_.notify_all();
  if (ticker_.joinable()) ticker_.join();
  if (width_ > 0) out_ << "\n" << std::flush;
}

}  // namespace tripack::report
