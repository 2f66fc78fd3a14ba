// A torus (bull-nose) end mill: outer radius R, corner radius r <= R.
//
// In the tool frame the corner is a circle of radius R0 = R - r (the
// "centre circle") at height r above the tip, swept by a ball of radius r;
// above the centre circle the flank is the cylinder of radius R. The tip is
// the centre of the end face (docs/ARCHITECTURE.md, "Frames"), so the centre
// circle's centre, the "tool centre" c, is tip + r a.
//
// The solid is the set of points within r of the half-infinite solid
// cylinder D = {radius <= R0, height >= 0} around c: convex, so the
// distance to it, and to any translate of it along a line, is convex too.
#ifndef TPOPT_MODEL_TORUS_CUTTER_H_
#define TPOPT_MODEL_TORUS_CUTTER_H_

#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "model/base/status.h"

namespace tpopt {

struct TorusCutter {
  double radius_mm = 8.0;         // R, > 0
  double corner_radius_mm = 2.0;  // r, in (0, R]

  double centre_circle_radius_mm() const { return radius_mm - corner_radius_mm; }
  // `why` names the field and value at fault.
  bool IsValid(std::string* why) const;
};

// Signed distance (mm) from q to the cutter solid with tip `tip` and unit
// axis `axis`, one frame: exact outside the solid, negative inside (exact
// within r of the corner and flank).
double SignedDistanceToTorus(const TorusCutter& cutter, const Eigen::Vector3d& q,
                             const Eigen::Vector3d& tip, const Eigen::Vector3d& axis);

// Where the cutter touches a surface at `contact` with unit surface normal
// `normal` (pointing from the surface towards the tool), for a unit tool
// axis: the tip that puts the cutter's corner point whose outward normal is
// -normal onto `contact`. Meant for axis.dot(normal) > 0 (the contact on
// the lower half of the corner); otherwise the placement is still finite
// but the cutter cuts into the surface, which the strip evaluation reports
// as a gouge. With the axis along the normal the end face touches at its
// centre (tip = contact).
Eigen::Vector3d TipForContact(const TorusCutter& cutter, const Eigen::Vector3d& contact,
                              const Eigen::Vector3d& normal, const Eigen::Vector3d& axis);

// Centre of the centre circle: tip + r axis.
inline Eigen::Vector3d ToolCentre(const TorusCutter& cutter, const Eigen::Vector3d& tip,
                                  const Eigen::Vector3d& axis) {
  return tip + cutter.corner_radius_mm * axis;
}

// Effective cutting radius (mm) at a contact on the corner, with the feed
// direction in the plane of the axis and the normal (zero tilt) and lead
// angle `lead_rad` between them: the normal curvature of the torus across
// the feed is sin(lead) / (R0 + r sin(lead)) (Meusnier on the parallel
// circle through the contact), so R_eff = r + R0 / sin(lead).
double EffectiveRadiusAtLead(const TorusCutter& cutter, double lead_rad);

}  // namespace tpopt

#endif  // TPOPT_MODEL_TORUS_CUTTER_H_
