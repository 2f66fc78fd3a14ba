#include "model/deviation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <glog/logging.h>

#include "model/rail_projection.h"

namespace tpopt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The path prepared for distance queries.
struct Motion {
  const Cutter* cutter;
  const Machine* machine;
  const std::vector<JointVector>* joints;
  std::vector<int> moves;        // i such that i -> i+1 cuts
  std::vector<double> move_u;    // contact u at the start of each cut move
};

double DistanceAt(const Motion& m, int move, double s, const Eigen::Vector3d& q) {
  const int i = m.moves[move];
  const JointVector j = (1.0 - s) * (*m.joints)[i] + s * (*m.joints)[i + 1];
  Eigen::Vector3d tip, axis;
  m.machine->ToWorkpiece(j, &tip, &axis);
  return SignedDistanceToCutter<double>(*m.cutter, q, tip, axis);
}

// Least distance over one move: coarse samples, then golden-section search
// around the best sample.
double MinOverMove(const Motion& m, int move, const Eigen::Vector3d& q, int substeps) {
  double best = kInf;
  int best_k = 0;
  for (int k = 0; k <= substeps; ++k) {
    const double d = DistanceAt(m, move, static_cast<double>(k) / substeps, q);
    if (d < best) {
      best = d;
      best_k = k;
    }
  }
  double lo = std::max(0.0, (best_k - 1.0) / substeps);
  double hi = std::min(1.0, (best_k + 1.0) / substeps);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = DistanceAt(m, move, x1, q), f2 = DistanceAt(m, move, x2, q);
  while (hi - lo > 1e-9) {
    if (f1 < f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - g * (hi - lo);
      f1 = DistanceAt(m, move, x1, q);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + g * (hi - lo);
      f2 = DistanceAt(m, move, x2, q);
    }
  }
  return std::min({best, f1, f2});
}

Status Prepare(const Cutter& cutter, const ToolPath& path, const Machine& machine,
               const std::vector<JointVector>& joints, const RuledSurface& surface, Motion* m) {
  CHECK_EQ(joints.size(), path.poses.size());
  m->cutter = &cutter;
  m->machine = &machine;
  m->joints = &joints;
  const std::vector<double> u = ProjectPathOntoRail(surface.rail(0), path);
  for (size_t i = 0; i + 1 < path.poses.size(); ++i) {
    if (path.poses[i + 1].rapid) continue;
    m->moves.push_back(static_cast<int>(i));
    m->move_u.push_back(0.5 * (u[i] + u[i + 1]));
  }
  if (m->moves.empty()) return Status::Error("the path has no cutting move to evaluate");
  return Status::Ok();
}

void InitGrid(const Motion& m, const DeviationOptions& o, DeviationReport* r) {
  const auto [lo, hi] = std::minmax_element(m.move_u.begin(), m.move_u.end());
  r->u.resize(o.samples_u);
  r->v.resize(o.samples_v);
  for (int i = 0; i < o.samples_u; ++i) r->u[i] = *lo + (*hi - *lo) * i / (o.samples_u - 1);
  for (int j = 0; j < o.samples_v; ++j) r->v[j] = static_cast<double>(j) / (o.samples_v - 1);
  r->deviation_mm.assign(r->u.size() * r->v.size(), 0.0);
}

void Summarise(DeviationReport* r) {
  double sum_sq = 0.0;
  r->max_overcut_mm = r->max_undercut_mm = 0.0;
  const size_t nv = r->v.size();
  for (size_t k = 0; k < r->deviation_mm.size(); ++k) {
    const double d = r->deviation_mm[k];
    sum_sq += d * d;
    if (-d > r->max_overcut_mm) {
      r->max_overcut_mm = -d;
      r->overcut_u = r->u[k / nv];
      r->overcut_v = r->v[k % nv];
    }
    if (d > r->max_undercut_mm) {
      r->max_undercut_mm = d;
      r->undercut_u = r->u[k / nv];
      r->undercut_v = r->v[k % nv];
    }
  }
  r->rms_deviation_mm = std::sqrt(sum_sq / std::max<size_t>(1, r->deviation_mm.size()));
}

// Moves whose contact u is nearest to u, plus `count` either side.
std::pair<int, int> CandidateMoves(const std::vector<double>& move_u, double u, int count) {
  int nearest = 0;
  double best = kInf;
  // Contact u is monotone along a flank pass, but a path may hold several
  // passes: scan all, it is cheap next to the distance evaluations.
  for (size_t k = 0; k < move_u.size(); ++k) {
    const double d = std::abs(move_u[k] - u);
    if (d < best) {
      best = d;
      nearest = static_cast<int>(k);
    }
  }
  const int n = static_cast<int>(move_u.size());
  return {std::max(0, nearest - count), std::min(n - 1, nearest + count)};
}

}  // namespace

bool DeviationOptions::IsValid(std::string* why) const {
  if (samples_u >= 2 && samples_v >= 2 && substeps >= 1 && neighbour_moves >= 1) return true;
  if (why != nullptr) {
    std::ostringstream err;
    err << "deviation grid " << samples_u << " x " << samples_v << " must be at least 2 x 2, "
        << "substeps " << substeps << " and neighbour moves " << neighbour_moves << " >= 1";
    *why = err.str();
  }
  return false;
}

namespace {

// Prepares the motion and the grid, fills every grid point with
// least_distance(motion, u, q) and summarises. One driver for the fast
// evaluator and its brute-force reference, so that both see the same grid.
template <typename LeastDistance>
Status EvaluateOnGrid(const RuledSurface& surface, const Cutter& cutter, const ToolPath& path,
                      const Machine& machine, const std::vector<JointVector>& joints,
                      const DeviationOptions& options, LeastDistance least_distance,
                      DeviationReport* report) {
  std::string why;
  if (!options.IsValid(&why)) return Status::Error(why);
  Motion m;
  Status s = Prepare(cutter, path, machine, joints, surface, &m);
  if (!s.ok()) return s;
  InitGrid(m, options, report);
  const size_t nv = report->v.size();
  for (size_t iu = 0; iu < report->u.size(); ++iu) {
    for (size_t iv = 0; iv < nv; ++iv) {
      const Eigen::Vector3d q = surface.Point(report->u[iu], report->v[iv]);
      report->deviation_mm[iu * nv + iv] = least_distance(m, report->u[iu], q);
    }
  }
  Summarise(report);
  return Status::Ok();
}

}  // namespace

Status EvaluateDeviation(const RuledSurface& surface, const Cutter& cutter, const ToolPath& path,
                         const Machine& machine, const std::vector<JointVector>& joints,
                         const DeviationOptions& options, DeviationReport* report) {
  auto pruned = [&](const Motion& m, double u, const Eigen::Vector3d& q) {
    const auto [first, last] = CandidateMoves(m.move_u, u, options.neighbour_moves);
    double best = kInf;
    for (int move = first; move <= last; ++move) {
      best = std::min(best, MinOverMove(m, move, q, options.substeps));
    }
    return best;
  };
  return EvaluateOnGrid(surface, cutter, path, machine, joints, options, pruned, report);
}

Status EvaluateDeviationBruteForce(const RuledSurface& surface, const Cutter& cutter,
                                   const ToolPath& path, const Machine& machine,
                                   const std::vector<JointVector>& joints,
                                   const DeviationOptions& options, int substeps_per_move,
                                   DeviationReport* report) {
  auto every_sample = [&](const Motion& m, double, const Eigen::Vector3d& q) {
    double best = kInf;
    for (size_t move = 0; move < m.moves.size(); ++move) {
      for (int k = 0; k <= substeps_per_move; ++k) {
        best = std::min(best, DistanceAt(m, static_cast<int>(move),
                                         static_cast<double>(k) / substeps_per_move, q));
      }
    }
    return best;
  };
  return EvaluateOnGrid(surface, cutter, path, machine, joints, options, every_sample, report);
}

}  // namespace tpopt
