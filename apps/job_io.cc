#include "apps/job_io.h"

#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <utility>
#include <vector>

#include "apps/flags.h"
#include "model/io/apt_io.h"
#include "model/io/gcode_io.h"
#include "model/io/json_io.h"
#include "model/io/linuxcnc_ini.h"
#include "model/io/linuxcnc_tool_table.h"
#include "model/path/part_setup.h"
#include "model/path/program_frame.h"
#include "model/path/standing_moves.h"
#include "model/io/freeform_surface_json.h"

namespace tpopt {
namespace {

std::string Extension(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  const size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  return ext;
}

double LongestRulingMm(const RuledSurface& surface) {
  double longest = 0.0;
  for (int i = 0; i <= 100; ++i) longest = std::max(longest, surface.Dv(i / 100.0).norm());
  return longest;
}

// The flute length of a cutter that no program or flag gives one.
double DefaultFluteLengthMm(const RuledSurface* surface) {
  return surface != nullptr ? 1.25 * LongestRulingMm(*surface) : 100.0;
}

bool IsApt(const std::string& ext) { return ext == "cls" || ext == "apt" || ext == "cl"; }
bool IsGcode(const std::string& ext) { return ext == "ngc" || ext == "nc"; }

Status UnknownFormat(const std::string& path, const std::string& ext) {
  return Status::Error(path + ": unknown tool-path format '." + ext +
                       "' (expected .cls, .apt, .cl, .ngc or .nc)");
}

GcodeStyle StyleOf(const std::string& flag) {
  return flag == "joint" ? GcodeStyle::kJoint : GcodeStyle::kTcp;
}

CadReadOptions CadOptionsFromFlags() {
  CadReadOptions options;
  options.face_index = FLAGS_face;
  options.ruling = FLAGS_ruling;
  options.flip_cutter_side = FLAGS_flip_cutter_side;
  options.max_ruled_deviation_mm = FLAGS_max_ruled_deviation_mm;
  return options;
}

}  // namespace

Status LoadRuledSurface(const std::string& path, RuledSurface* surface,
                        std::optional<CadSurfaceInfo>* cad) {
  if (!IsCadSurfacePath(path)) return ReadSurfaceJson(path, surface);
  CadSurfaceInfo info;
  Status s = ReadCadRuledSurface(path, CadOptionsFromFlags(), surface, &info);
  if (s.ok() && cad != nullptr) *cad = info;
  return s;
}

Status LoadBSplineSurface(const std::string& path, BSplineSurface* surface,
                          std::optional<CadSurfaceInfo>* cad) {
  if (!IsCadSurfacePath(path)) return ReadBSplineSurfaceJson(path, surface);
  CadSurfaceInfo info;
  double side_sign = 1.0;
  Status s = ReadCadBSplineSurface(path, CadOptionsFromFlags(), surface, &side_sign, &info);
  if (s.ok() && cad != nullptr) *cad = info;
  return s;
}

Status LoadFreeformSurface(const std::string& path, FreeformSurface* surface,
                           std::optional<CadSurfaceInfo>* cad) {
  if (!IsCadSurfacePath(path)) return ReadFreeformSurfaceJson(path, surface);
  CadSurfaceInfo info;
  BSplineSurface bspline;
  double side_sign = 1.0;
  RETURN_IF_ERROR(ReadCadBSplineSurface(path, CadOptionsFromFlags(), &bspline, &side_sign, &info));
  const std::string what = path + ": face " + std::to_string(info.face.index);
  if (bspline.degree_u() != 3 || bspline.degree_v() != 3) {
    return Status::Error(what + ": degree " + std::to_string(bspline.degree_u()) + " x " +
                         std::to_string(bspline.degree_v()) + ", stripwidth needs bicubic");
  }
  const size_t slash = path.find_last_of('/');
  const std::string name = path.substr(slash == std::string::npos ? 0 : slash + 1) + " face " +
                           std::to_string(info.face.index);
  Status s = FreeformSurface::Create(name, bspline.knots_u(), bspline.knots_v(),
                                     PatchOf(bspline).poles, side_sign, what, surface);
  if (s.ok() && cad != nullptr) *cad = info;
  return s;
}

nlohmann::json CadInfoJson(const CadSurfaceInfo& info) {
  nlohmann::json j = {{"file", info.file},
                      {"length_unit", info.length_unit},
                      {"faces_in_file", info.face_count},
                      {"face", info.face.index},
                      {"surface_type", info.face.surface_type},
                      {"degree", {info.face.degree_u, info.face.degree_v}},
                      {"poles", {info.face.poles_u, info.face.poles_v}},
                      {"trimmed", info.trimmed},
                      {"face_reversed", info.face_reversed}};
  if (!info.ruling.empty()) {
    j["ruling"] = info.ruling;
    j["exact_ruled"] = info.exact_ruled;
    j["ruled_deviation_mm"] = info.ruled_deviation_mm;
  }
  return j;
}

Status LoadToolPath(const std::string& path, const Machine& machine, bool quiet,
                    ToolPath* tool_path) {
  const std::string ext = Extension(path);
  std::vector<std::string> warnings;
  Status s;
  if (IsApt(ext)) {
    s = ReadApt(path, tool_path, &warnings);
  } else if (IsGcode(ext)) {
    s = ReadGcode(path, machine, StyleOf(FLAGS_gcode_in_style), tool_path, &warnings);
  } else {
    return UnknownFormat(path, ext);
  }
  if (!quiet) {
    for (const std::string& w : warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  }
  return s;
}

Status SaveToolPath(const std::string& path, const Machine& machine, const ToolPath& tool_path,
                    const std::vector<AptCurveSpan>& spans, const ToolPath* source) {
  const std::string ext = Extension(path);
  if (IsApt(ext)) {
    PartSetup setup;
    RETURN_IF_ERROR(PartSetupFromFlag(&setup));
    const bool program = source != nullptr && tool_path.program != nullptr &&
                         tool_path.program->format == ProgramFormat::kApt;
    if (setup.IsIdentity()) {
      return program ? WriteAptProgram(path, *source, tool_path, spans)
                     : WriteApt(path, tool_path, spans);
    }
    // Back into the program's own frame: the output, and the source its
    // kept moves are compared with.
    ToolPath out = tool_path;
    UnplacePart(setup, &out);
    std::vector<AptCurveSpan> out_spans = spans;
    for (AptCurveSpan& span : out_spans) {
      for (Eigen::Vector3d& q : span.bezier) q = UnplacePoint(setup, q);
    }
    if (!program) return WriteApt(path, out, out_spans);
    ToolPath in = *source;
    UnplacePart(setup, &in);
    return WriteAptProgram(path, in, out, out_spans);
  }
  if (!IsGcode(ext)) return UnknownFormat(path, ext);
  GcodeOptions options;
  options.style = StyleOf(FLAGS_gcode_style);
  options.inverse_time = FLAGS_gcode_inverse_time;
  options.preamble = FLAGS_gcode_preamble;
  options.postamble = FLAGS_gcode_postamble;
  options.default_feed_mm_per_min = FLAGS_feed;
  if (source != nullptr && tool_path.program != nullptr &&
      tool_path.program->format == ProgramFormat::kGcode) {
    return WriteGcodeProgram(path, *source, tool_path, machine, options);
  }
  return WriteGcode(path, tool_path, machine, options);
}

Status InterpolationFromFlags(const std::string& path, const std::string& gcode_style,
                              Interpolation* interpolation) {
  if (FLAGS_interpolation.empty()) {
    const bool joint_gcode = IsGcode(Extension(path)) && StyleOf(gcode_style) == GcodeStyle::kJoint;
    *interpolation = joint_gcode ? Interpolation::kJoint : Interpolation::kTcp;
    return Status::Ok();
  }
  if (ParseInterpolation(FLAGS_interpolation, interpolation)) return Status::Ok();
  return Status::Usage("--interpolation=" + FLAGS_interpolation + " must be tcp or joint");
}

Status PartSetupFromFlag(PartSetup* setup) {
  *setup = PartSetup();
  if (FLAGS_part_setup.empty()) return Status::Ok();
  return ParsePartSetup(FLAGS_part_setup, setup);
}

Status CheckPartSetupFlag() {
  PartSetup setup;
  const Status s = PartSetupFromFlag(&setup);
  return s.ok() ? s : Status::Usage(s.message());
}

Status LoadMachine(const std::string& path, Machine* machine) {
  if (path.empty()) {
    *machine = Machine();
    machine->name = "ideal A/C table at the origin, no limits";
    return Status::Ok();
  }
  if (IsLinuxCncIni(path)) return ReadLinuxCncIni(path, machine);
  return ReadMachineJson(path, machine);
}

namespace {

// The first tool that cuts (a feed move with a sized tool) and the first
// after it of another size (diameter or flute length), or null.
std::pair<const ToolRecord*, const ToolRecord*> DifferingTools(const ToolPath& path) {
  const ToolRecord* first = nullptr;
  for (const ToolPose& p : path.poses) {
    if (p.rapid || p.tool < 0 || !path.tools[p.tool].cutter) continue;
    const ToolRecord& t = path.tools[p.tool];
    if (first == nullptr) first = &t;
    if (t.cutter->radius_mm != first->cutter->radius_mm ||
        t.cutter->flute_length_mm != first->cutter->flute_length_mm) {
      return {first, &t};
    }
  }
  return {first, nullptr};
}

}  // namespace

Status ResolveCutter(const ToolPath& path, const RuledSurface* surface, double radius_flag_mm,
                     double flute_flag_mm, Cutter* cutter) {
  Cutter c;
  const bool have_file = path.cutter.has_value();
  if (have_file) c = *path.cutter;
  if (radius_flag_mm != 0.0) {
    c.radius_mm = radius_flag_mm;
  } else if (!have_file) {
    return Status::Error("the path names no cutter (TLDATA/CUTTER): give --cutter_radius");
  }
  if (flute_flag_mm != 0.0) {
    c.flute_length_mm = flute_flag_mm;
  } else if (!have_file) {
    c.flute_length_mm = DefaultFluteLengthMm(surface);
  }
  RETURN_IF_ERROR(c.Validate("cutter"));
  *cutter = c;
  return Status::Ok();
}

namespace {

// The surface, in the CAD model's frame, brought into the frame the path's
// poses are in: an APT program's own (its MSYS, model/path/program_frame.h),
// then placed on the table as the program is (--part_setup).
Status SurfaceIntoPathFrame(const ToolPath& path, const PartSetup& setup, RuledSurface* surface) {
  ProgramFrame frame;
  if (path.program != nullptr && path.program->format == ProgramFormat::kApt) {
    RETURN_IF_ERROR(ReadProgramFrame(*path.program, &frame));
  }
  if (frame.IsIdentity() && setup.IsIdentity()) return Status::Ok();
  // q_w = R_setup (R_frame^T (q - origin)) + t_setup.
  const Eigen::Matrix3d into_program = frame.rotation.transpose();
  const Eigen::Matrix3d r = setup.Rotation() * into_program;
  const Eigen::Vector3d t =
      setup.translation_mm - setup.Rotation() * (into_program * frame.origin_mm);
  RuledSurface moved;
  Status s = MoveRuledSurface(*surface, r, t, &moved);
  if (s.ok()) *surface = std::move(moved);
  return s;
}

// Sizes a G-code program's tools from --tool_table, or from the tool table
// a --machine INI names; the flute length is --flute_length or the default
// ResolveCutter takes.
Status SizeGcodeTools(const RuledSurface* surface, ToolPath* path) {
  if (path->program == nullptr || path->program->format != ProgramFormat::kGcode) {
    return Status::Ok();
  }
  std::string table_path = FLAGS_tool_table;
  if (table_path.empty() && IsLinuxCncIni(FLAGS_machine)) {
    RETURN_IF_ERROR(LinuxCncIniToolTable(FLAGS_machine, &table_path));
  }
  if (table_path.empty()) return Status::Ok();
  LinuxCncToolTable table;
  RETURN_IF_ERROR(ReadLinuxCncToolTable(table_path, &table));
  const double flute =
      FLAGS_flute_length != 0.0 ? FLAGS_flute_length : DefaultFluteLengthMm(surface);
  Status s = SizeToolsFromTable(table, table_path, flute, path);
  if (!s.ok()) return Status::Error(FLAGS_in + ": " + s.message());
  return Status::Ok();
}

}  // namespace

Status LoadJob(bool quiet, const LinkMoveOptions& links, Job* job) {
  job->has_surface = !FLAGS_surface.empty();
  Status s = LoadMachine(FLAGS_machine, &job->machine);
  if (s.ok()) s = LoadToolPath(FLAGS_in, job->machine, quiet, &job->path);
  PartSetup setup;
  if (s.ok()) s = PartSetupFromFlag(&setup);
  if (s.ok() && !setup.IsIdentity()) {
    if (job->path.program == nullptr || job->path.program->format != ProgramFormat::kApt) {
      s = Status::Error(FLAGS_in +
                        ": --part_setup places APT programs; a G-code program's X Y Z are "
                        "already the machine's (tcp: the table's frame, joint: the joints)");
    } else {
      PlacePart(setup, &job->path);
    }
  }
  if (s.ok()) MarkLinkMoves(links, &job->path);
  if (s.ok()) MarkStandingMoves(&job->path);
  if (s.ok() && job->has_surface) {
    s = LoadRuledSurface(FLAGS_surface, &job->surface, &job->surface_cad);
    if (s.ok()) s = SurfaceIntoPathFrame(job->path, setup, &job->surface);
  }
  if (s.ok() && !FLAGS_cnc_summary.empty()) {
    job->controller.emplace();
    s = ReadControllerRun(FLAGS_cnc_summary, &*job->controller);
  }
  if (s.ok()) s = SizeGcodeTools(job->surface_or_null(), &job->path);
  if (s.ok()) {
    job->cutter_per_tool = job->has_surface && FLAGS_cutter_radius == 0.0 &&
                           FLAGS_flute_length == 0.0 && DifferingTools(job->path).second != nullptr;
    s = ResolveCutter(job->path, job->surface_or_null(), FLAGS_cutter_radius, FLAGS_flute_length,
                      &job->cutter);
    if (!s.ok()) s = Status::Error(FLAGS_in + ": " + s.message());
  }
  return s;
}

Status CheckGcodeFlags() {
  for (const auto& [name, value] :
       {std::pair<const char*, std::string>{"gcode_style", FLAGS_gcode_style},
        {"gcode_in_style", FLAGS_gcode_in_style}}) {
    if (value != "tcp" && value != "joint") {
      return Status::Usage(std::string("--") + name + "=" + value + " must be tcp or joint");
    }
  }
  return Status::Ok();
}

Status CheckOutputFolders(const std::vector<std::string>& paths) {
  for (const std::string& path : paths) {
    if (path.empty()) continue;
    const size_t slash = path.find_last_of('/');
    const std::string folder = slash == std::string::npos ? "." : path.substr(0, slash + 1);
    struct stat info;
    if (stat(folder.c_str(), &info) != 0 || !S_ISDIR(info.st_mode)) {
      return Status::Error(path + ": cannot write: folder '" + folder + "' does not exist");
    }
  }
  return Status::Ok();
}

Status Require(const std::string& value, const std::string& flag) {
  if (!value.empty()) return Status::Ok();
  return Status::Usage("--" + flag + " is required");
}

}  // namespace tpopt
