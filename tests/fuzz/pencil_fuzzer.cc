// Any bytes given to the pencil job's readers (bicubic surface JSON and
// guide-curve JSON); what reads must evaluate, place and project without a
// crash.
#include <cstddef>
#include <cstdint>

#include "model/io/json_io.h"
#include "model/geometry/surface_projection.h"
#include "tests/fuzz/json_fuzz_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = FuzzFile(data, size);
  tpopt::BSplineSurface surface;
  if (tpopt::ReadBSplineSurfaceJson(path, &surface).ok()) {
    for (double u : {0.0, 0.37, 1.0}) surface.Evaluate(u, 0.5).UnitNormal();
    tpopt::SurfaceHit hit;
    tpopt::ProjectAlongDirection(surface, surface.Point(0.5, 0.5) + Eigen::Vector3d(0, 0, 10),
                                 Eigen::Vector3d(0, 0, -1), nullptr, &hit);
  }
  std::vector<tpopt::BSplineCurve> curves;
  tpopt::GuidePlacement placement;
  if (tpopt::ReadGuideCurvesJson(path, &curves, &placement).ok()) {
    for (const tpopt::BSplineCurve& c : curves) c.Evaluate(0.5, 1);
  }
  return 0;
}
