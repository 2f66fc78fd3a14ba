// A returned status for user-facing failures. The library throws no
// exceptions and CHECKs only programmer errors; anything that can go wrong
// because of a file or a flag comes back as a Status whose message names the
// file, the line or pose index, and the offending value. Its code says what
// kind of failure it is; the tpopt command maps the code to its exit code in
// one place (apps/exit_codes.h).
#ifndef TPOPT_MODEL_STATUS_H_
#define TPOPT_MODEL_STATUS_H_

#include <string>
#include <utility>

namespace tpopt {

enum class StatusCode {
  kOk,
  kBadInput,  // a file's content, or a value the run cannot use
  kUsage,     // a flag or a combination of flags
  kSolver,    // the solver found no acceptable result; nothing is written
  kIo,        // the system refused to read or write a file
};

class Status {
 public:
  static Status Ok() { return Status(); }
  // Bad input, the most common failure.
  static Status Error(std::string message) {
    return WithCode(StatusCode::kBadInput, std::move(message));
  }
  static Status Usage(std::string message) {
    return WithCode(StatusCode::kUsage, std::move(message));
  }
  static Status SolverFailure(std::string message) {
    return WithCode(StatusCode::kSolver, std::move(message));
  }
  static Status IoError(std::string message) {
    return WithCode(StatusCode::kIo, std::move(message));
  }

  bool ok() const { return code_ == StatusCode::kOk; }
  StatusCode code() const { return code_; }
  const std::string& message() const { return message_; }

 private:
  static Status WithCode(StatusCode code, std::string message) {
    Status s;
    s.code_ = code;
    s.message_ = std::move(message);
    return s;
  }

  StatusCode code_ = StatusCode::kOk;
  std::string message_;
};

}  // namespace tpopt

// Evaluates `expr` (a Status) once and returns it from the calling function
// unless it is ok.
#define RETURN_IF_ERROR(expr)                                  \
  do {                                                         \
    ::tpopt::Status tpopt_status_return_if_error_ = (expr);    \
    if (!tpopt_status_return_if_error_.ok()) {                 \
      return tpopt_status_return_if_error_;                    \
    }                                                          \
  } while (false)

#endif  // TPOPT_MODEL_STATUS_H_
