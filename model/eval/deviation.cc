#include "model/eval/deviation.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <utility>

#include "model/base/invalid_field.h"
#include "model/path/rail_projection.h"
#include "model/geometry/segment_distance.h"

namespace tpopt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Tolerance of the final refinement, in the move parameter s.
constexpr double kRefineTolerance = 1e-9;

// An axis farther than this from unit length is bad input (no machine).
constexpr double kUnitTolerance = 1e-6;
// A move whose axes are nearer than this to opposite has no great circle.
constexpr double kAntipodalRad = 1e-6;

// The cutting moves of a path and the tool pose along each of them.
class Motion {
 public:
  // Joint interpolation on `machine`; `joints` one per pose.
  Motion(const ToolPath& path, const Machine& machine,
         const std::vector<JointVector>& joints, Interpolation interpolation)
      : path_(&path), machine_(&machine), joints_(&joints),
        interpolation_(interpolation) {
    CHECK_EQ(joints.size(), path.poses.size());
    FindMoves();
  }
  // Tip linear, axis slerp.
  explicit Motion(const ToolPath& path) : path_(&path) { FindMoves(); }

  // Without a machine, checks that every axis of a cutting move is unit and
  // that no move turns it by half a turn, and caches the turn angles.
  Status PrepareSlerp();

  int num_moves() const { return static_cast<int>(moves_.size()); }
  // Index of the pose a move starts from; it ends at the next pose.
  int start_pose(int move) const { return moves_[move]; }

  // Tip and unit axis in W at s in [0, 1] along `move`.
  void PoseAt(int move, double s, Eigen::Vector3d* tip,
              Eigen::Vector3d* axis) const;

 private:
  void FindMoves() {
    for (size_t i = 0; i + 1 < path_->poses.size(); ++i) {
      if (!path_->poses[i + 1].rapid) moves_.push_back(static_cast<int>(i));
    }
  }

  const ToolPath* path_;
  const Machine* machine_ = nullptr;
  const std::vector<JointVector>* joints_ = nullptr;
  Interpolation interpolation_ = Interpolation::kJoint;
  std::vector<int> moves_;
  std::vector<double> turn_rad_;  // slerp only: angle between the axes
};

Status Motion::PrepareSlerp() {
  turn_rad_.resize(moves_.size());
  for (size_t k = 0; k < moves_.size(); ++k) {
    const int i = moves_[k];
    for (int p : {i, i + 1}) {
      const ToolPose& pose = path_->poses[p];
      const double norm = pose.a_w.norm();
      if (!(std::abs(norm - 1.0) <= kUnitTolerance)) {
        std::ostringstream err;
        err << "pose " << p << " (line " << pose.source_line
            << "): tool axis length " << norm << " is not 1";
        return Status::Error(err.str());
      }
    }
    const Eigen::Vector3d& a0 = path_->poses[i].a_w;
    const Eigen::Vector3d& a1 = path_->poses[i + 1].a_w;
    turn_rad_[k] = std::atan2(a0.cross(a1).norm(), a0.dot(a1));
    if (turn_rad_[k] > M_PI - kAntipodalRad) {
      std::ostringstream err;
      err << "pose " << i + 1 << " (line " << path_->poses[i + 1].source_line
          << "): the tool axis turns by half a turn from the pose before; "
             "the motion between them is undefined";
      return Status::Error(err.str());
    }
  }
  return Status::Ok();
}

void Motion::PoseAt(int move, double s, Eigen::Vector3d* tip,
                    Eigen::Vector3d* axis) const {
  const int i = moves_[move];
  const ToolPose& p0 = path_->poses[i];
  const ToolPose& p1 = path_->poses[i + 1];
  if (machine_ != nullptr) {
    InterpolateMove<double>(machine_->kinematics, interpolation_, (*joints_)[i],
                            (*joints_)[i + 1], p0.p_w_tip, p1.p_w_tip, s, tip, axis);
    return;
  }
  *tip = (1.0 - s) * p0.p_w_tip + s * p1.p_w_tip;
  const double theta = turn_rad_[move];
  if (theta < 1e-9) {
    // The slerp weights become 0 / 0 as theta -> 0; the chord is the arc.
    *axis = ((1.0 - s) * p0.a_w + s * p1.a_w).normalized();
    return;
  }
  *axis =
      (std::sin((1.0 - s) * theta) * p0.a_w + std::sin(s * theta) * p1.a_w) /
      std::sin(theta);
}

// Bounds on SignedDistanceToCutter for a cutter known only approximately.
//
// Lower(): a lower bound for every cutter whose axis segment [tip, tip + L
// axis] lies within `margin` of a set that q is `distance` from. With
// x = distance - margin - R_max, R_max = R(L) the largest flank radius, the
// cutter's solid lies within R_max of its axis segment, so:
//  - inside the flute's height the value is (r - R(t)) cos(taper) with
//    r >= x + R_max >= x + R(t), hence >= x cos(taper) for x > 0 and >= x
//    otherwise;
//  - beyond the flute it is >= 0, and for x > 0 at least
//    x cos(taper) / (1 + tan(taper)) (above the top the formula measures
//    the flank radially, up to a factor 1 + tan(taper) shorter than the
//    Euclidean distance; exact for the cylinder).
// Slack(): how much the value can drop when both ends of the axis segment
// move by at most h: the solid's points move by at most h (1 + 2 R_max / L)
// (translation plus a turn of at most 2 h / L at radius R_max), and the
// value is a distance, up to the same taper factor.
// With several cutters (one a move), the bound takes the largest reach, the
// shortest flute and the smallest factor, which bounds each of them.
class DistanceBound {
 public:
  explicit DistanceBound(const std::vector<const Cutter*>& cutters) {
    CHECK(!cutters.empty());
    for (const Cutter* cutter : cutters) {
      reach_mm_ = std::max(reach_mm_, cutter->RadiusAt(cutter->flute_length_mm));
      length_mm_ = std::min(length_mm_, cutter->flute_length_mm);
      positive_factor_ =
          std::min(positive_factor_, std::cos(cutter->taper_rad) / (1.0 + std::tan(cutter->taper_rad)));
    }
  }

  double Lower(double distance_mm, double margin_mm) const {
    const double x = distance_mm - margin_mm - reach_mm_;
    return x > 0.0 ? x * positive_factor_ : x;
  }
  double Slack(double end_motion_mm) const {
    return end_motion_mm * (1.0 + 2.0 * reach_mm_ / length_mm_) /
           positive_factor_;
  }

 private:
  double reach_mm_ = 0.0;
  double length_mm_ = std::numeric_limits<double>::infinity();
  double positive_factor_ = 1.0;
};

// Least value of f on [lo, hi] by Brent's method (parabolic steps
// safeguarded by golden sections; Numerical Recipes 3rd ed., 10.3), started
// from x in [lo, hi] with f(x) = fx known, until the bracket is within
// `tolerance` of the minimiser. Returns the least value seen, <= fx. The
// parabolic steps make it several times cheaper than pure golden section on
// the smooth distance; at the kinks of the cutter's caps it falls back to
// golden steps.
template <typename F>
double BrentMinimum(F f, double lo, double hi, double x, double fx,
                    double tolerance) {
  constexpr double kGolden = 0.3819660112501051;  // (3 - sqrt 5) / 2
  double w = x, v = x, fw = fx, fv = fx;
  double step = 0.0, step_before = 0.0;
  for (int iter = 0; iter < 200; ++iter) {
    const double mid = 0.5 * (lo + hi);
    if (std::abs(x - mid) <= 2.0 * tolerance - 0.5 * (hi - lo)) break;
    bool parabolic = false;
    if (std::abs(step_before) > tolerance) {
      // Vertex of the parabola through (v, fv), (w, fw), (x, fx).
      const double r = (x - w) * (fx - fv);
      double q = (x - v) * (fx - fw);
      double p = (x - v) * q - (x - w) * r;
      q = 2.0 * (q - r);
      if (q > 0.0) p = -p;
      q = std::abs(q);
      // Accepted only inside the bracket and shorter than half the step
      // before last, which guarantees progress.
      if (std::abs(p) < std::abs(0.5 * q * step_before) && p > q * (lo - x) &&
          p < q * (hi - x)) {
        step_before = step;
        step = p / q;
        const double u = x + step;
        if (u - lo < 2.0 * tolerance || hi - u < 2.0 * tolerance) {
          step = std::copysign(tolerance, mid - x);
        }
        parabolic = true;
      }
    }
    if (!parabolic) {
      step_before = x >= mid ? lo - x : hi - x;
      step = kGolden * step_before;
    }
    const double u = std::abs(step) >= tolerance
                         ? x + step
                         : x + std::copysign(tolerance, step);
    const double fu = f(u);
    if (fu <= fx) {
      (u >= x ? lo : hi) = x;
      v = w, fv = fw;
      w = x, fw = fx;
      x = u, fx = fu;
    } else {
      (u < x ? lo : hi) = u;
      if (fu <= fw || w == x) {
        v = w, fv = fw;
        w = u, fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u, fv = fu;
      }
    }
  }
  return fx;
}

// A move prepared for queries: its poses at uniform s (tips, axes; at
// least substeps + 1 of them, more where the cutter moves far, see
// PrepareMove), the chord each sub-interval spans, and its mid axis segment
// with a margin that holds the axis segment of every pose of the move.
struct PreparedMove {
  std::vector<Eigen::Vector3d> tips, axes;
  // chord_mm[k]: the farther that tip or top (tip + L axis) moves from
  // sample k to sample k + 1.
  std::vector<double> chord_mm;
  Eigen::Vector3d mid_tip, mid_top;
  double margin_mm = 0.0;
};

void SampleMove(const Motion& motion, double length_mm, int move, int count,
                PreparedMove* out) {
  out->tips.resize(count + 1);
  out->axes.resize(count + 1);
  out->chord_mm.resize(count);
  for (int k = 0; k <= count; ++k) {
    motion.PoseAt(move, static_cast<double>(k) / count, &out->tips[k],
                  &out->axes[k]);
    if (k == 0) continue;
    const Eigen::Vector3d top = out->tips[k] + length_mm * out->axes[k];
    const Eigen::Vector3d top_before =
        out->tips[k - 1] + length_mm * out->axes[k - 1];
    out->chord_mm[k - 1] = std::max((out->tips[k] - out->tips[k - 1]).norm(),
                                    (top - top_before).norm());
  }
}

// The samples must resolve the distance as a function of s: the
// refinement is local (LeastOverMove), so a pass of the cutter past a
// surface point must not fit between two samples unseen. A rotary swing
// (e.g. C turning fast near the pole) can carry the cutter tens of mm in one
// move; such moves get more samples, so that no point of the axis moves
// more than half the cutter radius between two.
PreparedMove PrepareMove(const Motion& motion, const Cutter& cutter, int move,
                         int substeps) {
  constexpr int kMaxSamples = 4096;
  const double length = cutter.flute_length_mm;
  PreparedMove out;
  SampleMove(motion, length, move, substeps, &out);
  const double chord =
      *std::max_element(out.chord_mm.begin(), out.chord_mm.end());
  const double factor = std::ceil(chord / (0.5 * cutter.radius_mm));
  if (factor > 1.0) {
    const int count =
        static_cast<int>(std::min<double>(kMaxSamples, substeps * factor));
    SampleMove(motion, length, move, count, &out);
  }
  Eigen::Vector3d mid_axis;
  motion.PoseAt(move, 0.5, &out.mid_tip, &mid_axis);
  out.mid_top = out.mid_tip + length * mid_axis;
  // The axis segment at s is within max(|tip(s) - mid_tip|, |top(s) -
  // mid_top|) of the mid segment (its points are the same convex
  // combinations of tip and top). Between samples a point is at most half
  // a sub-arc from a sample; 1.5 x the chord covers arcs that turn up to
  // about 150 degrees within one sub-interval.
  double far = 0.0;
  for (size_t k = 0; k < out.tips.size(); ++k) {
    const Eigen::Vector3d top = out.tips[k] + length * out.axes[k];
    far = std::max(
        {far, (out.tips[k] - out.mid_tip).norm(), (top - out.mid_top).norm()});
  }
  out.margin_mm =
      far + 0.75 * *std::max_element(out.chord_mm.begin(), out.chord_mm.end());
  return out;
}

// Bounding-volume hierarchy over the moves in path order: neighbouring
// moves are neighbours in space, so halving the index range groups them.
// Each node is a capsule: a representative axis segment [tip, top] and a
// radius within which lies the axis segment of every pose of every move
// below it. Capsules, not boxes, because the long, tilted, nearly parallel
// axes of a flank path fill their boxes poorly.
struct BvhNode {
  Eigen::Vector3d tip, top;
  double radius_mm = 0.0;
  int left = -1, right = -1;  // children, or -1 for a leaf
  int move = -1;              // leaf only
};

int BuildBvh(const std::vector<PreparedMove>& moves, int first, int last,
             std::vector<BvhNode>* nodes) {
  const int index = static_cast<int>(nodes->size());
  nodes->emplace_back();
  const int middle = first + (last - first) / 2;
  BvhNode node;
  node.tip = moves[middle].mid_tip;
  node.top = moves[middle].mid_top;
  if (first == last) {
    node.move = first;
    node.radius_mm = moves[first].margin_mm;
  } else {
    node.left = BuildBvh(moves, first, middle, nodes);
    node.right = BuildBvh(moves, middle + 1, last, nodes);
    // A child's segment is within max(|d tip|, |d top|) of this one (same
    // convex combinations of the ends), so its capsule is within that
    // plus its radius.
    for (int child : {node.left, node.right}) {
      const BvhNode& c = (*nodes)[child];
      node.radius_mm = std::max(
          node.radius_mm,
          std::max((c.tip - node.tip).norm(), (c.top - node.top).norm()) +
              c.radius_mm);
    }
  }
  (*nodes)[index] = node;
  return index;
}

// Least signed distance from q to the cutter over the motion, found by
// branch and bound over the hierarchy.
class SweptDistance {
 public:
  // cutters[m] cuts move m.
  SweptDistance(const Motion& motion, const std::vector<const Cutter*>& cutters, int substeps)
      : motion_(motion), bound_(cutters) {
    CHECK_EQ(static_cast<int>(cutters.size()), motion.num_moves());
    moves_.reserve(motion.num_moves());
    flanks_.reserve(motion.num_moves());
    for (int m = 0; m < motion.num_moves(); ++m) {
      moves_.push_back(PrepareMove(motion, *cutters[m], m, substeps));
      flanks_.emplace_back(*cutters[m]);
    }
    nodes_.reserve(2 * moves_.size());
    BuildBvh(moves_, 0, static_cast<int>(moves_.size()) - 1, &nodes_);
  }

  // `hint` (in/out): a move likely to be near the minimum, tried first so
  // that the bound prunes from the start; set to the move of the minimum.
  double Least(const Eigen::Vector3d& q, int* hint) const;

 private:
  double LowerBound(const BvhNode& node, const Eigen::Vector3d& q) const {
    return bound_.Lower(DistanceToSegment(q, node.tip, node.top),
                        node.radius_mm);
  }
  double DistanceAt(int move, double s, const Eigen::Vector3d& q) const {
    Eigen::Vector3d tip, axis;
    motion_.PoseAt(move, s, &tip, &axis);
    return SignedDistanceToCutter<double>(flanks_[move], q, tip, axis);
  }
  double LeastOverMove(int move, const Eigen::Vector3d& q,
                       double to_beat) const;

  const Motion& motion_;
  std::vector<FlankShape> flanks_;  // flanks_[m] cuts move m
  DistanceBound bound_;
  std::vector<PreparedMove> moves_;
  std::vector<BvhNode> nodes_;
};

// The move's least distance from its samples: each local minimum of the
// samples that could beat the best so far is refined by Brent's method over
// the sub-intervals either side of it, the lowest first. "Could beat": the
// distance inside a sub-interval cannot drop more than Slack(0.75 x its
// chord) below its end values (see PrepareMove for the 0.75). Returns the
// least distance when it is below `to_beat`, else some value >= to_beat.
double SweptDistance::LeastOverMove(int move, const Eigen::Vector3d& q,
                                    double to_beat) const {
  const PreparedMove& m = moves_[move];
  const int count = static_cast<int>(m.tips.size()) - 1;
  std::vector<double> value(count + 1);
  double best = to_beat;
  for (int k = 0; k <= count; ++k) {
    value[k] = SignedDistanceToCutter<double>(flanks_[move], q, m.tips[k], m.axes[k]);
    best = std::min(best, value[k]);
  }
  std::vector<std::pair<double, int>> minima;
  for (int k = 0; k <= count; ++k) {
    const bool left_higher = k == 0 || value[k - 1] >= value[k];
    const bool right_higher = k == count || value[k + 1] >= value[k];
    if (!left_higher || !right_higher) continue;
    const double chord = std::max(k > 0 ? m.chord_mm[k - 1] : 0.0,
                                  k < count ? m.chord_mm[k] : 0.0);
    minima.emplace_back(value[k] - bound_.Slack(0.75 * chord), k);
  }
  std::sort(minima.begin(), minima.end());
  for (const auto& [lowest, k] : minima) {
    if (lowest >= best) break;
    auto f = [&](double s) { return DistanceAt(move, s, q); };
    const double lo = static_cast<double>(std::max(0, k - 1)) / count;
    const double hi = static_cast<double>(std::min(count, k + 1)) / count;
    best =
        std::min(best, BrentMinimum(f, lo, hi, static_cast<double>(k) / count,
                                    value[k], kRefineTolerance));
  }
  return best;
}

double SweptDistance::Least(const Eigen::Vector3d& q, int* hint) const {
  double best = kInf;
  int best_move = -1;
  if (*hint >= 0) {
    best = LeastOverMove(*hint, q, kInf);
    best_move = *hint;
  }
  // Depth first, the nearer child first; a node is skipped when its bound
  // cannot beat the best so far, which keeps the result exact.
  std::vector<std::pair<int, double>> stack;
  stack.reserve(64);
  stack.emplace_back(0, LowerBound(nodes_[0], q));
  while (!stack.empty()) {
    const auto [index, lower] = stack.back();
    stack.pop_back();
    if (lower >= best) continue;
    const BvhNode& node = nodes_[index];
    if (node.move >= 0) {
      if (node.move == *hint) continue;
      const double d = LeastOverMove(node.move, q, best);
      if (d < best) {
        best = d;
        best_move = node.move;
      }
      continue;
    }
    const double l = LowerBound(nodes_[node.left], q);
    const double r = LowerBound(nodes_[node.right], q);
    if (l <= r) {
      stack.emplace_back(node.right, r);
      stack.emplace_back(node.left, l);
    } else {
      stack.emplace_back(node.left, l);
      stack.emplace_back(node.right, r);
    }
  }
  *hint = best_move;
  return best;
}

// The grid's u range: the options' or the contact u the cutting poses span.
std::pair<double, double> GridRangeU(const RuledSurface& surface,
                                     const ToolPath& path,
                                     const DeviationOptions& options) {
  if (!std::isnan(options.u_min)) return {options.u_min, options.u_max};
  std::pair<double, double> range;
  CoveredRangeU(surface, path, &range.first, &range.second);
  return range;
}

void InitGrid(double u_lo, double u_hi, const DeviationOptions& o,
              DeviationReport* r) {
  r->u.resize(o.samples_u);
  r->v.resize(o.samples_v);
  for (int i = 0; i < o.samples_u; ++i) {
    r->u[i] = u_lo + (u_hi - u_lo) * i / (o.samples_u - 1);
  }
  for (int j = 0; j < o.samples_v; ++j) {
    r->v[j] = static_cast<double>(j) / (o.samples_v - 1);
  }
  r->deviation_mm.assign(r->u.size() * r->v.size(), 0.0);
}

void Summarise(DeviationReport* r) {
  double sum_sq = 0.0;
  r->max_overcut_mm = r->max_undercut_mm = 0.0;
  r->overcut_u = r->overcut_v = r->undercut_u = r->undercut_v = 0.0;
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
  r->rms_deviation_mm = std::sqrt(sum_sq / static_cast<double>(std::max<size_t>(
                                               1, r->deviation_mm.size())));
}

// Checks the inputs shared by every evaluator.
Status CheckInputs(const Cutter& cutter, const Motion& motion,
                   const DeviationOptions& options) {
  std::string why;
  if (!options.IsValid(&why)) return Status::Error("deviation: " + why);
  RETURN_IF_ERROR(cutter.Validate("deviation"));
  if (motion.num_moves() == 0) {
    return Status::Error("deviation: the path has no cutting move to evaluate");
  }
  return Status::Ok();
}

// The cutter of each move of `motion` (DeviationOptions::cutter_per_tool):
// the cutter of the tool that makes the pose the move goes to, where the
// program defines one, else `cutter`. Fails naming the tool and its line for
// a tool's cutter that is not valid.
Status MoveCutters(const Cutter& cutter, const ToolPath& path, const Motion& motion,
                   const DeviationOptions& options, std::vector<const Cutter*>* cutters) {
  cutters->assign(motion.num_moves(), &cutter);
  if (!options.cutter_per_tool) return Status::Ok();
  for (int m = 0; m < motion.num_moves(); ++m) {
    const int tool = path.poses[motion.start_pose(m) + 1].tool;
    if (tool < 0 || static_cast<size_t>(tool) >= path.tools.size()) continue;
    const ToolRecord& record = path.tools[tool];
    if (!record.cutter) continue;
    RETURN_IF_ERROR(record.cutter->Validate("deviation: tool " + std::to_string(record.number) +
                                            " (line " + std::to_string(record.source_line) + ")"));
    (*cutters)[m] = &*record.cutter;
  }
  return Status::Ok();
}

// Fills every grid point with least(q) and summarises. One driver for the
// fast evaluator and its brute-force reference, so both see the same grid.
// `least` is called in grid order (u outer, v inner).
template <typename Least>
Status EvaluateOnGrid(const RuledSurface& surface, const Cutter& cutter,
                      const ToolPath& path, const Motion& motion,
                      const DeviationOptions& options, Least least,
                      DeviationReport* report) {
  CHECK(report != nullptr);
  RETURN_IF_ERROR(CheckInputs(cutter, motion, options));
  const auto [u_lo, u_hi] = GridRangeU(surface, path, options);
  DeviationReport out;
  InitGrid(u_lo, u_hi, options, &out);
  const size_t nv = out.v.size();
  for (size_t iu = 0; iu < out.u.size(); ++iu) {
    for (size_t iv = 0; iv < nv; ++iv) {
      const Eigen::Vector3d q = surface.Point(out.u[iu], out.v[iv]);
      out.deviation_mm[iu * nv + iv] = least(q);
    }
  }
  Summarise(&out);
  *report = std::move(out);
  return Status::Ok();
}

Status EvaluateFast(const RuledSurface& surface, const Cutter& cutter,
                    const ToolPath& path, const Motion& motion,
                    const DeviationOptions& options, DeviationReport* report) {
  Status s = CheckInputs(cutter, motion, options);
  std::vector<const Cutter*> cutters;
  if (s.ok()) s = MoveCutters(cutter, path, motion, options, &cutters);
  if (!s.ok()) return s;
  const SweptDistance swept(motion, cutters, options.substeps);
  // Neighbouring grid points are cut by the same or nearby moves.
  int hint = -1;
  auto least = [&](const Eigen::Vector3d& q) { return swept.Least(q, &hint); };
  return EvaluateOnGrid(surface, cutter, path, motion, options, least, report);
}

Status EvaluateBrute(const RuledSurface& surface, const Cutter& cutter,
                     const ToolPath& path, const Motion& motion,
                     const DeviationOptions& options, int substeps_per_move,
                     DeviationReport* report) {
  if (substeps_per_move < 1) {
    return Status::Error("deviation: substeps per move " +
                         std::to_string(substeps_per_move) + " must be >= 1");
  }
  std::vector<const Cutter*> cutters;
  RETURN_IF_ERROR(MoveCutters(cutter, path, motion, options, &cutters));
  std::vector<FlankShape> flanks;
  for (const Cutter* c : cutters) flanks.emplace_back(*c);
  auto least = [&](const Eigen::Vector3d& q) {
    double best = kInf;
    for (int m = 0; m < motion.num_moves(); ++m) {
      for (int k = 0; k <= substeps_per_move; ++k) {
        Eigen::Vector3d tip, axis;
        motion.PoseAt(m, static_cast<double>(k) / substeps_per_move, &tip,
                      &axis);
        best = std::min(best, SignedDistanceToCutter<double>(flanks[m], q, tip, axis));
      }
    }
    return best;
  };
  return EvaluateOnGrid(surface, cutter, path, motion, options, least, report);
}

// Builds the motion for an optional machine: joints from AssignJoints, or
// the slerp motion checked for bad axes.
Status MakeMotion(const ToolPath& path, const Machine* machine,
                  Interpolation interpolation, std::vector<JointVector>* joints,
                  std::unique_ptr<Motion>* out) {
  if (machine == nullptr) {
    *out = std::make_unique<Motion>(path);
    return (*out)->PrepareSlerp();
  }
  RETURN_IF_ERROR(machine->AssignJoints(path, joints));
  *out = std::make_unique<Motion>(path, *machine, *joints, interpolation);
  return Status::Ok();
}

}  // namespace

std::vector<double> CuttingContactU(const RuledSurface& surface, const ToolPath& path) {
  const std::vector<double> u = ProjectPathOntoRail(surface.rail(0), path);
  std::vector<double> cutting;
  for (size_t i = 0; i < path.poses.size(); ++i) {
    // A pose takes part in the move out of it or into it (as
    // Motion::FindMoves: every move but a rapid cuts).
    const bool out = i + 1 < path.poses.size() && !path.poses[i + 1].rapid;
    const bool in = i > 0 && !path.poses[i].rapid;
    if (out || in) cutting.push_back(u[i]);
  }
  return cutting;
}

bool CoveredRangeU(const RuledSurface& surface, const ToolPath& path,
                   double* u_min, double* u_max) {
  CHECK(u_min != nullptr && u_max != nullptr);
  const std::vector<double> u = CuttingContactU(surface, path);
  *u_min = u.empty() ? kInf : *std::min_element(u.begin(), u.end());
  *u_max = u.empty() ? -kInf : *std::max_element(u.begin(), u.end());
  return !u.empty();
}

bool DeviationOptions::IsValid(std::string* why) const {
  std::string problem;
  const bool auto_u = std::isnan(u_min) && std::isnan(u_max);
  if (samples_u < 2) {
    problem = InvalidField("--samples_u", samples_u, ">= 2");
  } else if (samples_v < 2) {
    problem = InvalidField("--samples_v", samples_v, ">= 2");
  } else if (substeps < 1) {
    problem = InvalidField("substeps", substeps, ">= 1");
  } else if (!auto_u && !(u_min >= 0.0 && u_min <= u_max && u_max <= 1.0)) {
    std::ostringstream err;
    err << "u range (u_min, u_max) must satisfy 0 <= u_min <= u_max <= 1, or both be NaN for "
           "the path's (got ["
        << u_min << ", " << u_max << "])";
    problem = err.str();
  } else {
    return true;
  }
  if (why != nullptr) *why = problem;
  return false;
}

Status EvaluateDeviation(const RuledSurface& surface, const Cutter& cutter,
                         const ToolPath& path, const Machine* machine,
                         const DeviationOptions& options,
                         DeviationReport* report) {
  std::vector<JointVector> joints;
  std::unique_ptr<Motion> motion;
  RETURN_IF_ERROR(MakeMotion(path, machine, options.interpolation, &joints, &motion));
  return EvaluateFast(surface, cutter, path, *motion, options, report);
}

Status EvaluateDeviation(const RuledSurface& surface, const Cutter& cutter,
                         const ToolPath& path, const Machine& machine,
                         const std::vector<JointVector>& joints,
                         const DeviationOptions& options,
                         DeviationReport* report) {
  const Motion motion(path, machine, joints, options.interpolation);
  return EvaluateFast(surface, cutter, path, motion, options, report);
}

Status EvaluateDeviationBruteForce(const RuledSurface& surface,
                                   const Cutter& cutter, const ToolPath& path,
                                   const Machine* machine,
                                   const DeviationOptions& options,
                                   int substeps_per_move,
                                   DeviationReport* report) {
  std::vector<JointVector> joints;
  std::unique_ptr<Motion> motion;
  RETURN_IF_ERROR(MakeMotion(path, machine, options.interpolation, &joints, &motion));
  return EvaluateBrute(surface, cutter, path, *motion, options,
                       substeps_per_move, report);
}

Status EvaluateDeviationBruteForce(const RuledSurface& surface,
                                   const Cutter& cutter, const ToolPath& path,
                                   const Machine& machine,
                                   const std::vector<JointVector>& joints,
                                   const DeviationOptions& options,
                                   int substeps_per_move,
                                   DeviationReport* report) {
  const Motion motion(path, machine, joints, options.interpolation);
  return EvaluateBrute(surface, cutter, path, motion, options,
                       substeps_per_move, report);
}

}  // namespace tpopt
