#include <cstdio>

#include "apps/commands.h"
#include "apps/exit_codes.h"

namespace tpopt {

int RunSmooth(const Invocation&) {
  std::fprintf(stderr, "tpopt smooth: not built yet\n");
  return kExitUsage;
}

}  // namespace tpopt
