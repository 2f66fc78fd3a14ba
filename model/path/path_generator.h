// Flank-milling CL paths from a ruled surface, as a CAM system would write
// them, optionally with the CAM-like U/V mismatch the seed paper describes.
//
// Single-point offset (SPO, Liu): the axis is parallel to the ruling
// C2(u) - C1(u); the tip is C1(u) + R n(u, 0), n the unit surface normal on
// the cutter side. Exact on developable surfaces; on non-developable ones the
// cutter drifts off the ruling towards rail 1.
// Double-point offset (DPO, Liu): both ends of the ruling are offset along
// their own normals, Q1 = C1(u) + R n(u, 0), Q2 = C2(u) + R n(u, 1); the axis
// is Q2 - Q1 and the tip Q1. (Liu's refined DPO offsets two interior points
// of the ruling; the classic end-point form is what CAM systems call DPO.)
// U/V distortion: the CAM pairs C1(u) with C2(u + delta(u)), delta a smooth
// local bump, and offsets that distorted "ruling" with the normal of its own
// distorted parametrisation, so the axis swings over the bump and the
// cutter leaves the surface — the orientation jumps of the seed.
#ifndef TPOPT_MODEL_PATH_GENERATOR_H_
#define TPOPT_MODEL_PATH_GENERATOR_H_

#include <string>

#include "model/geometry/ruled_surface.h"
#include "model/base/status.h"
#include "model/path/tool_path.h"

namespace tpopt {

enum class FlankStrategy { kSinglePointOffset, kDoublePointOffset };

struct FlankPathOptions {
  // Cutter radius, mm. > 0.
  double cutter_radius_mm = 4.0;
  // Poses at u uniform in [0, 1]. >= 2.
  int poses = 300;
  FlankStrategy strategy = FlankStrategy::kSinglePointOffset;
  // Programmed feed on every pose, mm/min. > 0.
  double feed_mm_per_min = 1000.0;
  // Peak of the U/V mismatch delta(u), in u. 0 = a clean path.
  double uv_distortion = 0.0;
  // Centre and full width (in u) of the bump delta(u).
  double distortion_center = 0.5;
  double distortion_width = 0.08;
  // Standard deviation of random axis tilts, degrees; 0 = none.
  double axis_noise_deg = 0.0;
  // Seed of the noise; the same seed gives the same path.
  unsigned noise_seed = 1;
  // Flute length written with the cutter, mm; 0 = 1.25 x longest ruling.
  double flute_length_mm = 0.0;
  // Half cone angle of a tapered cutter, radians, in [0, pi/4); 0 is a
  // cylinder. SPO tilts the axis by it off the ruling towards the cutter
  // side so that the cone's line of contact is the ruling; DPO puts both
  // ruling ends on the cone (the radius at the top end is the cone's there).
  double taper_rad = 0.0;

  bool IsValid(std::string* why) const;
};

// delta(u) = amp cos^2(pi (u - u0) / w) for |u - u0| < w / 2, else 0: C1
// and zero at the bump's edges.
double UvDistortion(const FlankPathOptions& options, double u);

// The clean pose of `options`' strategy at contact ruling u in [0, 1] (no
// axis noise; the U/V mismatch if options.uv_distortion is set), with the
// tip at C1(u) + R n as above; `ruling_mm` (may be null) gets the length of
// the ruling paired with C1(u). Options must be valid. Fails naming u where
// the surface normal vanishes.
Status FlankPoseAt(const RuledSurface& surface, const FlankPathOptions& options, double u,
                   ToolPose* pose, double* ruling_mm = nullptr);

// Fails naming the value for bad options and naming u where the surface
// normal vanishes.
Status GenerateFlankPath(const RuledSurface& surface, const FlankPathOptions& options,
                         ToolPath* path);

// `passes` copies of `pass` one after another, as a multi-pass program
// runs them: a rapid to the start of each pass but the first.
ToolPath RepeatedPasses(const ToolPath& pass, int passes);

}  // namespace tpopt

#endif  // TPOPT_MODEL_PATH_GENERATOR_H_
