#include "solver/smooth/feed_scheduler.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glog/logging.h>

#include "model/machine/axis_metrics.h"
#include "model/base/invalid_field.h"
#include "model/machine/planner_time.h"

namespace tpopt {
namespace {

// Smallest factor (<= 1) that brings |value| within margin * limit if feed^k
// scales it, 1 when already within the limit.
double Factor(double value, double limit, int k, double margin) {
  if (!std::isfinite(limit) || std::abs(value) <= limit) return 1.0;
  return std::pow(margin * limit / std::abs(value), 1.0 / k);
}

// One pass of corrections; returns the number of violations found.
int CorrectOnce(const Machine& machine, const MotionSamples& m, double margin,
                std::vector<double>* scale) {
  int violations = 0;
  const size_t segments = m.dt_s.size();
  auto apply = [&](size_t segment, double factor) {
    if (factor < 1.0) (*scale)[segment] = std::min((*scale)[segment], factor);
  };
  for (size_t i = 0; i < segments; ++i) {
    if (!m.cutting[i]) continue;
    for (int a = 0; a < 5; ++a) {
      const AxisLimits& lim = machine.limits[a];
      const double fv = Factor(m.velocity[i][a], lim.max_velocity, 1, margin);
      apply(i, fv);
      // Acceleration and jerk at pose i involve segments i - 1 and i (and
      // i - 2 for jerk).
      double fa = m.has_acceleration[i] ? Factor(m.acceleration[i][a], lim.max_acceleration, 2,
                                                 margin)
                                        : 1.0;
      double fj = m.has_jerk[i] ? Factor(m.jerk[i][a], lim.max_jerk, 3, margin) : 1.0;
      violations += (fv < 1.0) + (fa < 1.0) + (fj < 1.0);
      const double f = std::min(fa, fj);
      if (f < 1.0) {
        apply(i, f);
        if (i >= 1) apply(i - 1, f);
        if (fj < 1.0 && i >= 2) apply(i - 2, fj);
      }
    }
  }
  return violations;
}

// One pass over `path` as it stands: its samples, and in `scale` the factor
// of each segment's feed that its violations ask; counts them in `report`.
MotionSamples CorrectPass(const Machine& machine, const std::vector<JointVector>& joints,
                          const FeedScheduleOptions& options, const ToolPath& path, int pass,
                          std::vector<double>* scale, FeedScheduleReport* report) {
  MotionSamples m = ComputeMotionSamples(machine, path, joints, options.default_feed_mm_per_min);
  scale->assign(path.poses.size() - 1, 1.0);
  report->violations_left = CorrectOnce(machine, m, options.margin, scale);
  report->passes = pass + 1;
  return m;
}

// `machine` with kRaise's ceilings: each axis's acceleration and jerk limit
// no higher than the input's own peak (where the input has one).
Machine RaiseLimits(const Machine& machine, const FeedScheduleOptions& options) {
  Machine capped = machine;
  if (!options.keep_input_peaks) return capped;
  for (int a = 0; a < 5; ++a) {
    AxisLimits& lim = capped.limits[a];
    const double peak_acceleration = options.input_peak_acceleration[a];
    const double peak_jerk = options.input_peak_jerk[a];
    if (peak_acceleration > 0) lim.max_acceleration = std::min(lim.max_acceleration, peak_acceleration);
    if (peak_jerk > 0) lim.max_jerk = std::min(lim.max_jerk, peak_jerk);
  }
  return capped;
}

// kRaise: feed[i] is the feed of the move into pose i. Starts at each
// move's ceiling; each pass bounds the ratio of neighbouring feeds, then
// lowers the feeds around every violation; ends when a pass finds none.
void RaiseFeeds(const Machine& machine, const std::vector<JointVector>& joints,
                const FeedScheduleOptions& options, const std::vector<double>& programmed,
                ToolPath* path, FeedScheduleReport* report) {
  const size_t n = path->poses.size();
  const std::vector<bool> cutting =
      ComputeMotionSamples(machine, *path, joints, options.default_feed_mm_per_min).cutting;
  PlannerOptions planner;
  planner.default_feed_mm_per_min = options.default_feed_mm_per_min;
  std::vector<double> feed(n, 0.0);
  for (size_t i = 1; i < n; ++i) {
    // Never above the speed a blending planner can reach and leave again
    // within the move, unless the program itself asked for more (the
    // velocity limits are the passes' below, with their margin).
    const double reachable_mm_per_min =
        cutting[i - 1] ? 60.0 * PlanMove(machine, *path, joints, i - 1, planner).triangle_speed
                       : std::numeric_limits<double>::infinity();
    feed[i] = std::min({options.max_feed_factor * programmed[i], options.max_feed_mm_per_min,
                        std::max(programmed[i], reachable_mm_per_min)});
  }
  const Machine capped = RaiseLimits(machine, options);
  const double step = 1.0 + options.max_feed_step;
  // Bounds the ratio of neighbouring feed moves, forwards and backwards.
  auto bound_steps = [&](std::vector<double>* f) {
    for (size_t i = 1; i + 1 < n; ++i) {
      if (cutting[i] && cutting[i - 1]) (*f)[i + 1] = std::min((*f)[i + 1], (*f)[i] * step);
    }
    for (size_t i = n - 1; i-- > 1;) {
      if (cutting[i] && cutting[i - 1]) (*f)[i] = std::min((*f)[i], (*f)[i + 1] * step);
    }
  };
  // The input's peaks never bring a feed below the programmed one (within
  // the step): the program had them at its own feeds, and a ceiling that
  // a feed change itself exceeds would otherwise drive the feeds down
  // without end. The machine's limits may.
  std::vector<double> floor = programmed;
  bound_steps(&floor);
  for (int pass = 0; pass < options.max_passes; ++pass) {
    bound_steps(&feed);
    for (size_t i = 1; i < n; ++i) {
      if (cutting[i - 1]) path->poses[i].feed_mm_per_min = feed[i];
    }
    std::vector<double> scale_input, scale_machine;
    CorrectPass(capped, joints, options, *path, pass, &scale_input, report);
    const int input_violations = report->violations_left;
    CorrectPass(machine, joints, options, *path, pass, &scale_machine, report);
    if (input_violations == 0 && report->violations_left == 0) break;
    bool changed = false;
    for (size_t i = 0; i + 1 < n; ++i) {
      const double f = std::min(std::max(floor[i + 1], feed[i + 1] * scale_input[i]),
                                feed[i + 1] * scale_machine[i]);
      changed |= f < feed[i + 1] * (1 - 1e-12);
      feed[i + 1] = std::min(feed[i + 1], f);
    }
    if (!changed) break;  // what is left of the input's peaks is the program's own
  }
}

// kKeepRunTime: spreads each cutting run's time over its moves in
// proportion to the run's smoothed tip speed (see the header).
void KeepRunTimes(const Machine& machine, const std::vector<JointVector>& joints,
                  const FeedScheduleOptions& options, ToolPath* path,
                  FeedScheduleReport* report) {
  const MotionSamples m =
      ComputeMotionSamples(machine, *path, joints, options.default_feed_mm_per_min);
  const size_t segments = m.dt_s.size();
  // Segment i is the move into pose i + 1. Rotary-only moves, whose feed
  // is in degrees, end a run as positioning moves do.
  auto in_run = [&](size_t i) {
    return m.cutting[i] && !IsPositioningMove(path->poses[i + 1]) && m.ds_mm[i] > 1e-9;
  };
  const double half_window = 0.5 * options.keep_run_time_window_mm;
  for (size_t b = 0; b < segments;) {
    if (!in_run(b)) {
      ++b;
      continue;
    }
    size_t e = b;
    while (e < segments && in_run(e)) ++e;
    // Run [b, e): mean speed over the window around each move's middle.
    std::vector<double> s_mid(e - b);
    double s = 0.0, run_time_s = 0.0;
    for (size_t i = b; i < e; ++i) {
      s_mid[i - b] = s + 0.5 * m.ds_mm[i];
      s += m.ds_mm[i];
      run_time_s += m.dt_s[i];
    }
    std::vector<double> speed(e - b);
    size_t lo = 0, hi = 0;  // window [lo, hi) of the run's moves
    double length = 0.0, time = 0.0;
    for (size_t j = 0; j < e - b; ++j) {
      while (hi < e - b && s_mid[hi] <= s_mid[j] + half_window) {
        length += m.ds_mm[b + hi];
        time += m.dt_s[b + hi];
        ++hi;
      }
      while (s_mid[lo] < s_mid[j] - half_window) {
        length -= m.ds_mm[b + lo];
        time -= m.dt_s[b + lo];
        ++lo;
      }
      speed[j] = length / time;
    }
    double new_time_s = 0.0;
    for (size_t j = 0; j < e - b; ++j) new_time_s += m.ds_mm[b + j] / speed[j];
    const double scale = new_time_s / run_time_s;
    for (size_t j = 0; j < e - b; ++j) {
      path->poses[b + j + 1].feed_mm_per_min = 60.0 * speed[j] * scale;
    }
    report->runs_retimed += e - b >= 2;
    b = e;
  }
}

}  // namespace

bool FeedScheduleOptions::IsValid(std::string* why) const {
  FirstInvalid check;
  check.Require(margin > 0 && margin < 1, InvalidField("margin", margin, "in (0, 1)"));
  check.Require(max_feed_step > 0 && std::isfinite(max_feed_step),
          InvalidField("--max_feed_step", max_feed_step, "finite and > 0"));
  check.Require(default_feed_mm_per_min > 0 && std::isfinite(default_feed_mm_per_min),
          InvalidField("--feed", default_feed_mm_per_min, "finite and > 0 mm/min"));
  check.Require(max_passes >= 1, InvalidField("max_passes", max_passes, ">= 1"));
  check.Require(max_feed_mm_per_min > 0,
          InvalidField("--max_feed_mm_per_min", max_feed_mm_per_min, "> 0"));
  check.Require(max_feed_factor >= 1 && std::isfinite(max_feed_factor),
          InvalidField("--max_feed_factor", max_feed_factor, "finite and >= 1"));
  check.Require(keep_run_time_window_mm > 0,
          InvalidField("--keep_run_time_window_mm", keep_run_time_window_mm, "> 0"));
  return check.Report(why);
}

Status ScheduleFeed(const Machine& machine, const std::vector<JointVector>& joints,
                    const FeedScheduleOptions& options, ToolPath* path,
                    FeedScheduleReport* report) {
  std::string why;
  if (!options.IsValid(&why)) return Status::Error(why);
  CHECK_EQ(joints.size(), path->poses.size());
  *report = FeedScheduleReport();
  const size_t n = path->poses.size();
  if (n < 2) return Status::Ok();
  std::vector<double> programmed(n);
  for (size_t i = 0; i < n; ++i) {
    const double f = path->poses[i].feed_mm_per_min;
    programmed[i] = f > 0 ? f : options.default_feed_mm_per_min;
    path->poses[i].feed_mm_per_min = programmed[i];
  }
  if (options.mode == FeedMode::kKeepRunTime) KeepRunTimes(machine, joints, options, path, report);
  const double step = 1.0 + options.max_feed_step;
  for (int pass = 0; options.mode != FeedMode::kRaise && pass < options.max_passes; ++pass) {
    std::vector<double> scale;
    const MotionSamples m = CorrectPass(machine, joints, options, *path, pass, &scale, report);
    if (report->violations_left == 0) break;
    std::vector<double> feed(n - 1);
    for (size_t i = 0; i + 1 < n; ++i) feed[i] = path->poses[i + 1].feed_mm_per_min * scale[i];
    // Bound the ratio of neighbouring feed moves, forwards and backwards.
    for (size_t i = 1; i + 1 < n; ++i) {
      if (m.cutting[i] && m.cutting[i - 1]) feed[i] = std::min(feed[i], feed[i - 1] * step);
    }
    for (size_t i = n - 1; i-- > 1;) {
      if (m.cutting[i] && m.cutting[i - 1]) feed[i - 1] = std::min(feed[i - 1], feed[i] * step);
    }
    for (size_t i = 0; i + 1 < n; ++i) {
      if (m.cutting[i]) path->poses[i + 1].feed_mm_per_min = feed[i];
    }
  }
  if (options.mode == FeedMode::kRaise) {
    RaiseFeeds(machine, joints, options, programmed, path, report);
  }
  report->min_feed_mm_per_min = programmed[0];
  report->max_feed_mm_per_min = programmed[0];
  for (size_t i = 1; i < n; ++i) {
    const double f = path->poses[i].feed_mm_per_min;
    report->moves_slowed += f < programmed[i] * (1 - 1e-9);
    report->moves_raised += f > programmed[i] * (1 + 1e-9);
    report->min_feed_mm_per_min = std::min(report->min_feed_mm_per_min, f);
    report->max_feed_mm_per_min = std::max(report->max_feed_mm_per_min, f);
  }
  return Status::Ok();
}

}  // namespace tpopt
