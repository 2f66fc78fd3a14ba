// A pencil job as read from its files: the B-spline surface (JSON) and the
// planar guide curves (model/io/json_io.h), with the geometry of
// model/path/pencil_path.h placed over that surface.
#ifndef TPOPT_MODEL_PENCIL_JOB_H_
#define TPOPT_MODEL_PENCIL_JOB_H_

#include <string>
#include <vector>

#include "model/geometry/bspline_curve.h"
#include "model/geometry/bspline_surface.h"
#include "model/path/pencil_path.h"
#include "model/base/status.h"

namespace tpopt {

// Everything a pencil job reads: the surface, the guides, and the geometry
// placed over that surface (which points into this object: not copyable).
struct PencilJob {
  PencilJob() = default;
  PencilJob(const PencilJob&) = delete;
  PencilJob& operator=(const PencilJob&) = delete;
  BSplineSurface surface;
  std::vector<BSplineCurve> guides;
  GuidePlacement placement;
  PencilGeometry geometry;
};

// Reads the surface and guide-curve JSON files and places the guides;
// errors name the file at fault.
Status LoadPencilJob(const std::string& surface_path, const std::string& curve_path,
                     double ball_radius_mm, PencilJob* job);

// LoadPencilJob for a job whose surface is already set (read from a CAD
// file): reads the guide curves and builds the geometry.
Status CompletePencilJob(const std::string& curve_path, double ball_radius_mm, PencilJob* job);

}  // namespace tpopt

#endif  // TPOPT_MODEL_PENCIL_JOB_H_
