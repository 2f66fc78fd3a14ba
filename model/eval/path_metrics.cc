#include "model/eval/path_metrics.h"

#include <algorithm>

#include <glog/logging.h>

#include "model/path/link_moves.h"

namespace tpopt {

Status EvaluatePath(const ToolPath& path, const Machine& machine, const RuledSurface* surface,
                    const Cutter& cutter, const DeviationOptions& deviation_options,
                    const MotionOptions& motion_options, PathMetrics* metrics) {
  CHECK(metrics != nullptr);
  PathMetrics out;
  out.poses = static_cast<int>(path.poses.size());
  out.link_moves = CountLinks(path);
  std::vector<JointVector> joints;
  RETURN_IF_ERROR(machine.AssignJoints(path, &joints, &out.warning));
  out.motion = EvaluateMotion(machine, path, joints, motion_options);
  if (surface != nullptr) {
    DeviationReport deviation;
    RETURN_IF_ERROR(
        EvaluateDeviation(*surface, cutter, path, machine, joints, deviation_options, &deviation));
    out.deviation = std::move(deviation);
  }
  *metrics = std::move(out);
  return Status::Ok();
}

double WorstDeviationMm(const PathMetrics& m) {
  return m.deviation ? std::max(m.deviation->max_overcut_mm, m.deviation->max_undercut_mm) : 0.0;
}

bool IsWorseThan(const PathMetrics& candidate, const PathMetrics& reference) {
  const double dev = WorstDeviationMm(candidate), dev_ref = WorstDeviationMm(reference);
  const int viol = candidate.motion.limit_violations;
  const int viol_ref = reference.motion.limit_violations;
  const bool worse = dev > dev_ref * (1 + 1e-6) + 1e-9 || viol > viol_ref;
  const bool better = dev < dev_ref * (1 - 1e-6) || viol < viol_ref;
  return worse && !better;
}

}  // namespace tpopt
