#include "solver/spline_smoother.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glog/logging.h>

#include "model/rail_projection.h"
#include "solver/smoothing_spline.h"

namespace tpopt {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;
constexpr double kMinStepMm = 1e-6;

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
// its neighbours without a step.
class PinnedFit {
 public:
  PinnedFit(const SmoothingSpline& fit, const std::vector<double>& s,
            const std::vector<double>& y, const std::vector<bool>& zone)
      : fit_(fit), left_(s.size()), right_(s.size()) {
    const size_t n = s.size();
    for (size_t i = 0; i < n; ++i) {
      if (!zone[i] || (i > 0 && zone[i - 1])) continue;
      size_t end = i;
      while (end + 1 < n && zone[end + 1]) ++end;
      const size_t l = i > 0 ? i - 1 : i, r = end + 1 < n ? end + 1 : end;
      for (size_t k = i; k <= end; ++k) {
        left_[k] = {s[l], y[l] - fit(s[l])};
        right_[k] = {s[r], y[r] - fit(s[r])};
      }
      i = end;
    }
  }

  // Value at arc length s_mm for pose i; outside zones the pins are zero
  // and this is the plain fit.
  double At(size_t i, double s_mm) const {
    const auto [s_l, d_l] = left_[i];
    const auto [s_r, d_r] = right_[i];
    const double t = s_r > s_l ? std::clamp((s_mm - s_l) / (s_r - s_l), 0.0, 1.0) : 0.0;
    return fit_(s_mm) + d_l + (d_r - d_l) * t;
  }

 private:
  const SmoothingSpline& fit_;
  std::vector<std::pair<double, double>> left_, right_;  // (s, offset) per pose
};

}  // namespace

bool SplineSmootherOptions::IsValid(std::string* why) const {
  std::ostringstream err;
  if (!(zone_factor > 1) || !std::isfinite(zone_factor)) {
    err << "zone factor " << zone_factor << " must be > 1";
  } else if (zone_padding < 0) {
    err << "zone padding " << zone_padding << " must be >= 0";
  } else if (!(angle_tolerance_deg > 0) || !std::isfinite(angle_tolerance_deg)) {
    err << "angle tolerance " << angle_tolerance_deg << " deg must be > 0";
  } else if (!(zone_weight > 0 && zone_weight <= 1)) {
    err << "zone weight " << zone_weight << " must be in (0, 1]";
  } else {
    return true;
  }
  if (why != nullptr) *why = err.str();
  return false;
}

namespace {

// The method on one cutting run (no rapid after its first pose).
Status SmoothRun(const ToolPath& in, const Machine& machine, const RuledSurface* surface,
                 const Cutter& cutter, const SplineSmootherOptions& options, ToolPath* out,
                 SplineSmootherReport* report) {
  std::vector<JointVector> joints;
  Status st = machine.AssignJoints(in, &joints);
  if (!st.ok()) return st;
  const size_t n = in.poses.size();
  if (n < 4) {  // nothing to smooth
    *out = in;
    return Status::Ok();
  }
  std::vector<double> s(n, 0.0), a(n), c(n);
  for (size_t i = 0; i < n; ++i) {
    a[i] = joints[i][kA];
    c[i] = joints[i][kC];
    if (i > 0) {
      s[i] = s[i - 1] + std::max(kMinStepMm, (in.poses[i].p_w_tip - in.poses[i - 1].p_w_tip).norm());
    }
  }
  std::vector<bool> zone(n, false);
  MarkAbove(SecondDerivative(s, a), options.zone_factor, &zone);
  MarkAbove(SecondDerivative(s, c), options.zone_factor, &zone);
  std::vector<double> u;
  if (surface != nullptr) {
    u = ProjectPathOntoRail(surface->rail(0), in);
    std::vector<double> dk(n, 0.0);
    for (size_t i = 1; i + 1 < n; ++i) {
      dk[i] = std::abs(surface->GaussianCurvature(u[i + 1], 0.5) -
                       surface->GaussianCurvature(u[i - 1], 0.5)) /
              (s[i + 1] - s[i - 1]);
    }
    MarkAbove(dk, options.zone_factor, &zone);
  }
  report->zones += PadZones(options.zone_padding, &zone);
  std::vector<double> weights(n, 1.0);
  for (size_t i = 0; i < n; ++i) {
    report->poses_in_zones += zone[i];
    if (zone[i]) weights[i] = options.zone_weight;
  }
  const double tol_rad = options.angle_tolerance_deg / kRadToDeg;
  SmoothingSpline a_fit, c_fit;
  st = SmoothingSpline::FitWithinTolerance(s, a, weights, tol_rad, &a_fit);
  if (st.ok()) st = SmoothingSpline::FitWithinTolerance(s, c, weights, tol_rad, &c_fit);
  if (!st.ok()) return st;

  // A pose may move when neither it nor a neighbour is a rapid end.
  auto movable = [&](size_t i) {
    return !in.poses[i].rapid && (i + 1 >= n || !in.poses[i + 1].rapid);
  };
  const PinnedFit a_pinned(a_fit, s, a, zone), c_pinned(c_fit, s, c, zone);
  auto pose_at = [&](size_t i, const ToolPose& base, double s_mm, double u_contact) {
    ToolPose p = base;
    p.a_w = AnglesToAxis(a_pinned.At(i, s_mm), c_pinned.At(i, s_mm));
    if (surface != nullptr) p.p_w_tip = TangentTip(*surface, cutter.radius_mm, u_contact, p.a_w);
    return p;
  };
  *out = WithoutPoses(in);
  out->poses.reserve(options.insert_transitions ? 2 * n : n);
  for (size_t i = 0; i < n; ++i) {
    if (!movable(i) || (!zone[i] && !options.smooth_outside_zones)) {
      out->poses.push_back(in.poses[i]);
      continue;
    }
    report->max_angle_change_deg = std::max(
        {report->max_angle_change_deg, std::abs(a_pinned.At(i, s[i]) - a[i]) * kRadToDeg,
         std::abs(c_pinned.At(i, s[i]) - c[i]) * kRadToDeg});
    const bool insert = options.insert_transitions && i > 0 && zone[i] && zone[i - 1] &&
                        movable(i - 1);
    if (insert) {
      ToolPose mid = pose_at(i, Derived(in.poses[i]), 0.5 * (s[i - 1] + s[i]),
                             surface ? 0.5 * (u[i - 1] + u[i]) : 0.0);
      if (surface == nullptr) mid.p_w_tip = 0.5 * (in.poses[i - 1].p_w_tip + in.poses[i].p_w_tip);
      out->poses.push_back(mid);
      ++report->poses_inserted;
    }
    out->poses.push_back(pose_at(i, in.poses[i], s[i], surface ? u[i] : 0.0));
  }
  return Status::Ok();
}

}  // namespace

Status SmoothWithSplines(const ToolPath& in, const Machine& machine, const RuledSurface* surface,
                         const Cutter& cutter, const SplineSmootherOptions& options,
                         ToolPath* out, SplineSmootherReport* report) {
  std::string why;
  if (!options.IsValid(&why)) return Status::Error("spline options: " + why);
  *report = SplineSmootherReport();
  ToolPath result = WithoutPoses(in);
  result.poses.reserve(in.poses.size());
  // Each cutting run separately: a spline must not bridge a rapid between
  // two passes. A run starts at the pose a rapid reaches.
  const size_t n = in.poses.size();
  for (size_t first = 0; first < n;) {
    size_t end = first + 1;
    while (end < n && !in.poses[end].rapid) ++end;
    // Not a copy of `in`: that would copy every pose once per run.
    ToolPath run = WithoutPoses(in);
    run.poses.assign(in.poses.begin() + first, in.poses.begin() + end);
    ToolPath smoothed;
    Status st = SmoothRun(run, machine, surface, cutter, options, &smoothed, report);
    if (!st.ok()) return st;
    result.poses.insert(result.poses.end(), smoothed.poses.begin(), smoothed.poses.end());
    first = end;
  }
  *out = std::move(result);
  return Status::Ok();
}

}  // namespace tpopt
