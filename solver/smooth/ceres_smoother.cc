#include "solver/smooth/ceres_smoother.h"

#include <ceres/version.h>
#include <glog/logging.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>
#include <utility>

#include "model/base/invalid_field.h"
#include "model/machine/axis_metrics.h"
#include "model/machine/interpolation.h"
#include "model/path/rail_projection.h"
#include "model/path/standing_moves.h"
#include "solver/smooth/coarse_to_fine.h"
#include "solver/smooth/cost/axis_limit_cost.h"
#include "solver/smooth/cost/deviation_cost.h"
#include "solver/smooth/cost/peak_second_cost.h"
#include "solver/smooth/cost/smoothness_cost.h"
#include "solver/smooth/cost/tip_height_cost.h"
#include "solver/smooth/cost/tip_slide_cost.h"
#include "solver/smooth/cost/tolerance_band_cost.h"
#include "solver/smooth/cost/wall_cost.h"
#include "solver/smooth/ruling_angles.h"
#include "solver/spline/overhang.h"

namespace tpopt {
namespace {

// Divided differences need distinct abscissae; a repeated pose gets this
// much arc length (mm) or time (s).
constexpr double kMinStep = 1e-6;

// Logs each Ceres iteration at verbosity 1 and passes it to the caller's
// observer, if any.
class IterationObserver : public ceres::IterationCallback {
 public:
  explicit IterationObserver(const std::function<void(int, double)>& observer)
      : observer_(observer) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    VLOG(1) << "high_accuracy iter " << s.iteration << "  cost " << s.cost << "  change "
            << -s.cost_change << "  |step| " << s.step_norm;
    if (observer_) observer_(s.iteration, s.cost);
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const std::function<void(int, double)>& observer_;
};

// Poses that may move: not rapid or link targets, on a cutting move, and not held
// at an end of the problem (a window's seams, see solver/smooth/windowed_solve.h).
std::vector<bool> FreePoses(const SmoothingInputs& in) {
  const ToolPath& path = *in.input;
  const size_t n = path.poses.size();
  std::vector<bool> cutting(n, false);
  for (size_t i = 0; i + 1 < n; ++i) {
    if (!IsPositioningMove(path.poses[i + 1])) cutting[i] = cutting[i + 1] = true;
  }
  for (size_t i = 0; i < n; ++i) {
    const bool held = i < in.held_first || i + in.held_last >= n;
    cutting[i] = cutting[i] && !IsPositioningMove(path.poses[i]) && !held;
  }
  return cutting;
}

// The moves a stencil may not span (the move into pose j of the path): the
// limits stop only at rapids, because a link is a feed move the machine must
// keep within its limits like any other; smoothness stops at rapids, links
// and standing moves (model/path/standing_moves.h), which have no length to
// differentiate over, but runs into a held pose. A held pose keeps its
// target, yet the move into it is a cut the machine makes from the pose
// before, which the solve moves: with no stencil across that move, the free
// pose beside a held one (the last of a program, the start of a standing
// move) may sit anywhere its band allows, and on 0.05 mm moves that jump
// broke axis limits the input kept (issue 17). With the stencil the held pose
// is the run's fixed end, as a rapid target is its fixed start.
using StencilBreak = bool (*)(const ToolPath&, size_t j);
bool IsRapid(const ToolPath& path, size_t j) { return path.poses[j].rapid; }
bool BreaksSmoothness(const ToolPath& path, size_t j) {
  const ToolPose& pose = path.poses[j];
  if (pose.rapid || pose.link) return true;
  return pose.held && (pose.p_w_tip - path.poses[j - 1].p_w_tip).norm() < kStandingMoveMm;
}

// True when no move between poses first..first+count-1 is a `breaks` move.
bool Connected(const ToolPath& path, size_t first, size_t count, StencilBreak breaks) {
  for (size_t j = first + 1; j < first + count; ++j) {
    if (breaks(path, j)) return false;
  }
  return true;
}

// The arc length pose i stands for in a per-pose family: half the span
// from the pose before it to the pose after it (one side at the path's ends).
double PoseShareMm(const SmoothingState& state, size_t i) {
  const size_t n = state.s_mm.size();
  return (state.s_mm[std::min(i + 1, n - 1)] - state.s_mm[i > 0 ? i - 1 : 0]) / 2;
}

template <int kCount>
std::array<double, kCount> Window(const std::vector<double>& v, size_t first) {
  std::array<double, kCount> out;
  for (int j = 0; j < kCount; ++j) out[j] = v[first + j];
  return out;
}

// Contact points on the ruling at u, and guard points on the rulings at
// the options' guard distances (mm along rail 0) either side: a cylinder
// that holds its own ruling can still cut into rulings a millimetre or two
// away where the surface twists, whatever the pose spacing.
// Guards sit at the ruling's ends and middle only: a cylinder crossing the
// twisted surface does so along its whole length, so three heights see it,
// and they cost a third of guarding every contact height. The end guards
// (options.end_guard_distances_mm) sit at the two ends alone.
DeviationCost::Points RulingPoints(const RuledSurface& surface, double u,
                                   const HighAccuracyOptions& o) {
  const int samples = o.ruling_samples;
  const double speed_mm = std::max(surface.rail(0).Evaluate(u, 1)[1].norm(), 1e-9);
  DeviationCost::Points points;
  const RuledSurface::Ruling contact = surface.RulingAt(u);
  for (int k = 0; k < samples; ++k) points.contact_w.push_back(contact.Point(k / (samples - 1.0)));
  // The guard rulings at each distance, either side (absent past an end),
  // each evaluated once for its two or three points: the rails'
  // evaluations were most of the time spent building a large problem.
  using GuardRulings = std::array<std::optional<RuledSurface::Ruling>, 2>;
  const auto rulings_at = [&](double distance_mm) {
    GuardRulings g;
    for (int k = 0; k < 2; ++k) {
      const double ug = u + (k == 0 ? -1.0 : 1.0) * distance_mm / speed_mm;
      if (ug >= 0.0 && ug <= 1.0) g[k] = surface.RulingAt(ug);
    }
    return g;
  };
  std::vector<GuardRulings> end_guards, guards;
  for (double d : o.end_guard_distances_mm) end_guards.push_back(rulings_at(d));
  for (double d : o.guard_distances_mm) guards.push_back(rulings_at(d));
  const auto guard_at = [&](const GuardRulings& g, double v) {
    for (const std::optional<RuledSurface::Ruling>& ruling : g) {
      if (ruling) points.guard_w.push_back(ruling->Point(v));
    }
  };
  for (double v : {0.0, 0.5, 1.0}) {
    if (v != 0.5) {
      for (const GuardRulings& g : end_guards) guard_at(g, v);
    }
    for (const GuardRulings& g : guards) guard_at(g, v);
  }
  return points;
}

// RulingPoints' points all as guards: what a cutter that touches no ruling
// of its own (a lead beyond the surface's ends) must stay out of.
DeviationCost::Points EndRulingGuards(const RuledSurface& surface, double u,
                                      const HighAccuracyOptions& o) {
  DeviationCost::Points guard = RulingPoints(surface, u, o);
  guard.guard_w.insert(guard.guard_w.end(), guard.contact_w.begin(), guard.contact_w.end());
  guard.contact_w.clear();
  return guard;
}

// Adds the stencils of one derivative family over every window that no
// `breaks` move splits.
template <int kOrder, typename MakeCost>
void AddStencils(const ToolPath& path, const std::vector<bool>& free_pose, StencilBreak breaks,
                 SmoothingState* state, ceres::Problem* problem, const std::string& family,
                 MakeCost make_cost) {
  const size_t n = path.poses.size();
  for (size_t i = 0; i + kOrder < n; ++i) {
    if (!Connected(path, i, kOrder + 1, breaks)) continue;
    bool any_free = false;
    std::vector<double*> blocks;
    for (size_t j = i; j <= i + kOrder; ++j) {
      any_free = any_free || free_pose[j];
      blocks.push_back(state->poses[j].data());
    }
    if (!any_free) continue;
    ceres::CostFunction* cost = make_cost(i);
    if (cost == nullptr) continue;
    state->families[family].push_back(problem->AddResidualBlock(cost, nullptr, blocks));
  }
}

// Queues `cost` (over pose i alone) for the pose's stacked block.
void AddPosePart(SmoothingState* state, size_t i, const std::string& family,
                 ceres::CostFunction* cost) {
  state->pose_parts[i].push_back({family, std::unique_ptr<ceres::CostFunction>(cost)});
}

// One residual block a pose for its queued parts: the part itself where it
// is alone, else their StackedCost.
void AddPoseParts(SmoothingState* state, ceres::Problem* problem) {
  for (size_t i = 0; i < state->pose_parts.size(); ++i) {
    std::vector<SmoothingState::PosePart>& parts = state->pose_parts[i];
    if (parts.size() == 1) {
      state->families[parts[0].family].push_back(
          problem->AddResidualBlock(parts[0].cost.release(), nullptr, state->poses[i].data()));
    } else if (parts.size() > 1) {
      auto block = std::make_unique<StackedCost>();
      for (size_t k = 0; k < parts.size(); ++k) {
        block->Add(std::move(parts[k].cost));
        state->stacked_parts.push_back({parts[k].family, block.get(), k, i});
      }
      problem->AddResidualBlock(block.release(), nullptr, state->poses[i].data());
    }
    parts.clear();
  }
}

template <int kOrder>
void AddLimitFamily(const SmoothingInputs& in, const HighAccuracyOptions& o, double length_mm,
                    const std::vector<bool>& free_pose, SmoothingState* state,
                    ceres::Problem* problem) {
  std::array<double, 5> limits;
  bool any = false;
  for (int a = 0; a < 5; ++a) {
    const AxisLimits& l = in.machine->limits[a];
    limits[a] = kOrder == 1 ? l.max_velocity : kOrder == 2 ? l.max_acceleration : l.max_jerk;
    any = any || std::isfinite(limits[a]);
  }
  if (!any || o.w_limits <= 0) return;
  AddStencils<kOrder>(*in.input, free_pose, IsRapid, state, problem, "limits", [&](size_t i) {
    const double h = (state->s_mm[i + kOrder] - state->s_mm[i]) / kOrder;
    return AxisLimitCost<kOrder>::Create(Window<kOrder + 1>(state->t_s, i), limits,
                                         in.machine->kinematics,
                                         std::sqrt(o.w_limits * h / length_mm), o.limit_margin);
  });
}

void AddDeviationFamily(const SmoothingInputs& in, const HighAccuracyOptions& o,
                        double length_mm, const std::vector<bool>& free_pose,
                        SmoothingState* state, ceres::Problem* problem) {
  DeviationCost::Settings settings{*in.cutter,       in.machine->kinematics, o.tolerance_mm,
                                   o.overcut_factor, o.interpolation,        0.0};
  const ToolPath& path = *in.input;
  const size_t n = path.poses.size();
  const int m = o.ruling_samples;
  // Quadrature points per move: the pose it starts from and, on a move
  // longer than between_min_move_mm, between_samples points inside it.
  const auto parts_of_move = [&](size_t i) {
    const bool long_move = state->s_mm[i + 1] - state->s_mm[i] >= o.between_min_move_mm;
    return long_move ? o.between_samples + 1 : 1;
  };
  for (size_t i = 0; i < n; ++i) {
    if (!free_pose[i]) continue;
    if (state->beyond_ends[i]) {
      // A lead-in or lead-out pose touches no ruling: tied to the end
      // ruling like the pose that cuts it, it was pulled millimetres along
      // the path onto it. It is only kept out of the surface there.
      const double h = PoseShareMm(*state, i);
      AddPosePart(
          state, i, "deviation",
          DeviationCost::CreateAtPose(EndRulingGuards(*in.surface, state->u[i], o), settings,
                                      std::sqrt(o.w_deviation * h / (length_mm * m))));
      continue;
    }
    // (A move to or from beyond the ends holds no ruling of its own; below,
    // its points are kept out of the end ruling.)
    const bool back_cut =
        i > 0 && !IsPositioningMove(path.poses[i]) && !state->beyond_ends[i - 1];
    const double back = back_cut ? state->s_mm[i] - state->s_mm[i - 1] : 0;
    const bool forward_cut =
        i + 1 < n && !IsPositioningMove(path.poses[i + 1]) && !state->beyond_ends[i + 1];
    const double ahead = forward_cut ? state->s_mm[i + 1] - state->s_mm[i] : 0;
    const int parts = forward_cut ? parts_of_move(i) : 1;
    // The pose stands for half a part of each neighbouring move.
    const double h_pose = back / (2.0 * (back_cut ? parts_of_move(i - 1) : 1)) + ahead / (2.0 * parts);
    AddPosePart(state, i, "deviation",
                DeviationCost::CreateAtPose(RulingPoints(*in.surface, state->u[i], o), settings,
                                            std::sqrt(o.w_deviation * h_pose / (length_mm * m))));
    if (!forward_cut) continue;
    for (int k = 1; k < parts; ++k) {
      const double lambda = static_cast<double>(k) / parts;
      const double u = (1 - lambda) * state->u[i] + lambda * state->u[i + 1];
      const double scale = std::sqrt(o.w_deviation * ahead / parts / (length_mm * m));
      state->families["deviation"].push_back(
          problem->AddResidualBlock(DeviationCost::CreateBetweenPoses(
                                        RulingPoints(*in.surface, u, o), settings, scale, lambda),
                                    nullptr, state->poses[i].data(), state->poses[i + 1].data()));
    }
  }
  // A move between a lead pose and the pose that cuts the end ruling sweeps
  // past that ruling, so its cutter is kept out of the surface inside the
  // move too: unguarded, a lead-in's cutter cut 3 um into the end ruling
  // 0.7 of the way in (random case 52), more than the whole rest of the
  // path left.
  for (size_t i = 0; i + 1 < n; ++i) {
    if (!(free_pose[i] || free_pose[i + 1]) || state->beyond_ends[i] == state->beyond_ends[i + 1] ||
        IsPositioningMove(path.poses[i + 1])) {
      continue;
    }
    const size_t lead = state->beyond_ends[i] ? i : i + 1;
    const int parts = parts_of_move(i);
    const double scale =
        std::sqrt(o.w_deviation * (state->s_mm[i + 1] - state->s_mm[i]) / parts / (length_mm * m));
    const DeviationCost::Points guards = EndRulingGuards(*in.surface, state->u[lead], o);
    for (int k = 1; k < parts; ++k) {
      state->families["deviation"].push_back(
          problem->AddResidualBlock(DeviationCost::CreateBetweenPoses(
                                        guards, settings, scale, static_cast<double>(k) / parts),
                                    nullptr, state->poses[i].data(), state->poses[i + 1].data()));
    }
  }
}

constexpr double kToleranceTargetFraction = 0.8;

// The active set of points held to the tolerance: each on every move of
// the path whose two contact rulings bracket its u, at the matching
// fraction of the move, both ways; and, since the swept envelope cuts a
// point with whichever pose's cutter reaches it, as a guard (overcut only)
// at every free pose whose contact ruling lies within the guard distances of
// it, at the middle of the moves between them (or, with
// held_point_guard_spacing_mm > 0, at points that far apart inside every
// move with one such pose at an end) and inside the moves either side of a
// cut's end pose: a point gouged from a neighbouring pose
// was otherwise held only where it was not cut, and stayed beyond at any
// weight (0.0119 mm at 1000 times, issue 16 seed 46).
void AddTolerancePoints(const SmoothingInputs& in, const HighAccuracyOptions& o,
                        const std::vector<bool>& free_pose, SmoothingState* state,
                        ceres::Problem* problem) {
  // Under joint interpolation a point at a cut's end is swept by the lead
  // move's cutter, its tip bowed off the line from beyond the surface, and
  // by the first cut move's, neither at the fraction the point's u gives:
  // those two moves are guarded at as many points inside as the judge
  // samples a move (DeviationOptions::substeps, 8), at
  // HighAccuracyOptions::end_of_cut_guard_weight. With the lead move
  // unguarded, a floor corner stayed cut 0.0113 mm deep at every penalty
  // (random case 173). Under TCP, where the tip keeps to its line, guards
  // inside the lead moves lost three of the 200 random cases (36, 60, 160)
  // and gained one, and with the first cut move's too 36 and 60 stayed
  // lost (README, "Random cases", stop 49).
  constexpr int kEndOfCutMoveGuards = 7;
  if (in.surface == nullptr || in.tolerance_points == nullptr) return;
  // Only a point's excess over kToleranceTargetFraction of its bound (the
  // tolerance, or a lower one) counts, in units of that bound (the margin
  // covers the gap between this point on the move and the judge's exact
  // envelope).
  const ToolPath& path = *in.input;
  const size_t n = path.poses.size();
  double guard_reach_mm = 0.0;
  for (const std::vector<double>* distances : {&o.guard_distances_mm, &o.end_guard_distances_mm}) {
    for (double d : *distances) guard_reach_mm = std::max(guard_reach_mm, d);
  }
  for (const TolerancePoint& point : *in.tolerance_points) {
    const double bound_mm = std::min(o.tolerance_mm, point.bound_mm);
    const DeviationCost::Settings settings{*in.cutter,       in.machine->kinematics, bound_mm,
                                           o.overcut_factor, o.interpolation,
                                           kToleranceTargetFraction * bound_mm};
    const Eigen::Vector3d q_w = in.surface->Point(point.u, point.v);
    const double scale = std::sqrt(o.w_deviation * point.weight);
    const double end_scale = std::sqrt(o.end_of_cut_guard_weight) * scale;
    DeviationCost::Points contact, guard;
    contact.contact_w.push_back(q_w);
    guard.guard_w.push_back(q_w);
    bool bracketed = false;
    for (size_t i = 0; i + 1 < path.poses.size(); ++i) {
      if (state->beyond_ends[i] || state->beyond_ends[i + 1]) continue;  // cuts in the air
      if (IsPositioningMove(path.poses[i + 1]) || !(free_pose[i] || free_pose[i + 1])) continue;
      const double u0 = state->u[i], u1 = state->u[i + 1];
      if (point.u < std::min(u0, u1) || point.u > std::max(u0, u1)) continue;
      const double lambda = u1 != u0 ? (point.u - u0) / (u1 - u0) : 0.0;
      bracketed = true;
      state->families["tolerance_points"].push_back(problem->AddResidualBlock(
          DeviationCost::CreateBetweenPoses(contact, settings, scale, lambda), nullptr,
          state->poses[i].data(), state->poses[i + 1].data()));
    }
    // A point past the contact rulings of every pose (an end ruling the
    // last pose stops a hair short of) is held at the nearest free pose.
    size_t nearest = n;
    for (size_t i = 0; i < n; ++i) {
      if (free_pose[i] && !state->beyond_ends[i] &&
          (nearest == n ||
           std::abs(state->u[i] - point.u) < std::abs(state->u[nearest] - point.u))) {
        nearest = i;
      }
    }
    if (!bracketed && nearest < n) {
      state->families["tolerance_points"].push_back(
          problem->AddResidualBlock(DeviationCost::CreateAtPose(contact, settings, scale), nullptr,
                                    state->poses[nearest].data()));
    }
    const double speed_mm = std::max(in.surface->rail(0).Evaluate(point.u, 1)[1].norm(), 1e-9);
    const double reach_u = guard_reach_mm / speed_mm;
    const auto near = [&](size_t i) {
      return !state->beyond_ends[i] && std::abs(state->u[i] - point.u) <= reach_u;
    };
    for (size_t i = 0; i < path.poses.size(); ++i) {
      if (!near(i)) continue;
      if (free_pose[i]) {
        state->families["tolerance_points"].push_back(problem->AddResidualBlock(
            DeviationCost::CreateAtPose(guard, settings, scale), nullptr,
            state->poses[i].data()));
      }
    }
    // The moves either side of the nearest pose where it is the first or
    // last of its cut (kEndOfCutMoveGuards).
    const bool cut_end = o.interpolation == Interpolation::kJoint && nearest < n &&
                         ((nearest > 0 && state->beyond_ends[nearest - 1]) ||
                          (nearest + 1 < n && state->beyond_ends[nearest + 1]));
    const double spacing_mm = o.held_point_guard_spacing_mm;
    for (size_t i = 0; i + 1 < n; ++i) {
      const bool end_move = cut_end && (i == nearest || i + 1 == nearest);
      const bool guarded =
          end_move || (spacing_mm > 0 ? near(i) || near(i + 1) : near(i) && near(i + 1));
      if (!guarded || IsPositioningMove(path.poses[i + 1]) || !(free_pose[i] || free_pose[i + 1])) {
        continue;
      }
      const double move_mm = state->s_mm[i + 1] - state->s_mm[i];
      int per_move = spacing_mm > 0
                         ? std::clamp(static_cast<int>(std::ceil(move_mm / spacing_mm)) - 1, 1, 15)
                         : 1;
      if (end_move) per_move = std::max(per_move, kEndOfCutMoveGuards);
      for (int k = 1; k <= per_move; ++k) {
        state->families["tolerance_points"].push_back(problem->AddResidualBlock(
            DeviationCost::CreateBetweenPoses(guard, settings, end_move ? end_scale : scale,
                                              k / (per_move + 1.0)),
            nullptr, state->poses[i].data(), state->poses[i + 1].data()));
      }
    }
  }
}

// The walls every free pose stays within whatever the other families pull:
// the machine's linear travel and, with a surface, the cone round the
// input's axis and the cutter's side of the surface.
void AddWallFamily(const SmoothingInputs& in, const HighAccuracyOptions& o, double length_mm,
                   const std::vector<bool>& free_pose, SmoothingState* state) {
  if (o.w_walls <= 0) return;
  const ToolPath& path = *in.input;
  const size_t n = path.poses.size();
  std::array<double, 3> lo, hi;
  bool any_travel = false;
  for (int j = 0; j < 3; ++j) {
    lo[j] = in.machine->limits[j].min;
    hi[j] = in.machine->limits[j].max;
    any_travel = any_travel || std::isfinite(lo[j]) || std::isfinite(hi[j]);
  }
  for (size_t i = 0; i < n; ++i) {
    if (!free_pose[i]) continue;
    const double h = std::max(PoseShareMm(*state, i), kMinStep);
    const double scale = std::sqrt(o.w_walls * h / length_mm);
    WallCost::Walls walls;
    if (any_travel) walls.travel.emplace(in.machine->kinematics, lo, hi, o.travel_margin_mm, scale);
    if (in.surface != nullptr) {
      const ToolPose& input = path.poses[i];
      walls.cone.emplace(input.a_w, o.axis_cone_deg * M_PI / 180.0, scale);
      std::array<SurfaceSideCost::End, 2> ends;
      for (int k = 0; k < 2; ++k) {
        ends[k].q_w = in.surface->Point(state->u[i], k);
        ends[k].normal_w = in.surface->Normal(state->u[i], k);
        const double height_mm = (ends[k].q_w - input.p_w_tip).dot(input.a_w);
        ends[k].radius_mm = std::max(in.cutter->RadiusAt(height_mm), 1e-3);
      }
      walls.side.emplace(ends, scale);
    }
    if (!walls.travel && !walls.cone) continue;
    AddPosePart(state, i, "walls", new WallCost(walls));
  }
}

// The band around the original program of every free pose (surface-free).
ToleranceBandCost::Band BandOf(const ToolPath& path, const HighAccuracyOptions& o, size_t i) {
  const size_t n = path.poses.size();
  const size_t prev = i > 0 && !IsPositioningMove(path.poses[i]) ? i - 1 : i;
  const size_t next = i + 1 < n && !IsPositioningMove(path.poses[i + 1]) ? i + 1 : i;
  ToleranceBandCost::Band band;
  band.p0_w = path.poses[i].p_w_tip;
  band.a0_w = path.poses[i].a_w;
  const Eigen::Vector3d chord = path.poses[next].p_w_tip - path.poses[prev].p_w_tip;
  band.tangent_w = chord.norm() > 1e-12 ? Eigen::Vector3d(chord.normalized())
                                        : Eigen::Vector3d::Zero();
  band.step_mm = std::max(chord.norm() / std::max<size_t>(1, next - prev), 1e-3);
  band.tolerance_mm = o.tolerance_mm;
  band.angle_tolerance_rad = o.angle_tolerance_deg * M_PI / 180.0;
  return band;
}

void AddToleranceFamily(const SmoothingInputs& in, const HighAccuracyOptions& o,
                        double length_mm, const std::vector<bool>& free_pose,
                        SmoothingState* state, ceres::Problem* problem) {
  for (size_t i = 0; i < free_pose.size(); ++i) {
    if (!free_pose[i]) continue;
    const ToleranceBandCost::Band band = BandOf(*in.input, o, i);
    state->families["tolerance"].push_back(problem->AddResidualBlock(
        ToleranceBandCost::Create(band, std::sqrt(o.w_band * band.step_mm / length_mm),
                                  o.slide_weight),
        nullptr, state->poses[i].data()));
  }
}

// With a surface, a lead-in or lead-out pose beyond its ends is tied to no
// ruling, and held by nothing but the smoothness, the walls and its guards
// it moved off its programmed line by up to 6.4 mm on the random cases
// (issue 16): a CAM system's approach, through air it chose. It keeps
// within kLeadBandMm of that line and within the axis cone of its
// programmed axis, free to slide along the line (what that costs: README,
// "Random cases", stop 24).
void AddLeadBandFamily(const SmoothingInputs& in, const HighAccuracyOptions& o,
                       double length_mm, const std::vector<bool>& free_pose,
                       SmoothingState* state, ceres::Problem* problem) {
  HighAccuracyOptions lead = o;
  lead.tolerance_mm = kLeadBandMm;
  lead.angle_tolerance_deg = o.axis_cone_deg;
  for (size_t i = 0; i < free_pose.size(); ++i) {
    if (!free_pose[i] || !state->beyond_ends[i]) continue;
    const ToleranceBandCost::Band band = BandOf(*in.input, lead, i);
    state->families["lead_band"].push_back(problem->AddResidualBlock(
        ToleranceBandCost::Create(band, std::sqrt(o.w_band * band.step_mm / length_mm),
                                  /*slide_weight=*/0.0),
        nullptr, state->poses[i].data()));
  }
}

// Moves a pose back inside its band where the solve left it a little
// outside, so that the surface-free promise holds exactly.
bool ClampToBand(const ToleranceBandCost::Band& band, ToolPose* pose) {
  bool clamped = false;
  const Eigen::Vector3d d = pose->p_w_tip - band.p0_w;
  const Eigen::Vector3d along = d.dot(band.tangent_w) * band.tangent_w;
  const Eigen::Vector3d perp = d - along;
  if (perp.norm() > band.tolerance_mm) {
    pose->p_w_tip = band.p0_w + along + perp * (band.tolerance_mm / perp.norm());
    clamped = true;
  }
  const double angle = std::acos(std::clamp(pose->a_w.dot(band.a0_w), -1.0, 1.0));
  if (angle > band.angle_tolerance_rad) {
    const Eigen::Vector3d axis = band.a0_w.cross(pose->a_w).normalized();
    pose->a_w = Eigen::AngleAxisd(band.angle_tolerance_rad, axis) * band.a0_w;
    clamped = true;
  }
  return clamped;
}

}  // namespace

bool HighAccuracyOptions::IsValid(std::string* why) const {
  FirstInvalid check;
  auto finite_at_least = [](double v, double lo) { return v >= lo && std::isfinite(v); };
  check.Require(tolerance_mm > 0 && std::isfinite(tolerance_mm),
          InvalidField("--tolerance_mm", tolerance_mm, "finite and > 0"));
  check.Require(finite_at_least(overcut_factor, 1),
          InvalidField("--overcut_factor", overcut_factor, "finite and >= 1"));
  const std::pair<const char*, double> weights[] = {
      {"--w_deviation", w_deviation},
      {"--w_second", w_second},
      {"--w_third", w_third},
      {"--w_tip_second", w_tip_second},
      {"--w_tip_third", w_tip_third},
      {"--w_limits", w_limits},
      {"--w_tip_height", w_tip_height},
      {"--w_tip_slide", w_tip_slide},
      {"--w_walls", w_walls},
      {"--w_peak_second", w_peak_second},
      {"peak_second_cap_per_mm2[0]", peak_second_cap_per_mm2[0]},
      {"peak_second_cap_per_mm2[1]", peak_second_cap_per_mm2[1]},
      {"--ruling_departure_factor", ruling_departure_factor},
      {"--end_of_cut_guard_weight", end_of_cut_guard_weight}};
  for (const auto& [flag, w] : weights) {
    check.Require(finite_at_least(w, 0), InvalidField(flag, w, "finite and >= 0"));
  }
  check.Require(axis_cone_deg > 0 && axis_cone_deg <= 90,
          InvalidField("--axis_cone_deg", axis_cone_deg, "in (0, 90]"));
  check.Require(travel_margin_mm > 0 && std::isfinite(travel_margin_mm),
          InvalidField("travel_margin_mm", travel_margin_mm, "finite and > 0"));
  check.Require(limit_margin > 0 && limit_margin <= 1,
          InvalidField("--limit_margin", limit_margin, "in (0, 1]"));
  for (const auto& [name, distances] :
       {std::pair<std::string, const std::vector<double>*>{"guard_distances_mm", &guard_distances_mm},
        {"end_guard_distances_mm", &end_guard_distances_mm}}) {
    for (size_t k = 0; k < distances->size(); ++k) {
      const double d = (*distances)[k];
      const std::string field = name + "[" + std::to_string(k) + "]";
      check.Require(d > 0 && std::isfinite(d), InvalidField(field, d, "finite and > 0"));
      // A guard ruling at a distance listed twice would weigh twice.
      const bool end_list = distances == &end_guard_distances_mm;
      const bool repeated =
          std::find(distances->begin(), distances->begin() + k, d) != distances->begin() + k ||
          (end_list && std::find(guard_distances_mm.begin(), guard_distances_mm.end(), d) !=
                           guard_distances_mm.end());
      check.Require(!repeated, InvalidField(field, d,
                                            end_list ? "distinct from those before it and from "
                                                       "guard_distances_mm"
                                                     : "distinct from those before it"));
    }
  }
  check.Require(finite_at_least(between_min_move_mm, 0),
          InvalidField("between_min_move_mm", between_min_move_mm, "finite and >= 0"));
  check.Require(ruling_samples >= 2, InvalidField("--ruling_samples", ruling_samples, ">= 2"));
  check.Require(between_samples >= 0, InvalidField("--between_samples", between_samples, ">= 0"));
  check.Require(finite_at_least(held_point_guard_spacing_mm, 0),
                InvalidField("held_point_guard_spacing_mm", held_point_guard_spacing_mm,
                             "finite and >= 0"));
  check.Require(angle_tolerance_deg > 0,
          InvalidField("--angle_tolerance_deg", angle_tolerance_deg, "> 0"));
  check.Require(w_band > 0, InvalidField("w_band", w_band, "> 0"));
  check.Require(slide_weight >= 0, InvalidField("slide_weight", slide_weight, ">= 0"));
  check.Require(default_feed_mm_per_min > 0,
          InvalidField("--feed", default_feed_mm_per_min, "> 0 mm/min"));
  check.Require(window_poses == 0 || window_poses >= 100,
          InvalidField("--window_poses", window_poses, "0 (no windows) or >= 100"));
  check.Require(pole_window_path_poses >= 0,
          InvalidField("--pole_window_path_poses", pole_window_path_poses, ">= 0"));
  check.Require(coarse_poses >= 0, InvalidField("--coarse_poses", coarse_poses, ">= 0"));
  check.Require(refine_iterations >= 0,
          InvalidField("--refine_iterations", refine_iterations, ">= 0"));
  check.Require(pole_passage_deg >= 0 && pole_passage_deg < 90,
          InvalidField("--pole_passage_deg", pole_passage_deg, "in [0, 90)"));
  check.Require(max_iterations >= 0, InvalidField("--max_iterations", max_iterations, ">= 0"));
  check.Require(num_threads >= 1, InvalidField("--num_threads", num_threads, ">= 1"));
  return check.Report(why);
}

HighAccuracyOptions HighAccuracyOptions::SurfaceFree() {
  HighAccuracyOptions options;
  options.w_second = 1e6;
  options.w_third = 0.0;
  options.w_tip_second = 0.0;
  return options;
}

namespace {

// BuildProblem's first stage: the guess's joints as the parameters, and the
// parameters s (mm) and t (s) of every pose.
Status InitialState(const SmoothingInputs& in, const HighAccuracyOptions& o,
                    SmoothingState* state) {
  const ToolPath& guess = in.initial_guess ? *in.initial_guess : *in.input;
  const ToolPath& path = *in.input;
  const size_t n = path.poses.size();
  if (guess.poses.size() != n) {
    return Status::Error("initial guess has " + std::to_string(guess.poses.size()) +
                         " poses, the input " + std::to_string(n));
  }
  state->u = in.surface ? ProjectPathOntoRail(in.surface->rail(0), path)
                        : std::vector<double>(n, 0.0);
  state->beyond_ends = in.surface ? PosesBeyondRailEnds(in.surface->rail(0), path, state->u)
                                  : std::vector<bool>(n, false);
  // A pose beyond the ends starts where the program has it: a start placed
  // on the surface puts it on the end ruling, millimetres from there. Its
  // joints are assigned with the guess's, on the guess's branch and C
  // winding (the input's own may be the other branch: seed 20 of the
  // random cases led in at A = +20.6 deg into a cut started at -20.3).
  ToolPath start = guess;
  for (size_t i = 0; i < n; ++i) {
    if (state->beyond_ends[i]) start.poses[i] = path.poses[i];
  }
  std::vector<JointVector> joints;
  RETURN_IF_ERROR(in.machine->AssignJoints(start, &joints));
  state->poses.resize(n);
  state->s_mm.assign(n, 0.0);
  state->t_s.assign(n, 0.0);
  // Arc length of the contact along rail 0, not of the tip: in a tight
  // concave bend the tip hardly moves while the contact sweeps the bend,
  // and a tip parameter would crush the deviation weight and blow up the
  // derivatives there. Beyond the surface's ends, where the contact stands
  // at the end ruling, the tip's. Repeated poses get a floor of 1e-3 of the
  // mean step, so that divided differences stay finite and tame.
  std::vector<double> ds(n, 0.0);
  double total_mm = 0.0;
  for (size_t i = 1; i < n; ++i) {
    const bool on_surface =
        in.surface != nullptr && !state->beyond_ends[i - 1] && !state->beyond_ends[i];
    ds[i] = on_surface ? (in.surface->rail(0).Point(state->u[i]) -
                          in.surface->rail(0).Point(state->u[i - 1]))
                             .norm()
                       : (path.poses[i].p_w_tip - path.poses[i - 1].p_w_tip).norm();
    total_mm += ds[i];
  }
  const double floor_mm = std::max(kMinStep, 1e-3 * total_mm / std::max<size_t>(1, n - 1));
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& p = start.poses[i].p_w_tip;
    const JointVector& j = joints[i];
    state->poses[i] = {j[kA], j[kC], p.x(), p.y(), p.z()};
    if (i == 0) continue;
    state->s_mm[i] = state->s_mm[i - 1] + std::max(ds[i], floor_mm);
    const double dt = SegmentTime(*in.machine, path, joints, i - 1, o.default_feed_mm_per_min);
    state->t_s[i] = state->t_s[i - 1] + std::max(dt, kMinStep);
  }
  return Status::Ok();
}

// One parameter block a pose: held poses constant, A of the free ones
// within its travel.
void AddPoseBlocks(const SmoothingInputs& in, const std::vector<bool>& free_pose,
                   SmoothingState* state, ceres::Problem* problem) {
  const size_t n = in.input->poses.size();
  const AxisLimits& a_travel = in.machine->limits[kA];
  for (size_t i = 0; i < n; ++i) {
    double* pose = state->poses[i].data();
    problem->AddParameterBlock(pose, kPoseSize);
    if (!free_pose[i]) {
      problem->SetParameterBlockConstant(pose);
      continue;
    }
    // The flank distance does not change when the axis is reversed about
    // the tip, so nothing but the travel keeps a pose from flipping over.
    if (std::isfinite(a_travel.min)) problem->SetParameterLowerBound(pose, kPoseA, a_travel.min);
    if (std::isfinite(a_travel.max)) problem->SetParameterUpperBound(pose, kPoseA, a_travel.max);
  }
}

// With a surface, each free pose's tip held at the input's overhang below
// the floor (solver/smooth/cost/tip_height_cost.h).
Status AddTipHeightFamily(const SmoothingInputs& in, const HighAccuracyOptions& o, double length_mm,
                          const std::vector<bool>& free_pose, SmoothingState* state) {
  const ToolPath& path = *in.input;
  const size_t n = path.poses.size();
  std::vector<double> overhang_mm;
  if (in.surface != nullptr) {
    RETURN_IF_ERROR(PoseOverhangs(in.surface->rail(0), path, state->u, &overhang_mm));
  }
  for (size_t i = 0; i < n; ++i) {
    if (!free_pose[i] || o.w_tip_height <= 0 || in.surface == nullptr || state->beyond_ends[i]) {
      continue;
    }
    const double h = PoseShareMm(*state, i);
    const Eigen::Vector3d floor_w = in.surface->rail(0).Point(state->u[i]);
    AddPosePart(state, i, "tip_height",
                TipHeightCost::Create(floor_w, overhang_mm[i],
                                      std::sqrt(o.w_tip_height * h / length_mm) / o.tolerance_mm));
  }
  return Status::Ok();
}

// With a surface and w_tip_slide > 0, each free pose's tip held along the
// path where the solve starts it (solver/smooth/cost/tip_slide_cost.h),
// the path's direction there from the pose before to the pose after.
void AddTipSlideFamily(const SmoothingInputs& in, const HighAccuracyOptions& o, double length_mm,
                       const std::vector<bool>& free_pose, SmoothingState* state) {
  if (!(o.w_tip_slide > 0) || in.surface == nullptr) return;
  const size_t n = state->poses.size();
  const auto tip = [&](size_t i) { return PoseTip(state->poses[i].data()); };
  for (size_t i = 0; i < n; ++i) {
    if (!free_pose[i] || state->beyond_ends[i]) continue;
    const Eigen::Vector3d along = tip(std::min(i + 1, n - 1)) - tip(i > 0 ? i - 1 : 0);
    // Standing still, the pose has no direction to hold it along.
    if (!(along.norm() > kMinStep)) continue;
    const double h = PoseShareMm(*state, i);
    AddPosePart(state, i, "tip_slide",
                TipSlideCost::Create(tip(i), along.normalized(),
                                     std::sqrt(o.w_tip_slide * h / length_mm) / o.tolerance_mm));
  }
}

// The ruling angles (solver/smooth/ruling_angles.h) of the poses
// first..first+kCount-1 into *out, and for A and for C whether every one of
// them has it (where not, that angle's reference is left 0).
template <int kCount>
std::array<bool, 2> RulingWindow(const std::vector<RulingReference>& angles, size_t first,
                                 std::array<std::array<double, 2>, kCount>* out) {
  std::array<bool, 2> all = {true, true};
  for (int j = 0; j < kCount; ++j) {
    const RulingReference& r = angles[first + j];
    all[0] = all[0] && r.a.has_value();
    all[1] = all[1] && r.c.has_value();
  }
  for (int j = 0; j < kCount; ++j) {
    const RulingReference& r = angles[first + j];
    (*out)[j] = {all[0] ? *r.a : 0.0, all[1] ? *r.c : 0.0};
  }
  return all;
}

// The angle weights of a stencil: `w` times the departure factor for an
// angle that has its reference, `w` for one that has not.
std::array<double, 2> AngleWeights(double w, double factor, const std::array<bool, 2>& referenced) {
  return {referenced[0] ? factor * w : w, referenced[1] ? factor * w : w};
}

// The second and third derivatives of the joints and the tip along s.
void AddSmoothnessFamilies(const SmoothingInputs& in, const HighAccuracyOptions& o,
                           double length_mm, const std::vector<bool>& free_pose,
                           SmoothingState* state, ceres::Problem* problem) {
  const ToolPath& path = *in.input;
  const double factor = o.ruling_departure_factor;
  std::vector<RulingReference> ruling(path.poses.size());
  if (in.surface != nullptr && factor > 0) {
    std::vector<Eigen::Vector2d> start(path.poses.size());
    for (size_t i = 0; i < start.size(); ++i) {
      start[i] = {state->poses[i][kPoseA], state->poses[i][kPoseC]};
    }
    ruling = RulingAngles(*in.surface, state->u, state->beyond_ends, start, o.axis_cone_deg,
                          o.ruling_a_near_pole);
  }
  // A family whose weights are all zero adds nothing but work: its zero
  // Jacobians still go through the linear algebra (more than half the
  // surface-free preset's solve, which sets w_third = 0).
  if (o.w_second > 0 || o.w_tip_second > 0) {
    AddStencils<2>(path, free_pose, BreaksSmoothness, state, problem, "second", [&](size_t i) {
      SmoothnessCost<2>::Reference r;
      const std::array<bool, 2> referenced = RulingWindow<3>(ruling, i, &r);
      return SmoothnessCost<2>::Create(Window<3>(state->s_mm, i), length_mm,
                                       AngleWeights(o.w_second, factor, referenced),
                                       o.w_tip_second, r);
    });
  }
  if (o.w_third > 0 || o.w_tip_third > 0) {
    AddStencils<3>(path, free_pose, BreaksSmoothness, state, problem, "third", [&](size_t i) {
      SmoothnessCost<3>::Reference r;
      const std::array<bool, 2> referenced = RulingWindow<4>(ruling, i, &r);
      return SmoothnessCost<3>::Create(Window<4>(state->s_mm, i), length_mm,
                                       AngleWeights(o.w_third, factor, referenced),
                                       o.w_tip_third, r);
    });
  }
}

// The cap on the peaks of d2A/ds2 and d2C/ds2 (peak_second_cost.h), where
// one is set.
void AddPeakSecondFamily(const SmoothingInputs& in, const HighAccuracyOptions& o, double length_mm,
                         const std::vector<bool>& free_pose, SmoothingState* state,
                         ceres::Problem* problem) {
  const std::array<double, 2>& cap = o.peak_second_cap_per_mm2;
  if (o.w_peak_second <= 0 || (cap[0] <= 0 && cap[1] <= 0)) return;
  AddStencils<2>(*in.input, free_pose, BreaksSmoothness, state, problem, "peak_second",
                 [&](size_t i) {
                   const double h = (state->s_mm[i + 2] - state->s_mm[i]) / 2;
                   return PeakSecondCost::Create(cap, std::sqrt(o.w_peak_second * h / length_mm));
                 });
}

}  // namespace

Status BuildProblem(const SmoothingInputs& in, const HighAccuracyOptions& o,
                    SmoothingState* state, ceres::Problem* problem) {
  CHECK(in.input && in.cutter && in.machine && state && problem);
  RETURN_IF_ERROR(InitialState(in, o, state));
  const double length_mm = std::max(state->s_mm.back(), kMinStep);
  const std::vector<bool> free_pose = FreePoses(in);
  AddPoseBlocks(in, free_pose, state, problem);
  state->pose_parts.clear();
  state->pose_parts.resize(in.input->poses.size());
  state->stacked_parts.clear();
  if (in.surface == nullptr) {
    AddToleranceFamily(in, o, length_mm, free_pose, state, problem);
  } else {
    AddDeviationFamily(in, o, length_mm, free_pose, state, problem);
    AddLeadBandFamily(in, o, length_mm, free_pose, state, problem);
  }
  AddWallFamily(in, o, length_mm, free_pose, state);
  AddTolerancePoints(in, o, free_pose, state, problem);
  RETURN_IF_ERROR(AddTipHeightFamily(in, o, length_mm, free_pose, state));
  AddTipSlideFamily(in, o, length_mm, free_pose, state);
  AddPoseParts(state, problem);
  AddSmoothnessFamilies(in, o, length_mm, free_pose, state, problem);
  AddPeakSecondFamily(in, o, length_mm, free_pose, state, problem);
  AddLimitFamily<1>(in, o, length_mm, free_pose, state, problem);
  AddLimitFamily<2>(in, o, length_mm, free_pose, state, problem);
  AddLimitFamily<3>(in, o, length_mm, free_pose, state, problem);
  return Status::Ok();
}

namespace {

// A pose this close to the distinct pose before it (CAM paths carry
// micrometre steps) is not solved on its own but placed on the solved move
// across it: solved apart, its last-digit disagreement with its neighbour
// over a micrometre was a peak d2A/ds2 thousands of times the clean path's
// (issue 16: the random cases' peaks sat at their 1 um steps), and a move of
// a micrometre is no shape the cutter can follow.
constexpr double kNearRepeatMm = 2e-3;

// The distinct poses of a path: index[i] is the distinct pose pose i
// repeats or follows within kNearRepeatMm (itself when it moves farther);
// inside[i] says pose i is such a near repeat, to be placed on the move out
// of its distinct pose rather than on it.
struct DistinctPoses {
  std::vector<size_t> index;
  std::vector<bool> inside;
};

DistinctPoses FindDistinctPoses(const ToolPath& path) {
  const size_t n = path.poses.size();
  DistinctPoses d{std::vector<size_t>(n), std::vector<bool>(n, false)};
  size_t distinct = 0, last = 0;  // `last`: the pose of the current distinct one
  for (size_t i = 0; i < n; ++i) {
    const ToolPose& pose = path.poses[i];
    const bool cut = i > 0 && !IsPositioningMove(pose);
    const bool repeat = cut && (pose.p_w_tip - path.poses[i - 1].p_w_tip).norm() < 1e-9 &&
                        (pose.a_w - path.poses[i - 1].a_w).norm() < 1e-12;
    // A near repeat needs a cut move after it to be placed on.
    const bool near = cut && !repeat && i + 1 < n && !IsPositioningMove(path.poses[i + 1]) &&
                      (pose.p_w_tip - path.poses[last].p_w_tip).norm() < kNearRepeatMm;
    if (i > 0 && !repeat && !near) {
      ++distinct;
      last = i;
    }
    d.index[i] = distinct;
    d.inside[i] = near || (repeat && i > 0 && d.inside[i - 1]);
  }
  return d;
}

ToolPath Distinct(const ToolPath& path, const std::vector<size_t>& index) {
  ToolPath out = WithoutPoses(path);
  for (size_t i = 0; i < path.poses.size(); ++i) {
    if (i == 0 || index[i] != index[i - 1]) out.poses.push_back(path.poses[i]);
  }
  return out;
}

}  // namespace

Status SmoothHighAccuracy(const SmoothingInputs& inputs, const HighAccuracyOptions& options,
                          ToolPath* out, HighAccuracyReport* report) {
  CHECK(inputs.input != nullptr);
  // CAM files repeat poses; a repeat carries no motion and would give the
  // divided differences a zero step, so the problem is solved over the
  // distinct poses and each repeat takes its original's result; a near
  // repeat is placed on the solved move across it.
  const ToolPath& path = *inputs.input;
  const DistinctPoses d = FindDistinctPoses(path);
  const std::vector<size_t>& index = d.index;
  if (index.empty() || index.back() + 1 == index.size()) {
    return SolveCoarseToFine(inputs, options, out, report);
  }
  const ToolPath input = Distinct(path, index);
  const ToolPath guess = Distinct(inputs.initial_guess ? *inputs.initial_guess : path, index);
  SmoothingInputs distinct = inputs;
  distinct.input = &input;
  distinct.initial_guess = &guess;
  ToolPath solved;
  RETURN_IF_ERROR(SolveCoarseToFine(distinct, options, &solved, report));
  std::vector<JointVector> joints;
  RETURN_IF_ERROR(inputs.machine->AssignJoints(solved, &joints));
  *out = path;
  for (size_t i = 0; i < out->poses.size(); ++i) {
    const size_t k = index[i];
    out->poses[i].p_w_tip = solved.poses[k].p_w_tip;
    out->poses[i].a_w = solved.poses[k].a_w;
    if (!d.inside[i]) continue;
    // At its fraction of the input's move between the two distinct poses,
    // by the tip's distance along it.
    const Eigen::Vector3d& from = input.poses[k].p_w_tip;
    const double along = (path.poses[i].p_w_tip - from).norm();
    const double move = (input.poses[k + 1].p_w_tip - from).norm();
    const double lambda = move > 0 ? std::min(along / move, 1.0) : 0.0;
    InterpolateMove<double>(inputs.machine->kinematics, options.interpolation, joints[k],
                            joints[k + 1], solved.poses[k].p_w_tip, solved.poses[k + 1].p_w_tip,
                            lambda, &out->poses[i].p_w_tip, &out->poses[i].a_w);
  }
  return Status::Ok();
}

Status SolveWholeProblem(const SmoothingInputs& inputs, const HighAccuracyOptions& options,
                         ToolPath* out, HighAccuracyReport* report) {
  std::string why;
  if (!options.IsValid(&why)) return Status::Error("high_accuracy options: " + why);
  const auto start = std::chrono::steady_clock::now();
  ceres::Problem problem;
  SmoothingState state;
  RETURN_IF_ERROR(BuildProblem(inputs, options, &state, &problem));

  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  solver_options.max_num_iterations = options.max_iterations;
  solver_options.function_tolerance = options.function_tolerance;
  solver_options.num_threads = options.num_threads;
  solver_options.logging_type = ceres::SILENT;
  IterationObserver observer(options.on_iteration);
  solver_options.callbacks.push_back(&observer);
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &problem, &summary);

  report->converged = summary.IsSolutionUsable();
  report->message = summary.message;
  report->iterations = static_cast<int>(summary.iterations.size()) - 1;
  report->initial_cost = summary.initial_cost;
  report->final_cost = summary.final_cost;
  std::map<std::string, double> cost_by_family;
  for (const auto& [family, blocks] : state.families) {
    // (An empty list would make Ceres evaluate every block.)
    if (blocks.empty()) continue;
    ceres::Problem::EvaluateOptions eval;
    eval.residual_blocks = blocks;
    double cost = 0.0;
    problem.Evaluate(eval, &cost, nullptr, nullptr, nullptr);
    cost_by_family[family] = cost;
  }
  for (const SmoothingState::StackedPart& p : state.stacked_parts) {
    cost_by_family[p.family] += p.block->PartCost(p.part, state.poses[p.pose].data());
  }
  report->final_cost_by_family = std::move(cost_by_family);
  *out = *inputs.input;
  const std::vector<bool> free_pose = FreePoses(inputs);
  const ToolPath& guess = inputs.initial_guess ? *inputs.initial_guess : *inputs.input;
  for (size_t i = 0; i < out->poses.size(); ++i) {
    if (!free_pose[i]) {
      // Held: the guess itself, not its round trip through A and C (which
      // would move it by ~1e-16 and break a seam's exact match).
      out->poses[i].p_w_tip = guess.poses[i].p_w_tip;
      out->poses[i].a_w = guess.poses[i].a_w;
      continue;
    }
    const auto& p = state.poses[i];
    out->poses[i].p_w_tip = Eigen::Vector3d(p[kPoseTip], p[kPoseTip + 1], p[kPoseTip + 2]);
    out->poses[i].a_w = AnglesToAxis<double>(p[kPoseA], p[kPoseC]);
    if (inputs.surface == nullptr && free_pose[i]) {
      report->poses_clamped += ClampToBand(BandOf(*inputs.input, options, i), &out->poses[i]);
    }
  }
  report->solve_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // Every solve, at every coarse level and in every window, is held to the
  // travel here, where its own poses are known: judged only on the final
  // path, a level's excursion would surface later as an error about a pose
  // the input never had.
  std::vector<JointVector> joints;
  Status s = inputs.machine->AssignJoints(*out, &joints);
  if (s.ok()) s = inputs.machine->CheckTravel(*out, joints);
  if (!s.ok()) {
    return Status::Error("a solve over " + std::to_string(out->poses.size()) +
                         " poses moved a pose out of the machine (the value is the solver's; "
                         "the input fits): " + s.message());
  }
  return Status::Ok();
}

std::string CeresVersion() { return CERES_VERSION_STRING; }

}  // namespace tpopt
