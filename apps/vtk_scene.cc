#include "apps/vtk_scene.h"

namespace tpopt {
namespace {

// Adds the surface grid's points and quads with their deviation.
void AddSurface(const RuledSurface& surface, const SurfaceGrid& grid, PolyData* data,
                std::vector<double>* deviation, std::vector<double>* part) {
  const int nu = static_cast<int>(grid.u.size()), nv = static_cast<int>(grid.v.size());
  for (int iu = 0; iu < nu; ++iu) {
    for (int iv = 0; iv < nv; ++iv) {
      data->points_w.push_back(surface.Point(grid.u[iu], grid.v[iv]));
      deviation->push_back(grid.deviation_mm[iu * nv + iv]);
      part->push_back(kSurfacePart);
    }
  }
  for (int iu = 0; iu + 1 < nu; ++iu) {
    for (int iv = 0; iv + 1 < nv; ++iv) {
      const int corner = iu * nv + iv;
      data->polys.push_back({corner, corner + nv, corner + nv + 1, corner + 1});
    }
  }
}

}  // namespace

PolyData BuildPathScene(const ToolPath& path, const Cutter& cutter, const RuledSurface* surface,
                        const std::optional<SurfaceGrid>& grid) {
  PolyData data;
  std::vector<double> deviation, part;
  if (surface != nullptr && grid) AddSurface(*surface, *grid, &data, &deviation, &part);
  const int first_tip = static_cast<int>(data.points_w.size());
  const int n = static_cast<int>(path.poses.size());
  for (const ToolPose& pose : path.poses) data.points_w.push_back(pose.p_w_tip);
  for (const ToolPose& pose : path.poses) {
    data.points_w.push_back(pose.p_w_tip + cutter.flute_length_mm * pose.a_w);
  }
  deviation.resize(data.points_w.size(), 0.0);
  part.resize(first_tip + n, kTipPart);
  part.resize(data.points_w.size(), kAxisEndPart);
  std::vector<int> tip_path;
  for (int i = 0; i < n; ++i) {
    data.lines.push_back({first_tip + i, first_tip + n + i});
    tip_path.push_back(first_tip + i);
  }
  if (n >= 2) data.lines.push_back(tip_path);
  data.point_scalars = {{"deviation_mm", deviation}, {"part", part}};
  return data;
}

}  // namespace tpopt
