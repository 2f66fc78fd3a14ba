#include "apps/progress_display.h"

#include <unistd.h>

namespace tpopt {
namespace {

constexpr auto kTickPeriod = std::chrono::milliseconds(100);
// Least time between two detail lines written to a pipe or file, s.
constexpr double kLogLinePeriodS = 0.5;

}  // namespace

ProgressDisplay::ProgressDisplay(FILE* out, const std::string& label, bool enabled,
                                 double delay_s)
    : out_(out),
      label_(label),
      delay_s_(delay_s),
      enabled_(enabled),
      terminal_(isatty(fileno(out)) != 0),
      start_(std::chrono::steady_clock::now()) {
  if (enabled) ticker_ = std::thread([this] { Tick(); });
}

ProgressDisplay::~ProgressDisplay() {
  if (!enabled_) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  ticker_.join();
  if (terminal_ && drawn_) std::fprintf(out_, "\r\033[K");
  // A log keeps the last state it was told, however soon the run ended.
  if (!terminal_) {
    std::lock_guard<std::mutex> lock(mutex_);
    const double elapsed_s = ElapsedS();
    if (elapsed_s >= delay_s_) LogLineLocked(elapsed_s);
  }
  std::fflush(out_);
}

double ProgressDisplay::ElapsedS() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ProgressDisplay::SetStage(const std::string& stage) {
  std::lock_guard<std::mutex> lock(mutex_);
  stage_ = stage;
  detail_.clear();
  // Stages are few and each is news: a log gets every one past the delay,
  // however short, not only those a tick happens to see.
  const double elapsed_s = ElapsedS();
  if (enabled_ && !terminal_ && elapsed_s >= delay_s_) LogLineLocked(elapsed_s);
}

void ProgressDisplay::SetDetail(const std::string& detail) {
  std::lock_guard<std::mutex> lock(mutex_);
  detail_ = detail;
}

std::string ProgressDisplay::LineLocked(double elapsed_s) const {
  char seconds[32];
  std::snprintf(seconds, sizeof(seconds), "%.1f s", elapsed_s);
  std::string line = label_ + " [" + seconds + "] " + stage_;
  if (!detail_.empty()) line += ": " + detail_;
  return line;
}

void ProgressDisplay::LogLineLocked(double elapsed_s) {
  // The elapsed time alone is no news: compare without it.
  const std::string news = stage_ + "\n" + detail_;
  if (stage_.empty() || news == last_logged_) return;
  std::fprintf(out_, "%s\n", LineLocked(elapsed_s).c_str());
  std::fflush(out_);
  last_logged_ = news;
  last_log_s_ = elapsed_s;
}

void ProgressDisplay::Tick() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, kTickPeriod, [this] { return stopping_; })) {
    const double elapsed_s = ElapsedS();
    if (elapsed_s < delay_s_ || stage_.empty()) continue;
    if (!terminal_) {
      if (elapsed_s - last_log_s_ >= kLogLinePeriodS) LogLineLocked(elapsed_s);
      continue;
    }
    // The elapsed time changes every tick, so the line is redrawn in place.
    std::fprintf(out_, "\r\033[K%s", LineLocked(elapsed_s).c_str());
    std::fflush(out_);
    drawn_ = true;
  }
}

}  // namespace tpopt
