// Writes the STEP versions of the shared surfaces, data/surfaces/NAME.stp
// from NAME.json, with a fixed header time stamp so that a rerun gives the
// same bytes. Usage: tpopt_write_step_surfaces SOURCE_DIR
// (tests/cad_io_test.cc checks that the checked-in files match the JSON).
#include <cstdio>
#include <string>
#include <vector>

#include "model/cad/cad_io.h"
#include "model/geometry/freeform_surface.h"
#include "model/io/freeform_surface_json.h"
#include "model/io/json_io.h"

namespace tpopt {
namespace {

int Run(const std::string& source_dir) {
  const std::string dir = source_dir + "/data/surfaces/";
  Status s;
  for (const std::string name : {"hypar", "impeller_blade", "jcde2022"}) {
    RuledSurface surface;
    s = ReadSurfaceJson(dir + name + ".json", &surface);
    if (s.ok())
      s = WriteCadRuledSurface(dir + name + ".stp", surface, CadWriteOptions());
    if (!s.ok()) break;
    std::printf("wrote %s%s.stp\n", dir.c_str(), name.c_str());
  }
  const std::string freeform = "propeller_blade_freeform";
  BSplineSurface bspline;
  FreeformSurface with_side;
  if (s.ok()) s = ReadBSplineSurfaceJson(dir + freeform + ".json", &bspline);
  if (s.ok()) s = ReadFreeformSurfaceJson(dir + freeform + ".json", &with_side);
  if (s.ok()) {
    CadPatch patch = PatchOf(bspline);
    patch.reversed = with_side.cutter_side_sign() < 0;
    s = WriteCadPatches(dir + freeform + ".stp", {patch}, CadWriteOptions());
  }
  if (!s.ok()) {
    std::fprintf(stderr, "tpopt_write_step_surfaces: %s\n",
                 s.message().c_str());
    return 1;
  }
  std::printf("wrote %s%s.stp\n", dir.c_str(), freeform.c_str());
  return 0;
}

}  // namespace
}  // namespace tpopt

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: tpopt_write_step_surfaces SOURCE_DIR\n");
    return 2;
  }
  return tpopt::Run(argv[1]);
}
