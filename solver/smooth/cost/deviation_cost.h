// Deviation of the swept cutter from the ruled surface.
//
// For a pose (or a point of the joint-space move between two poses) and the
// surface points q_k = r(u, v_k) of the ruling it is tied to (its contact
// points), the residual is the signed distance from q_k to the cutter's
// flank, in units of the tolerance, with overcut (negative distance: the
// tool is inside the material) weighted by `overcut_factor`:
//   d_k = SignedDistanceToFlank(q_k, p_w_tip, a_w)              [mm]
//   r_k = sqrt(w h / (L n)) * d_k / tol * (d_k < 0 ? overcut_factor : 1)
// with n sample points per ruling, h the arc-length step the ruling stands
// for and L the path length, so that the cost approximates
//   E = w (1/L) integral mean_k (d_k / tol)^2 ds,
// dimensionless, independent of point density; w is dimensionless.
//
// A cylinder can hold a whole ruling on its surface and still cross the
// surface there, gouging the neighbouring rulings, because on a
// non-developable surface the normal turns along the ruling. So each pose
// also has guard points on nearby rulings, which may lie anywhere outside
// the cutter (the swept envelope takes the minimum over time, so a guard
// point's own pose measures its undercut) but not inside it:
//   r_g = sqrt(w h / (L n)) * min(d_g, 0) / tol * overcut_factor.
//
// With a dead band b > 0 a contact point costs only its excess over b,
//   r_k = sqrt(w h / (L n)) * sign(d_k) max(|d_k| - b, 0) / tol * (...),
// and a guard point only its overcut beyond b,
//   r_g = sqrt(w h / (L n)) * min(d_g + b, 0) / tol * overcut_factor,
// the exact penalties of the constraints |d_k| <= b and d_g >= -b: the
// points held to the tolerance (solver/smooth/ceres_smoother.cc,
// AddTolerancePoints) are pushed inside it, not to zero, so that holding
// them does not pull the rest of the path off.
//
// Between poses the pose at fraction lambda of the move i -> i+1 is the
// controller's (model/machine/interpolation.h): joint, J = (1 - lambda) J_i +
// lambda J_i+1 mapped back to W by the kinematics, or TCP, the tip linear
// in W with A, C linear; the two-pose form evaluates the ruling at the
// matching surface parameter against that pose.
#ifndef TPOPT_SOLVER_DEVIATION_COST_H_
#define TPOPT_SOLVER_DEVIATION_COST_H_

#include <cmath>
#include <vector>

#include <ceres/ceres.h>

#include "model/cutter/cutter.h"
#include "model/machine/interpolation.h"
#include "model/machine/machine.h"
#include "solver/smooth/cost/pose_parameters.h"

namespace tpopt {

class DeviationCost {
 public:
  struct Settings {
    Cutter cutter;
    KinematicParams kinematics;
    double tolerance_mm = 0.01;
    double overcut_factor = 3.0;
    Interpolation interpolation = Interpolation::kJoint;
    // Contact deviation within +-dead_band_mm costs nothing, mm; >= 0.
    double dead_band_mm = 0.0;
  };

  // The sample points in W: contact points (on the pose's own ruling) and
  // guard points (on neighbouring rulings).
  struct Points {
    std::vector<Eigen::Vector3d> contact_w, guard_w;
    int size() const { return static_cast<int>(contact_w.size() + guard_w.size()); }
  };

  // scale = sqrt(w h / (L n)); lambda: fraction of the move (two-pose form).
  DeviationCost(Points points, const Settings& settings, double scale, double lambda = 0.0)
      : points_(std::move(points)),
        settings_(settings),
        flank_(settings.cutter),
        scale_(scale),
        lambda_(lambda) {}

  template <typename T>
  bool operator()(const T* const pose, T* r) const {
    Residuals(PoseTip(pose), PoseAxis(pose), r);
    return true;
  }

  template <typename T>
  bool operator()(const T* const pose0, const T* const pose1, T* r) const {
    const Eigen::Matrix<T, 5, 1> j0 = PoseJoints(settings_.kinematics, pose0);
    const Eigen::Matrix<T, 5, 1> j1 = PoseJoints(settings_.kinematics, pose1);
    Eigen::Matrix<T, 3, 1> tip, axis;
    InterpolateMove<T>(settings_.kinematics, settings_.interpolation, j0, j1, PoseTip(pose0),
                       PoseTip(pose1), T(lambda_), &tip, &axis);
    Residuals(tip, axis, r);
    return true;
  }

  // Residuals for one pose.
  static ceres::CostFunction* CreateAtPose(Points points, const Settings& settings,
                                           double scale) {
    const int n = points.size();
    return new ceres::AutoDiffCostFunction<DeviationCost, ceres::DYNAMIC, kPoseSize>(
        new DeviationCost(std::move(points), settings, scale), n);
  }

  // Residuals at fraction lambda of the move between two poses.
  static ceres::CostFunction* CreateBetweenPoses(Points points, const Settings& settings,
                                                 double scale, double lambda) {
    const int n = points.size();
    return new ceres::AutoDiffCostFunction<DeviationCost, ceres::DYNAMIC, kPoseSize, kPoseSize>(
        new DeviationCost(std::move(points), settings, scale, lambda), n);
  }

 private:
  template <typename T>
  void Residuals(const Eigen::Matrix<T, 3, 1>& tip, const Eigen::Matrix<T, 3, 1>& axis,
                 T* r) const {
    const double unit = scale_ / settings_.tolerance_mm;
    for (const Eigen::Vector3d& q : points_.contact_w) {
      T d = SignedDistanceToFlank<T>(flank_, q.cast<T>(), tip, axis);
      const double band = settings_.dead_band_mm;
      if (band > 0.0) d = d > T(band) ? d - T(band) : d < T(-band) ? d + T(band) : T(0.0);
      *r++ = T(unit * (d < T(0.0) ? settings_.overcut_factor : 1.0)) * d;
    }
    // Most guard points lie outside the cutter, where the residual and its
    // derivatives are exactly zero; a plain double distance finds those, so
    // only the few inside pay for the differentiated one.
    const Eigen::Vector3d tip_value = ValueOf(tip), axis_value = ValueOf(axis);
    const double band = settings_.dead_band_mm;
    for (const Eigen::Vector3d& q : points_.guard_w) {
      if (SignedDistanceToFlank<double>(flank_, q, tip_value, axis_value) >= -band) {
        *r++ = T(0.0);
        continue;
      }
      const T d = SignedDistanceToFlank<T>(flank_, q.cast<T>(), tip, axis) + T(band);
      *r++ = d < T(0.0) ? T(unit * settings_.overcut_factor) * d : T(0.0);
    }
  }

  static double ValueOf(double x) { return x; }
  template <int N>
  static double ValueOf(const ceres::Jet<double, N>& x) {
    return x.a;
  }
  template <typename T>
  static Eigen::Vector3d ValueOf(const Eigen::Matrix<T, 3, 1>& v) {
    return Eigen::Vector3d(ValueOf(v.x()), ValueOf(v.y()), ValueOf(v.z()));
  }

  Points points_;
  Settings settings_;
  FlankShape flank_;
  double scale_;
  double lambda_;
};

}  // namespace tpopt

#endif  // TPOPT_SOLVER_DEVIATION_COST_H_
