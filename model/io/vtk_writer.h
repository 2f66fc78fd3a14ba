// VTK poly data for ParaView: points, polylines, polygons and per-point
// scalars, as VTK XML PolyData (.vtp, ASCII) or the legacy format (.vtk,
// ASCII POLYDATA), chosen by the file's extension.
#ifndef TPOPT_MODEL_VTK_WRITER_H_
#define TPOPT_MODEL_VTK_WRITER_H_

#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "model/base/status.h"

namespace tpopt {

struct PolyData {
  std::vector<Eigen::Vector3d> points_w;  // mm, workpiece frame
  // Each line is a polyline through point indices (two for a segment).
  std::vector<std::vector<int>> lines;
  // Each polygon lists its corners' point indices in order.
  std::vector<std::vector<int>> polys;
  // Named arrays with one value per point. Names are plain identifiers
  // (no spaces or markup): both formats take them verbatim.
  std::vector<std::pair<std::string, std::vector<double>>> point_scalars;
};

enum class VtkFormat { kXmlPolyData, kLegacy };

// .vtp gives kXmlPolyData, .vtk kLegacy (any case); false for anything else.
bool VtkFormatOf(const std::string& path, VtkFormat* format);

// The file's text in either format. Precondition: every index is a valid
// point and every scalar array has one value per point (CHECKed).
std::string VtpText(const PolyData& data);
std::string LegacyVtkText(const PolyData& data);

// Writes `data` in the format of `path`'s extension, whole or not at all;
// the message names the file on failure or an unknown extension.
Status WritePolyData(const std::string& path, const PolyData& data);

}  // namespace tpopt

#endif  // TPOPT_MODEL_VTK_WRITER_H_
