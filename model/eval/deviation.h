// Signed deviation of the swept cutter from the ruled surface.
//
// At a surface point q the deviation is the least signed distance from q to
// the cutter over the whole continuous motion (model/cutter/cutter.h,
// SignedDistanceToCutter): negative where the tool passed below the design
// surface (overcut, gouge), positive where it never reached it (undercut,
// material left).
//
// The motion between two consecutive poses i -> i+1 ("a move", s in [0, 1]):
//  - with a machine, as DeviationOptions::interpolation says
//    (model/machine/interpolation.h, docs/ARCHITECTURE.md "Interpolation models"): the
//    joints X, Y, Z, A, C linear, pose(s) = ToWorkpiece((1 - s) J_i +
//    s J_i+1), or TCP, the tip linear in W and A, C linear in the joints,
//    J from Machine::AssignJoints;
//  - without one, the tip moves on the straight line and the axis turns on
//    the great circle between the two axes (slerp), which is what a
//    controller with tool-centre-point control and vector interpolation does.
// A move into a rapid pose is positioning, not cutting, and is ignored; a
// link (model/path/link_moves.h) is a feed move, checked like any other.
//
// The evaluator must stay exact on dense paths: on a twisted surface the
// pose that cuts deepest at q lies about R sin(alpha) of arc length away
// from q's own ruling (the seed's principle error, model/eval/principle_error.h),
// which is many poses on a 10k-pose path. So candidate moves are not picked
// by u but by a bounding-volume hierarchy of capsules around the moves'
// axis segments, with a lower bound on the signed distance, searched branch
// and bound. Within a move the distance is sampled (more densely where a
// rotary swing carries the cutter far) and each sampled local minimum that
// could beat the best so far is refined by Brent's method to 1e-9 in s.
#ifndef TPOPT_MODEL_DEVIATION_H_
#define TPOPT_MODEL_DEVIATION_H_

#include <limits>
#include <string>
#include <vector>

#include "model/cutter/cutter.h"
#include "model/machine/interpolation.h"
#include "model/machine/machine.h"
#include "model/geometry/ruled_surface.h"
#include "model/base/status.h"
#include "model/path/tool_path.h"

namespace tpopt {

struct DeviationOptions {
  // Grid over the surface: samples_u values of u uniform over [u_min, u_max]
  // and samples_v values of v uniform over [0, 1] (each ruling end to end).
  // >= 2 each.
  int samples_u = 200;
  int samples_v = 21;
  // The u range evaluated. NaN (default) for both means the range the path
  // under evaluation covers (CoveredRangeU). That is right for a program as
  // it came in (evaluating the whole [0, 1] would report the uncut ends of
  // a partial path as undercut) but never for a path derived from it: a
  // smoothed path that retreats from the surface's ends must be charged for
  // what it leaves, so it is judged on its input's range (RunSmoothing does
  // so) or, by choice, on the whole surface, [0, 1]. Otherwise both finite
  // with 0 <= u_min <= u_max <= 1 (equal for the one ruling of a path that
  // stands on it, as the covered range of one then is).
  double u_min = std::numeric_limits<double>::quiet_NaN();
  double u_max = std::numeric_limits<double>::quiet_NaN();
  // Coarse samples per move before the least distance is refined by Brent's
  // method to 1e-9 in s. >= 1. A move along which some point of the axis
  // travels more than half the cutter radius per sample gets
  // proportionally more (at most 4096). The samples also build each move's
  // bounding volume.
  int substeps = 8;
  // The controller's motion between poses when there is a machine. The
  // library keeps the joint model by default; the tpopt command picks TCP
  // for APT and tcp-style G-code and joint for joint-style G-code.
  Interpolation interpolation = Interpolation::kJoint;
  // Each move is cut by the cutter of its tool (ToolPose::tool of the pose
  // it goes to, ToolPath::tools), where the program defines one; the
  // `cutter` argument cuts the rest. Off by default: the one cutter given
  // cuts every move (e.g. a --cutter_radius that overrides the program's).
  bool cutter_per_tool = false;

  bool IsValid(std::string* why) const;
};

struct DeviationReport {
  // Magnitudes, mm (>= 0): the most negative and the most positive signed
  // deviation on the grid, 0 when there is none of that sign.
  double max_overcut_mm = 0.0;
  double max_undercut_mm = 0.0;
  // Root mean square of the signed deviation over the grid, mm.
  double rms_deviation_mm = 0.0;
  // Surface parameters of the grid points where the extremes occur.
  double overcut_u = 0.0, overcut_v = 0.0;
  double undercut_u = 0.0, undercut_v = 0.0;
  // The grid: u values (samples_u), v values (samples_v) and the signed
  // deviations in mm, row-major: deviation_mm[iu * v.size() + iv].
  std::vector<double> u, v, deviation_mm;

  double At(size_t iu, size_t iv) const {
    return deviation_mm[iu * v.size() + iv];
  }
};

// The least and greatest contact u, on rail 0, of the poses that take part
// in a cutting move of `path` (the foot of each tip on rail 0, see
// model/path/rail_projection.h). False, leaving u_min > u_max, when the path has
// no cutting move.
bool CoveredRangeU(const RuledSurface& surface, const ToolPath& path,
                   double* u_min, double* u_max);

// The contact u on rail 0 (as above) of every pose of `path` that takes part
// in a cutting move, in path order.
std::vector<double> CuttingContactU(const RuledSurface& surface, const ToolPath& path);

// Evaluates the deviation of `path` cut with `cutter` from `surface` on the
// grid of `options`. `machine` may be null (tip linear, axis slerp, see
// above); otherwise the joints come from machine->AssignJoints. Fails, with
// a message naming the problem, for invalid options, a path without a
// cutting move, joints the machine cannot assign, or (without a machine) an
// axis that is not unit or turns by half a turn in one move.
Status EvaluateDeviation(const RuledSurface& surface, const Cutter& cutter,
                         const ToolPath& path, const Machine* machine,
                         const DeviationOptions& options,
                         DeviationReport* report);

// As above, with joints already assigned: joints.size() == path.poses.size(),
// joints[i] the joint vector of pose i on `machine` (Machine::AssignJoints).
Status EvaluateDeviation(const RuledSurface& surface, const Cutter& cutter,
                         const ToolPath& path, const Machine& machine,
                         const std::vector<JointVector>& joints,
                         const DeviationOptions& options,
                         DeviationReport* report);

// Reference for tests: on the same grid, the least distance over
// `substeps_per_move` + 1 uniform samples of every cutting move, with no
// pruning and no refinement. Slow: O(grid x moves x substeps).
Status EvaluateDeviationBruteForce(const RuledSurface& surface,
                                   const Cutter& cutter, const ToolPath& path,
                                   const Machine* machine,
                                   const DeviationOptions& options,
                                   int substeps_per_move,
                                   DeviationReport* report);
Status EvaluateDeviationBruteForce(const RuledSurface& surface,
                                   const Cutter& cutter, const ToolPath& path,
                                   const Machine& machine,
                                   const std::vector<JointVector>& joints,
                                   const DeviationOptions& options,
                                   int substeps_per_move,
                                   DeviationReport* report);

}  // namespace tpopt

#endif  // TPOPT_MODEL_DEVIATION_H_
