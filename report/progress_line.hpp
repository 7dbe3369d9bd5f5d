// The one renderer of Progress (core/progress.hpp) for every long command. On a terminal: one line
// redrawn five times a second by a ticker thread from the latest report (callbacks only store it,
// so a fast stream of reports costs nothing), with a bar and ETA when the job knows its fraction
// or its item count. Elsewhere (a log, a batch job): one line per stage change and/or per
// finished item, which scripts can parse (tests/cli/campaign_soak.sh reads the campaign's).
#pragma once

#include <condition_variable>
#include <mutex>
#include <ostream>
#include <string>
#include <thread>

#include "core/progress.hpp"
#include "core/timing.hpp"

namespace tripack::report {

struct ProgressLineOptions {
  std::string job;           // the line's prefix: "billiards n=22", "campaign", "explore", ...
  bool terminal = false;     // redraw one line (else log lines)
  double quiet_seconds = 0;  // terminal: draw nothing before this (short builds stay silent)
  long long log_every = 0;   // log: a line for every log_every-th finished item and the last
  bool log_stages = false;   // log: a line when the stage changes
};

// The terminal line's text for a report `elapsed` seconds into the job.
std::string progress_text(const std::string& job, const Progress& p, double elapsed);

class ProgressLine {
 public:
  ProgressLine(std::ostream& out, ProgressLineOptions options);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  // Safe to call from any thread. On a terminal the first call starts the ticker.
  ProgressFn callback();
  // Stops the ticker and ends the line (also done by the destructor).
  void finish();

 private:
  void receive(const Progress& p);
  void tick();
  void draw();  // with mutex_ held

  std::ostream& out_;
  ProgressLineOptions options_;
  Clock::time_point start_ = Clock::now();
  std::mutex mutex_;
  std::condition_variable wake_;
  Progress latest_;
  bool has_report_ = false, stopped_ = false;
  std::string last_stage_;
  std::size_t width_ = 0;
  std::thread ticker_;
};

}  // namespace tripack::report
