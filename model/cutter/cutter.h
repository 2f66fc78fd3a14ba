// Flank-milling cutters: a cylindrical flat end mill, or a tapered (conical)
// end mill, described in the tool frame by the tip (centre of the end face)
// and the unit axis pointing from the tip into the spindle.
#ifndef TPOPT_MODEL_CUTTER_H_
#define TPOPT_MODEL_CUTTER_H_

#include <cmath>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "model/base/status.h"

namespace tpopt {

struct Cutter {
  // Radius at the tip (end face), mm. > 0.
  double radius_mm = 4.0;
  // Length of the cutting flank measured from the tip along the axis, mm.
  // > 0. Points beyond it are not cut.
  double flute_length_mm = 50.0;
  // Half cone angle of a tapered flank, radians, in [0, pi/4); the radius
  // grows as radius_mm + t tan(taper) at height t. 0 is a cylinder.
  double taper_rad = 0.0;

  // Checks the ranges above; `why` names the offending field and value.
  bool IsValid(std::string* why) const;
  Status Validate(const std::string& what) const;

  double RadiusAt(double height_mm) const {
    return radius_mm + height_mm * std::tan(taper_rad);
  }
};

// A cutter's shape as the distance functions below evaluate it, with its
// taper's tangent and cosine worked out once, not at every point: the
// optimiser and the judge measure millions of points against one cutter.
struct FlankShape {
  explicit FlankShape(const Cutter& cutter)
      : radius_mm(cutter.radius_mm),
        half_flute_mm(0.5 * cutter.flute_length_mm),
        tan_taper(std::tan(cutter.taper_rad)),
        cos_taper(std::cos(cutter.taper_rad)) {}
  double radius_mm, half_flute_mm, tan_taper, cos_taper;
};

// Signed distance (mm) from point q to the cutter placed at `tip` with unit
// `axis`, all in one frame, as the deviation of a wall point: within the
// flute's height range (0 <= t <= flute length) it is the distance to the
// flank measured normal to it, negative inside the cutter (the depth of a
// gouge in the wall at q's height, even next to the end face); beyond the
// flute it is the exact, positive distance to the cutter's solid. Exact for
// the cylinder; for a taper the flank distance is taken in the axial plane.
// Templated on the scalar so that Ceres residuals can differentiate through
// it.
template <typename T>
T SignedDistanceToCutter(const FlankShape& flank, const Eigen::Matrix<T, 3, 1>& q,
                         const Eigen::Matrix<T, 3, 1>& tip, const Eigen::Matrix<T, 3, 1>& axis) {
  using std::abs;
  using std::sqrt;
  const Eigen::Matrix<T, 3, 1> d = q - tip;
  const T t = d.dot(axis);                            // height above the tip
  const T r2 = (d - t * axis).squaredNorm();
  // sqrt is not differentiable at 0; a point on the axis is deep inside.
  const T r = r2 > T(1e-24) ? T(sqrt(r2)) : T(0.0);
  const T half_length = T(flank.half_flute_mm);
  // Radial distance to the flank measured normal to it, and axial distance
  // to the nearer cap.
  const T radial = (r - (T(flank.radius_mm) + t * flank.tan_taper)) * flank.cos_taper;
  const T axial = abs(t - half_length) - half_length;
  if (axial <= T(0.0)) return radial;
  if (radial <= T(0.0)) return axial;
  return T(sqrt(radial * radial + axial * axial));
}

template <typename T>
T SignedDistanceToCutter(const Cutter& cutter, const Eigen::Matrix<T, 3, 1>& q,
                         const Eigen::Matrix<T, 3, 1>& tip, const Eigen::Matrix<T, 3, 1>& axis) {
  return SignedDistanceToCutter<T>(FlankShape(cutter), q, tip, axis);
}

// Signed distance (mm) from q to the cutter's flank surface extended past
// its caps: (r - R(t)) cos(taper), r the distance of q from the axis line,
// t its height above the tip. Smooth everywhere except on the axis, which is
// what an optimiser needs; the caps are handled by keeping the tip at the
// contact rail (see solver/smooth/cost/tip_height_cost.h).
template <typename T>
T SignedDistanceToFlank(const FlankShape& flank, const Eigen::Matrix<T, 3, 1>& q,
                        const Eigen::Matrix<T, 3, 1>& tip, const Eigen::Matrix<T, 3, 1>& axis) {
  using std::sqrt;
  const Eigen::Matrix<T, 3, 1> d = q - tip;
  const T t = d.dot(axis);
  const T r2 = (d - t * axis).squaredNorm();
  const T r = r2 > T(1e-24) ? T(sqrt(r2)) : T(0.0);
  return (r - (T(flank.radius_mm) + t * flank.tan_taper)) * flank.cos_taper;
}

template <typename T>
T SignedDistanceToFlank(const Cutter& cutter, const Eigen::Matrix<T, 3, 1>& q,
                        const Eigen::Matrix<T, 3, 1>& tip, const Eigen::Matrix<T, 3, 1>& axis) {
  return SignedDistanceToFlank<T>(FlankShape(cutter), q, tip, axis);
}

}  // namespace tpopt

#endif  // TPOPT_MODEL_CUTTER_H_
