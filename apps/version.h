// The version tpopt reports (--version, report JSON, HTML report).
#ifndef TPOPT_APPS_VERSION_H_
#define TPOPT_APPS_VERSION_H_

namespace tpopt {

constexpr char kTpoptVersion[] = "0.1.0";

}  // namespace tpopt

#endif  // TPOPT_APPS_VERSION_H_
