#include "model/machine/machine.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <sstream>

#include <glog/logging.h>

#include "model/base/units.h"

namespace tpopt {
namespace {

constexpr double kPi = M_PI;

// Wraps an angle to (-pi, pi].
double WrapPi(double angle_rad) {
  // Within a turn of zero, which is nearly every call (steps along a path,
  // C + pi), the remainder is the angle itself or the angle minus a turn,
  // the latter exact (Sterbenz), so std::remainder, which is slow, is
  // needed only beyond.
  constexpr double kTurn = 2.0 * kPi;
  double w = angle_rad;
  if (std::abs(angle_rad) >= kTurn || std::isnan(angle_rad)) {
    w = std::remainder(angle_rad, kTurn);
  } else if (std::abs(angle_rad) >= kPi) {
    w = angle_rad - std::copysign(kTurn, angle_rad);
  }
  if (w <= -kPi) w += kTurn;
  return w;
}

// (A, C) of one pose on the two branches (AxisToAngles); C is NaN where it
// is undefined. A branch the program did not choose is not allowed.
struct PoseAngles {
  double a_rad[2];
  double c_rad[2];
  bool allowed[2] = {true, true};
};

// The pose's programmed joints if a_w is still the axis they give (the pose
// is as programmed), else nothing: a pose a smoother turned has lost them,
// whatever the copy of the source pose it started from carries.
std::optional<RotaryJoints> KeptProgrammedJoints(const ToolPose& pose) {
  // Far below the 1e-4 deg a program is written to, far above round-off.
  constexpr double kSameAxis = 1e-9;
  const std::optional<RotaryJoints>& p = pose.programmed;
  if (p && (AnglesToAxis(p->a_rad, p->c_rad) - pose.a_w).norm() < kSameAxis) return p;
  return std::nullopt;
}

// Branch 0's (A, C) of a unit axis, C = 0 when `singular` (within
// kSingularSinA of the pole, where C is undefined).
struct PolarAngles {
  double a_rad, c_rad;
  bool singular;
};

PolarAngles Polar(const Eigen::Vector3d& axis) {
  const double sin_a = std::hypot(axis.x(), axis.y());
  // atan2 keeps full precision near the pole, where acos(a_z) does not.
  const double a = std::atan2(sin_a, axis.z());
  const bool singular = sin_a < Machine::kSingularSinA;
  return {a, singular ? 0.0 : std::atan2(axis.x(), axis.y()), singular};
}

// A pose that keeps its programmed joints has them on the branch the
// program chose (both, at A = 0), and its C is defined even at A = 0.
PoseAngles CandidateAngles(const ToolPose& pose) {
  if (const std::optional<RotaryJoints> kept = KeptProgrammedJoints(pose)) {
    const double c = WrapPi(kept->c_rad);
    const int branch = kept->a_rad < 0 ? 1 : 0;  // branch 1 is (-A, C + pi)
    PoseAngles out{{branch == 0 ? kept->a_rad : -kept->a_rad,
                    branch == 0 ? -kept->a_rad : kept->a_rad},
                   {c, c}};
    if (kept->a_rad != 0.0) out.allowed[1 - branch] = false;
    return out;
  }
  const PolarAngles p = Polar(pose.a_w);
  const double undefined = std::nan("");
  return {{p.a_rad, -p.a_rad},
          {p.singular ? undefined : p.c_rad, p.singular ? undefined : WrapPi(p.c_rad + kPi)}};
}

// Least-motion (A, C) for poses[0, n) by dynamic programming over the two
// branches. Away from the pole, changing branch between neighbours would flip
// C by half a turn, which is forbidden, so the whole path stays on one
// branch; at a pass over (or near) the pole the two branches meet, and
// following the motion continuously means the sign of A changes, which the
// programme allows when the joint step stays below a quarter turn of C. A
// pose that keeps its programmed joints may be reached on its branch from
// the other one anywhere: that change is the program's, not a choice.
// Undefined C (exactly at the pole) holds the previous C. C comes out wrapped
// to (-pi, pi]. Returns false when no sequence keeps A inside the travel.
//
// The candidates are made pose by pose as the programme goes, and only what
// the way back needs is kept per pose (the C held on each branch and the
// branch it came from): on long paths fresh memory costs more than the
// arithmetic.
bool LeastMotionAngles(const ToolPose* poses, size_t n, const AxisLimits& a_lim,
                       std::vector<double>* a_rad, std::vector<double>* c_rad) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<std::array<double, 2>> held_c(n);
  std::vector<std::array<signed char, 2>> from(n, {-1, -1});
  a_rad->resize(n);  // branch 0's A until the way back
  c_rad->resize(n);
  std::array<double, 2> prev_cost{kInf, kInf};
  PoseAngles prev{};
  for (size_t i = 0; i < n; ++i) {
    const PoseAngles cand = CandidateAngles(poses[i]);
    (*a_rad)[i] = cand.a_rad[0];
    std::array<double, 2> cost{kInf, kInf};
    for (int b = 0; b < 2; ++b) {
      if (!cand.allowed[b] || !a_lim.InTravel(cand.a_rad[b])) continue;
      if (i == 0) {
        cost[b] = 0.0;
        held_c[0][b] = cand.c_rad[b];
        continue;
      }
      for (int p = 0; p < 2; ++p) {
        if (prev_cost[p] == kInf) continue;
        const double c_prev = held_c[i - 1][p];
        double c_here = cand.c_rad[b];
        double dc = 0.0;
        if (std::isnan(c_here)) {
          c_here = c_prev;
        } else if (!std::isnan(c_prev)) {
          dc = std::abs(WrapPi(c_here - c_prev));
        }
        // A change of branch away from the pole is a half turn of C that
        // tpopt never chooses; into a pose whose branch the program fixed
        // (its kept joints) by a positioning move (a rapid, a link, or the
        // move after a tool change or another block, all kept as
        // programmed) it is the program's own motion, and refusing it would
        // leave no sequence at all, whatever the travel. Inside a cut it
        // stays refused: a smoother would cut across that half turn.
        const ToolPose& here = poses[i];
        const bool program_changes_branch =
            !cand.allowed[1 - b] && (here.rapid || here.link || here.held);
        if (p != b && dc > kPi / 2 && !program_changes_branch) continue;
        const double step = prev_cost[p] + std::abs(cand.a_rad[b] - prev.a_rad[p]) + dc;
        if (step < cost[b]) {
          cost[b] = step;
          held_c[i][b] = c_here;
          from[i][b] = static_cast<signed char>(p);
        }
      }
    }
    prev_cost = cost;
    prev = cand;
  }
  if (n == 0) return true;
  int b = prev_cost[0] <= prev_cost[1] ? 0 : 1;
  if (prev_cost[b] == kInf) return false;
  for (size_t i = n; i-- > 0;) {
    // Branch 1 is (-A, C + pi); 0 - A rather than -A so that A = 0 (a park
    // at A 0, say) is written "A0.000000", not "A-0.000000".
    if (b == 1) (*a_rad)[i] = 0.0 - (*a_rad)[i];
    (*c_rad)[i] = held_c[i][b];
    if (i > 0) b = from[i][b];
  }
  // Leading poses at the pole take the first defined C; a path entirely at
  // the pole uses C = 0.
  const auto first = std::find_if(c_rad->begin(), c_rad->end(),
                                  [](double c) { return !std::isnan(c); });
  const double first_c = first == c_rad->end() ? 0.0 : *first;
  for (double& c : *c_rad) {
    if (!std::isnan(c)) break;
    c = first_c;
  }
  return true;
}

// Unwraps C (wrapped, one per pose of poses[0, n)) along the path, and
// returns whether any pose keeps its programmed joints. Where a program gave
// the joints its winding is kept, because a different winding is real table
// motion: a rapid target (or the first pose, which is written as one) that
// keeps its programmed joints takes the programmed C exactly, so a rapid
// turns the table as the program does (re-winding it, say) and parks where
// the program parks; a kept pose after a kept pose keeps the program's step
// (exactly the programmed C when the stretch started at a rapid target).
// Every other pose takes the whole turn of C nearest to the pose before it,
// and a kept pose reached that way sets the whole turns its stretch is off
// the program's winding.
bool UnwrapC(const ToolPose* poses, size_t n, std::vector<double>* c_rad) {
  std::vector<double>& c = *c_rad;
  bool any_kept = false, previous_kept = false;
  double turns_rad = 0.0;  // the running C minus the programmed C
  for (size_t i = 0; i < n; ++i) {
    const std::optional<RotaryJoints> kept = KeptProgrammedJoints(poses[i]);
    const bool anchor = i == 0 || poses[i].rapid;
    if (kept && (anchor || previous_kept)) {
      if (anchor) turns_rad = 0.0;
      c[i] = kept->c_rad + turns_rad;
    } else {
      if (i > 0) c[i] = c[i - 1] + WrapPi(c[i] - c[i - 1]);
      if (kept) {
        turns_rad = 2.0 * kPi * std::round((c[i] - kept->c_rad) / (2.0 * kPi));
        c[i] = kept->c_rad + turns_rad;
      }
    }
    any_kept = any_kept || kept.has_value();
    previous_kept = kept.has_value();
  }
  return any_kept;
}

// Index of the first of poses[0, n) outside the A travel on the given
// branch, or -1.
int FirstOutsideTravel(const AxisLimits& a_limits, const ToolPose* poses, size_t n, int branch) {
  for (size_t i = 0; i < n; ++i) {
    const PoseAngles cand = CandidateAngles(poses[i]);
    if (!cand.allowed[branch] || !a_limits.InTravel(cand.a_rad[branch])) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

// Shifts C by whole turns into [min, max]; false if the span does not fit.
bool ShiftIntoTravel(const AxisLimits& c_limits, std::vector<double>* c_rad) {
  if (c_rad->empty()) return true;
  const auto [lo_it, hi_it] = std::minmax_element(c_rad->begin(), c_rad->end());
  const double lo = *lo_it, hi = *hi_it;
  if (lo >= c_limits.min && hi <= c_limits.max) return true;
  // Smallest shift that brings the low end above the minimum, else the
  // largest that brings the high end below the maximum.
  double turns = 0.0;
  if (lo < c_limits.min) {
    turns = std::ceil((c_limits.min - lo) / (2.0 * kPi));
  } else {
    turns = -std::ceil((hi - c_limits.max) / (2.0 * kPi));
  }
  const double shift = turns * 2.0 * kPi;
  if (lo + shift < c_limits.min || hi + shift > c_limits.max) return false;
  for (double& c : *c_rad) c += shift;
  return true;
}

}  // namespace

std::array<Eigen::Vector2d, 2> AxisToAngles(const Eigen::Vector3d& a_w) {
  const PolarAngles p = Polar(a_w);
  return {Eigen::Vector2d(p.a_rad, p.c_rad),
          Eigen::Vector2d(-p.a_rad, p.singular ? 0.0 : WrapPi(p.c_rad + kPi))};
}

JointVector Machine::ToJoints(const Eigen::Vector3d& p_w_tip, double a_rad,
                              double c_rad) const {
  JointVector j;
  j.head<3>() = WorkpieceToJoints<double>(kinematics, p_w_tip, a_rad, c_rad);
  j[kA] = a_rad;
  j[kC] = c_rad;
  return j;
}

void Machine::ToWorkpiece(const JointVector& joints, Eigen::Vector3d* p_w_tip,
                          Eigen::Vector3d* a_w) const {
  if (p_w_tip != nullptr) {
    *p_w_tip = JointsToWorkpiece<double>(kinematics, joints[kX], joints[kY],
                                         joints[kZ], joints[kA], joints[kC]);
  }
  if (a_w != nullptr) *a_w = AnglesToAxis<double>(joints[kA], joints[kC]);
}

Status Machine::CheckTravel(const ToolPath& path, const std::vector<JointVector>& joints) const {
  CHECK_EQ(joints.size(), path.poses.size());
  for (size_t i = 0; i < joints.size(); ++i) {
    // A tool length offset raises joint Z by itself (ToolPose::length_offset_mm).
    const double offset = path.poses[i].length_offset_mm;
    for (int a = 0; a < 5; ++a) {
      const AxisLimits& travel = limits[a];
      const double joint = joints[i][a] + (a == kZ ? offset : 0.0);
      if (travel.InTravel(joint)) continue;
      // Rotary joints are radians inside; the machine file gives degrees.
      const double scale = a >= kA ? kRadToDeg : 1.0;
      std::ostringstream err;
      err << "pose " << i << " (line " << path.poses[i].source_line << "): " << kAxisNames[a]
          << " = " << joint * scale << " is outside the travel [" << travel.min * scale << ", "
          << travel.max * scale << "]";
      if (a == kZ && offset != 0.0) err << " (with the tool length offset of " << offset << " mm)";
      return Status::Error(err.str());
    }
  }
  return Status::Ok();
}

Status Machine::AssignRotaryAngles(const ToolPath& path, size_t first, size_t end,
                                   std::vector<double>* a_rad, std::vector<double>* c_rad) const {
  CHECK(first <= end && end <= path.poses.size());
  for (size_t i = first; i < end; ++i) {
    const double norm = path.poses[i].a_w.norm();
    if (!(std::abs(norm - 1.0) < 1e-6)) {
      std::ostringstream err;
      err << "pose " << i - first << " (line " << path.poses[i].source_line
          << "): tool axis length " << norm << " is not 1";
      return Status::Error(err.str());
    }
  }
  const ToolPose* const poses = path.poses.data() + first;
  const size_t n = end - first;
  const bool fits_a = LeastMotionAngles(poses, n, limits[kA], a_rad, c_rad);
  // Programmed C is absolute: a path that keeps any is not shifted.
  const bool absolute_c = fits_a && UnwrapC(poses, n, c_rad);
  if (!fits_a || (!absolute_c && !ShiftIntoTravel(limits[kC], c_rad))) {
    std::ostringstream err;
    const int i0 = FirstOutsideTravel(limits[kA], poses, n, 0);
    const int i1 = FirstOutsideTravel(limits[kA], poses, n, 1);
    if (fits_a) {
      err << "the C rotation of the path (unwrapped) does not fit the C travel ["
          << limits[kC].min * kRadToDeg << ", " << limits[kC].max * kRadToDeg << "] deg";
    } else {
      // Name the pose where the branch that gets furthest stops, and why
      // each branch is out there: the travel, the program's own branch, or
      // (the other branch fitting there) a change of branch away from the
      // pole, which was needed to reach it.
      const int b = (i0 < 0 || (i1 >= 0 && i1 > i0)) ? 1 : 0;
      const int i = std::max(b == 0 ? i0 : i1, 0);
      const PoseAngles cand = CandidateAngles(poses[i]);
      std::ostringstream travel;
      travel << "outside the A travel [" << limits[kA].min * kRadToDeg << ", "
             << limits[kA].max * kRadToDeg << "] deg";
      const auto why = [&](int branch) -> std::string {
        if (!limits[kA].InTravel(cand.a_rad[branch])) return travel.str();
        if (!cand.allowed[branch]) return "not the branch the program gives";
        return "inside the travel but reached only by a change of branch away from the pole";
      };
      const int first_named = cand.allowed[b] ? b : 1 - b;  // the program's branch first
      err << "pose " << i << " (line " << poses[i].source_line << "): A = "
          << cand.a_rad[first_named] * kRadToDeg << " deg is " << why(first_named)
          << ", and A = " << cand.a_rad[1 - first_named] * kRadToDeg
          << " deg on the other branch is " << why(1 - first_named);
    }
    return Status::Error(err.str());
  }
  return Status::Ok();
}

Status Machine::AssignJoints(const ToolPath& path, std::vector<JointVector>* joints,
                             std::string* warning) const {
  CHECK(joints != nullptr);
  std::vector<double> a_rad, c_rad;
  RETURN_IF_ERROR(AssignRotaryAngles(path, 0, path.poses.size(), &a_rad, &c_rad));
  joints->resize(path.poses.size());
  double min_sin_a = 1.0;
  size_t min_sin_index = 0;
  for (size_t i = 0; i < path.poses.size(); ++i) {
    (*joints)[i] = ToJoints(path.poses[i].p_w_tip, a_rad[i], c_rad[i]);
    const double sin_a = std::abs(std::sin(a_rad[i]));
    if (sin_a < min_sin_a) {
      min_sin_a = sin_a;
      min_sin_index = i;
    }
  }
  if (warning != nullptr) {
    warning->clear();
    if (min_sin_a < std::sin(1.0 / kRadToDeg)) {
      std::ostringstream w;
      w << "pose " << min_sin_index << " (line " << path.poses[min_sin_index].source_line
        << ") passes within " << std::asin(min_sin_a) * kRadToDeg
        << " deg of the A = 0 singularity, where C swings by about dtheta / sin A";
      *warning = w.str();
    }
  }
  return Status::Ok();
}

}  // namespace tpopt
