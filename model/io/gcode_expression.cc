#include "model/io/gcode_expression.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

#include "model/base/units.h"

namespace tpopt {
namespace {

// Numbered parameters above this are LinuxCNC's persistent and system ones
// (work offsets, tool data, the current position): machine state.
constexpr int kLastUserParameter = 5000;
constexpr int kLastParameter = 5602;

bool IsAlpha(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool IsDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

std::string At(const std::string& code, size_t pos) { return "'" + code.substr(pos, 12) + "'"; }

struct BinaryOperator {
  const char* name;
  int level;  // LinuxCNC's precedence: higher binds tighter
};

// Longest names first, so that "**" is not read as "*".
constexpr BinaryOperator kOperators[] = {{"**", 4}, {"*", 3},  {"/", 3},   {"MOD", 3}, {"+", 2},
                                         {"-", 2},  {"EQ", 1}, {"NE", 1},  {"GT", 1},  {"GE", 1},
                                         {"LT", 1}, {"LE", 1}, {"AND", 0}, {"OR", 0},  {"XOR", 0}};
constexpr int kLowestLevel = 0;
constexpr int kOperandLevel = 5;

const BinaryOperator* OperatorAt(const std::string& code, size_t pos) {
  for (const BinaryOperator& op : kOperators) {
    if (code.compare(pos, std::string(op.name).size(), op.name) == 0) return &op;
  }
  return nullptr;
}

Status Apply(const std::string& op, double a, double b, double* value) {
  if (op == "**") {
    *value = std::pow(a, b);
  } else if (op == "*") {
    *value = a * b;
  } else if (op == "/") {
    if (b == 0) return Status::Error("division by zero in an expression");
    *value = a / b;
  } else if (op == "MOD") {
    if (b == 0) return Status::Error("MOD by zero in an expression");
    *value = a - b * std::floor(a / b);
  } else if (op == "+") {
    *value = a + b;
  } else if (op == "-") {
    *value = a - b;
  } else if (op == "EQ") {
    *value = a == b;
  } else if (op == "NE") {
    *value = a != b;
  } else if (op == "GT") {
    *value = a > b;
  } else if (op == "GE") {
    *value = a >= b;
  } else if (op == "LT") {
    *value = a < b;
  } else if (op == "LE") {
    *value = a <= b;
  } else if (op == "AND") {
    *value = a != 0 && b != 0;
  } else if (op == "OR") {
    *value = a != 0 || b != 0;
  } else {
    *value = (a != 0) != (b != 0);  // XOR
  }
  if (!std::isfinite(*value)) return Status::Error("the expression's " + op + " is not finite");
  return Status::Ok();
}

// LinuxCNC's unary functions of one bracketed argument (angles in degrees).
bool ApplyFunction(const std::string& name, double x, double* value) {
  if (name == "ABS")
    *value = std::abs(x);
  else if (name == "ACOS")
    *value = std::acos(x) / kDegToRad;
  else if (name == "ASIN")
    *value = std::asin(x) / kDegToRad;
  else if (name == "COS")
    *value = std::cos(x * kDegToRad);
  else if (name == "SIN")
    *value = std::sin(x * kDegToRad);
  else if (name == "TAN")
    *value = std::tan(x * kDegToRad);
  else if (name == "EXP")
    *value = std::exp(x);
  else if (name == "LN")
    *value = std::log(x);
  else if (name == "SQRT")
    *value = std::sqrt(x);
  else if (name == "FIX")
    *value = std::floor(x);
  else if (name == "FUP")
    *value = std::ceil(x);
  else if (name == "ROUND")
    *value = std::round(x);
  else
    return false;
  return true;
}

}  // namespace

Status GcodeParameters::ReadValue(const std::string& code, size_t* pos, double* value) const {
  size_t& i = *pos;
  if (i >= code.size()) return Status::Error("a value is missing at the end of the block");
  // A sign before a number is the number's; before anything else unary.
  if ((code[i] == '-' || code[i] == '+') && i + 1 < code.size() &&
      (code[i + 1] == '#' || code[i + 1] == '[' || IsAlpha(code[i + 1]))) {
    const double sign = code[i] == '-' ? -1.0 : 1.0;
    ++i;
    Status s = ReadValue(code, pos, value);
    *value *= sign;
    return s;
  }
  if (code[i] == '[') {
    ++i;
    RETURN_IF_ERROR(ReadExpression(code, pos, value));
    if (i >= code.size() || code[i] != ']') {
      return Status::Error("an expression lacks its closing ']' at " + At(code, i));
    }
    ++i;
    return Status::Ok();
  }
  if (code[i] == '#') {
    std::string key;
    Status s = ReadKey(code, pos, &key);
    return s.ok() ? Lookup(key, value) : s;
  }
  if (IsAlpha(code[i])) {
    size_t j = i;
    while (j < code.size() && IsAlpha(code[j])) ++j;
    const std::string name = code.substr(i, j - i);
    if (j >= code.size() || code[j] != '[') {
      return Status::Error("expected a number, #parameter or [expression] at " + At(code, i));
    }
    i = j;
    double x = 0.0;
    if (name == "EXISTS") {
      ++i;
      std::string key;
      RETURN_IF_ERROR(i < code.size() && code[i] == '#'
                          ? ReadKey(code, pos, &key)
                          : Status::Error("EXISTS needs a #parameter"));
      if (i >= code.size() || code[i] != ']') return Status::Error("EXISTS lacks its ']'");
      ++i;
      *value = values_.count(key) > 0;
      return Status::Ok();
    }
    RETURN_IF_ERROR(ReadValue(code, pos, &x));
    if (name == "ATAN") {
      double x2 = 0.0;
      if (i >= code.size() || code[i] != '/') return Status::Error("ATAN needs ATAN[y]/[x]");
      ++i;
      RETURN_IF_ERROR(ReadValue(code, pos, &x2));
      *value = std::atan2(x, x2) / kDegToRad;
      return Status::Ok();
    }
    if (!ApplyFunction(name, x, value)) {
      return Status::Error("unknown function '" + name + "' in an expression");
    }
    if (!std::isfinite(*value))
      return Status::Error(name + " of " + std::to_string(x) + " is not finite");
    return Status::Ok();
  }
  // A number is [+-]digits[.digits]: no exponents, no hex (a plain strtod
  // would read "G0X1" as the hexadecimal 0x1).
  size_t j = i;
  if (j < code.size() && (code[j] == '+' || code[j] == '-')) ++j;
  const size_t digits_start = j;
  while (j < code.size() && (IsDigit(code[j]) || code[j] == '.')) ++j;
  const std::string number = code.substr(i, j - i);
  if (j == digits_start || number.find('.') != number.rfind('.') ||
      number.find_first_of("0123456789") == std::string::npos) {
    return Status::Error("no valid number at " + At(code, i));
  }
  *value = std::strtod(number.c_str(), nullptr);
  i = j;
  return Status::Ok();
}

Status GcodeParameters::ReadAssignment(const std::string& code, size_t* pos,
                                       std::pair<std::string, double>* assignment) const {
  RETURN_IF_ERROR(ReadKey(code, pos, &assignment->first));
  if (*pos >= code.size() || code[*pos] != '=') {
    return Status::Error("parameter " + assignment->first + " is not followed by '='");
  }
  ++*pos;
  return ReadValue(code, pos, &assignment->second);
}

Status GcodeParameters::ReadKey(const std::string& code, size_t* pos, std::string* key) const {
  size_t& i = *pos;
  ++i;  // the '#'
  if (i < code.size() && code[i] == '<') {
    const size_t close = code.find('>', i);
    if (close == std::string::npos || close == i + 1) {
      return Status::Error("a named parameter lacks its name or '>' at " + At(code, i - 1));
    }
    *key = "#" + code.substr(i, close + 1 - i);
    i = close + 1;
    return Status::Ok();
  }
  double number = 0.0;
  RETURN_IF_ERROR(ReadValue(code, pos, &number));
  if (number != std::round(number) || number < 1 || number > kLastParameter) {
    return Status::Error("parameter number " + std::to_string(number) + " is not an integer in 1-" +
                         std::to_string(kLastParameter));
  }
  *key = "#" + std::to_string(static_cast<int>(number));
  return Status::Ok();
}

Status GcodeParameters::Lookup(const std::string& key, double* value) const {
  const auto it = values_.find(key);
  if (it != values_.end()) {
    *value = it->second;
    return Status::Ok();
  }
  if (key[1] == '<') {
    return Status::Error("named parameter " + key + " is read before the program sets it" +
                         (key[2] == '_' ? " (LinuxCNC's predefined parameters are machine state, "
                                          "which is not modelled)"
                                        : ""));
  }
  if (std::atoi(key.c_str() + 1) > kLastUserParameter) {
    return Status::Error("parameter " + key +
                         " is LinuxCNC machine state (offsets, tool data, position), which is "
                         "not modelled");
  }
  *value = 0.0;  // LinuxCNC's numbered parameters start at 0
  return Status::Ok();
}

Status GcodeParameters::ReadExpression(const std::string& code, size_t* pos, double* value) const {
  return ReadBinary(code, pos, kLowestLevel, value);
}

Status GcodeParameters::ReadBinary(const std::string& code, size_t* pos, int level,
                                   double* value) const {
  if (level == kOperandLevel) return ReadValue(code, pos, value);
  Status s = ReadBinary(code, pos, level + 1, value);
  while (s.ok() && *pos < code.size()) {
    const BinaryOperator* op = OperatorAt(code, *pos);
    if (op == nullptr || op->level != level) break;
    *pos += std::string(op->name).size();
    double right = 0.0;
    s = ReadBinary(code, pos, level + 1, &right);
    if (s.ok()) s = Apply(op->name, *value, right, value);
  }
  return s;
}

}  // namespace tpopt
