#include "model/json_io.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

namespace tpopt {
namespace {

using nlohmann::json;

constexpr double kDegToRad = M_PI / 180.0;

// Parses the whole file; a syntax error names its line.
Status ParseFile(const std::string& path, json* out) {
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
Status Number(const json& j, const std::string& what, double* out) {
  if (!j.is_number()) return Status::Error(what + " must be a number, got " + j.dump());
  *out = j.get<double>();
  // Geometry beyond a kilometre is a corrupt file, and squaring 1e308
  // overflows every distance computed from it.
  if (!std::isfinite(*out) || std::abs(*out) > 1e6) {
    return Status::Error(what + " = " + j.dump() + " is out of range (|v| <= 1e6)");
  }
  return Status::Ok();
}

// [x, y, z], or [x, y] (z = 0) for a planar curve when `dimension` is 2.
Status Point(const json& j, const std::string& what, Eigen::Vector3d* p, int dimension = 3) {
  if (!j.is_array() || static_cast<int>(j.size()) != dimension) {
    return Status::Error(what + " must be " + (dimension == 3 ? "[x, y, z]" : "[x, y]") +
                         ", got " + j.dump());
  }
  p->setZero();
  for (int k = 0; k < dimension; ++k) {
    Status s = Number(j[k], what + "[" + std::to_string(k) + "]", &(*p)[k]);
    if (!s.ok()) return s;
  }
  return Status::Ok();
}

// An array of numbers at j[key].
Status Numbers(const json& j, const std::string& key, const std::string& what,
               std::vector<double>* out) {
  if (!j.contains(key) || !j[key].is_array()) {
    return Status::Error(what + "." + key + " must be an array");
  }
  out->resize(j[key].size());
  for (size_t k = 0; k < out->size(); ++k) {
    Status s = Number(j[key][k], what + "." + key + "[" + std::to_string(k) + "]", &(*out)[k]);
    if (!s.ok()) return s;
  }
  return Status::Ok();
}

// An integer at j[key].
Status Integer(const json& j, const std::string& key, const std::string& what, int* out) {
  if (!j.contains(key) || !j[key].is_number_integer()) {
    return Status::Error(what + "." + key + " must be an integer");
  }
  *out = j[key].get<int>();
  return Status::Ok();
}

Status Rail(const json& j, const std::string& what, BSplineCurve* curve, int dimension = 3) {
  if (!j.is_object()) return Status::Error(what + " must be an object");
  if (!j.contains("degree") || !j["degree"].is_number_integer()) {
    return Status::Error(what + ".degree must be an integer");
  }
  if (!j.contains("knots") || !j["knots"].is_array()) {
    return Status::Error(what + ".knots must be an array");
  }
  if (!j.contains("control_points") || !j["control_points"].is_array()) {
    return Status::Error(what + ".control_points must be an array");
  }
  std::vector<double> knots;
  Status s = Numbers(j, "knots", what, &knots);
  if (!s.ok()) return s;
  std::vector<Eigen::Vector3d> points(j["control_points"].size());
  for (size_t k = 0; k < points.size(); ++k) {
    s = Point(j["control_points"][k], what + ".control_points[" + std::to_string(k) + "]",
              &points[k], dimension);
    if (!s.ok()) return s;
  }
  return BSplineCurve::Create(j["degree"].get<int>(), std::move(knots), std::move(points), what,
                              curve);
}

// Optional number at j[key], in file units times `scale`.
Status Optional(const json& j, const std::string& key, const std::string& what, double scale,
                double* out) {
  if (!j.contains(key) || j[key].is_null()) return Status::Ok();
  double v = 0.0;
  Status s = Number(j[key], what + "." + key, &v);
  if (!s.ok()) return s;
  *out = v * scale;
  return Status::Ok();
}

Status AxisFromJson(const json& j, const std::string& what, double scale, AxisLimits* l) {
  if (!j.is_object()) return Status::Error(what + " must be an object");
  for (const auto& [key, value] : j.items()) {
    static const char* kKeys[] = {"min", "max", "max_velocity", "max_acceleration", "max_jerk"};
    if (std::find(std::begin(kKeys), std::end(kKeys), key) == std::end(kKeys)) {
      return Status::Error(what + ": unknown key '" + key + "'");
    }
  }
  Status s = Optional(j, "min", what, scale, &l->min);
  if (s.ok()) s = Optional(j, "max", what, scale, &l->max);
  if (s.ok()) s = Optional(j, "max_velocity", what, scale, &l->max_velocity);
  if (s.ok()) s = Optional(j, "max_acceleration", what, scale, &l->max_acceleration);
  if (s.ok()) s = Optional(j, "max_jerk", what, scale, &l->max_jerk);
  if (!s.ok()) return s;
  if (l->min > l->max) {
    std::ostringstream err;
    err << what << ": min " << l->min / scale << " is above max " << l->max / scale;
    return Status::Error(err.str());
  }
  for (double v : {l->max_velocity, l->max_acceleration, l->max_jerk}) {
    if (!(v > 0)) {
      std::ostringstream err;
      err << what << ": velocity, acceleration and jerk limits must be > 0, got " << v / scale;
      return Status::Error(err.str());
    }
  }
  return Status::Ok();
}

// j[key] as a string, `fallback` when absent; an error when not a string.
Status StringOr(const json& j, const std::string& key, const std::string& what,
                const std::string& fallback, std::string* out) {
  if (!j.contains(key)) {
    *out = fallback;
    return Status::Ok();
  }
  if (!j[key].is_string()) return Status::Error(what + "." + key + " must be a string, got " + j[key].dump());
  *out = j[key].get<std::string>();
  return Status::Ok();
}

Status SurfaceFromJson(const std::string& path, const json& j, RuledSurface* surface) {
  std::string kind, units, side_name, name;
  Status s = StringOr(j, "kind", path + ": surface", "ruled", &kind);
  if (s.ok()) s = StringOr(j, "units", path + ": surface", "mm", &units);
  if (s.ok()) s = StringOr(j, "cutter_side", path + ": surface", "positive", &side_name);
  if (s.ok()) s = StringOr(j, "name", path + ": surface", path, &name);
  if (!s.ok()) return s;
  if (kind != "ruled") {
    return Status::Error(path + ": kind \"" + kind + "\" is not supported (\"ruled\")");
  }
  if (units != "mm") {
    return Status::Error(path + ": units \"" + units + "\" are not supported (\"mm\")");
  }
  if (side_name != "positive" && side_name != "negative") {
    return Status::Error(path + ": cutter_side \"" + side_name +
                         "\" must be \"positive\" or \"negative\"");
  }
  const CutterSide side = side_name == "negative" ? CutterSide::kNegative : CutterSide::kPositive;
  if (!j.contains("rails") || !j["rails"].is_array() || j["rails"].size() != 2) {
    return Status::Error(path + ": rails must be an array of exactly two curves");
  }
  BSplineCurve rails[2];
  for (int i = 0; i < 2; ++i) {
    s = Rail(j["rails"][i], path + ": rails[" + std::to_string(i) + "]", &rails[i]);
    if (!s.ok()) return s;
  }
  *surface = RuledSurface(name, rails[0], rails[1], side);
  return Status::Ok();
}

Status MachineFromJson(const std::string& path, const json& j, Machine* machine) {
  std::string kinematics;
  Machine m;
  Status s = StringOr(j, "kinematics", path + ": machine", "(absent)", &kinematics);
  if (s.ok()) s = StringOr(j, "name", path + ": machine", path, &m.name);
  if (!s.ok()) return s;
  if (kinematics != "xyzac-trt") {
    return Status::Error(path + ": kinematics \"" + kinematics +
                         "\" is not supported (\"xyzac-trt\")");
  }
  if (j.contains("rotary_pivot")) {
    s = Point(j["rotary_pivot"], path + ": rotary_pivot", &m.kinematics.rotary_pivot_mm);
    if (!s.ok()) return s;
  }
  s = Optional(j, "y_offset", path + ": machine", 1.0, &m.kinematics.y_offset_mm);
  if (s.ok()) s = Optional(j, "z_offset", path + ": machine", 1.0, &m.kinematics.z_offset_mm);
  if (s.ok()) s = Optional(j, "tool_length", path + ": machine", 1.0, &m.kinematics.tool_length_mm);
  if (!s.ok()) return s;
  if (j.contains("axes")) {
    if (!j["axes"].is_object()) return Status::Error(path + ": axes must be an object");
    for (const auto& [key, value] : j["axes"].items()) {
      const auto it = std::find(kAxisNames.begin(), kAxisNames.end(), key);
      if (it == kAxisNames.end()) {
        return Status::Error(path + ": axes." + key + " is not one of X, Y, Z, A, C");
      }
      const int axis = static_cast<int>(it - kAxisNames.begin());
      s = AxisFromJson(value, path + ": axes." + key, axis >= kA ? kDegToRad : 1.0,
                       &m.limits[axis]);
      if (!s.ok()) return s;
    }
  }
  *machine = m;
  return Status::Ok();
}

// "units" must be mm and "kind" `kind` (both optional).
Status CheckKindAndUnits(const json& j, const std::string& path, const std::string& kind) {
  std::string found_kind, units;
  Status s = StringOr(j, "kind", path + ": file", kind, &found_kind);
  if (s.ok()) s = StringOr(j, "units", path + ": file", "mm", &units);
  if (!s.ok()) return s;
  if (found_kind != kind) {
    return Status::Error(path + ": kind \"" + found_kind + "\" is not supported (\"" + kind +
                         "\")");
  }
  if (units != "mm") {
    return Status::Error(path + ": units \"" + units + "\" are not supported (\"mm\")");
  }
  return Status::Ok();
}

Status BSplineSurfaceFromJson(const std::string& path, const json& j, BSplineSurface* surface) {
  Status s = CheckKindAndUnits(j, path, "bspline_surface");
  int degree_u = 0, degree_v = 0;
  std::vector<double> knots_u, knots_v;
  if (s.ok()) s = Integer(j, "degree_u", path + ": surface", &degree_u);
  if (s.ok()) s = Integer(j, "degree_v", path + ": surface", &degree_v);
  if (s.ok()) s = Numbers(j, "knots_u", path + ": surface", &knots_u);
  if (s.ok()) s = Numbers(j, "knots_v", path + ": surface", &knots_v);
  if (!s.ok()) return s;
  if (!j.contains("control_points") || !j["control_points"].is_array()) {
    return Status::Error(path + ": surface.control_points must be an array of rows");
  }
  const json& rows = j["control_points"];
  std::vector<std::vector<Eigen::Vector3d>> net(rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    const std::string row = path + ": surface.control_points[" + std::to_string(i) + "]";
    if (!rows[i].is_array()) return Status::Error(row + " must be an array of points");
    net[i].resize(rows[i].size());
    for (size_t k = 0; k < net[i].size(); ++k) {
      s = Point(rows[i][k], row + "[" + std::to_string(k) + "]", &net[i][k]);
      if (!s.ok()) return s;
    }
  }
  return BSplineSurface::Create(degree_u, degree_v, std::move(knots_u), std::move(knots_v),
                                std::move(net), path + ": surface", surface);
}

Status PlacementFromJson(const std::string& path, const json& j, GuidePlacement* placement) {
  if (!j.contains("placement")) return Status::Ok();
  const json& p = j["placement"];
  const std::string what = path + ": placement";
  if (!p.is_object()) return Status::Error(what + " must be an object");
  for (const auto& [key, value] : p.items()) {
    if (key != "anchor_uv" && key != "lift_mm" && key != "spin_deg") {
      return Status::Error(what + ": unknown key '" + key + "'");
    }
  }
  Status s;
  if (p.contains("anchor_uv")) {
    std::vector<double> uv;
    s = Numbers(p, "anchor_uv", what, &uv);
    if (s.ok() && uv.size() != 2) s = Status::Error(what + ".anchor_uv must be [u, v]");
    if (!s.ok()) return s;
    placement->anchor_u = uv[0];
    placement->anchor_v = uv[1];
  }
  s = Optional(p, "lift_mm", what, 1.0, &placement->lift_mm);
  if (s.ok()) s = Optional(p, "spin_deg", what, 1.0, &placement->spin_deg);
  if (!s.ok()) return s;
  std::string why;
  if (!placement->IsValid(&why)) return Status::Error(what + ": " + why);
  return Status::Ok();
}

struct GuideCurves {
  std::vector<BSplineCurve> curves;
  GuidePlacement placement;
};

Status GuideCurvesFromJson(const std::string& path, const json& j, GuideCurves* guides) {
  Status s = CheckKindAndUnits(j, path, "planar_curves");
  if (s.ok()) s = PlacementFromJson(path, j, &guides->placement);
  if (!s.ok()) return s;
  if (!j.contains("curves") || !j["curves"].is_array() || j["curves"].empty()) {
    return Status::Error(path + ": curves must be a non-empty array of curves");
  }
  guides->curves.resize(j["curves"].size());
  for (size_t i = 0; i < guides->curves.size(); ++i) {
    s = Rail(j["curves"][i], path + ": curves[" + std::to_string(i) + "]", &guides->curves[i], 2);
    if (!s.ok()) return s;
  }
  return Status::Ok();
}

// Parses and converts; any type surprise nlohmann still raises is turned
// into a status naming the file instead of escaping the library.
template <typename Value, typename Convert>
Status ReadJsonFile(const std::string& path, Convert convert, Value* value) {
  json j;
  Status s = ParseFile(path, &j);
  if (!s.ok()) return s;
  try {
    return convert(path, j, value);
  } catch (const json::exception& e) {
    return Status::Error(path + ": unexpected JSON content (" + e.what() + ")");
  }
}

}  // namespace

Status ReadBSplineSurfaceJson(const std::string& path, BSplineSurface* surface) {
  return ReadJsonFile(path, BSplineSurfaceFromJson, surface);
}

Status ReadGuideCurvesJson(const std::string& path, std::vector<BSplineCurve>* curves,
                           GuidePlacement* placement) {
  GuideCurves guides;
  Status s = ReadJsonFile(path, GuideCurvesFromJson, &guides);
  if (!s.ok()) return s;
  *curves = std::move(guides.curves);
  *placement = guides.placement;
  return Status::Ok();
}

Status ReadSurfaceJson(const std::string& path, RuledSurface* surface) {
  return ReadJsonFile(path, SurfaceFromJson, surface);
}

Status ReadMachineJson(const std::string& path, Machine* machine) {
  return ReadJsonFile(path, MachineFromJson, machine);
}

}  // namespace tpopt
