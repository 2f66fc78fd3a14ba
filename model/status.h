// A returned status for user-facing failures. The library throws no
// exceptions and CHECKs only programmer errors; anything that can go wrong
// because of a file or a flag comes back as a Status whose message names the
// file, the line or pose index, and the offending value.
#ifndef TPOPT_MODEL_STATUS_H_
#define TPOPT_MODEL_STATUS_H_

#include <string>
#include <utility>

namespace tpopt {

class Status {
 public:
  static Status Ok() { return Status(); }
  static Status Error(std::string message) {
    Status s;
    s.ok_ = false;
    s.message_ = std::move(message);
    return s;
  }

  bool ok() const { return ok_; }
  const std::string& message() const { return message_; }

 private:
  bool ok_ = true;
  std::string message_;
};

}  // namespace tpopt

#endif  // TPOPT_MODEL_STATUS_H_
