#include "model/io/json_fields.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace tpopt {

using nlohmann::json;

// Parses the whole file; a syntax error names its line.
Status ParseJsonFile(const std::string& path, json* out) {
  std::ifstream in(path);
  if (!in) return Status::Error(path + ": cannot open file");
  std::ostringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  try {
    *out = json::parse(s);
  } catch (const json::parse_error& e) {
    const size_t byte = std::min<size_t>(e.byte, s.size());
    const long line = 1 + std::count(s.begin(), s.begin() + byte, '\n');
    return Status::Error(path + ":" + std::to_string(line) + ": malformed JSON (" + e.what() +
                         ")");
  } catch (const json::exception& e) {
    // E.g. a number too large for a double: nlohmann reports no position.
    return Status::Error(path + ": unreadable JSON (" + e.what() + ")");
  }
  if (!out->is_object()) return Status::Error(path + ": the top level must be a JSON object");
  return Status::Ok();
}

// A finite number at j[key]; `what` names it in messages.
Status JsonNumber(const json& j, const std::string& what, double* out) {
  if (!j.is_number()) return Status::Error(what + " must be a number, got " + j.dump());
  *out = j.get<double>();
  // Geometry beyond a kilometre is a corrupt file, and squaring 1e308
  // overflows every distance computed from it.
  if (!std::isfinite(*out) || std::abs(*out) > 1e6) {
    return Status::Error(what + " = " + j.dump() + " is out of range (|v| <= 1e6)");
  }
  return Status::Ok();
}

Status JsonPoint(const json& j, const std::string& what, Eigen::Vector3d* p, int dimension) {
  if (!j.is_array() || static_cast<int>(j.size()) != dimension) {
    return Status::Error(what + " must be " + (dimension == 3 ? "[x, y, z]" : "[x, y]") +
                         ", got " + j.dump());
  }
  p->setZero();
  for (int k = 0; k < dimension; ++k) {
    RETURN_IF_ERROR(JsonNumber(j[k], what + "[" + std::to_string(k) + "]", &(*p)[k]));
  }
  return Status::Ok();
}

Status JsonControlNet(const json& j, const std::string& what,
                      std::vector<std::vector<Eigen::Vector3d>>* net) {
  if (!j.is_array()) return Status::Error(what + " must be an array of rows of [x, y, z]");
  net->resize(j.size());
  for (size_t i = 0; i < j.size(); ++i) {
    const std::string row = what + "[" + std::to_string(i) + "]";
    if (!j[i].is_array()) return Status::Error(row + " must be an array of [x, y, z]");
    (*net)[i].resize(j[i].size());
    for (size_t k = 0; k < j[i].size(); ++k) {
      RETURN_IF_ERROR(JsonPoint(j[i][k], row + "[" + std::to_string(k) + "]", &(*net)[i][k]));
    }
  }
  return Status::Ok();
}

Status JsonNumbers(const json& j, const std::string& what, std::vector<double>* out) {
  if (!j.is_array()) return Status::Error(what + " must be an array of numbers");
  out->resize(j.size());
  for (size_t k = 0; k < out->size(); ++k) {
    RETURN_IF_ERROR(JsonNumber(j[k], what + "[" + std::to_string(k) + "]", &(*out)[k]));
  }
  return Status::Ok();
}

// j[key] as a string, `fallback` when absent; an error when not a string.
Status JsonStringOr(const json& j, const std::string& key, const std::string& what,
                const std::string& fallback, std::string* out) {
  if (!j.contains(key)) {
    *out = fallback;
    return Status::Ok();
  }
  if (!j[key].is_string()) return Status::Error(what + "." + key + " must be a string, got " + j[key].dump());
  *out = j[key].get<std::string>();
  return Status::Ok();
}

}  // namespace tpopt
