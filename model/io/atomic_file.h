// Whole-or-nothing file output: a file tpopt writes is either complete or
// absent, never half written.
#ifndef TPOPT_MODEL_ATOMIC_FILE_H_
#define TPOPT_MODEL_ATOMIC_FILE_H_

#include <string>

#include "model/base/status.h"

namespace tpopt {

// Writes `contents` to a temporary file beside `path`, flushes it to disk
// and renames it over `path`. On failure (missing folder, read-only folder,
// full disk) the temporary is removed, `path` is untouched and the message
// names `path` and the system's reason. A replaced file keeps its
// permission bits; a new one gets 0666 less the umask. Concurrent writers
// of one `path` each leave a whole file; the last rename wins.
Status WriteFileAtomically(const std::string& path, const std::string& contents);

}  // namespace tpopt

#endif  // TPOPT_MODEL_ATOMIC_FILE_H_
