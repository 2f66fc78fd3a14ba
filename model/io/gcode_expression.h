// The values of LinuxCNC G-code words: numbers, parameters (#1, #<name>,
// indirect ##1) and [bracketed] expressions with LinuxCNC's operators and
// unary functions, as the LinuxCNC G-code manual ("Numbers, Parameters and
// Expressions") defines them. A program's own assignments are kept; what it
// reads but never set is refused where LinuxCNC would read machine state.
#ifndef TPOPT_MODEL_GCODE_EXPRESSION_H_
#define TPOPT_MODEL_GCODE_EXPRESSION_H_

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "model/base/status.h"

namespace tpopt {

class GcodeParameters {
 public:
  // Reads a real value starting at code[*pos] and moves *pos past it. `code`
  // is a block without comments or spaces, in upper case. Errors (without
  // file or line: the caller adds them) name the construct and the value.
  Status ReadValue(const std::string& code, size_t* pos, double* value) const;

  // Reads "#<key>=<value>" starting at code[*pos] (at the '#') and moves *pos
  // past it; the assignment is returned, not made: LinuxCNC makes a line's
  // assignments after reading all of its values.
  Status ReadAssignment(const std::string& code, size_t* pos,
                        std::pair<std::string, double>* assignment) const;

  // Sets parameter `key` ("#12" or "#<name>", as ReadAssignment gives it).
  void Set(const std::string& key, double value) { values_[key] = value; }

 private:
  Status ReadKey(const std::string& code, size_t* pos, std::string* key) const;
  Status Lookup(const std::string& key, double* value) const;
  Status ReadExpression(const std::string& code, size_t* pos, double* value) const;
  Status ReadBinary(const std::string& code, size_t* pos, int level, double* value) const;

  std::map<std::string, double> values_;
};

}  // namespace tpopt

#endif  // TPOPT_MODEL_GCODE_EXPRESSION_H_
