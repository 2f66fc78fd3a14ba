// Any bytes given to the APT reader: a status, never a crash.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "model/io/apt_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  tpopt::ToolPath path;
  std::vector<std::string> warnings;
  const tpopt::Status s = tpopt::ReadAptStream(in, "fuzz.cls", &path, &warnings);
  if (s.ok()) {
    // A path that read must write and read back to the same pose count.
    std::istringstream again(tpopt::FormatApt(path));
    tpopt::ToolPath back;
    if (!tpopt::ReadAptStream(again, "again.cls", &back, &warnings).ok() ||
        back.poses.size() != path.poses.size()) {
      __builtin_trap();
    }
  }
  return 0;
}
