// Any bytes given to the G-code reader: a status, never a crash.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "model/io/gcode_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  tpopt::Machine machine;
  machine.kinematics.y_offset_mm = 20;
  machine.kinematics.z_offset_mm = 10;
  tpopt::ToolPath path;
  std::vector<std::string> warnings;
  const tpopt::GcodeStyle style = size % 2 ? tpopt::GcodeStyle::kJoint : tpopt::GcodeStyle::kTcp;
  tpopt::ReadGcodeStream(in, "fuzz.ngc", machine, style, &path, &warnings);
  return 0;
}
