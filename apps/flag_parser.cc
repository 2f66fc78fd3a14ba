#include "apps/flag_parser.h"

#include <fstream>
#include <sstream>

#include <gflags/gflags.h>

namespace tpopt {
namespace {

constexpr int kMaxFlagfileDepth = 8;

Status ApplyArgs(const std::vector<std::string>& args, const std::string& where_prefix,
                 const std::vector<int>& lines, int depth, std::vector<std::string>* positional);

Status ApplyFlagfile(const std::string& path, int depth) {
  if (depth > kMaxFlagfileDepth) {
    return Status::Error(path + ": --flagfile nested more than 8 deep");
  }
  std::ifstream in(path);
  if (!in) return Status::Error(path + ": cannot open flag file");
  std::vector<std::string> args;
  std::vector<int> lines;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    const size_t b = line.find_first_not_of(" \t\r");
    if (b == std::string::npos || line[b] == '#') continue;
    const size_t e = line.find_last_not_of(" \t\r");
    args.push_back(line.substr(b, e - b + 1));
    lines.push_back(n);
  }
  std::vector<std::string> positional;
  Status s = ApplyArgs(args, path, lines, depth, &positional);
  if (s.ok() && !positional.empty()) {
    return Status::Error(path + ": '" + positional.front() + "' is not a --flag");
  }
  return s;
}

// Sets one flag; `value_from_next` is set when the value is the next arg.
Status ApplyOne(const std::string& arg, const std::string& next, bool* used_next,
                const std::string& where, int depth) {
  std::string name = arg.substr(arg[1] == '-' ? 2 : 1);
  std::string value;
  bool has_value = false;
  const size_t eq = name.find('=');
  if (eq != std::string::npos) {
    value = name.substr(eq + 1);
    name = name.substr(0, eq);
    has_value = true;
  }
  if (name == "flagfile") {
    if (!has_value) return Status::Error(where + "--flagfile needs =FILE");
    return ApplyFlagfile(value, depth + 1);
  }
  gflags::CommandLineFlagInfo info;
  bool negated = false;
  if (!gflags::GetCommandLineFlagInfo(name.c_str(), &info)) {
    if (name.rfind("no", 0) == 0 && !has_value &&
        gflags::GetCommandLineFlagInfo(name.substr(2).c_str(), &info) && info.type == "bool") {
      negated = true;
      name = name.substr(2);
    } else {
      return Status::Error(where + "unknown flag --" + name + " (see tpopt --help)");
    }
  }
  if (info.type == "bool" && !has_value) {
    value = negated ? "false" : "true";
  } else if (!has_value) {
    if (next.empty() || next[0] == '-') {
      return Status::Error(where + "flag --" + name + " needs a value");
    }
    value = next;
    *used_next = true;
  }
  if (gflags::SetCommandLineOption(name.c_str(), value.c_str()).empty()) {
    return Status::Error(where + "bad value '" + value + "' for --" + name + " (a " + info.type +
                         ")");
  }
  return Status::Ok();
}

Status ApplyArgs(const std::vector<std::string>& args, const std::string& where_prefix,
                 const std::vector<int>& lines, int depth, std::vector<std::string>* positional) {
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.size() < 2 || arg[0] != '-') {
      positional->push_back(arg);
      continue;
    }
    std::string where;
    if (!where_prefix.empty()) where = where_prefix + ":" + std::to_string(lines[i]) + ": ";
    bool used_next = false;
    const std::string next = i + 1 < args.size() ? args[i + 1] : "";
    RETURN_IF_ERROR(ApplyOne(arg, where_prefix.empty() ? next : "", &used_next, where, depth));
    if (used_next) ++i;
  }
  return Status::Ok();
}

}  // namespace

Status ParseFlags(const std::vector<std::string>& args, std::vector<std::string>* positional) {
  return ApplyArgs(args, "", std::vector<int>(args.size(), 0), 0, positional);
}

std::string JoinCommandLine(int argc, char** argv) {
  std::ostringstream out;
  for (int i = 0; i < argc; ++i) out << (i ? " " : "") << argv[i];
  return out.str();
}

}  // namespace tpopt
