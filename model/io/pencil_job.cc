#include "model/io/pencil_job.h"

#include "model/io/json_io.h"

namespace tpopt {

Status LoadPencilJob(const std::string& surface_path, const std::string& curve_path,
                     double ball_radius_mm, PencilJob* job) {
  Status s = ReadBSplineSurfaceJson(surface_path, &job->surface);
  return s.ok() ? CompletePencilJob(curve_path, ball_radius_mm, job) : s;
}

Status CompletePencilJob(const std::string& curve_path, double ball_radius_mm, PencilJob* job) {
  RETURN_IF_ERROR(ReadGuideCurvesJson(curve_path, &job->guides, &job->placement));
  Status s = PencilGeometry::Create(job->surface, job->placement, ball_radius_mm, &job->geometry);
  if (!s.ok()) return Status::Error(curve_path + ": " + s.message());
  return Status::Ok();
}

}  // namespace tpopt
