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

// Rulings nearer the A = 0 pole than this give no C reference: there C
// turns as 1 / sin A, and a departure of a degree in the axis is tens of
// degrees of C, which no smoothness in the joints describes.
constexpr double kRulingAnglesPoleDeg = 15.0;

// Near the pole, A (the axis' angle from it) departs smoothly from its
// ruling's A only where the ruling lies farther from the pole than this many
// times the start axis lies from the ruling: a ruling that passes the pole
// much nearer than the axis does has a V in A that the axis does not follow
// (the hypar of data/surfaces passes at 0.04 deg, its CAM path at 1.1 deg).
constexpr double kRulingAPoleClearance = 2.0;

// A pose's reference angles, radians; either absent where no ruling gives it.
struct RulingReference {
  std::optional<double> a, c;
};

// Per pose, the (A, C) whose axis (AnglesToAxis) is the unit ruling
// direction at contact u[i] (pointing the way of the pose's start axis), on
// the branch and C winding nearest the start angles start_ac[i]. Both are
// absent for a pose beyond the surface's ends (beyond_ends[i]) or whose
// start axis is more than cone_deg from its ruling (a pose no ruling
// describes). Near the pole (within kRulingAnglesPoleDeg) C is absent, and
// A too unless `a_near_pole` and the ruling clears the pole by
// kRulingAPoleClearance.
// Precondition: u, beyond_ends and start_ac have one entry per pose.
std::vector<RulingReference> RulingAngles(const RuledSurface& surface, const std::vector<double>& u,
                                          const std::vector<bool>& beyond_ends,
                                          const std::vector<Eigen::Vector2d>& start_ac,
                                          double cone_deg, bool a_near_pole);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_RULING_ANGLES_H_
