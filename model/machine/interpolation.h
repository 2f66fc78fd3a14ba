// How the controller moves the tool between two blocks of a program.
//
// TCP (tool-centre-point control: LinuxCNC M428, Siemens TRAORI, Heidenhain
// M128; also the reading of APT CL): the tip moves on the straight line in
// the workpiece frame W, and A and C move linearly in the joints:
//   p_w(s) = (1 - s) p_w_0 + s p_w_1,   (A, C)(s) = (1 - s) (A, C)_0 + s (A, C)_1.
// Joint: all five joints X, Y, Z, A, C move linearly and the tip in W is
// where the kinematics put it,
//   p_w(s) = ToWorkpiece((1 - s) J_0 + s J_1),
// which bows away from the chord wherever the rotaries turn: by about
// |pivot distance| x (turn)^2 / 8, large where C swings near the A = 0
// pole. Both give the axis a(s) = AnglesToAxis(A(s), C(s)).
#ifndef TPOPT_MODEL_INTERPOLATION_H_
#define TPOPT_MODEL_INTERPOLATION_H_

#include <string>

#include <Eigen/Core>

#include "model/machine/machine.h"

namespace tpopt {

enum class Interpolation { kTcp, kJoint };

// "tcp" or "joint".
const char* InterpolationName(Interpolation interpolation);
// Parses "tcp" or "joint"; false (leaving *out alone) for anything else.
bool ParseInterpolation(const std::string& name, Interpolation* out);

// The tip and unit axis in W at fraction s in [0, 1] of the move from
// joints j0 (tip p0_w) to joints j1 (tip p1_w) on a machine with
// kinematics `k`. p0_w and p1_w must be the tips of j0 and j1; the joint
// model does not read them. Templated so residuals can differentiate.
template <typename T>
void InterpolateMove(const KinematicParams& k, Interpolation interpolation,
                     const Eigen::Matrix<T, 5, 1>& j0, const Eigen::Matrix<T, 5, 1>& j1,
                     const Eigen::Matrix<T, 3, 1>& p0_w, const Eigen::Matrix<T, 3, 1>& p1_w,
                     const T& s, Eigen::Matrix<T, 3, 1>* tip_w, Eigen::Matrix<T, 3, 1>* axis_w) {
  const Eigen::Matrix<T, 5, 1> j = (T(1.0) - s) * j0 + s * j1;
  *axis_w = AnglesToAxis<T>(j[kA], j[kC]);
  if (interpolation == Interpolation::kTcp) {
    *tip_w = (T(1.0) - s) * p0_w + s * p1_w;
  } else {
    *tip_w = JointsToWorkpiece<T>(k, j[kX], j[kY], j[kZ], j[kA], j[kC]);
  }
}

}  // namespace tpopt

#endif  // TPOPT_MODEL_INTERPOLATION_H_
