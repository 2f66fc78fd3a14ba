// The optimisation variables of one pose: a 5-vector [A, C, x, y, z] with
// the rotary joints in radians and the tool tip p_w_tip in W in mm. One
// parameter block per pose keeps the normal matrix banded.
#ifndef TPOPT_SOLVER_POSE_PARAMETERS_H_
#define TPOPT_SOLVER_POSE_PARAMETERS_H_

#include <Eigen/Core>

#include "model/machine/machine.h"

namespace tpopt {

constexpr int kPoseSize = 5;
constexpr int kPoseA = 0;
constexpr int kPoseC = 1;
constexpr int kPoseTip = 2;  // x, y, z follow

template <typename T>
Eigen::Matrix<T, 3, 1> PoseTip(const T* pose) {
  return Eigen::Matrix<T, 3, 1>(pose[kPoseTip], pose[kPoseTip + 1], pose[kPoseTip + 2]);
}

template <typename T>
Eigen::Matrix<T, 3, 1> PoseAxis(const T* pose) {
  return AnglesToAxis<T>(pose[kPoseA], pose[kPoseC]);
}

// Machine joints [X, Y, Z, A, C] of a pose through the kinematics.
template <typename T>
Eigen::Matrix<T, 5, 1> PoseJoints(const KinematicParams& kinematics, const T* pose) {
  const Eigen::Matrix<T, 3, 1> xyz =
      WorkpieceToJoints<T>(kinematics, PoseTip(pose), pose[kPoseA], pose[kPoseC]);
  Eigen::Matrix<T, 5, 1> joints;
  joints << xyz, pose[kPoseA], pose[kPoseC];
  return joints;
}

}  // namespace tpopt

#endif  // TPOPT_SOLVER_POSE_PARAMETERS_H_
