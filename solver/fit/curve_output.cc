#include "solver/fit/curve_output.h"

#include <cmath>
#include <sstream>

#include "model/base/invalid_field.h"

namespace tpopt {
namespace {

// Consecutive poses closer than this are one point to the fit.
constexpr double kSamePointMm = 1e-9;

double TurnDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / M_PI;
}

// Index ranges [first, last] of the runs: a run ends before a rapid or a link, at a
// corner, or at a repeated point.
std::vector<std::pair<size_t, size_t>> SplitRuns(const ToolPath& in, double corner_angle_deg) {
  std::vector<std::pair<size_t, size_t>> runs;
  size_t first = 0;
  for (size_t i = 1; i <= in.poses.size(); ++i) {
    bool ends = i == in.poses.size() || IsPositioningMove(in.poses[i]);
    if (!ends) {
      const Eigen::Vector3d move = in.poses[i].p_w_tip - in.poses[i - 1].p_w_tip;
      ends = move.norm() < kSamePointMm;
      if (!ends && i - first >= 2) {
        const Eigen::Vector3d before = in.poses[i - 1].p_w_tip - in.poses[i - 2].p_w_tip;
        ends = TurnDeg(before, move) > corner_angle_deg;
      }
    }
    if (!ends) continue;
    // A corner pose ends one run and starts the next; a rapid or link target or a
    // repeated point starts the next run on its own.
    runs.emplace_back(first, i - 1);
    first = i == in.poses.size() || IsPositioningMove(in.poses[i]) ||
                    (in.poses[i].p_w_tip - in.poses[i - 1].p_w_tip).norm() < kSamePointMm
                ? i
                : i - 1;
  }
  return runs;
}

ToolPose Between(const ToolPose& from, const ToolPose& to, const Eigen::Vector3d& tip, double t) {
  ToolPose pose = Derived(to);
  pose.p_w_tip = tip;
  const Eigen::Vector3d axis = (1.0 - t) * from.a_w + t * to.a_w;
  pose.a_w = axis.norm() > 1e-12 ? axis.normalized() : to.a_w;
  return pose;
}

}  // namespace

bool CurveOutputOptions::IsValid(std::string* why) const {
  if (!fit.IsValid(why)) return false;
  std::string problem;
  if (!(sample_step_mm > 0) || !std::isfinite(sample_step_mm)) {
    problem = InvalidField("--curve_step_mm", sample_step_mm, "finite and > 0");
  } else if (!(corner_angle_deg > 0 && corner_angle_deg <= 180)) {
    problem = InvalidField("corner_angle_deg", corner_angle_deg, "in (0, 180]");
  }
  if (why) *why = problem;
  return problem.empty();
}

void AppendFittedRun(const std::vector<ToolPose>& poses, const std::vector<CubicSpan>& spans,
                     double sample_step_mm, ToolPath* out, std::vector<AptCurveSpan>* records) {
  for (size_t i = 0; i < spans.size(); ++i) {
    records->push_back({out->poses.size() - 1, spans[i].bezier});
    const double chord = (poses[i + 1].p_w_tip - poses[i].p_w_tip).norm();
    // The tolerance keeps a chord of exactly n steps (up to rounding) at n pieces.
    const int pieces = std::max(1, static_cast<int>(std::ceil(chord / sample_step_mm - 1e-9)));
    for (int k = 1; k < pieces; ++k) {
      const double t = double(k) / pieces;
      out->poses.push_back(Between(poses[i], poses[i + 1], spans[i].Point(t), t));
    }
    out->poses.push_back(poses[i + 1]);
  }
}

Status FitToolPathCurves(const ToolPath& in, const CurveOutputOptions& options, ToolPath* out,
                         std::vector<AptCurveSpan>* records) {
  std::string why;
  if (!options.IsValid(&why)) return Status::Error(why);
  *out = WithoutPoses(in);
  records->clear();
  // Input index of the last input pose written; a run that starts at a
  // corner starts where the run before ended.
  size_t written = in.poses.size();
  for (const auto& [first, last] : SplitRuns(in, options.corner_angle_deg)) {
    if (written != first) out->poses.push_back(in.poses[first]);
    written = last;
    const std::vector<ToolPose> run(in.poses.begin() + first, in.poses.begin() + last + 1);
    if (run.size() < 4) {
      out->poses.insert(out->poses.end(), run.begin() + 1, run.end());
      continue;
    }
    std::vector<Eigen::Vector3d> points, tangents;
    for (const ToolPose& p : run) points.push_back(p.p_w_tip);
    std::vector<CubicSpan> spans;
    Status s = EstimateUnitTangents(points, &tangents);
    if (s.ok()) s = FitPolyline(points, tangents, options.fit, &spans, first);
    if (!s.ok()) {
      return Status::Error("the run from pose " + std::to_string(first) + ": " + s.message());
    }
    AppendFittedRun(run, spans, options.sample_step_mm, out, records);
  }
  return Status::Ok();
}

}  // namespace tpopt
