// Interpolating cubic splines through the tip (x, y, z) and the rotary
// joints (A, C, unwrapped) of a run of poses, over a parameter s the caller
// chooses (arc length), with natural or not-a-knot ends. Spline in the
// joints rather than in the axis vector so that the rotaries move smoothly
// between the poses it yields too.
// Serves the output resampling (solver/smooth/resample.h) and the coarse-to-fine
// high-accuracy solve (solver/smooth/coarse_to_fine.h).
#ifndef TPOPT_SOLVER_POSE_SPLINE_H_
#define TPOPT_SOLVER_POSE_SPLINE_H_

#include <array>
#include <vector>

#include "model/machine/machine.h"
#include "model/base/status.h"
#include "model/path/tool_path.h"
#include "solver/spline/smoothing_spline.h"

namespace tpopt {

// The least step of TipArcLength: max(min_step_mm, of_mean_step x the mean
// step of the poses). A pose that only turns the axis (the tip standing)
// still gets a parameter of its own, as PoseSpline::Fit needs strictly
// increasing ones.
struct ArcLengthStepFloor {
  double min_step_mm = 0.0;
  double of_mean_step = 0.0;
};

// The tip's arc length along poses[0, n), s[0] = 0, each step at least
// `floor`'s.
std::vector<double> TipArcLength(const ToolPose* poses, size_t n, const ArcLengthStepFloor& floor);

class PoseSpline {
 public:
  enum class Ends {
    kNatural,   // zero curvature at the ends
    kNotAKnot,  // SmoothingSpline::InterpolateNotAKnot's
  };

  // Interpolates poses `indices` of `path` (joints[i] the joint vector of
  // pose i) at the strictly increasing parameters `s`, one per index.
  static Status Fit(const ToolPath& path, const std::vector<JointVector>& joints,
                    const std::vector<size_t>& indices, const std::vector<double>& s, Ends ends,
                    PoseSpline* out);

  // Sets the tip and the axis of `pose` to the splines' values at s.
  void Evaluate(double s, ToolPose* pose) const;

 private:
  std::array<SmoothingSpline, 5> fit_;  // x, y, z, A, C of the tip/joints
};

}  // namespace tpopt

#endif  // TPOPT_SOLVER_POSE_SPLINE_H_
