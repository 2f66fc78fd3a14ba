#include "model/cutter/torus_cutter.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace tpopt {

bool TorusCutter::IsValid(std::string* why) const {
  std::ostringstream err;
  if (!(radius_mm > 0.0) || !std::isfinite(radius_mm) || radius_mm > 1e4) {
    err << "torus radius R = " << radius_mm << " mm must be in (0, 1e4]";
  } else if (!(corner_radius_mm > 0.0) || corner_radius_mm > radius_mm) {
    err << "torus corner radius r = " << corner_radius_mm << " mm must be in (0, R = "
        << radius_mm << "]";
  } else {
    return true;
  }
  if (why != nullptr) *why = err.str();
  return false;
}

double SignedDistanceToTorus(const TorusCutter& cutter, const Eigen::Vector3d& q,
                             const Eigen::Vector3d& tip, const Eigen::Vector3d& axis) {
  const Eigen::Vector3d d = q - ToolCentre(cutter, tip, axis);
  const double height = d.dot(axis);
  const double radial = (d - height * axis).norm();
  // Distance to the half cylinder D, then less the corner radius. Inside D
  // (radial <= R0 and height >= 0) this gives -r, a bound, not exact.
  const double out_radial = std::max(radial - cutter.centre_circle_radius_mm(), 0.0);
  const double below = std::min(height, 0.0);
  return std::hypot(out_radial, below) - cutter.corner_radius_mm;
}

Eigen::Vector3d TipForContact(const TorusCutter& cutter, const Eigen::Vector3d& contact,
                              const Eigen::Vector3d& normal, const Eigen::Vector3d& axis) {
  // The corner point with outward normal m = -normal is c + R0 e + r m,
  // where e is the unit radial direction of m in the plane normal to the
  // axis: e = unit(m - (m . a) a).
  const Eigen::Vector3d m = -normal;
  const Eigen::Vector3d radial = m - m.dot(axis) * axis;
  // Axis along the normal: the flat end face touches, at its centre.
  if (radial.norm() < 1e-12) return contact;
  const Eigen::Vector3d e = radial.normalized();
  const Eigen::Vector3d centre =
      contact - cutter.corner_radius_mm * m - cutter.centre_circle_radius_mm() * e;
  return centre - cutter.corner_radius_mm * axis;
}

double EffectiveRadiusAtLead(const TorusCutter& cutter, double lead_rad) {
  return cutter.corner_radius_mm + cutter.centre_circle_radius_mm() / std::sin(lead_rad);
}

}  // namespace tpopt
