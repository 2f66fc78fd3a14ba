// Surface parameters of CL poses: the u of the contact ruling of each pose.
//
// For a flank pose the tip sits at C1(u) + R n' with n' normal to the rail's
// tangent C1'(u) (the surface normal at v = 0 is normal to r_u = C1'(u)), so
// u is the foot point of the tip on rail 0: (p_w_tip - C1(u)) . C1'(u) = 0.
// CAM also writes flank paths with the tip below the floor (the flute
// overhanging rail 0 by 1-3 mm); there the tip's foot lies off the contact
// ruling by the overhang times the axis' lean along the rail, and past the
// rail's end near it. So where a run's median overhang
// h = (C1(u) - p_w_tip) . a_w is more than a noise-level 0.25 mm, the axis
// point x = p_w_tip + h a_w takes the tip's place. (A tip above the floor,
// h < 0, is the cutter's point nearest to it, and keeps its own foot.) For a
// tip on the floor (SPO, and the U/V-distorted paths of
// model/path/path_generator.h) x is the tip itself.
#ifndef TPOPT_MODEL_RAIL_PROJECTION_H_
#define TPOPT_MODEL_RAIL_PROJECTION_H_

#include <vector>

#include <Eigen/Core>

#include "model/geometry/bspline_curve.h"
#include "model/path/tool_path.h"

namespace tpopt {

// Foot point parameter in [0, 1] of `point` on `curve`, by a coarse scan of
// `scan_samples` over [u_lo, u_hi] and Newton refinement (safeguarded by
// bisection); returns the clamped end when the foot lies beyond it.
double ProjectOntoCurve(const BSplineCurve& curve, const Eigen::Vector3d& point, double u_lo = 0.0,
                        double u_hi = 1.0, int scan_samples = 64);

// The overhang of each pose of `path` (u: its contact rulings on `rail`,
// rail 0), mm: the height of the floor C1(u) above the tip along the axis,
// (C1(u_i) - p_w_tip) . a_w, as the median over the pose's cutting run. A
// run's median, not each pose's own: that carries the axis noise times the
// cutter radius (0.02 mm at 0.3 deg and R 4), and a smoother holding each
// tip to it would roughen the path by as much.
std::vector<double> RunOverhangs(const BSplineCurve& rail, const ToolPath& path,
                                 const std::vector<double>& u);

// u of every pose of `path` on `rail`, monotone along the path: each pose is
// searched near its predecessor's u (a window of +-window_u) so that a path
// over a rail that nearly folds back never jumps rulings. A rapid or link
// target (the start of a cut) is searched over the whole rail.
std::vector<double> ProjectPathOntoRail(const BSplineCurve& rail, const ToolPath& path,
                                        double window_u = 0.05);

// The poses of a lead-in or lead-out that CAM writes beyond an end of the
// surface: those whose u (ProjectPathOntoRail's, which clamps a foot beyond
// an end to it) is an end of `rail` and whose axis point level with the
// floor (as above) lies more than a noise-level 0.25 mm past that end along
// the rail's tangent there. They touch no ruling of their own.
std::vector<bool> PosesBeyondRailEnds(const BSplineCurve& rail, const ToolPath& path,
                                      const std::vector<double>& u);

}  // namespace tpopt

#endif  // TPOPT_MODEL_RAIL_PROJECTION_H_
