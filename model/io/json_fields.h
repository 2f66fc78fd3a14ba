// Field readers shared by the JSON file readers: each error names the file
// (or field path given in `what`) and the value at fault.
#ifndef TPOPT_MODEL_JSON_FIELDS_H_
#define TPOPT_MODEL_JSON_FIELDS_H_

#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "model/base/status.h"

namespace tpopt {

// Parses the whole file into an object; a syntax error names its line.
Status ParseJsonFile(const std::string& path, nlohmann::json* out);

// A finite number with |v| <= 1e6; `what` names it in messages.
Status JsonNumber(const nlohmann::json& j, const std::string& what, double* out);

// [x, y, z] of such numbers, or [x, y] (z = 0) when `dimension` is 2
// (planar curves).
Status JsonPoint(const nlohmann::json& j, const std::string& what, Eigen::Vector3d* p,
                 int dimension = 3);

// A control net: an array of rows, each an array of [x, y, z].
Status JsonControlNet(const nlohmann::json& j, const std::string& what,
                      std::vector<std::vector<Eigen::Vector3d>>* net);

// An array of such numbers.
Status JsonNumbers(const nlohmann::json& j, const std::string& what, std::vector<double>* out);

// j[key] as a string, `fallback` when absent; an error when not a string.
Status JsonStringOr(const nlohmann::json& j, const std::string& key, const std::string& what,
                    const std::string& fallback, std::string* out);

// Parses `path` and converts it; any type surprise nlohmann still raises is
// turned into a status naming the file instead of escaping the library.
template <typename Value, typename Convert>
Status ReadJsonFile(const std::string& path, Convert convert, Value* value) {
  nlohmann::json j;
  RETURN_IF_ERROR(ParseJsonFile(path, &j));
  try {
    return convert(path, j, value);
  } catch (const nlohmann::json::exception& e) {
    return Status::Error(path + ": unexpected JSON content (" + e.what() + ")");
  }
}

}  // namespace tpopt

#endif  // TPOPT_MODEL_JSON_FIELDS_H_
