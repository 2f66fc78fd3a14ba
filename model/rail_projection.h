// Surface parameters of CL poses: the u of the contact ruling of each pose.
//
// For a flank pose the tip sits at C1(u) + R n' with n' normal to the rail's
// tangent C1'(u) (the surface normal at v = 0 is normal to r_u = C1'(u)), so
// u is the foot point of the tip on rail 0: (p_w_tip - C1(u)) . C1'(u) = 0.
#ifndef TPOPT_MODEL_RAIL_PROJECTION_H_
#define TPOPT_MODEL_RAIL_PROJECTION_H_

#include <vector>

#include <Eigen/Core>

#include "model/bspline_curve.h"
#include "model/tool_path.h"

namespace tpopt {

// Foot point parameter in [0, 1] of `point` on `curve`, by a coarse scan of
// `scan_samples` over [u_lo, u_hi] and Newton refinement (safeguarded by
// bisection); returns the clamped end when the foot lies beyond it.
double ProjectOntoCurve(const BSplineCurve& curve, const Eigen::Vector3d& point, double u_lo = 0.0,
                        double u_hi = 1.0, int scan_samples = 64);

// u of every pose of `path` on `rail`, monotone along the path: each pose is
// searched near its predecessor's u (a window of +-window_u) so that a path
// over a rail that nearly folds back never jumps rulings. A rapid or link
// target (the start of a cut) is searched over the whole rail.
std::vector<double> ProjectPathOntoRail(const BSplineCurve& rail, const ToolPath& path,
                                        double window_u = 0.05);

}  // namespace tpopt

#endif  // TPOPT_MODEL_RAIL_PROJECTION_H_
