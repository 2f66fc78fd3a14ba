// The subcommands of tpopt. Each reads its flags (already parsed) and
// returns an ExitCode.
#ifndef TPOPT_APPS_COMMANDS_H_
#define TPOPT_APPS_COMMANDS_H_

#include <string>

namespace tpopt {

struct Invocation {
  std::string command_line;  // as typed, for reports
};

int RunGenerate(const Invocation& invocation);
int RunEvaluate(const Invocation& invocation);
int RunSmooth(const Invocation& invocation);
int RunStripWidth(const Invocation& invocation);
int RunPencil(const Invocation& invocation);

}  // namespace tpopt

#endif  // TPOPT_APPS_COMMANDS_H_
