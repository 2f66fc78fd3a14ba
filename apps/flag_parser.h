// Command-line parsing on top of gflags' registry that never exits the
// process: an unknown flag, a malformed value or a broken --flagfile comes
// back as an error (exit code 2), naming the flag file and line if any.
#ifndef TPOPT_APPS_FLAG_PARSER_H_
#define TPOPT_APPS_FLAG_PARSER_H_

#include <string>
#include <vector>

#include "model/base/status.h"

namespace tpopt {

// Applies each `--name=value`, `--name value`, `--bool`/`--nobool` and
// `--flagfile=F` (one flag a line, `#` comments; nested files allowed) in
// order; later settings win. Non-flag arguments go to `positional`.
// `-v=N`/`--v=N` is glog's verbosity.
Status ParseFlags(const std::vector<std::string>& args, std::vector<std::string>* positional);

// The arguments as given, joined for the report's command line.
std::string JoinCommandLine(int argc, char** argv);

}  // namespace tpopt

#endif  // TPOPT_APPS_FLAG_PARSER_H_
