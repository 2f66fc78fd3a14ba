// Signed deviation of the swept cutter from the ruled surface.
//
// At a surface point q the deviation is the least signed distance from q to
// the cutter over the whole motion (model/cutter.h, SignedDistanceToCutter):
// negative where the tool passed below the design surface (overcut, gouge),
// positive where it never reached it (undercut, material left). Between two
// blocks the controller interpolates its joints X, Y, Z, A, C linearly, so
// the motion is J(s) = (1 - s) J_i + s J_i+1 mapped back to W through the
// kinematics. Moves into a rapid pose do not cut.
#ifndef TPOPT_MODEL_DEVIATION_H_
#define TPOPT_MODEL_DEVIATION_H_

#include <string>
#include <vector>

#include "model/cutter.h"
#include "model/machine.h"
#include "model/ruled_surface.h"
#include "model/status.h"
#include "model/tool_path.h"

namespace tpopt {

struct DeviationOptions {
  // Grid over the surface: samples along u (over the u range the cutting
  // poses cover, from their contact rulings) and along each ruling v in
  // [0, 1]. >= 2 each.
  int samples_u = 200;
  int samples_v = 21;
  // Coarse samples per move before refining the minimum by golden-section
  // search. >= 1.
  int substeps = 8;
  // Moves either side of the nearest pose searched for each surface point.
  // >= 1. The cutter is tangent to the surface near its own ruling only, so
  // farther moves cannot hold the minimum on a path of sane density.
  int neighbour_moves = 3;

  bool IsValid(std::string* why) const;
};

struct DeviationReport {
  // Magnitudes, mm (>= 0).
  double max_overcut_mm = 0.0;
  double max_undercut_mm = 0.0;
  double rms_deviation_mm = 0.0;
  // Where the extremes occur on the surface.
  double overcut_u = 0.0, overcut_v = 0.0;
  double undercut_u = 0.0, undercut_v = 0.0;
  // The grid: u values, v values and signed deviations (mm), row-major
  // deviation_mm[iu * v.size() + iv].
  std::vector<double> u, v, deviation_mm;
};

// Evaluates the deviation with pruning and refinement. `joints` are the
// path's joints from Machine::AssignJoints on `machine`, one per pose.
Status EvaluateDeviation(const RuledSurface& surface, const Cutter& cutter, const ToolPath& path,
                         const Machine& machine, const std::vector<JointVector>& joints,
                         const DeviationOptions& options, DeviationReport* report);

// Reference for tests: every move, `substeps_per_move` uniform samples, no
// pruning, no refinement. Slow; same grid as EvaluateDeviation.
Status EvaluateDeviationBruteForce(const RuledSurface& surface, const Cutter& cutter,
                                   const ToolPath& path, const Machine& machine,
                                   const std::vector<JointVector>& joints,
                                   const DeviationOptions& options, int substeps_per_move,
                                   DeviationReport* report);

}  // namespace tpopt

#endif  // TPOPT_MODEL_DEVIATION_H_
