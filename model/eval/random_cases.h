// Random flank-milling cases: a ruled surface, a machine, and a CL path
// written the way CAM systems write them, with the clean offset paths of the
// same surface as references. The fixed-seed CI cases
// (tests/random_cases_test.cc) and the random-case benchmark
// (benchmarks/random_case_benchmark.cc) share it, so a method is judged on
// geometry and conventions it was not built on.
//
// The surface, in a local frame: rail 0 is an arc of length `size` turning by
// `wrap` (a straight line for degree 1), bowed out of its plane; the ruling
// of length `height` leans by lean(u) = lean + twist (u - 1/2) about the rail
// tangent, so its direction turns by `twist` end to end (non-developable).
// Both rails are B-splines of one degree (1-3) with their control points at
// the Greville abscissae of the curves, so the rulings of the B-spline
// surface are those of the curves at the control points. The part is then
// tilted and turned into W; a case near the pole has the ruling pass within
// `pole_offset` of +Z (A = 0) at some u.
//
// The CAM path is built here, not by model/path/path_generator, so that the two
// share nothing but the surface: at contact parameter u the CAM pairs C1(u)
// with C2(u + delta(u)) (the U/V bump of UvDistortion's shape), tilts the
// ruling e by the taper towards the cutter side,
//   a = cos(taper) e + sin(taper) n_e,   n_e the normal made orthogonal to e,
// adds axis noise, and places the tip `overhang` below the bottom rail along
// the axis with the contact kept on the flank:
//   tip = C1(u) + (R + overhang tan(taper)) n_perp - overhang a,
// n_perp the surface normal at C1(u) made orthogonal to a. The poses' u are
// unevenly spaced, a few pairs of poses lie 1 micrometre apart, and lead-in
// and lead-out poses continue the tip in a straight line beyond the
// surface's ends with the end axis.
#ifndef TPOPT_MODEL_RANDOM_CASES_H_
#define TPOPT_MODEL_RANDOM_CASES_H_

#include <string>
#include <vector>

#include "model/cutter/cutter.h"
#include "model/machine/machine.h"
#include "model/geometry/ruled_surface.h"
#include "model/base/status.h"
#include "model/path/tool_path.h"

namespace tpopt {

struct RandomCaseOptions {
  // CAM poses over the surface, u in [0, 1], before the 1 micrometre
  // extra poses and the lead-in/out poses. >= 4. The clean reference paths
  // have this many poses at uniform u.
  int poses = 60;
  // Probability that a case passes near the A = 0 pole, in [0, 1].
  double near_pole_fraction = 0.3;
  // Programmed feed, mm/min. > 0.
  double feed_mm_per_min = 1000.0;

  bool IsValid(std::string* why) const;
};

// What the generator drew, in file units (mm, degrees).
struct RandomCaseParameters {
  int rail_degree = 3;
  double size_mm = 0;    // rail 0 length
  double height_mm = 0;  // ruling length
  double wrap_deg = 0;   // turn of rail 0's tangent end to end
  double twist_deg = 0;  // turn of the ruling end to end (signed)
  double lean_deg = 0;   // ruling lean at u = 1/2 in the local frame
  double tilt_deg = 0;   // tilt of the part in W
  bool near_pole = false;
  double pole_offset_deg = 0;  // near the pole: least angle of a ruling to +Z
  CutterSide side = CutterSide::kPositive;
  double cutter_radius_mm = 4;
  double taper_deg = 0;
  double overhang_mm = 0;
  double uv_bump = 0;  // peak of delta(u), in u
  double uv_bump_center = 0.5, uv_bump_width = 0.1;
  double axis_noise_deg = 0;
  int lead_in_poses = 0, lead_out_poses = 0;
  double lead_step_mm = 0;
  int micro_steps = 0;  // pairs of poses 1 micrometre apart
  Eigen::Vector3d placement_w_mm = Eigen::Vector3d::Zero();  // part centre in W
};

struct RandomCase {
  unsigned seed = 0;
  RandomCaseParameters parameters;
  RuledSurface surface;
  Machine machine;
  Cutter cutter;
  // The CAM path (see above), first pose a feed pose, no rapids.
  ToolPath cam_path;
  // Per pose of cam_path: the u of its contact point C1(u), NaN for the
  // lead-in and lead-out poses.
  std::vector<double> cam_u;
  // Clean single- and double-point-offset paths of the same surface and
  // cutter (GenerateFlankPath, `poses` at uniform u, no bump, no noise).
  ToolPath clean_spo, clean_dpo;
  // True when the CAM path and both references fit the machine's travel
  // (Machine::AssignJoints and CheckTravel pass); otherwise `fit_note` says
  // which path and why.
  bool fits_machine = false;
  std::string fit_note;
  // One line naming the seed and what was drawn.
  std::string description;
};

// Makes the case of `seed` on one of `machines` (chosen by the seed; at
// least one). The part is placed at the first of a few positions in W where
// every path fits the travel, or at the first position when none does
// (fits_machine false). Fails only for invalid options or when the drawn
// surface is degenerate (a vanishing normal; never for the ranges drawn).
Status MakeRandomCase(unsigned seed, const RandomCaseOptions& options,
                      const std::vector<Machine>& machines, RandomCase* out);

}  // namespace tpopt

#endif  // TPOPT_MODEL_RANDOM_CASES_H_
