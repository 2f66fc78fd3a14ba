#include "solver/smooth/lead_continuation.h"

#include <cmath>

#include <glog/logging.h>

namespace tpopt {
namespace {

constexpr double kDeg = M_PI / 180.0;
// A cut move shorter than this gives no rate to continue (CAM's
// micrometre steps).
constexpr double kShortestRateMoveMm = 1e-3;
// Nearer the pole than this C turns as 1 / sin A, and a continued C says
// nothing of the axis.
constexpr double kPoleDeg = 1.0;

// The stretch of lead poses [first, end) of `path` joined by a feed move
// to the cut pose `junction`, and the cut pose beyond it, `rate_from`,
// that gives the rate. False when there is no such cut.
struct Stretch {
  size_t first = 0, end = 0, junction = 0, rate_from = 0;
};

bool JoinedCut(const ToolPath& path, const std::vector<bool>& lead, size_t first, size_t end,
               Stretch* s) {
  const size_t n = path.poses.size();
  // A lead-in ends with a feed move into the cut; a lead-out starts with
  // one out of it.
  const bool into = end < n && !lead[end] && !IsPositioningMove(path.poses[end]);
  const bool out_of = first > 0 && !lead[first - 1] && !IsPositioningMove(path.poses[first]);
  if (into == out_of) return false;
  s->first = first;
  s->end = end;
  s->junction = into ? end : first - 1;
  // The first pose of the cut more than kShortestRateMoveMm from the
  // junction, along feed moves.
  const Eigen::Vector3d& at = path.poses[s->junction].p_w_tip;
  for (size_t k = s->junction;;) {
    if (into) {
      if (k + 1 >= n || lead[k + 1] || IsPositioningMove(path.poses[k + 1])) return false;
      ++k;
    } else {
      if (k == 0 || lead[k - 1] || IsPositioningMove(path.poses[k])) return false;
      --k;
    }
    if ((path.poses[k].p_w_tip - at).norm() > kShortestRateMoveMm) {
      s->rate_from = k;
      return true;
    }
  }
}

// Sets the stretch's poses; false, changing nothing, where a rule of the
// header says to leave it.
bool Continue(const Machine& machine, const ToolPath& programmed, const LeadContinuation& how,
              const std::vector<JointVector>& joints, const Stretch& s, ToolPath* path) {
  // The stretch's poses may move (a held pose keeps its programmed axis)
  // and the moves between them are feed moves.
  for (size_t i = s.first; i < s.end; ++i) {
    if (path->poses[i].held || (i > s.first && IsPositioningMove(path->poses[i]))) return false;
  }
  const JointVector& j = joints[s.junction];
  const double step = (path->poses[s.rate_from].p_w_tip - path->poses[s.junction].p_w_tip).norm();
  // The rates towards the lead: the cut's rates away from it, reversed.
  const double rate_a = how.rate_fraction * (j[kA] - joints[s.rate_from][kA]) / step;
  const double rate_c = how.rate_fraction * (j[kC] - joints[s.rate_from][kC]) / step;
  const Eigen::Vector3d& tip = path->poses[s.junction].p_w_tip;
  const Eigen::Vector3d towards = (tip - path->poses[s.rate_from].p_w_tip) / step;
  ToolPath continued = *path;
  // Outwards from the junction, by the tips' arc length.
  const bool lead_in = s.junction == s.end;
  double away_mm = 0.0;
  size_t previous = s.junction;
  for (size_t k = 0; k < s.end - s.first; ++k) {
    const size_t i = lead_in ? s.end - 1 - k : s.first + k;
    away_mm += (path->poses[i].p_w_tip - path->poses[previous].p_w_tip).norm();
    previous = i;
    const double a = j[kA] + rate_a * away_mm, c = j[kC] + rate_c * away_mm;
    if (std::abs(a) < kPoleDeg * kDeg) return false;
    const Eigen::Vector3d axis = AnglesToAxis(a, c);
    if (axis.dot(programmed.poses[i].a_w) < std::cos(how.cone_deg * kDeg)) return false;
    continued.poses[i].a_w = axis;
    if (how.along_cut) {
      continued.poses[i].p_w_tip = tip + away_mm * towards;
      if ((continued.poses[i].p_w_tip - programmed.poses[i].p_w_tip).norm() > how.band_mm) {
        return false;
      }
    }
  }
  std::vector<JointVector> continued_joints;
  if (!machine.AssignJoints(continued, &continued_joints).ok() ||
      !machine.CheckTravel(continued, continued_joints).ok()) {
    return false;
  }
  *path = std::move(continued);
  return true;
}

}  // namespace

int ContinueLeads(const Machine& machine, const std::vector<bool>& lead,
                  const ToolPath& programmed, const LeadContinuation& how, ToolPath* path) {
  const size_t n = path->poses.size();
  CHECK(lead.size() == n && programmed.poses.size() == n);
  int set = 0;
  for (size_t first = 0; first < n;) {
    if (!lead[first]) {
      ++first;
      continue;
    }
    size_t end = first;
    while (end < n && lead[end]) ++end;
    Stretch s;
    std::vector<JointVector> joints;
    if (JoinedCut(*path, lead, first, end, &s) && machine.AssignJoints(*path, &joints).ok() &&
        Continue(machine, programmed, how, joints, s, path)) {
      set += static_cast<int>(end - first);
    }
    first = end;
  }
  return set;
}

}  // namespace tpopt
