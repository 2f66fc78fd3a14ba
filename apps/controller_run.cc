#include "apps/controller_run.h"

#include <cmath>
#include <cstdio>
#include <tuple>

#include "model/io/json_fields.h"

namespace tpopt {
namespace {

constexpr const char* kRotaries[2] = {"A", "C"};

Status Number(const nlohmann::json& j, const std::string& path, const std::string& key,
              double* out) {
  if (!j.contains(key)) return Status::Error(path + ": " + key + " is missing");
  if (!j[key].is_number() || !std::isfinite(j[key].get<double>())) {
    return Status::Error(path + ": " + key + " must be a number, got " + j[key].dump());
  }
  *out = j[key].get<double>();
  return Status::Ok();
}

Status FromJson(const std::string& path, const nlohmann::json& j, ControllerRun* run) {
  ControllerRun r;
  RETURN_IF_ERROR(JsonStringOr(j, "program", path, "", &r.program));
  if (!j.contains("completed") || !j["completed"].is_boolean()) {
    return Status::Error(path + ": completed (true or false) is missing");
  }
  r.completed = j["completed"].get<bool>();
  if (!r.completed) {
    *run = r;
    return Status::Ok();
  }
  double stops = 0;
  RETURN_IF_ERROR(Number(j, path, "cycle_time_s", &r.cycle_time_s));
  RETURN_IF_ERROR(Number(j, path, "stops_in_cuts", &stops));
  r.stops_in_cuts = static_cast<int>(stops);
  if (j.contains("limit_excess") && j["limit_excess"].is_array()) {
    r.limits_exceeded = static_cast<int>(j["limit_excess"].size());
  }
  for (int k = 0; k < 2; ++k) {
    const std::string where = std::string("joints.") + kRotaries[k] + ".cuts";
    if (!j.contains("joints") || !j["joints"].contains(kRotaries[k]) ||
        !j["joints"][kRotaries[k]].contains("cuts")) {
      return Status::Error(path + ": " + where + " is missing");
    }
    const nlohmann::json& cuts = j["joints"][kRotaries[k]]["cuts"];
    for (const auto& [quantity, peak, p99] :
         {std::tuple<const char*, double*, double*>{"acceleration", &r.peak_acceleration[k],
                                                    &r.p99_acceleration[k]},
          {"jerk", &r.peak_jerk[k], &r.p99_jerk[k]}}) {
      if (!cuts.contains(quantity)) {
        return Status::Error(path + ": " + where + "." + quantity + " is missing");
      }
      RETURN_IF_ERROR(Number(cuts[quantity], path + ": " + where + "." + quantity, "peak", peak));
      RETURN_IF_ERROR(Number(cuts[quantity], path + ": " + where + "." + quantity, "p99", p99));
    }
  }
  *run = r;
  return Status::Ok();
}

std::string Fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", digits, v);
  return buf;
}

}  // namespace

Status ReadControllerRun(const std::string& path, ControllerRun* run) {
  return ReadJsonFile(path, FromJson, run);
}

nlohmann::json ControllerRunJson(const ControllerRun& run, double predicted_time_s) {
  nlohmann::json j = {{"program", run.program},
                      {"completed", run.completed},
                      {"predicted_time_s", predicted_time_s}};
  if (!run.completed) return j;
  j["cycle_time_s"] = run.cycle_time_s;
  j["stops_in_cuts"] = run.stops_in_cuts;
  j["limits_exceeded"] = run.limits_exceeded;
  for (int k = 0; k < 2; ++k) {
    j[kRotaries[k]] = {{"peak_acceleration", run.peak_acceleration[k]},
                       {"p99_acceleration", run.p99_acceleration[k]},
                       {"peak_jerk", run.peak_jerk[k]},
                       {"p99_jerk", run.p99_jerk[k]}};
  }
  return j;
}

std::string ControllerRunHtml(const ControllerRun& run, double predicted_time_s) {
  std::string out =
      "<h2>On LinuxCNC's controller</h2>\n<table class=\"controller\">\n"
      "<tr><td>tpopt's predicted time, s</td><td>" +
      Fixed(predicted_time_s, 1) + "</td></tr>\n";
  if (!run.completed) return out + "<tr><td>completed</td><td>no</td></tr>\n</table>\n";
  out += "<tr><td>cycle time on the controller, s</td><td>" + Fixed(run.cycle_time_s, 1) +
         "</td></tr>\n<tr><td>stops in cuts</td><td>" + std::to_string(run.stops_in_cuts) +
         "</td></tr>\n<tr><td>joint limits exceeded</td><td>" +
         std::to_string(run.limits_exceeded) + "</td></tr>\n";
  for (int k = 0; k < 2; ++k) {
    const std::string axis = kRotaries[k];
    out += "<tr><td>peak / p99 " + axis + " acceleration in cuts, deg/s^2</td><td>" +
           Fixed(run.peak_acceleration[k], 0) + " / " + Fixed(run.p99_acceleration[k], 0) +
           "</td></tr>\n<tr><td>peak / p99 " + axis + " jerk in cuts, deg/s^3</td><td>" +
           Fixed(run.peak_jerk[k], 0) + " / " + Fixed(run.p99_jerk[k], 0) + "</td></tr>\n";
  }
  return out + "</table>\n";
}

}  // namespace tpopt
