// A circular (or helical) arc in 3-D, as APT's CIRCLE/ and G-code's G2/G3
// describe it, turned into points that a straight-move path follows within
// a chord tolerance.
#ifndef TPOPT_MODEL_CIRCULAR_ARC_H_
#define TPOPT_MODEL_CIRCULAR_ARC_H_

#include <Eigen/Core>
#include <string>
#include <vector>

#include "model/base/status.h"

namespace tpopt {

struct CircularArc {
  // Centre, mm, any frame (the points come out in the same one).
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  // Unit normal of the arc's plane; the tool turns counter-clockwise about
  // it (the right-hand rule), as APT's CIRCLE/ axis i,j,k says.
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  // Radius, mm, > 0.
  double radius_mm = 1.0;
};

// The points of `arc` from `start` to `end` (both mm), the start excluded
// and `end` itself last, so that the chords between them stay within
// `chord_tolerance_mm` (> 0) of the arc. Start and end must lie at the
// radius from the axis line within `radius_tolerance_mm`; an offset along
// the axis between them is a helix, climbed linearly in the angle. End at
// the start is a full turn. Errors say which point is off the circle and by
// how much, or which argument is invalid; `what` names the arc (file:line).
Status ArcPoints(const CircularArc& arc, const Eigen::Vector3d& start, const Eigen::Vector3d& end,
                 double chord_tolerance_mm, double radius_tolerance_mm, const std::string& what,
                 std::vector<Eigen::Vector3d>* points);

}  // namespace tpopt

#endif  // TPOPT_MODEL_CIRCULAR_ARC_H_
