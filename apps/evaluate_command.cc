#include <cstdio>

#include "apps/commands.h"
#include "apps/exit_codes.h"

namespace tpopt {

int RunEvaluate(const Invocation&) {
  std::fprintf(stderr, "tpopt evaluate: not built yet\n");
  return kExitUsage;
}

}  // namespace tpopt
