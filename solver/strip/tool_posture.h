// Three ways to position a torus cutter at a cutter-contact (CC) point for
// strip-width machining, all on the cross section of model/eval/strip_width.h.
//
// A posture is the lead angle (tilt of the axis from the normal n towards
// the feed f), the tilt angle (from there towards the cross direction b),
//   a = cos(tilt) (cos(lead) n + sin(lead) f) + sin(tilt) b,
// and the cross offset s_c (mm) of the point where the cutter touches the
// surface; the contact is the cross-section point at s_c with its normal.
//
// - Sturz: a fixed lead, no tilt, contact at the CC point.
// - MPM (multi-point method): contact at the CC point; lead and tilt are
//   chosen for the widest strip that does not gouge. Where the surface is
//   concave enough the optimum is where the cutter touches the section at
//   further points besides the CC point (the multi-point contact); on
//   convex sections it is the least lead allowed.
// - MPEC (the seed's mid-point error control): the cutter is placed so that
//   the mid-point of its effective cutting segment (the strip) is the CC
//   point, which lets the contact move off the CC point by s_c; lead and
//   tilt are then chosen for the widest strip that does not gouge.
//
// The seed (Chen, Yue, Xu 2011) is available here only as its abstract; the
// details above (the deviation measure, "no gouge" as the constraint of
// both optimising methods, the search) are this implementation's.
#ifndef TPOPT_SOLVER_TOOL_POSTURE_H_
#define TPOPT_SOLVER_TOOL_POSTURE_H_

#include <cmath>
#include <string>

#include <Eigen/Core>

#include "model/eval/strip_width.h"
#include "model/cutter/torus_cutter.h"

namespace tpopt {

enum class PostureMethod { kSturz, kMultiPoint, kMidPointErrorControl };

struct Posture {
  double lead_rad = 0.0;
  double tilt_rad = 0.0;
  double contact_s_mm = 0.0;
};

struct PostureOptions {
  // Deviation tolerance of the strip, mm. > 0.
  double tolerance_mm = 0.01;
  // Sturz: the fixed lead angle, radians, in [min_lead_rad, max_lead_rad].
  double sturz_lead_rad = 10.0 * M_PI / 180.0;
  // Search box of MPM and MPEC, radians: lead in [min, max] (min > 0 keeps
  // the contact circle defined), |tilt| <= max_tilt.
  double min_lead_rad = 1.0 * M_PI / 180.0;
  double max_lead_rad = 40.0 * M_PI / 180.0;
  double max_tilt_rad = 20.0 * M_PI / 180.0;
  // A deviation below -gouge_tolerance_mm counts as a gouge. Numerical
  // noise of the deviation is ~1e-9 mm; a multi-point contact touches at 0.
  double gouge_tolerance_mm = 1e-6;
  // The search stops refining once its step is below this, radians.
  double angle_resolution_rad = 0.01 * M_PI / 180.0;
  // MPM and MPEC: strips whose widths differ by less than this fraction
  // count as equally wide, and the posture nearer the previous CC point's
  // wins (see ChoosePosture). 0 = always the wider.
  double continuity_tie = 0.005;

  bool IsValid(std::string* why) const;
};

// The tool in W for a posture: unit axis and tip.
struct PlacedTool {
  Eigen::Vector3d axis, tip;
};
PlacedTool PlaceTool(const TorusCutter& cutter, const CrossSection& section,
                     const Posture& posture);

// The strip of a posture on the section.
Strip EvaluatePosture(const TorusCutter& cutter, const CrossSection& section,
                      const Posture& posture, double tolerance_mm);

// The method's posture at this CC point, and its strip. `previous`, the
// posture at the CC point before (or null), breaks near-ties between
// equally wide strips in favour of continuity: a symmetric section has two
// mirror-image optima (tilt +t and -t), and picking between them by
// round-off makes the tool jump from side to side along the pass.
Posture ChoosePosture(PostureMethod method, const TorusCutter& cutter,
                      const CrossSection& section, const PostureOptions& options, Strip* strip,
                      const Posture* previous = nullptr);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_TOOL_POSTURE_H_
