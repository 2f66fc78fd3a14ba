#include "solver/fit/pencil_fit.h"

#include <algorithm>
#include <chrono>

#include <glog/logging.h>

namespace tpopt {
namespace {

ToolPose TipPose(const Eigen::Vector3d& ball_centre, const Eigen::Vector3d& axis, double radius,
                 double feed, bool rapid) {
  ToolPose pose;
  pose.p_w_tip = ball_centre - radius * axis;
  pose.a_w = axis;
  pose.feed_mm_per_min = feed;
  pose.rapid = rapid;
  return pose;
}

void Shift(const Eigen::Vector3d& offset, CubicSpan* span) {
  for (Eigen::Vector3d& p : span->bezier) p += offset;
}

}  // namespace

IdealCurve IdealPencilCurve(const PencilGeometry& geometry, const BSplineCurve& guide,
                            const PencilRun& run) {
  return [&geometry, &guide, &run](size_t i, double x) {
    const PencilPoint& a = run.points[i];
    Eigen::Vector2d uv(a.u, a.v);
    PencilPoint p;
    // The run was generated through these parameters, so the projection
    // cannot fail between two of its points.
    CHECK(geometry.At(guide, a.m + x * (run.points[i + 1].m - a.m), &uv, &p).ok());
    return p.cl;
  };
}

Status FitPencilRuns(const PencilGeometry& geometry, const std::vector<BSplineCurve>& guides,
                     const std::vector<PencilRun>& runs, double ball_radius_mm,
                     const CurveOutputOptions& options, bool write_spans,
                     PencilFitResult* result) {
  CHECK_EQ(guides.size(), runs.size());
  *result = PencilFitResult();
  const Eigen::Vector3d axis = geometry.tool_axis();
  for (size_t k = 0; k < runs.size(); ++k) {
    const std::vector<PencilPoint>& points = runs[k].points;
    std::vector<Eigen::Vector3d> cl, tangents;
    std::vector<ToolPose> poses;
    for (const PencilPoint& p : points) {
      if (p.dcl_dm.dot(p.dcc_dm) <= 0) ++result->folded_points;
      cl.push_back(p.cl);
      tangents.push_back(p.dcl_dm.normalized());
      poses.push_back(TipPose(p.cl, axis, ball_radius_mm, 0.0, false));
    }
    std::vector<CubicSpan> spans;
    const auto start = std::chrono::steady_clock::now();
    Status s = FitPolyline(cl, tangents, options.fit, &spans);
    result->fit_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!s.ok()) return Status::Error("curve " + std::to_string(k) + ": " + s.message());
    result->windows += cl.size() - 3;
    result->cl_points += cl.size();
    const SpanErrors e = MeasureSpanErrors(cl, spans, IdealPencilCurve(geometry, guides[k], runs[k]), 15);
    result->errors.max_chord_error_mm = std::max(result->errors.max_chord_error_mm, e.max_chord_error_mm);
    result->errors.max_fit_error_mm = std::max(result->errors.max_fit_error_mm, e.max_fit_error_mm);
    result->errors.max_join_angle_deg = std::max(result->errors.max_join_angle_deg, e.max_join_angle_deg);

    // Retract, move over the run's start, and feed down to it.
    ToolPath& path = result->path;
    if (!path.poses.empty()) {
      // Radius 0: the point given is the tip itself.
      path.poses.push_back(
          TipPose(path.poses.back().p_w_tip + kPencilClearanceMm * axis, axis, 0.0, 0.0, true));
    }
    path.poses.push_back(TipPose(cl[0] + kPencilClearanceMm * axis, axis, ball_radius_mm, 0.0, true));
    path.poses.push_back(poses[0]);
    if (!write_spans) {
      path.poses.insert(path.poses.end(), poses.begin() + 1, poses.end());
      continue;
    }
    for (CubicSpan& span : spans) Shift(-ball_radius_mm * axis, &span);
    AppendFittedRun(poses, spans, options.sample_step_mm, &path, &result->spans);
  }
  return Status::Ok();
}

}  // namespace tpopt
