// Exit codes of the tpopt command (DESIGN.md).
#ifndef TPOPT_APPS_EXIT_CODES_H_
#define TPOPT_APPS_EXIT_CODES_H_

namespace tpopt {

enum ExitCode {
  kExitSuccess = 0,
  kExitBadInput = 1,     // a message names the file, line and problem
  kExitUsage = 2,        // unknown subcommand, flag or flag value
  kExitSolverFailure = 3 // the output is not written
};

}  // namespace tpopt

#endif  // TPOPT_APPS_EXIT_CODES_H_
