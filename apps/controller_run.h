// What LinuxCNC's controller did with a program: the summary JSON that
// benchmarks/linuxcnc/run.sh writes (analyze.py), read back so that the
// report and the HTML report show it beside tpopt's prediction
// (`--cnc_summary`).
#ifndef TPOPT_APPS_CONTROLLER_RUN_H_
#define TPOPT_APPS_CONTROLLER_RUN_H_

#include <string>

#include <nlohmann/json.hpp>

#include "model/base/status.h"

namespace tpopt {

struct ControllerRun {
  std::string program;  // as the harness names it
  bool completed = false;
  double cycle_time_s = 0.0;
  int stops_in_cuts = 0;
  int limits_exceeded = 0;  // entries of limit_excess
  // Over the cuts, deg/s^2 and deg/s^3: [0] A, [1] C.
  double peak_acceleration[2] = {0, 0}, p99_acceleration[2] = {0, 0};
  double peak_jerk[2] = {0, 0}, p99_jerk[2] = {0, 0};
};

// Reads a harness summary; errors name the file and the field.
Status ReadControllerRun(const std::string& path, ControllerRun* run);

// The report's `controller` object: the run's figures and tpopt's
// `predicted_time_s` for the same program.
nlohmann::json ControllerRunJson(const ControllerRun& run, double predicted_time_s);

// The HTML report's section: a table of the same.
std::string ControllerRunHtml(const ControllerRun& run, double predicted_time_s);

}  // namespace tpopt

#endif  // TPOPT_APPS_CONTROLLER_RUN_H_
