// Exit codes of the tpopt command (docs/ARCHITECTURE.md, "Errors and exit
// codes"), and the one mapping from a Status's code to them.
#ifndef TPOPT_APPS_EXIT_CODES_H_
#define TPOPT_APPS_EXIT_CODES_H_

#include <cstdio>
#include <string>

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

// A subcommand's failure: prints "tpopt <subcommand>: <message>" on stderr
// and returns the exit code of `status`.
inline int ReportFailure(const char* subcommand, const Status& status,
                         const std::string& message) {
  std::fprintf(stderr, "tpopt %s: %s\n", subcommand, message.c_str());
  return ExitCodeOf(status);
}
inline int ReportFailure(const char* subcommand, const Status& status) {
  return ReportFailure(subcommand, status, status.message());
}

}  // namespace tpopt

#endif  // TPOPT_APPS_EXIT_CODES_H_
