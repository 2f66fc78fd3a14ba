// Any bytes given to the bicubic surface JSON reader; a surface that reads
// must evaluate everywhere, curvatures included, without a crash.
#include <cstddef>
#include <cstdint>

#include "model/io/freeform_surface_json.h"
#include "tests/fuzz/json_fuzz_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  tpopt::FreeformSurface surface;
  if (tpopt::ReadFreeformSurfaceJson(FuzzFile(data, size), &surface).ok()) {
    for (double u : {0.0, 0.37, 1.0}) {
      const tpopt::SurfaceDerivatives d = surface.Evaluate(u, 0.5);
      surface.Curvatures(d);
      surface.NormalCurvature(d, d.su + d.sv);
    }
  }
  return 0;
}
