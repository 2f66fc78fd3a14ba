// What `--vtk` shows in ParaView: the surface with its deviation map, the
// tool axes and the tip path, as one poly data set.
#ifndef TPOPT_APPS_VTK_SCENE_H_
#define TPOPT_APPS_VTK_SCENE_H_

#include <optional>

#include "apps/deviation_grid.h"
#include "model/cutter/cutter.h"
#include "model/geometry/ruled_surface.h"
#include "model/path/tool_path.h"
#include "model/io/vtk_writer.h"

namespace tpopt {

// Values of the "part" point array, so a ParaView Threshold can split the
// set into its pieces.
enum ScenePart { kSurfacePart = 0, kTipPart = 1, kAxisEndPart = 2 };

// Points: the surface grid (when `surface` and `grid` are given), then the
// tips, then each axis end (the tip plus the flute length along the axis).
// Lines: one segment per pose from tip to axis end, then the tip path as
// one polyline through every pose. Polygons: one quad per grid cell.
// Point arrays: "deviation_mm" (the signed deviation on the surface, 0 on
// the tool) and "part" (ScenePart).
PolyData BuildPathScene(const ToolPath& path, const Cutter& cutter, const RuledSurface* surface,
                        const std::optional<SurfaceGrid>& grid);

}  // namespace tpopt

#endif  // TPOPT_APPS_VTK_SCENE_H_
