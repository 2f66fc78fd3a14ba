// A one-line progress display on stderr for runs that take a while.
//
// Short runs stay silent: nothing is shown until `delay_s` has passed, so
// a command that finishes in under a second prints only its summary. After
// that a background ticker shows the current stage, its latest detail and
// the elapsed time: redrawn in place on a terminal; on a pipe or log file,
// a line for every new stage, for a changed detail at most twice a second
// (so a log does not fill with one line per Ceres iteration), and for the
// last state when the display ends.
#ifndef TPOPT_APPS_PROGRESS_DISPLAY_H_
#define TPOPT_APPS_PROGRESS_DISPLAY_H_

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>

namespace tpopt {

class ProgressDisplay {
 public:
  // Shows nothing at all when `enabled` is false (--quiet). `label` starts
  // each line, e.g. "tpopt smooth". `out` must outlive the display.
  ProgressDisplay(FILE* out, const std::string& label, bool enabled, double delay_s);
  // Stops the ticker; on a terminal, clears the line it drew.
  ~ProgressDisplay();
  ProgressDisplay(const ProgressDisplay&) = delete;
  ProgressDisplay& operator=(const ProgressDisplay&) = delete;

  // A new stage, e.g. "evaluating the input"; clears the detail.
  void SetStage(const std::string& stage);
  // Detail within the stage, e.g. "iteration 12, cost 3.1e-02".
  void SetDetail(const std::string& detail);

 private:
  void Tick();
  double ElapsedS() const;
  std::string LineLocked(double elapsed_s) const;
  // Writes the current state to a log unless it is the state last written.
  void LogLineLocked(double elapsed_s);

  FILE* out_;
  const std::string label_;
  const double delay_s_;
  const bool enabled_;
  const bool terminal_;
  const std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::string stage_, detail_, last_logged_;
  double last_log_s_ = -1.0;
  bool drawn_ = false;
  std::thread ticker_;  // last: started once every other member is ready
};

}  // namespace tpopt

#endif  // TPOPT_APPS_PROGRESS_DISPLAY_H_
