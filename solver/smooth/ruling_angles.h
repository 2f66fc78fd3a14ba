// The rotary angles of the rulings' own direction: what the smoothness
// families of high-accuracy mode measure the axis' turning against
// (HighAccuracyOptions::ruling_departure_factor). A flank path's axis follows
// the rulings, so the rulings' own turning is the surface's, not noise; only
// the axis' departure from it (the taper, the tilt that spreads the error
// along the cutter) should be smooth.
#ifndef TPOPT_SOLVER_RULING_ANGLES_H_
#define TPOPT_SOLVER_RULING_ANGLES_H_

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "model/geometry/ruled_surface.h"

namespace tpopt {

// Rulings nearer the A = 0 pole than this give no reference: there C turns
// as 1 / sin A, and a departure of a degree in the axis is tens of degrees
// of C, which no smoothness in the joints describes.
constexpr double kRulingAnglesPoleDeg = 15.0;

// Per pose, the (A, C) in radians whose axis (AnglesToAxis) is the unit
// ruling direction at contact u[i] (pointing the way of the pose's start
// axis), on the branch and C winding nearest the start angles start_ac[i].
// None for a pose beyond the surface's ends (beyond_ends[i]), whose ruling
// lies within kRulingAnglesPoleDeg of the pole, or whose start axis is more
// than cone_deg from its ruling (a pose no ruling describes).
// Precondition: u, beyond_ends and start_ac have one entry per pose.
std::vector<std::optional<Eigen::Vector2d>> RulingAngles(const RuledSurface& surface,
                                                         const std::vector<double>& u,
                                                         const std::vector<bool>& beyond_ends,
                                                         const std::vector<Eigen::Vector2d>& start_ac,
                                                         double cone_deg);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_RULING_ANGLES_H_
