// The seed's plain method (000 paper, section 3), the `--mode=spline` output
// and the initial guess of the high-accuracy mode:
//  1. unwrap A and C along the path (Machine::AssignRotaryAngles, the A
//     and C of Machine::AssignJoints);
//  2. find the zones of abrupt rotary acceleration — |d2A/ds2| or |d2C/ds2|
//     above `zone_factor` times its median over the path — and, with a
//     surface, of fast Gaussian-curvature change (|dK/ds| above
//     `zone_factor` times its median), padded by `zone_padding` poses;
//  3. fit cubic smoothing splines A(s), C(s) over the tip's arc length s,
//     with the zone poses down-weighted so the spline passes over their
//     jumps instead of through them, and the smoothing as strong as the
//     angle tolerance allows at the other poses;
//  4. move the zone poses' A, C onto the fitted curves — the seed's "modify
//     the CL points" — and, with `insert_transitions`, add a pose from the
//     fitted functions midway along every move inside a zone; with
//     `smooth_outside_zones` every pose moves onto the curves (noise within
//     the tolerance is smoothed away too);
//  5. recompute each tip so the cutter stays tangent at its contact point:
//     tip = C1(u_i) + R unit(n - (n.a) a), with u_i the contact ruling of the
//     input pose and n the surface normal there (without a surface the tip
//     stays).
// Before step 1, a pole passage (solver/spline/pole_passage.h) whose axes all lie
// within `pole_crossing_deg` of one plane through +Z is put on that plane
// (solver/spline/pole_crossing.h), so that the unwrap crosses the pole by a sign
// change of A with C held instead of swinging C by half a turn, and the
// passage is made a zone.
// Rapids and the poses next to them are never changed.
#ifndef TPOPT_SOLVER_SPLINE_SMOOTHER_H_
#define TPOPT_SOLVER_SPLINE_SMOOTHER_H_

#include <string>

#include "model/cutter/cutter.h"
#include "model/machine/machine.h"
#include "model/geometry/ruled_surface.h"
#include "model/base/status.h"
#include "model/path/tool_path.h"

namespace tpopt {

struct SplineSmootherOptions {
  // Zone threshold as a multiple of the path's median |second derivative|.
  double zone_factor = 8.0;
  // Poses added on each side of a zone.
  int zone_padding = 3;
  // Largest change of A or C the fit may make at poses outside the zones,
  // degrees. > 0. It sets the smoothing strength, and so how smoothly the
  // fitted zones join the untouched poses around them.
  double angle_tolerance_deg = 0.05;
  // Move the poses outside the zones onto the fitted curves too.
  bool smooth_outside_zones = false;
  // Weight of zone poses in the fit relative to 1 outside; (0, 1].
  double zone_weight = 1e-4;
  // Insert a pose at the middle of every move inside a zone.
  bool insert_transitions = false;
  // Pole passages: stretches whose axis stays within this angle of +Z while
  // C turns a quarter turn or more (as HighAccuracyOptions::
  // pole_passage_deg). Degrees, [0, 90); 0 = never look for them.
  double pole_passage_deg = 5.0;
  // Largest angle any axis of a passage may be from the fitted plane through
  // +Z for the passage to be routed straight through the pole, which moves
  // each axis by its angle from the plane. Degrees, >= 0; 0 = never. The
  // default admits a CAM path whose U/V error takes its passage a few
  // degrees off the plane, and stays below the 5 deg passage angle, so that
  // a passage circling the pole near that angle, which is no near miss, is
  // never flattened (README, "Figures behind the defaults").
  double pole_crossing_deg = 4.0;

  bool IsValid(std::string* why) const;
};

struct SplineSmootherReport {
  int zones = 0;
  int poses_in_zones = 0;
  int poses_inserted = 0;
  double max_angle_change_deg = 0.0;  // largest |dA| or |dC| applied
  int pole_crossings = 0;             // passages routed through the pole
};

// `options` as the high-accuracy mode's initial guess takes them: no
// inserted poses (the Ceres problem keeps the input's poses one for one)
// and no passage routed through the pole (see spline_smoother.cc).
SplineSmootherOptions ForHighAccuracyGuess(SplineSmootherOptions options);

// `surface` may be null (no tangency rebuild, no curvature zones).
Status SmoothWithSplines(const ToolPath& in, const Machine& machine, const RuledSurface* surface,
                         const Cutter& cutter, const SplineSmootherOptions& options,
                         ToolPath* out, SplineSmootherReport* report);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_SPLINE_SMOOTHER_H_
