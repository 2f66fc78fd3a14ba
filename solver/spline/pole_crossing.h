// Straight through the A = 0 pole: the spline mode's route for a pole
// passage (solver/spline/pole_passage.h) that only just misses the pole.
//
// A path whose true axis crosses +Z (A changing sign, C still) but which a
// CAM error makes miss the pole by a fraction of a degree has C swinging by
// about half a turn over a few poses, since C moves by roughly dtheta / sin A
// there. The spline method works in A and C and so keeps whichever side of
// the pole the data takes; smoothing a half turn of C does not remove it.
// Here the passage is put back on a plane through +Z instead: the plane
// spanned by +Z and the horizontal direction that best fits the passage's
// axes seen from above (a line through the origin fitted to the xy parts of
// the axes, by least squares, i.e. their principal direction), and each
// axis loses its component perpendicular to that plane. On the plane an
// axis is AnglesToAxis(A, C) with C the plane's azimuth and A of either
// sign, so the machine crosses the pole by a sign change of A with C held
// (Machine::AssignJoints takes that branch change where the A travel has
// room for it).
#ifndef TPOPT_SOLVER_POLE_CROSSING_H_
#define TPOPT_SOLVER_POLE_CROSSING_H_

#include <Eigen/Core>

#include "model/path/tool_path.h"
#include "solver/spline/pole_passage.h"

namespace tpopt {

struct PoleCrossing {
  PolePassage passage;
  // Azimuth of the plane through +Z, radians in (-pi, pi]: the plane holds
  // every axis AnglesToAxis(A, plane_c_rad) for any A. The passage's first
  // axis lies on its A >= 0 side (or on the plane's normal).
  double plane_c_rad = 0.0;
  // Largest angle between an axis of the passage and the plane, radians:
  // the most any axis moves when put on the plane.
  double miss_rad = 0.0;
};

// The plane that best fits the axes of `passage` of `path`, and how far
// they are from it. Precondition: passage within path.
PoleCrossing FitPoleCrossing(const ToolPath& path, const PolePassage& passage);

// Puts each axis of crossing.passage in `path` on the crossing's plane:
// drops its component along the plane's normal and scales it back to unit
// length, so it turns by exactly its angle from the plane, towards it.
// Tips are left where they are.
void RouteThroughPole(const PoleCrossing& crossing, ToolPath* path);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_POLE_CROSSING_H_
