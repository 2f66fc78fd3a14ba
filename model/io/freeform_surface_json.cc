#include "model/io/freeform_surface_json.h"

#include <string>
#include <vector>

#include "model/io/json_fields.h"

namespace tpopt {
namespace {

using nlohmann::json;

Status Degree(const json& j, const std::string& key, const std::string& what) {
  if (!j.contains(key)) return Status::Ok();  // bicubic is the only kind
  if (!j[key].is_number_integer() || j[key].get<int>() != 3) {
    return Status::Error(what + "." + key + " = " + j[key].dump() +
                         ": only bicubic (3) surfaces are supported");
  }
  return Status::Ok();
}

Status FreeformFromJson(const std::string& path, const json& j, FreeformSurface* surface) {
  const std::string what = path + ": surface";
  std::string kind, units, side, name;
  RETURN_IF_ERROR(JsonStringOr(j, "kind", what, "(absent)", &kind));
  RETURN_IF_ERROR(JsonStringOr(j, "units", what, "mm", &units));
  RETURN_IF_ERROR(JsonStringOr(j, "cutter_side", what, "positive", &side));
  RETURN_IF_ERROR(JsonStringOr(j, "name", what, path, &name));
  if (kind != "bspline_surface") {
    return Status::Error(path + ": kind \"" + kind + "\" is not \"bspline_surface\"");
  }
  if (units != "mm") return Status::Error(path + ": units \"" + units + "\" are not \"mm\"");
  if (side != "positive" && side != "negative") {
    return Status::Error(path + ": cutter_side \"" + side +
                         "\" must be \"positive\" or \"negative\"");
  }
  for (const char* key : {"knots_u", "knots_v", "control_points"}) {
    if (!j.contains(key)) return Status::Error(path + ": missing field \"" + key + "\"");
  }
  std::vector<double> knots_u, knots_v;
  std::vector<std::vector<Eigen::Vector3d>> net;
  RETURN_IF_ERROR(Degree(j, "degree_u", path));
  RETURN_IF_ERROR(Degree(j, "degree_v", path));
  RETURN_IF_ERROR(JsonNumbers(j["knots_u"], path + ": knots_u", &knots_u));
  RETURN_IF_ERROR(JsonNumbers(j["knots_v"], path + ": knots_v", &knots_v));
  RETURN_IF_ERROR(JsonControlNet(j["control_points"], path + ": control_points", &net));
  return FreeformSurface::Create(name, std::move(knots_u), std::move(knots_v), net,
                                 side == "negative" ? -1.0 : 1.0, path, surface);
}

}  // namespace

Status ReadFreeformSurfaceJson(const std::string& path, FreeformSurface* surface) {
  return ReadJsonFile(path, FreeformFromJson, surface);
}

}  // namespace tpopt
