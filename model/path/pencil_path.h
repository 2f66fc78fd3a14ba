// Pencil paths on a B-spline surface (seed 004): planar guide curves are
// placed above the surface, projected onto it along one direction to give
// the cutter-contact (CC) points, and offset by the ball radius along the
// surface normal to give the cutter-location (CL) points, the ball centres.
//
// Placement, concretely (the seed shows it only in a figure): the guide's
// plane is put through S(anchor) + lift * N0, with N0 the unit normal at the
// anchor (u0, v0) and the plane's x axis along S_u there projected into the
// plane (the rotation and translation), then turned by spin about N0 (the
// rotation about the normal at the projection point). Points are projected
// along O = -N0, and the tool axis is N0 (a 3-axis ball-end job).
#ifndef TPOPT_MODEL_PENCIL_PATH_H_
#define TPOPT_MODEL_PENCIL_PATH_H_

#include <string>
#include <vector>

#include <Eigen/Core>

#include "model/geometry/bspline_curve.h"
#include "model/geometry/bspline_surface.h"
#include "model/base/status.h"

namespace tpopt {

struct GuidePlacement {
  double anchor_u = 0.5, anchor_v = 0.5;  // in [0, 1]
  double lift_mm = 20.0;                  // height of the guide plane; finite
  double spin_deg = 0.0;                  // finite
  bool IsValid(std::string* why) const;
};

struct PencilOptions {
  double ball_radius_mm = 1.5;            // > 0 (the seed's 3 mm ball)
  double feed_mm_per_min = 3000.0;        // > 0
  double interpolation_period_s = 0.008;  // > 0
  bool IsValid(std::string* why) const;
  // Distance between consecutive CC points: one interpolation period at
  // the feed (0.4 mm under the seed's conditions).
  double StepMm() const { return feed_mm_per_min / 60.0 * interpolation_period_s; }
};

// One point of a pencil path at guide parameter m, with its derivatives
// along m (mm per unit m), which the step rule and the fit need.
struct PencilPoint {
  double m = 0.0, u = 0.0, v = 0.0;
  Eigen::Vector3d cc, dcc_dm;     // contact point on the surface
  Eigen::Vector3d normal;         // unit surface normal, towards the tool
  Eigen::Vector3d cl, dcl_dm;     // ball centre = cc + radius * normal
};

class PencilGeometry {
 public:
  // Places the guide plane over `surface` (which must outlive this).
  // Fails when the placement is invalid or the surface is singular at the
  // anchor.
  static Status Create(const BSplineSurface& surface, const GuidePlacement& placement,
                       double ball_radius_mm, PencilGeometry* geometry);

  // Unit projection direction O = -N0, and the tool axis N0.
  const Eigen::Vector3d& direction() const { return direction_; }
  Eigen::Vector3d tool_axis() const { return -direction_; }
  // A planar guide point (x, y) (z ignored) placed in space, mm.
  Eigen::Vector3d Place(const Eigen::Vector3d& planar) const;

  // The point of `guide` (planar) at m. `uv` carries the previous point's
  // surface parameters in and this one's out (null: search from scratch).
  // Fails where the projection misses the surface or the surface is
  // singular; the message gives m.
  Status At(const BSplineCurve& guide, double m, Eigen::Vector2d* uv, PencilPoint* point) const;

 private:
  const BSplineSurface* surface_ = nullptr;
  Eigen::Vector3d origin_, x_axis_, y_axis_, direction_;
  double ball_radius_mm_ = 0.0;
};

// One guide curve's path: points from m = 0 to m = 1 whose CC points are
// about one step apart, by the seed's first-order Taylor rule
// m_{k+1} = m_k + step / |dCC/dm| (eq. (6)), at most 0.1 at a time, the
// last one at m = 1.
struct PencilRun {
  std::vector<PencilPoint> points;
};

// Fails (naming the curve index and m) where a projection fails, or when a
// curve would need more than 1e6 points.
Status GeneratePencilRuns(const PencilGeometry& geometry, const std::vector<BSplineCurve>& guides,
                          const PencilOptions& options, std::vector<PencilRun>* runs);


}  // namespace tpopt

#endif  // TPOPT_MODEL_PENCIL_PATH_H_
