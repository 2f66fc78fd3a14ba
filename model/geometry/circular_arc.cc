#include "model/geometry/circular_arc.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <sstream>

namespace tpopt {

Status ArcPoints(const CircularArc& arc, const Eigen::Vector3d& start, const Eigen::Vector3d& end,
                 double chord_tolerance_mm, double radius_tolerance_mm, const std::string& what,
                 std::vector<Eigen::Vector3d>* points) {
  std::ostringstream err;
  err << what << ": ";
  if (!arc.center.allFinite() || !arc.axis.allFinite() || !(arc.axis.norm() > 1e-9)) {
    err << "arc axis (" << arc.axis.transpose() << ") is zero or not finite";
    return Status::Error(err.str());
  }
  if (!(std::isfinite(arc.radius_mm) && arc.radius_mm > 0.0)) {
    err << "arc radius " << arc.radius_mm << " mm must be finite and > 0";
    return Status::Error(err.str());
  }
  if (!(chord_tolerance_mm > 0.0) || !(radius_tolerance_mm >= 0.0)) {
    err << "chord tolerance " << chord_tolerance_mm << " mm must be > 0";
    return Status::Error(err.str());
  }
  const Eigen::Vector3d n = arc.axis.normalized();
  // In-plane offsets from the axis line, and heights along it.
  const Eigen::Vector3d d0 = start - arc.center, d1 = end - arc.center;
  const Eigen::Vector3d r0 = d0 - d0.dot(n) * n, r1 = d1 - d1.dot(n) * n;
  for (const auto& [name, r] :
       {std::pair<const char*, Eigen::Vector3d>{"start", r0}, {"end", r1}}) {
    if (std::abs(r.norm() - arc.radius_mm) > radius_tolerance_mm) {
      err << "the arc's " << name << " point lies " << r.norm()
          << " mm from its centre's axis, not at "
          << "the radius " << arc.radius_mm << " mm (tolerance " << radius_tolerance_mm << " mm)";
      return Status::Error(err.str());
    }
  }
  // Counter-clockwise angle from r0 to r1 about n, in (0, 2 pi]: an arc
  // that ends where it starts is a full circle.
  const Eigen::Vector3d u = r0.normalized(), v = n.cross(u);
  double sweep = std::atan2(r1.dot(v), r1.dot(u));
  if (sweep <= 1e-12) sweep += 2 * M_PI;
  // A chord of angle h sags r (1 - cos(h/2)) below the arc.
  const double cos_half = std::clamp(1.0 - chord_tolerance_mm / arc.radius_mm, -1.0, 1.0);
  const double max_step = std::max(2.0 * std::acos(cos_half), 1e-6);
  const int steps = std::max(1, static_cast<int>(std::ceil(sweep / max_step - 1e-12)));
  const double h0 = d0.dot(n), h1 = d1.dot(n);
  points->clear();
  for (int k = 1; k < steps; ++k) {
    const double t = static_cast<double>(k) / steps, angle = t * sweep;
    points->push_back(arc.center + arc.radius_mm * (std::cos(angle) * u + std::sin(angle) * v) +
                      (h0 + t * (h1 - h0)) * n);
  }
  points->push_back(end);
  return Status::Ok();
}

}  // namespace tpopt
