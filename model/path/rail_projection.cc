#include "model/path/rail_projection.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glog/logging.h>

namespace tpopt {
namespace {

// A run whose median tip is within this of the floor (mm along the axis) is
// on it: SPO and DPO tips sit at the floor's offset point, and axis noise or
// a tilt moves a pose's height by R sin(angle), 0.2 mm at 3 deg and R 4,
// with the foot of the tip still on its ruling.
constexpr double kOnTheFloorMm = 0.25;

// g(u) = (C(u) - point) . C'(u): zero at a foot point, derivative
// |C'|^2 + (C - point) . C''.
double FootResidual(const BSplineCurve& curve, const Eigen::Vector3d& point, double u,
                    double* slope) {
  const auto d = curve.Evaluate(u, 2);
  const Eigen::Vector3d diff = d[0] - point;
  if (slope != nullptr) *slope = d[1].squaredNorm() + diff.dot(d[2]);
  return diff.dot(d[1]);
}

}  // namespace

double ProjectOntoCurve(const BSplineCurve& curve, const Eigen::Vector3d& point, double u_lo,
                        double u_hi, int scan_samples) {
  u_lo = std::clamp(u_lo, 0.0, 1.0);
  u_hi = std::clamp(u_hi, u_lo, 1.0);
  // Coarse scan for the nearest sample.
  double best_u = u_lo, best_d = std::numeric_limits<double>::infinity();
  const int n = std::max(scan_samples, 2);
  for (int i = 0; i <= n; ++i) {
    const double u = u_lo + (u_hi - u_lo) * i / n;
    const double d = (curve.Point(u) - point).squaredNorm();
    if (d < best_d) {
      best_d = d;
      best_u = u;
    }
  }
  // Bracket the foot point within one scan step and refine by Newton, kept
  // inside the bracket by bisection.
  const double step = (u_hi - u_lo) / n;
  double lo = std::max(u_lo, best_u - step), hi = std::min(u_hi, best_u + step);
  double g_lo = FootResidual(curve, point, lo, nullptr);
  const double g_hi = FootResidual(curve, point, hi, nullptr);
  if (g_lo >= 0 && g_hi >= 0) return lo;  // foot at or before the low end
  if (g_lo <= 0 && g_hi <= 0) return hi;  // foot at or beyond the high end
  double u = best_u;
  for (int iter = 0; iter < 60 && hi - lo > 1e-15; ++iter) {
    double slope = 0.0;
    const double g = FootResidual(curve, point, u, &slope);
    if ((g < 0) == (g_lo < 0)) {
      lo = u;
      g_lo = g;
    } else {
      hi = u;
    }
    double next = slope > 0 ? u - g / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - u) < 1e-15) break;
    u = next;
  }
  return u;
}

std::vector<double> RunOverhangs(const BSplineCurve& rail, const ToolPath& path,
                                 const std::vector<double>& u) {
  CHECK_EQ(u.size(), path.poses.size());
  std::vector<double> overhang_mm(path.poses.size(), 0.0);
  for (size_t first = 0; first < path.poses.size();) {
    const size_t end = RunEnd(path, first);
    std::vector<double> heights;
    for (size_t i = first; i < end; ++i) {
      heights.push_back((rail.Point(u[i]) - path.poses[i].p_w_tip).dot(path.poses[i].a_w));
    }
    std::nth_element(heights.begin(), heights.begin() + heights.size() / 2, heights.end());
    std::fill(overhang_mm.begin() + first, overhang_mm.begin() + end, heights[heights.size() / 2]);
    first = end;
  }
  return overhang_mm;
}

std::vector<double> ProjectPathOntoRail(const BSplineCurve& rail, const ToolPath& path,
                                        double window_u) {
  std::vector<double> u(path.poses.size(), 0.0);
  bool have_previous = false;
  double previous = 0.0;
  for (size_t i = 0; i < path.poses.size(); ++i) {
    const Eigen::Vector3d& p = path.poses[i].p_w_tip;
    // A rapid or a link may come from anywhere (a retract, another pass):
    // search the whole rail for the pose it reaches.
    const bool fresh = !have_previous || IsPositioningMove(path.poses[i]);
    const double lo = std::max(0.0, previous - window_u), hi = std::min(1.0, previous + window_u);
    u[i] = fresh ? -1.0 : ProjectOntoCurve(rail, p, lo, hi, 16);
    // A foot on the window's edge means the step was larger than the
    // window: search the whole rail instead.
    if (fresh || (u[i] == lo && lo > 0.0) || (u[i] == hi && hi < 1.0)) {
      u[i] = ProjectOntoCurve(rail, p, 0.0, 1.0, 256);
    }
    previous = u[i];
    have_previous = true;
  }
  // From the tip's foot to the foot of the axis point at the run's overhang
  // (header). The overhang measured at the tip's foot is off by the foot's
  // error times the axis' lean along the rail; each pass shrinks that error
  // by the same factor, and three leave nothing measurable. A path whose
  // tips are all on the floor needs none.
  bool overhanging = true;
  for (int pass = 0; pass < 3 && overhanging; ++pass) {
    const std::vector<double> overhang_mm = RunOverhangs(rail, path, u);
    overhanging = false;
    for (size_t i = 0; i < path.poses.size(); ++i) {
      if (overhang_mm[i] <= kOnTheFloorMm) continue;
      overhanging = true;
      const Eigen::Vector3d x = path.poses[i].p_w_tip + overhang_mm[i] * path.poses[i].a_w;
      u[i] = ProjectOntoCurve(rail, x, std::max(0.0, u[i] - window_u),
                              std::min(1.0, u[i] + window_u), 16);
    }
  }
  return u;
}

std::vector<bool> PosesBeyondRailEnds(const BSplineCurve& rail, const ToolPath& path,
                                      const std::vector<double>& u) {
  const std::vector<double> overhang_mm = RunOverhangs(rail, path, u);
  std::vector<bool> beyond(path.poses.size(), false);
  for (size_t i = 0; i < path.poses.size(); ++i) {
    if (u[i] > 0.0 && u[i] < 1.0) continue;
    const ToolPose& pose = path.poses[i];
    const double overhang = overhang_mm[i] > kOnTheFloorMm ? overhang_mm[i] : 0.0;
    const Eigen::Vector3d x = pose.p_w_tip + overhang * pose.a_w;
    const std::array<Eigen::Vector3d, 4> end = rail.Evaluate(u[i], 1);
    const Eigen::Vector3d outward = (u[i] <= 0.0 ? -1.0 : 1.0) * end[1].normalized();
    beyond[i] = (x - end[0]).dot(outward) > kOnTheFloorMm;
  }
  return beyond;
}

}  // namespace tpopt
