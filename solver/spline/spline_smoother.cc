#include "solver/spline/spline_smoother.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include <glog/logging.h>

#include "model/base/invalid_field.h"
#include "model/path/rail_projection.h"
#include "model/base/units.h"
#include "solver/spline/overhang.h"
#include "solver/spline/pole_crossing.h"
#include "solver/spline/pose_spline.h"
#include "solver/spline/smoothing_spline.h"

namespace tpopt {
namespace {

constexpr double kMinStepMm = 1e-6;
// A pole passage this close to its plane through +Z already crosses the
// pole: a nanoradian, far above round-off, far below any CAM error.
constexpr double kOnPlaneRad = 1e-9;

double Median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// |d2 y / ds2| at interior poses from divided differences (0 at the ends).
std::vector<double> SecondDerivative(const std::vector<double>& s, const std::vector<double>& y) {
  std::vector<double> d(s.size(), 0.0);
  for (size_t i = 1; i + 1 < s.size(); ++i) {
    const double slope1 = (y[i + 1] - y[i]) / (s[i + 1] - s[i]);
    const double slope0 = (y[i] - y[i - 1]) / (s[i] - s[i - 1]);
    d[i] = std::abs(2.0 * (slope1 - slope0) / (s[i + 1] - s[i - 1]));
  }
  return d;
}

// Marks poses whose `measure` exceeds factor x its median.
void MarkAbove(const std::vector<double>& measure, double factor, std::vector<bool>* zone) {
  const double threshold = factor * Median(measure);
  for (size_t i = 0; i < measure.size(); ++i) {
    if (measure[i] > threshold && measure[i] > 0) (*zone)[i] = true;
  }
}

// Pads zones by `padding` poses and counts them.
int PadZones(int padding, std::vector<bool>* zone) {
  const std::vector<bool> core = *zone;
  const int n = static_cast<int>(core.size());
  for (int i = 0; i < n; ++i) {
    if (!core[i]) continue;
    for (int j = std::max(0, i - padding); j <= std::min(n - 1, i + padding); ++j) {
      (*zone)[j] = true;
    }
  }
  int zones = 0;
  for (int i = 0; i < n; ++i) zones += (*zone)[i] && (i == 0 || !(*zone)[i - 1]);
  return zones;
}

// Tangency rebuild: the axis line passes at R from the contact point along
// the surface normal made perpendicular to the axis.
Eigen::Vector3d TangentTip(const RuledSurface& surface, double radius_mm, double u,
                           const Eigen::Vector3d& axis) {
  const Eigen::Vector3d n = surface.Normal(u, 0.0);
  const Eigen::Vector3d offset = (n - n.dot(axis) * axis).normalized();
  return surface.rail(0).Point(u) + radius_mm * offset;
}

// Fitted angle with each zone's ends pinned to the untouched poses around
// it: the fit's offset from the data at the first pose before and after a
// zone is removed linearly across the zone, so the modified stretch joins
// its neighbours without a step. Pins are kept per zone, not per pose: a
// long path has few zones, and per-pose pins were a page-faulting array as
// large as the path.
class PinnedFit {
 public:
  PinnedFit(const SmoothingSpline& fit, const std::vector<double>& s,
            const std::vector<double>& y, const std::vector<bool>& zone)
      : fit_(fit) {
    const size_t n = s.size();
    for (size_t i = 0; i < n; ++i) {
      if (!zone[i] || (i > 0 && zone[i - 1])) continue;
      size_t end = i;
      while (end + 1 < n && zone[end + 1]) ++end;
      const size_t l = i > 0 ? i - 1 : i, r = end + 1 < n ? end + 1 : end;
      pins_.push_back({i, end, s[l], y[l] - fit(s[l]), s[r], y[r] - fit(s[r])});
      i = end;
    }
  }

  // Value at arc length s_mm for pose i; outside zones the pins are zero
  // and this is the plain fit.
  double At(size_t i, double s_mm) const {
    const Pin* pin = ZoneOf(i);
    if (pin == nullptr) return fit_(s_mm);
    const double t =
        pin->s_r > pin->s_l ? std::clamp((s_mm - pin->s_l) / (pin->s_r - pin->s_l), 0.0, 1.0)
                            : 0.0;
    return fit_(s_mm) + pin->d_l + (pin->d_r - pin->d_l) * t;
  }

 private:
  // Zone [first, last] and the fit's offsets (s, offset) at its two pins.
  struct Pin {
    size_t first, last;
    double s_l, d_l, s_r, d_r;
  };

  const Pin* ZoneOf(size_t i) const {
    const auto after = std::upper_bound(pins_.begin(), pins_.end(), i,
                                        [](size_t k, const Pin& pin) { return k < pin.first; });
    if (after == pins_.begin()) return nullptr;
    const Pin& pin = *(after - 1);
    return i <= pin.last ? &pin : nullptr;
  }

  const SmoothingSpline& fit_;
  std::vector<Pin> pins_;
};

}  // namespace

bool SplineSmootherOptions::IsValid(std::string* why) const {
  FirstInvalid check;
  check.Require(zone_factor > 1 && std::isfinite(zone_factor),
          InvalidField("--zone_factor", zone_factor, "finite and > 1"));
  check.Require(zone_padding >= 0, InvalidField("--zone_padding", zone_padding, ">= 0"));
  check.Require(angle_tolerance_deg > 0 && std::isfinite(angle_tolerance_deg),
          InvalidField("--spline_tolerance_deg", angle_tolerance_deg, "finite and > 0"));
  check.Require(zone_weight > 0 && zone_weight <= 1,
          InvalidField("zone_weight", zone_weight, "in (0, 1]"));
  check.Require(pole_passage_deg >= 0 && pole_passage_deg < 90,
          InvalidField("--pole_passage_deg", pole_passage_deg, "in [0, 90)"));
  check.Require(pole_crossing_deg >= 0 && std::isfinite(pole_crossing_deg),
          InvalidField("--pole_crossing_deg", pole_crossing_deg, "finite and >= 0"));
  return check.Report(why);
}

namespace {

// What every cutting run of one SmoothWithSplines call shares.
struct SplineJob {
  const ToolPath& in;
  const Machine& machine;
  const RuledSurface* surface;  // may be null
  const Cutter& cutter;
  const SplineSmootherOptions& options;
  std::vector<double> u;  // contact ruling of every pose of `in`; empty without a surface
  std::vector<double> overhang_mm;  // PoseOverhangs of `in`; empty without a surface
  std::vector<PolePassage> through_pole;  // passages of `in` routed through the pole
};

// Zones of abrupt rotary acceleration and, with a surface, of fast
// Gaussian-curvature change (u: the contact rulings), and the passages
// routed through the pole (poses first.. of job.in), padded.
std::vector<bool> FindZones(const SplineJob& job, size_t first, const std::vector<double>& s,
                            const std::vector<double>& a, const std::vector<double>& c,
                            SplineSmootherReport* report) {
  const SplineSmootherOptions& options = job.options;
  const RuledSurface* const surface = job.surface;
  const double* const u = surface != nullptr ? job.u.data() + first : nullptr;
  const size_t n = s.size();
  std::vector<bool> zone(n, false);
  // The step onto the plane at a passage's ends is for the spline to bridge.
  for (const PolePassage& passage : job.through_pole) {
    for (size_t i = std::max(passage.first, first); i <= passage.last && i < first + n; ++i) {
      zone[i - first] = true;
    }
  }
  MarkAbove(SecondDerivative(s, a), options.zone_factor, &zone);
  MarkAbove(SecondDerivative(s, c), options.zone_factor, &zone);
  if (surface != nullptr) {
    std::vector<double> dk(n, 0.0);
    for (size_t i = 1; i + 1 < n; ++i) {
      dk[i] = std::abs(surface->GaussianCurvature(u[i + 1], 0.5) -
                       surface->GaussianCurvature(u[i - 1], 0.5)) /
              (s[i + 1] - s[i - 1]);
    }
    MarkAbove(dk, options.zone_factor, &zone);
  }
  report->zones += PadZones(options.zone_padding, &zone);
  return zone;
}

// Zones of the run (arc length s, angles a and c). When every pose is to
// move onto the curves, the zones are found on a first fit without them:
// noise within the tolerance would otherwise set the median, and with it
// a threshold that only a distortion's peak exceeds, leaving its flanks
// out of the zone to hold the curves to them (README, "Figures behind the
// defaults").
Status FindZonesOfRun(const SplineJob& job, size_t first, const std::vector<double>& s,
                      const std::vector<double>& a, const std::vector<double>& c,
                      SplineSmootherReport* report, std::vector<bool>* zone) {
  if (!job.options.smooth_outside_zones) {
    *zone = FindZones(job, first, s, a, c, report);
    return Status::Ok();
  }
  SmoothingSpline a_fit, c_fit;
  RETURN_IF_ERROR(SmoothingSpline::FitEachWithinTolerance(
      s, {&a, &c}, {}, job.options.angle_tolerance_deg / kRadToDeg, {&a_fit, &c_fit}));
  *zone = FindZones(job, first, s, a_fit.values(), c_fit.values(), report);
  return Status::Ok();
}

// The method on the cutting run [first, end) of job.in (no rapid after its
// first pose); appends the run's poses to `out`.
// SmoothRun's first stage: the run's zones (`zone`, one flag a pose) and
// the smoothing splines of its angles a and c over its arc length s, the
// zones weighted by options.zone_weight.
Status FitRunAngles(const SplineJob& job, size_t first, const std::vector<double>& s,
                    const std::vector<double>& a, const std::vector<double>& c,
                    SplineSmootherReport* report, std::vector<bool>* zone,
                    SmoothingSpline* a_fit, SmoothingSpline* c_fit) {
  const SplineSmootherOptions& options = job.options;
  const size_t n = s.size();
  RETURN_IF_ERROR(FindZonesOfRun(job, first, s, a, c, report, zone));
  std::vector<double> weights(n, 1.0);
  for (size_t i = 0; i < n; ++i) {
    report->poses_in_zones += (*zone)[i];
    if ((*zone)[i]) weights[i] = options.zone_weight;
  }
  const double tol_rad = options.angle_tolerance_deg / kRadToDeg;
  RETURN_IF_ERROR(
      SmoothingSpline::FitEachWithinTolerance(s, {&a, &c}, weights, tol_rad, {a_fit, c_fit}));
  return Status::Ok();
}

// SmoothRun's second stage: the run's poses appended to `out`, those that
// may move set on the fitted angles (pinned to their untouched neighbours),
// with the tip on the surface when there is one.
void AppendRunPoses(const SplineJob& job, size_t first, const std::vector<double>& s,
                    const std::vector<double>& a, const std::vector<double>& c,
                    const std::vector<bool>& zone, const SmoothingSpline& a_fit,
                    const SmoothingSpline& c_fit, std::vector<ToolPose>* out,
                    SplineSmootherReport* report) {
  const SplineSmootherOptions& options = job.options;
  const ToolPose* const poses = job.in.poses.data() + first;
  const size_t n = s.size();
  const double* const u = job.surface != nullptr ? job.u.data() + first : nullptr;
  // A pose may move when neither it nor a neighbour is a rapid end.
  auto movable = [&](size_t i) {
    return !IsPositioningMove(poses[i]) && (i + 1 >= n || !IsPositioningMove(poses[i + 1]));
  };
  // Pins join a modified zone to untouched neighbours; when every pose
  // moves onto the curves there is nothing untouched to join.
  const std::vector<bool> pinned_zones =
      options.smooth_outside_zones ? std::vector<bool>(n, false) : zone;
  const PinnedFit a_pinned(a_fit, s, a, pinned_zones), c_pinned(c_fit, s, c, pinned_zones);
  auto pose_at = [&](size_t i, const ToolPose& base, double s_mm, double u_contact) {
    ToolPose p = base;
    p.a_w = AnglesToAxis(a_pinned.At(i, s_mm), c_pinned.At(i, s_mm));
    if (job.surface != nullptr) {
      // The tip keeps the input's overhang below the floor along its axis
      // (the programmer's choice, solver/spline/overhang.h).
      p.p_w_tip = TangentTip(*job.surface, job.cutter.radius_mm, u_contact, p.a_w) -
                  job.overhang_mm[first + i] * p.a_w;
    }
    return p;
  };
  for (size_t i = 0; i < n; ++i) {
    if (!movable(i) || (!zone[i] && !options.smooth_outside_zones)) {
      out->push_back(poses[i]);
      continue;
    }
    report->max_angle_change_deg = std::max(
        {report->max_angle_change_deg, std::abs(a_pinned.At(i, s[i]) - a[i]) * kRadToDeg,
         std::abs(c_pinned.At(i, s[i]) - c[i]) * kRadToDeg});
    const bool insert = options.insert_transitions && i > 0 && zone[i] && zone[i - 1] &&
                        movable(i - 1);
    if (insert) {
      ToolPose mid = pose_at(i, Derived(poses[i]), 0.5 * (s[i - 1] + s[i]),
                             u != nullptr ? 0.5 * (u[i - 1] + u[i]) : 0.0);
      if (u == nullptr) mid.p_w_tip = 0.5 * (poses[i - 1].p_w_tip + poses[i].p_w_tip);
      out->push_back(mid);
      ++report->poses_inserted;
    }
    out->push_back(pose_at(i, poses[i], s[i], u != nullptr ? u[i] : 0.0));
  }
}

Status SmoothRun(const SplineJob& job, size_t first, size_t end, std::vector<ToolPose>* out,
                 SplineSmootherReport* report) {
  std::vector<double> a, c;
  RETURN_IF_ERROR(job.machine.AssignRotaryAngles(job.in, first, end, &a, &c));
  const ToolPose* const poses = job.in.poses.data() + first;
  const size_t n = end - first;
  if (n < 4) {  // nothing to smooth
    out->insert(out->end(), poses, poses + n);
    return Status::Ok();
  }
  const std::vector<double> s = TipArcLength(poses, n, {kMinStepMm, 0.0});
  std::vector<bool> zone;
  SmoothingSpline a_fit, c_fit;
  RETURN_IF_ERROR(FitRunAngles(job, first, s, a, c, report, &zone, &a_fit, &c_fit));
  AppendRunPoses(job, first, s, a, c, zone, a_fit, c_fit, out, report);
  return Status::Ok();
}

// [first, end) of the cutting run that holds pose i of `path`: a run
// starts at a rapid or link target (or the path's start).
std::pair<size_t, size_t> RunAround(const ToolPath& path, size_t i) {
  size_t first = i;
  while (first > 0 && !IsPositioningMove(path.poses[first])) --first;
  return {first, RunEnd(path, i)};
}

// Whether the machine takes `passage` of `routed` (put on a plane through
// +Z) with C held, which it does by a sign change of A where the pole is
// crossed; where the A travel has no room for the other sign it must turn
// C half a turn there instead, which is worse than going round.
bool MachineHoldsC(const ToolPath& routed, const Machine& machine, const PolePassage& passage) {
  const auto [first, end] = RunAround(routed, passage.first);
  std::vector<double> a, c;
  if (!machine.AssignRotaryAngles(routed, first, end, &a, &c).ok()) return false;
  for (size_t i = passage.first; i <= passage.last; ++i) {
    // On the plane C is the plane's azimuth on one branch and half a turn
    // from it on the other; a quarter turn tells the two apart.
    if (std::abs(c[i - first] - c[passage.first - first]) >= M_PI / 2) return false;
  }
  return true;
}

// Puts each pole passage of `in` whose axes lie within
// options.pole_crossing_deg of a plane through +Z on that plane, where the
// machine can take it so, leaving rapids and the poses before them as they
// are. Returns whether any was: then `routed` is `in` with those passages
// moved, and `through_pole` lists them.
bool RouteThroughPoles(const ToolPath& in, const Machine& machine,
                       const SplineSmootherOptions& options, ToolPath* routed,
                       std::vector<PolePassage>* through_pole, SplineSmootherReport* report) {
  if (options.pole_passage_deg <= 0 || options.pole_crossing_deg <= 0) return false;
  const size_t n = in.poses.size();
  for (PolePassage passage : FindPolePassages(in, options.pole_passage_deg / kRadToDeg)) {
    const bool held_start = IsPositioningMove(in.poses[passage.first]);
    const bool held_end = passage.last + 1 < n && IsPositioningMove(in.poses[passage.last + 1]);
    if (passage.last - passage.first < size_t{held_start} + size_t{held_end}) continue;
    passage.first += held_start;  // a rapid or link target stays as programmed
    passage.last -= held_end;     // and so does the pose before one
    const PoleCrossing crossing = FitPoleCrossing(in, passage);
    const double miss_deg = crossing.miss_rad * kRadToDeg;
    // A passage already on its plane (to round-off) crosses the pole as it
    // is; making it a zone would only move poses that need no change.
    if (crossing.miss_rad < kOnPlaneRad) continue;
    if (miss_deg > options.pole_crossing_deg) {
      VLOG(1) << "spline: pole passage at poses " << passage.first << "-" << passage.last
              << " lies up to " << miss_deg << " deg off a plane through A = 0, more than "
              << options.pole_crossing_deg << " deg; left to go round the pole";
      continue;
    }
    if (through_pole->empty()) *routed = in;
    RouteThroughPole(crossing, routed);
    if (!MachineHoldsC(*routed, machine, passage)) {
      LOG(WARNING) << "spline: the A travel [" << machine.limits[kA].min * kRadToDeg << ", "
                   << machine.limits[kA].max * kRadToDeg << "] deg has no room for the sign "
                   << "change of A that crosses the pole at poses " << passage.first << "-"
                   << passage.last << "; the passage keeps going round it";
      std::copy(in.poses.begin() + passage.first, in.poses.begin() + passage.last + 1,
                routed->poses.begin() + passage.first);
      continue;
    }
    VLOG(1) << "spline: pole passage at poses " << passage.first << "-" << passage.last
            << " routed through A = 0 at C = " << crossing.plane_c_rad * kRadToDeg
            << " deg, axes moved by up to " << miss_deg << " deg";
    through_pole->push_back(passage);
    ++report->pole_crossings;
  }
  return !through_pole->empty();
}

}  // namespace

SplineSmootherOptions ForHighAccuracyGuess(SplineSmootherOptions options) {
  options.insert_transitions = false;
  // From a guess routed through the pole the hypar's distorted paths settle
  // where its clean path does, 0.013 mm short of the surface at the pole,
  // beyond the 0.01 mm tolerance (the result is refused), while the guess
  // that goes round the pole, solved both ways round
  // (solver/spline/pole_passage.h), comes within 0.0091 mm.
  options.pole_crossing_deg = 0.0;
  return options;
}

Status SmoothWithSplines(const ToolPath& in, const Machine& machine, const RuledSurface* surface,
                         const Cutter& cutter, const SplineSmootherOptions& options,
                         ToolPath* out, SplineSmootherReport* report) {
  std::string why;
  if (!options.IsValid(&why)) return Status::Error("spline options: " + why);
  *report = SplineSmootherReport();
  // The path is copied only when a passage is routed through the pole.
  ToolPath routed;
  std::vector<PolePassage> through_pole;
  const ToolPath& source =
      RouteThroughPoles(in, machine, options, &routed, &through_pole, report) ? routed : in;
  SplineJob job{source, machine, surface, cutter, options, {}, {}, std::move(through_pole)};
  // Projected once for the whole path: every run starts at a rapid (or the
  // path's start), where the projection searches the whole rail afresh.
  if (surface != nullptr) {
    job.u = ProjectPathOntoRail(surface->rail(0), in);
    RETURN_IF_ERROR(PoseOverhangs(surface->rail(0), in, job.u, &job.overhang_mm));
  }
  ToolPath result = WithoutPoses(in);
  result.poses.reserve(options.insert_transitions ? 2 * in.poses.size() : in.poses.size());
  // Each cutting run separately: a spline must not bridge a rapid between
  // two passes. A run starts at the pose a rapid reaches. Runs are read in
  // place and written straight into the result: copies of the poses were a
  // third of the method's time on long paths.
  const size_t n = in.poses.size();
  for (size_t first = 0; first < n;) {
    const size_t end = RunEnd(in, first);
    RETURN_IF_ERROR(SmoothRun(job, first, end, &result.poses, report));
    first = end;
  }
  *out = std::move(result);
  return Status::Ok();
}

}  // namespace tpopt
