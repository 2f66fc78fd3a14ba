// Any bytes given to the LinuxCNC INI reader: a status, never a crash.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "model/io/linuxcnc_ini.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  tpopt::Machine machine;
  if (tpopt::ParseLinuxCncIni(in, "fuzz.ini", "", &machine).ok()) {
    machine.ToJoints(Eigen::Vector3d(1, 2, 3), 0.3, 0.4);
  }
  return 0;
}
