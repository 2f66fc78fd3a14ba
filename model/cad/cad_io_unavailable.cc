// cad_io.h for a build configured with -DTPOPT_WITH_OCCT=OFF: STEP and IGES
// files are recognised by name and refused with a message saying why.
#include <cmath>

#include "model/cad/cad_io.h"

namespace tpopt {
namespace {

Status Unavailable(const std::string& path) {
  return Status::Error(
      path +
      ": tpopt was built without OpenCASCADE (-DTPOPT_WITH_OCCT=OFF), so it "
      "cannot read or write STEP or IGES files");
}

}  // namespace

bool IsCadSurfacePath(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || path.find('/', dot) != std::string::npos)
    return false;
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(::tolower(c));
  return ext == "stp" || ext == "step" || ext == "igs" || ext == "iges";
}

bool CadIoAvailable() { return false; }

bool CadReadOptions::IsValid(std::string* why) const {
  *why = "OpenCASCADE is not available";
  return false;
}

bool CadWriteOptions::IsValid(std::string* why) const {
  *why = "OpenCASCADE is not available";
  return false;
}

std::string CadFaceSummary::Describe() const {
  return "face " + std::to_string(index);
}

Status ListCadFaces(const std::string& path, std::vector<CadFaceSummary>*) {
  return Unavailable(path);
}

Status ReadCadRuledSurface(const std::string& path, const CadReadOptions&,
                           RuledSurface*, CadSurfaceInfo*) {
  return Unavailable(path);
}

Status ReadCadBSplineSurface(const std::string& path, const CadReadOptions&,
                             BSplineSurface*, double*, CadSurfaceInfo*) {
  return Unavailable(path);
}

Status WriteCadPatches(const std::string& path, const std::vector<CadPatch>&,
                       const CadWriteOptions&) {
  return Unavailable(path);
}

Status WriteCadRuledSurface(const std::string& path, const RuledSurface&,
                            const CadWriteOptions&) {
  return Unavailable(path);
}

}  // namespace tpopt
