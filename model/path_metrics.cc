#include "model/path_metrics.h"

#include <glog/logging.h>

namespace tpopt {

Status EvaluatePath(const ToolPath& path, const Machine& machine, const RuledSurface* surface,
                    const Cutter& cutter, const DeviationOptions& deviation_options,
                    const MotionOptions& motion_options, PathMetrics* metrics) {
  CHECK(metrics != nullptr);
  PathMetrics out;
  out.poses = static_cast<int>(path.poses.size());
  std::vector<JointVector> joints;
  Status s = machine.AssignJoints(path, &joints, &out.warning);
  if (!s.ok()) return s;
  out.motion = EvaluateMotion(machine, path, joints, motion_options);
  if (surface != nullptr) {
    DeviationReport deviation;
    s = EvaluateDeviation(*surface, cutter, path, machine, joints, deviation_options, &deviation);
    if (!s.ok()) return s;
    out.deviation = std::move(deviation);
  }
  *metrics = std::move(out);
  return Status::Ok();
}

}  // namespace tpopt
