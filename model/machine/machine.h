// A/C table-table machine (LinuxCNC xyzac-trt-kins) with its axis limits.
//
// Joint -> workpiece (docs/ARCHITECTURE.md, "Kinematics"), with dz' = z_offset + tool_length:
//   x =  cC(X-xr) + sC cA(Y-dy-yr) + sC sA(Z-dz'-zr) + sC dy + xr
//   y = -sC(X-xr) + cC cA(Y-dy-yr) + cC sA(Z-dz'-zr) + cC dy + yr
//   z = -sA(Y-dy-yr) + cA(Z-dz'-zr) + dz' + zr
// i.e. w - pivot = Rz'(C) (Rx'(A) (J - pivot - (0,dy,dz')) + (0,dy,dz'))
// with Rz'(C) = [[cC, sC, 0], [-sC, cC, 0], [0, 0, 1]] and
//      Rx'(A) = [[1, 0, 0], [0, cA, sA], [0, -sA, cA]].
// The tool axis (0,0,1) in M maps to a_w = (sA sC, sA cC, cA).
#ifndef TPOPT_MODEL_MACHINE_H_
#define TPOPT_MODEL_MACHINE_H_

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "model/base/status.h"
#include "model/path/tool_path.h"

namespace tpopt {

// Joint vector: X, Y, Z in mm, A, C in radians.
using JointVector = Eigen::Matrix<double, 5, 1>;
enum Axis { kX = 0, kY = 1, kZ = 2, kA = 3, kC = 4 };
constexpr std::array<const char*, 5> kAxisNames = {"X", "Y", "Z", "A", "C"};

// Limits of one axis, internal units (mm or rad, per s, s^2, s^3). Infinite
// values mean "no limit" (the key was absent in the machine file).
struct AxisLimits {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  double max_velocity = std::numeric_limits<double>::infinity();
  double max_acceleration = std::numeric_limits<double>::infinity();
  double max_jerk = std::numeric_limits<double>::infinity();

  // `joint` within [min, max], with a nanometre's (or nanoradian's) slack
  // for round-off.
  bool InTravel(double joint) const { return joint >= min - 1e-9 && joint <= max + 1e-9; }
};

struct KinematicParams {
  Eigen::Vector3d rotary_pivot_mm = Eigen::Vector3d::Zero();
  double y_offset_mm = 0.0;
  double z_offset_mm = 0.0;
  double tool_length_mm = 0.0;
};

// Tip position in W from joints; templated so residuals can differentiate.
template <typename T>
Eigen::Matrix<T, 3, 1> JointsToWorkpiece(const KinematicParams& k,
                                         const T& X, const T& Y, const T& Z,
                                         const T& A, const T& C) {
  using std::cos;
  using std::sin;
  const T dy = T(k.y_offset_mm);
  const T dz = T(k.z_offset_mm + k.tool_length_mm);
  const T ux = X - T(k.rotary_pivot_mm.x());
  const T uy = Y - dy - T(k.rotary_pivot_mm.y());
  const T uz = Z - dz - T(k.rotary_pivot_mm.z());
  const T cA = cos(A), sA = sin(A), cC = cos(C), sC = sin(C);
  const T vy = cA * uy + sA * uz + dy;
  const T vz = -sA * uy + cA * uz + dz;
  return Eigen::Matrix<T, 3, 1>(cC * ux + sC * vy + T(k.rotary_pivot_mm.x()),
                                -sC * ux + cC * vy + T(k.rotary_pivot_mm.y()),
                                vz + T(k.rotary_pivot_mm.z()));
}

// Joints X, Y, Z (mm) that put the tip at p_w with the rotaries at A, C.
template <typename T>
Eigen::Matrix<T, 3, 1> WorkpieceToJoints(const KinematicParams& k,
                                         const Eigen::Matrix<T, 3, 1>& p_w,
                                         const T& A, const T& C) {
  using std::cos;
  using std::sin;
  const T dy = T(k.y_offset_mm);
  const T dz = T(k.z_offset_mm + k.tool_length_mm);
  const T wx = p_w.x() - T(k.rotary_pivot_mm.x());
  const T wy = p_w.y() - T(k.rotary_pivot_mm.y());
  const T wz = p_w.z() - T(k.rotary_pivot_mm.z());
  const T cA = cos(A), sA = sin(A), cC = cos(C), sC = sin(C);
  // v + (0, dy, dz) = Rz'(C)^T (w - pivot)
  const T vx = cC * wx - sC * wy;
  const T vy = sC * wx + cC * wy - dy;
  const T vz = wz - dz;
  // u = Rx'(A)^T v
  const T uy = cA * vy - sA * vz;
  const T uz = sA * vy + cA * vz;
  return Eigen::Matrix<T, 3, 1>(vx + T(k.rotary_pivot_mm.x()),
                                uy + dy + T(k.rotary_pivot_mm.y()),
                                uz + dz + T(k.rotary_pivot_mm.z()));
}

// Unit tool axis in W for rotary joints A, C (radians).
template <typename T>
Eigen::Matrix<T, 3, 1> AnglesToAxis(const T& A, const T& C) {
  using std::cos;
  using std::sin;
  return Eigen::Matrix<T, 3, 1>(sin(A) * sin(C), sin(A) * cos(C), cos(A));
}

// The two (A, C) solutions for a unit axis, radians, C in (-pi, pi]:
// branch 0 = (acos a_z, atan2(a_x, a_y)), branch 1 = (-A, C + pi) wrapped.
// At A = 0 both have C = 0 (C is free there; see AssignJoints).
std::array<Eigen::Vector2d, 2> AxisToAngles(const Eigen::Vector3d& a_w);

class Machine {
 public:
  std::string name;
  KinematicParams kinematics;
  // Indexed by Axis.
  std::array<AxisLimits, 5> limits;

  JointVector ToJoints(const Eigen::Vector3d& p_w_tip, double a_rad,
                       double c_rad) const;
  // Tip and axis in W for a joint vector.
  void ToWorkpiece(const JointVector& joints, Eigen::Vector3d* p_w_tip,
                   Eigen::Vector3d* a_w) const;

  // Joint vectors for a whole path, with least total rotary motion
  // (sum of |dA| + |dC|) inside the A travel. Away from the pole the two
  // (A, C) branches are half a turn of C apart, and changing branch there is
  // never allowed, so the path keeps one branch; where the path passes over
  // or near the pole the branches meet, and the continuous motion there is a
  // sign change of A, which is taken (found by dynamic programming over the
  // two branches). C is unwrapped continuously and then shifted by whole
  // turns into the C travel if it has one.
  //
  // Programmed joints (ToolPose::programmed, from G-code input) are kept
  // where a pose's axis is still the one they give: such a pose has exactly
  // its programmed A, and C keeps the program's winding. A rapid target (or
  // the first pose) takes its programmed C exactly, so a path keeps every
  // rapid as programmed, including C at A = 0 and a rapid that re-winds C;
  // the poses after it are unwrapped from there, and a kept pose after a
  // kept pose keeps the program's step of C. A path with programmed joints
  // is not shifted into the C travel (CheckTravel judges it); a path without
  // any gets the rule above. A kept pose is on the program's branch, and the
  // path may reach it from the other branch anywhere (a program that
  // changes branch at a tool change, say): that half turn of C is the
  // program's motion, not a choice.
  //
  // Singularity rule: where sin A < kSingularSinA (the axis within 2e-4 deg
  // of +Z) C is undefined, so the pose (unless it keeps programmed joints)
  // keeps the C of the nearest non-singular pose before it (or after it, at
  // the start of the path). This keeps C still through a pass over the
  // pole instead of letting it spin by noise / sin A. Near (not at) the
  // pole C does swing by roughly d(theta) / sin A; that is real machine
  // motion and AxisMetrics reports it, and `warning` (if given) names the
  // pose with the smallest |sin A| when it lies within 1 deg of the pole.
  //
  // Fails (naming the pose index, its source line, both branches' A, the
  // travel and why each branch fails there) when no sequence keeps A inside
  // the travel, which an unbounded A travel always allows, or when a pose's
  // axis is not unit.
  Status AssignJoints(const ToolPath& path, std::vector<JointVector>* joints,
                      std::string* warning = nullptr) const;

  // The A and C (radians) that AssignJoints gives the poses [first, end) of
  // `path` taken as a path of their own (errors count poses from `first`),
  // without the linear joints, which the spline method does not need.
  Status AssignRotaryAngles(const ToolPath& path, size_t first, size_t end,
                            std::vector<double>* a_rad, std::vector<double>* c_rad) const;

  // Fails, naming the first pose (index and source line), the axis, its
  // value and the travel, when a joint vector of `joints` (one per pose of
  // `path`, from AssignJoints) lies outside an axis' travel; joint Z with
  // the pose's tool length offset added (ToolPose::length_offset_mm).
  Status CheckTravel(const ToolPath& path, const std::vector<JointVector>& joints) const;

  static constexpr double kSingularSinA = 1e-6;
};

}  // namespace tpopt

#endif  // TPOPT_MODEL_MACHINE_H_
