#include <cstdio>

#include "apps/commands.h"
#include "apps/exit_codes.h"

namespace tpopt {

int RunGenerate(const Invocation&) {
  std::fprintf(stderr, "tpopt generate: not built yet\n");
  return kExitUsage;
}

}  // namespace tpopt
