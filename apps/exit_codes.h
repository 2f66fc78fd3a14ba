// Exit codes of the tpopt command (docs/ARCHITECTURE.md, "Errors and exit
// codes"), and the one mapping from a Status's code to them.
#ifndef TPOPT_APPS_EXIT_CODES_H_
#define TPOPT_APPS_EXIT_CODES_H_

#include "model/base/status.h"

namespace tpopt {

enum ExitCode {
  kExitSuccess = 0,
  kExitBadInput = 1,     // a message names the file, line and problem
  kExitUsage = 2,        // unknown subcommand, flag or flag value
  kExitSolverFailure = 3 // the output is not written
};

// 0 for ok, 1 for bad input and for a file the system would not read or
// write, 2 for usage, 3 for a solver failure.
inline ExitCode ExitCodeOf(const Status& status) {
  switch (status.code()) {
    case StatusCode::kOk:
      return kExitSuccess;
    case StatusCode::kUsage:
      return kExitUsage;
    case StatusCode::kSolver:
      return kExitSolverFailure;
    case StatusCode::kBadInput:
    case StatusCode::kIo:
      return kExitBadInput;
  }
  return kExitBadInput;
}

}  // namespace tpopt

#endif  // TPOPT_APPS_EXIT_CODES_H_
