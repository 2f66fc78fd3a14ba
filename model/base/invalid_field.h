// The message of an options struct's IsValid: it names the field as the
// flag that sets it (or as the field, where no flag does) and the value,
// e.g. "--w_deviation must be finite and >= 0 (got -1)".
#ifndef TPOPT_MODEL_INVALID_FIELD_H_
#define TPOPT_MODEL_INVALID_FIELD_H_

#include <sstream>
#include <string>

namespace tpopt {

// "<field> must be <rule> (got <value>)"; a string value is quoted.
template <typename T>
std::string InvalidField(const std::string& field, const T& value,
                         const std::string& rule) {
  std::ostringstream out;
  out << field << " must be " << rule << " (got " << value << ")";
  return out.str();
}

inline std::string InvalidField(const std::string& field,
                                const std::string& value,
                                const std::string& rule) {
  return field + " must be " + rule + " (got '" + value + "')";
}

// Collects the first broken rule of an IsValid, in the order the rules are
// checked: Require(...) each rule, then `return check.Report(why);`.
class FirstInvalid {
 public:
  void Require(bool ok, const std::string& message) {
    if (problem_.empty() && !ok) problem_ = message;
  }
  // Writes the problem (empty when every rule held) to `why` if given;
  // true when every rule held.
  bool Report(std::string* why) const {
    if (why != nullptr) *why = problem_;
    return problem_.empty();
  }

 private:
  std::string problem_;
};

}  // namespace tpopt

#endif  // TPOPT_MODEL_INVALID_FIELD_H_
