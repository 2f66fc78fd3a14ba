#include "model/io/vtk_writer.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include <glog/logging.h>

#include "model/io/atomic_file.h"

namespace tpopt {
namespace {

// Enough digits that a mm coordinate survives to well below a micrometre.
std::string Num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.9g", v);
  return buf;
}

void CheckIndices(const PolyData& data) {
  const int n = static_cast<int>(data.points_w.size());
  for (const auto* cells : {&data.lines, &data.polys}) {
    for (const std::vector<int>& cell : *cells) {
      for (int index : cell) CHECK(index >= 0 && index < n) << "point index " << index;
    }
  }
  for (const auto& [name, values] : data.point_scalars) {
    CHECK_EQ(values.size(), data.points_w.size()) << name;
  }
}

std::string PointLines(const PolyData& data) {
  std::string out;
  for (const Eigen::Vector3d& p : data.points_w) {
    out += Num(p.x()) + " " + Num(p.y()) + " " + Num(p.z()) + "\n";
  }
  return out;
}

std::string Joined(const std::vector<int>& values) {
  std::string out;
  for (size_t i = 0; i < values.size(); ++i) out += (i ? " " : "") + std::to_string(values[i]);
  return out;
}

size_t IndexCount(const std::vector<std::vector<int>>& cells) {
  size_t count = 0;
  for (const std::vector<int>& cell : cells) count += cell.size();
  return count;
}

// <Lines> or <Polys>: all indices, then the running end of each cell.
// Absent when there are none: an empty ASCII array is one more thing for a
// reader to get right, and the Piece's count already says zero.
std::string XmlCells(const char* tag, const std::vector<std::vector<int>>& cells) {
  if (cells.empty()) return "";
  std::string connectivity, offsets;
  int end = 0;
  for (const std::vector<int>& cell : cells) {
    connectivity += Joined(cell) + "\n";
    end += static_cast<int>(cell.size());
    offsets += std::to_string(end) + " ";
  }
  return std::string("<") + tag + ">\n" +
         "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n" + connectivity +
         "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n" + offsets +
         "\n</DataArray>\n</" + tag + ">\n";
}

std::string ScalarValues(const std::vector<double>& values) {
  std::string out;
  for (double v : values) out += Num(v) + "\n";
  return out;
}

// LINES or POLYGONS: the count, then each cell as its size and indices.
std::string LegacyCells(const char* keyword, const std::vector<std::vector<int>>& cells) {
  if (cells.empty()) return "";
  std::string out = std::string(keyword) + " " + std::to_string(cells.size()) + " " +
                    std::to_string(cells.size() + IndexCount(cells)) + "\n";
  for (const std::vector<int>& cell : cells) {
    out += std::to_string(cell.size()) + " " + Joined(cell) + "\n";
  }
  return out;
}

}  // namespace

bool VtkFormatOf(const std::string& path, VtkFormat* format) {
  const size_t dot = path.find_last_of('.');
  const size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return false;
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == "vtp") {
    *format = VtkFormat::kXmlPolyData;
  } else if (ext == "vtk") {
    *format = VtkFormat::kLegacy;
  } else {
    return false;
  }
  return true;
}

std::string VtpText(const PolyData& data) {
  CheckIndices(data);
  std::string out =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n";
  out += "<Piece NumberOfPoints=\"" + std::to_string(data.points_w.size()) +
         "\" NumberOfVerts=\"0\" NumberOfLines=\"" + std::to_string(data.lines.size()) +
         "\" NumberOfStrips=\"0\" NumberOfPolys=\"" + std::to_string(data.polys.size()) + "\">\n";
  out += "<PointData";
  if (!data.point_scalars.empty()) out += " Scalars=\"" + data.point_scalars.front().first + "\"";
  out += ">\n";
  for (const auto& [name, values] : data.point_scalars) {
    out += "<DataArray type=\"Float64\" Name=\"" + name + "\" format=\"ascii\">\n" +
           ScalarValues(values) + "</DataArray>\n";
  }
  out += "</PointData>\n<Points>\n"
         "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n" +
         PointLines(data) + "</DataArray>\n</Points>\n";
  out += XmlCells("Lines", data.lines) + XmlCells("Polys", data.polys);
  return out + "</Piece>\n</PolyData>\n</VTKFile>\n";
}

std::string LegacyVtkText(const PolyData& data) {
  CheckIndices(data);
  std::string out =
      "# vtk DataFile Version 3.0\ntpopt tool path and surface\nASCII\nDATASET POLYDATA\n";
  out += "POINTS " + std::to_string(data.points_w.size()) + " double\n" + PointLines(data);
  out += LegacyCells("LINES", data.lines) + LegacyCells("POLYGONS", data.polys);
  if (!data.point_scalars.empty()) {
    out += "POINT_DATA " + std::to_string(data.points_w.size()) + "\n";
  }
  for (const auto& [name, values] : data.point_scalars) {
    out += "SCALARS " + name + " double 1\nLOOKUP_TABLE default\n" + ScalarValues(values);
  }
  return out;
}

Status WritePolyData(const std::string& path, const PolyData& data) {
  VtkFormat format;
  if (!VtkFormatOf(path, &format)) {
    return Status::Error(path + ": unknown VTK format (expected .vtp or .vtk)");
  }
  return WriteFileAtomically(
      path, format == VtkFormat::kXmlPolyData ? VtpText(data) : LegacyVtkText(data));
}

}  // namespace tpopt
