#include "model/io/json_io.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "model/io/json_fields.h"
#include "model/base/units.h"

namespace tpopt {
namespace {

using nlohmann::json;

// An array of numbers at j[key].
Status NumbersAt(const json& j, const std::string& key, const std::string& what,
                 std::vector<double>* out) {
  if (!j.contains(key)) return Status::Error(what + "." + key + " must be an array");
  return JsonNumbers(j[key], what + "." + key, out);
}

// An integer at j[key].
Status IntegerAt(const json& j, const std::string& key, const std::string& what, int* out) {
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
  if (!j.contains("knots")) return Status::Error(what + ".knots must be an array");
  if (!j.contains("control_points") || !j["control_points"].is_array()) {
    return Status::Error(what + ".control_points must be an array");
  }
  std::vector<double> knots;
  RETURN_IF_ERROR(JsonNumbers(j["knots"], what + ".knots", &knots));
  std::vector<Eigen::Vector3d> points(j["control_points"].size());
  for (size_t k = 0; k < points.size(); ++k) {
    RETURN_IF_ERROR(JsonPoint(j["control_points"][k],
                              what + ".control_points[" + std::to_string(k) + "]", &points[k],
                              dimension));
  }
  return BSplineCurve::Create(j["degree"].get<int>(), std::move(knots), std::move(points), what,
                              curve);
}

// Optional number at j[key], in file units times `scale`.
Status Optional(const json& j, const std::string& key, const std::string& what, double scale,
                double* out) {
  if (!j.contains(key) || j[key].is_null()) return Status::Ok();
  double v = 0.0;
  RETURN_IF_ERROR(JsonNumber(j[key], what + "." + key, &v));
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
  RETURN_IF_ERROR(Optional(j, "min", what, scale, &l->min));
  RETURN_IF_ERROR(Optional(j, "max", what, scale, &l->max));
  RETURN_IF_ERROR(Optional(j, "max_velocity", what, scale, &l->max_velocity));
  RETURN_IF_ERROR(Optional(j, "max_acceleration", what, scale, &l->max_acceleration));
  RETURN_IF_ERROR(Optional(j, "max_jerk", what, scale, &l->max_jerk));
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

Status SurfaceFromJson(const std::string& path, const json& j, RuledSurface* surface) {
  std::string kind, units, side_name, name;
  RETURN_IF_ERROR(JsonStringOr(j, "kind", path + ": surface", "ruled", &kind));
  RETURN_IF_ERROR(JsonStringOr(j, "units", path + ": surface", "mm", &units));
  RETURN_IF_ERROR(JsonStringOr(j, "cutter_side", path + ": surface", "positive", &side_name));
  RETURN_IF_ERROR(JsonStringOr(j, "name", path + ": surface", path, &name));
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
    RETURN_IF_ERROR(Rail(j["rails"][i], path + ": rails[" + std::to_string(i) + "]", &rails[i]));
  }
  *surface = RuledSurface(name, rails[0], rails[1], side);
  return Status::Ok();
}

Status MachineFromJson(const std::string& path, const json& j, Machine* machine) {
  std::string kinematics;
  Machine m;
  RETURN_IF_ERROR(JsonStringOr(j, "kinematics", path + ": machine", "(absent)", &kinematics));
  RETURN_IF_ERROR(JsonStringOr(j, "name", path + ": machine", path, &m.name));
  if (kinematics != "xyzac-trt") {
    return Status::Error(path + ": kinematics \"" + kinematics +
                         "\" is not supported (\"xyzac-trt\")");
  }
  if (j.contains("rotary_pivot")) {
    RETURN_IF_ERROR(
        JsonPoint(j["rotary_pivot"], path + ": rotary_pivot", &m.kinematics.rotary_pivot_mm));
  }
  RETURN_IF_ERROR(Optional(j, "y_offset", path + ": machine", 1.0, &m.kinematics.y_offset_mm));
  RETURN_IF_ERROR(Optional(j, "z_offset", path + ": machine", 1.0, &m.kinematics.z_offset_mm));
  RETURN_IF_ERROR(
      Optional(j, "tool_length", path + ": machine", 1.0, &m.kinematics.tool_length_mm));
  if (j.contains("axes")) {
    if (!j["axes"].is_object()) return Status::Error(path + ": axes must be an object");
    for (const auto& [key, value] : j["axes"].items()) {
      const auto it = std::find(kAxisNames.begin(), kAxisNames.end(), key);
      if (it == kAxisNames.end()) {
        return Status::Error(path + ": axes." + key + " is not one of X, Y, Z, A, C");
      }
      const int axis = static_cast<int>(it - kAxisNames.begin());
      RETURN_IF_ERROR(AxisFromJson(value, path + ": axes." + key, axis >= kA ? kDegToRad : 1.0,
                                   &m.limits[axis]));
    }
  }
  *machine = m;
  return Status::Ok();
}

// "units" must be mm and "kind" `kind` (both optional).
Status CheckKindAndUnits(const json& j, const std::string& path, const std::string& kind) {
  std::string found_kind, units;
  RETURN_IF_ERROR(JsonStringOr(j, "kind", path + ": file", kind, &found_kind));
  RETURN_IF_ERROR(JsonStringOr(j, "units", path + ": file", "mm", &units));
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
  if (s.ok()) s = IntegerAt(j, "degree_u", path + ": surface", &degree_u);
  if (s.ok()) s = IntegerAt(j, "degree_v", path + ": surface", &degree_v);
  if (s.ok()) s = NumbersAt(j, "knots_u", path + ": surface", &knots_u);
  if (s.ok()) s = NumbersAt(j, "knots_v", path + ": surface", &knots_v);
  if (!s.ok()) return s;
  if (!j.contains("control_points")) {
    return Status::Error(path + ": surface.control_points must be an array of rows");
  }
  std::vector<std::vector<Eigen::Vector3d>> net;
  RETURN_IF_ERROR(JsonControlNet(j["control_points"], path + ": surface.control_points", &net));
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
    RETURN_IF_ERROR(NumbersAt(p, "anchor_uv", what, &uv));
    if (uv.size() != 2) return Status::Error(what + ".anchor_uv must be [u, v]");
    placement->anchor_u = uv[0];
    placement->anchor_v = uv[1];
  }
  RETURN_IF_ERROR(Optional(p, "lift_mm", what, 1.0, &placement->lift_mm));
  RETURN_IF_ERROR(Optional(p, "spin_deg", what, 1.0, &placement->spin_deg));
  std::string why;
  if (!placement->IsValid(&why)) return Status::Error(what + ": " + why);
  return Status::Ok();
}

struct GuideCurves {
  std::vector<BSplineCurve> curves;
  GuidePlacement placement;
};

Status GuideCurvesFromJson(const std::string& path, const json& j, GuideCurves* guides) {
  RETURN_IF_ERROR(CheckKindAndUnits(j, path, "planar_curves"));
  RETURN_IF_ERROR(PlacementFromJson(path, j, &guides->placement));
  if (!j.contains("curves") || !j["curves"].is_array() || j["curves"].empty()) {
    return Status::Error(path + ": curves must be a non-empty array of curves");
  }
  guides->curves.resize(j["curves"].size());
  for (size_t i = 0; i < guides->curves.size(); ++i) {
    RETURN_IF_ERROR(
        Rail(j["curves"][i], path + ": curves[" + std::to_string(i) + "]", &guides->curves[i], 2));
  }
  return Status::Ok();
}

}  // namespace

Status ReadBSplineSurfaceJson(const std::string& path, BSplineSurface* surface) {
  return ReadJsonFile(path, BSplineSurfaceFromJson, surface);
}

Status ReadGuideCurvesJson(const std::string& path, std::vector<BSplineCurve>* curves,
                           GuidePlacement* placement) {
  GuideCurves guides;
  RETURN_IF_ERROR(ReadJsonFile(path, GuideCurvesFromJson, &guides));
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
