#include "solver/smooth/even_stations.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "model/path/rail_projection.h"

namespace tpopt {
namespace {

// The error of the controller's straight move of length h through the
// contact at u, per h^2 (mm/mm^2): the tip's chord sags from the rail by
// h^2 kappa / 8 and the interpolated axis turns off the ruling by
// h^2 |e''| / 8, which the ruling's length L carries to its far end; e is the
// unit ruling direction, '' the second derivative over rail 0's arc length
// (central differences over `du`).
double MoveErrorDensity(const RuledSurface& surface, double u) {
  constexpr double du = 1e-3;
  const double u0 = std::clamp(u, du, 1.0 - du);
  const auto ruling = [&](double t) {
    return Eigen::Vector3d(surface.rail(1).Point(t) - surface.rail(0).Point(t));
  };
  const Eigen::Vector3d e0 = ruling(u0 - du).normalized(), e1 = ruling(u0).normalized(),
                        e2 = ruling(u0 + du).normalized();
  const double h0 = (surface.rail(0).Point(u0) - surface.rail(0).Point(u0 - du)).norm();
  const double h1 = (surface.rail(0).Point(u0 + du) - surface.rail(0).Point(u0)).norm();
  if (!(h0 > 0 && h1 > 0)) return 0.0;
  const double e_ss = ((e2 - e1) / h1 - (e1 - e0) / h0).norm() * 2 / (h0 + h1);
  const double radius_mm = surface.rail(0).CurvatureRadius(u0);
  const double kappa = std::isfinite(radius_mm) && radius_mm > 0 ? 1 / radius_mm : 0.0;
  return (ruling(u0).norm() * e_ss + kappa) / 8;
}

// Appends to `out` the stretch of `path` from pose first to pose last as
// (last - first) * moves_per_move moves along its motion, each making the
// same error: at equal steps of the integral of sqrt(density) over tip arc
// length, the density (MoveErrorDensity at each pose's contact u) floored at
// its mean over the stretch, so that a nearly flat stretch is spaced evenly
// in arc length and poses gather only where the error concentrates (README,
// "Random cases", stop 26, for the floors tried). Every moves_per_move-th
// station is the program's pose of that place in the stretch; those between
// are new poses (Derived) of the move into the next of them.
void SpaceStretch(const ToolPath& path, const std::vector<JointVector>& joints,
                  const std::vector<double>& density, const KinematicParams& kinematics,
                  Interpolation interpolation, size_t first, size_t last, int moves_per_move,
                  ToolPath* out) {
  double mean = 0.0;
  for (size_t i = first; i <= last; ++i) mean += density[i] / (last - first + 1);
  // (A stretch that neither curves nor twists has no density: even steps.)
  const double floor = mean > 0 ? mean : 1.0;
  const auto weight = [&](size_t i) { return std::sqrt(std::max(density[i], floor)); };
  std::vector<double> phi(last - first + 1, 0.0);
  for (size_t i = first + 1; i <= last; ++i) {
    const double move_mm = (path.poses[i].p_w_tip - path.poses[i - 1].p_w_tip).norm();
    phi[i - first] = phi[i - 1 - first] + 0.5 * (weight(i - 1) + weight(i)) * move_mm;
  }
  const size_t stations = (last - first) * moves_per_move;
  out->poses.push_back(path.poses[first]);
  size_t move = first;  // the move move -> move + 1 holds the station
  for (size_t k = 1; k < stations; ++k) {
    const size_t program_pose = first + (k + moves_per_move - 1) / moves_per_move;
    ToolPose pose =
        k % moves_per_move == 0 ? path.poses[program_pose] : Derived(path.poses[program_pose]);
    const double station = phi.back() * static_cast<double>(k) / stations;
    while (move + 1 < last && phi[move + 1 - first] < station) ++move;
    const double span = phi[move + 1 - first] - phi[move - first];
    const double lambda = span > 0 ? (station - phi[move - first]) / span : 0.0;
    InterpolateMove<double>(kinematics, interpolation, joints[move], joints[move + 1],
                            path.poses[move].p_w_tip, path.poses[move + 1].p_w_tip, lambda,
                            &pose.p_w_tip, &pose.a_w);
    // Its joints are no longer those the program gave the block.
    pose.programmed.reset();
    out->poses.push_back(pose);
  }
  out->poses.push_back(path.poses[last]);
}

// Whether the move into pose i of `path` continues the cutting stretch
// that pose i - 1 is in (`beyond`: PosesBeyondRailEnds's).
bool ContinuesStretch(const ToolPath& path, const std::vector<bool>& beyond, size_t i) {
  const ToolPose& pose = path.poses[i];
  return !IsPositioningMove(pose) && !beyond[i] && !beyond[i - 1] &&
         pose.tool == path.poses[i - 1].tool;
}

}  // namespace

Status LargestJointBowMm(const ToolPath& path, const RuledSurface& surface, const Machine& machine,
                         double* bow_mm) {
  std::vector<JointVector> joints;
  RETURN_IF_ERROR(machine.AssignJoints(path, &joints));
  const std::vector<bool> beyond =
      PosesBeyondRailEnds(surface.rail(0), path, ProjectPathOntoRail(surface.rail(0), path));
  *bow_mm = 0.0;
  for (size_t i = 1; i < path.poses.size(); ++i) {
    if (!ContinuesStretch(path, beyond, i)) continue;
    const Eigen::Vector3d& p0 = path.poses[i - 1].p_w_tip;
    const Eigen::Vector3d& p1 = path.poses[i].p_w_tip;
    Eigen::Vector3d tip, axis;
    InterpolateMove<double>(machine.kinematics, Interpolation::kJoint, joints[i - 1], joints[i], p0,
                            p1, 0.5, &tip, &axis);
    *bow_mm = std::max(*bow_mm, (tip - 0.5 * (p0 + p1)).norm());
  }
  return Status::Ok();
}

Status EvenStations(const ToolPath& path, const RuledSurface& surface, const Machine& machine,
                    Interpolation interpolation, int moves_per_move, ToolPath* out) {
  if (moves_per_move < 1) {
    return Status::Error("even stations: " + std::to_string(moves_per_move) +
                         " moves per programmed move (at least 1)");
  }
  std::vector<JointVector> joints;
  RETURN_IF_ERROR(machine.AssignJoints(path, &joints));
  const std::vector<double> u = ProjectPathOntoRail(surface.rail(0), path);
  const std::vector<bool> beyond = PosesBeyondRailEnds(surface.rail(0), path, u);
  const size_t n = path.poses.size();
  std::vector<double> density(n, 0.0);
  for (size_t i = 0; i < n; ++i) density[i] = MoveErrorDensity(surface, u[i]);
  const auto continues = [&](size_t i) { return ContinuesStretch(path, beyond, i); };
  ToolPath stations = WithoutPoses(path);
  for (size_t first = 0; first < n;) {
    size_t last = first;
    while (last + 1 < n && continues(last + 1)) ++last;
    if (last > first) {
      SpaceStretch(path, joints, density, machine.kinematics, interpolation, first, last,
                   moves_per_move, &stations);
    } else {
      stations.poses.push_back(path.poses[first]);
    }
    first = last + 1;
  }
  *out = std::move(stations);
  return Status::Ok();
}

}  // namespace tpopt
