// Any bytes given to the surface JSON reader; a surface that reads must
// evaluate everywhere without a crash.
#include <cstddef>
#include <cstdint>

#include "model/io/json_io.h"
#include "tests/fuzz/json_fuzz_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  tpopt::RuledSurface surface;
  if (tpopt::ReadSurfaceJson(FuzzFile(data, size), &surface).ok()) {
    for (double u : {0.0, 0.37, 1.0}) {
      surface.Point(u, 0.5);
      surface.GaussianCurvature(u, 0.5);
      surface.RailCurvatureRadius(1, u);
    }
  }
  return 0;
}
