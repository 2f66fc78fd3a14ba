// Any bytes given to the machine JSON reader: a status, never a crash.
#include <cstddef>
#include <cstdint>

#include "model/io/json_io.h"
#include "tests/fuzz/json_fuzz_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  tpopt::Machine machine;
  if (tpopt::ReadMachineJson(FuzzFile(data, size), &machine).ok()) {
    machine.ToJoints(Eigen::Vector3d(1, 2, 3), 0.3, 0.4);
  }
  return 0;
}
