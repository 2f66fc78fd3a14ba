// Reading and writing what a subcommand's flags name, with messages fit for
// a user; the file format follows the extension.
#ifndef TPOPT_APPS_JOB_IO_H_
#define TPOPT_APPS_JOB_IO_H_

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/controller_run.h"
#include "model/io/apt_io.h"
#include "model/geometry/bspline_surface.h"
#include "model/cad/cad_io.h"
#include "model/geometry/freeform_surface.h"
#include "model/cutter/cutter.h"
#include "model/machine/interpolation.h"
#include "model/path/link_moves.h"
#include "model/machine/machine.h"
#include "model/path/part_setup.h"
#include "model/geometry/ruled_surface.h"
#include "model/base/status.h"
#include "model/path/tool_path.h"

namespace tpopt {

// A tool path by its extension: .cls, .apt or .cl (APT), .ngc or .nc
// (LinuxCNC G-code, read with the machine and --gcode_style). Reader
// warnings go to stderr unless quiet.
Status LoadToolPath(const std::string& path, const Machine& machine, bool quiet,
                    ToolPath* tool_path);

// Writes a tool path by its extension (as LoadToolPath), whole or not at
// all; G-code follows the --gcode_* flags. Curve spans go into APT files as
// NURBS records; G-code gets the poses only. A path read from a program
// and written in its format is that program block for block
// (WriteGcodeProgram, WriteAptProgram), given `source`, the path as read;
// APT is written in the part's frame (--part_setup undone).
Status SaveToolPath(const std::string& path, const Machine& machine, const ToolPath& tool_path,
                    const std::vector<AptCurveSpan>& spans = {},
                    const ToolPath* source = nullptr);

// --part_setup (model/path/part_setup.h); empty is the identity. Errors are
// usage errors; CheckPartSetupFlag checks it before a run.
Status PartSetupFromFlag(PartSetup* setup);
Status CheckPartSetupFlag();

// The machine file, or without one an ideal A/C table at the origin with
// no limits (A/C metrics are exact; X/Y/Z are relative to that pivot).
Status LoadMachine(const std::string& path, Machine* machine);

// The cutter: --cutter_radius / --flute_length when set, else the path's
// TLDATA/CUTTER; a path without one needs --cutter_radius. Without a flute
// length anywhere, 1.25 x the surface's longest ruling (or 100 mm). A
// program that cuts with tools of different sizes has each move judged and
// smoothed with its own tool's cutter (Job::cutter_per_tool); `cutter` then
// cuts the moves of tools the program gives no size.
Status ResolveCutter(const ToolPath& path, const RuledSurface* surface, double radius_flag_mm,
                     double flute_flag_mm, Cutter* cutter);

// --surface as a ruled surface: tpopt's JSON, or a STEP/IGES face chosen
// by --face, --ruling, --flip_cutter_side and --max_ruled_deviation_mm, in
// which case *cad (if not null) says what was read.
Status LoadRuledSurface(const std::string& path, RuledSurface* surface,
                        std::optional<CadSurfaceInfo>* cad);

// --surface as a bicubic free-form surface (stripwidth): JSON or a STEP/IGES
// face (--face, --flip_cutter_side).
Status LoadFreeformSurface(const std::string& path, FreeformSurface* surface,
                           std::optional<CadSurfaceInfo>* cad);

// --surface as a B-spline surface of degree 1 to 3 (pencil): JSON or a
// STEP/IGES face (--face).
Status LoadBSplineSurface(const std::string& path, BSplineSurface* surface,
                          std::optional<CadSurfaceInfo>* cad);

// The report's "surface_cad" object: file, unit, face, ruling, exactness,
// ruled deviation, trim and orientation.
nlohmann::json CadInfoJson(const CadSurfaceInfo& info);

// Everything a subcommand reads, loaded from --in, --surface, --machine,
// --cutter_radius, --flute_length and --part_setup (APT programs are placed
// on the table: their poses are in the machine's workpiece frame).
struct Job {
  ToolPath path;
  RuledSurface surface;
  bool has_surface = false;
  std::optional<CadSurfaceInfo> surface_cad;  // set when --surface is STEP or IGES
  Machine machine;
  Cutter cutter;
  // Each move is judged and smoothed with its own tool's cutter
  // (DeviationOptions::cutter_per_tool): against a surface, when the program
  // cuts with tools of different sizes and neither --cutter_radius nor
  // --flute_length names one cutter for all.
  bool cutter_per_tool = false;
  // From --cnc_summary, if given.
  std::optional<ControllerRun> controller;
  const RuledSurface* surface_or_null() const { return has_surface ? &surface : nullptr; }
};

// Loads a Job from the flags, its links marked by `links`; errors name the
// file at fault.
Status LoadJob(bool quiet, const LinkMoveOptions& links, Job* job);

// --interpolation, or without it the model of the program `path` written
// or read in G-code style `gcode_style` ("tcp" or "joint"): joint for
// joint-style G-code, TCP for tcp-style G-code and for APT. Fails (usage)
// for another --interpolation.
Status InterpolationFromFlags(const std::string& path, const std::string& gcode_style,
                              Interpolation* interpolation);

// Fails (usage) when --gcode_style or --gcode_in_style is not tcp or joint.
Status CheckGcodeFlags();

// Fails (bad input, naming the file) when a non-empty path among `paths`
// lies in a folder that does not exist: checked before a run so that a
// mistyped output costs no solve.
Status CheckOutputFolders(const std::vector<std::string>& paths);

// Fails (usage) when a required flag is empty.
Status Require(const std::string& value, const std::string& flag);

}  // namespace tpopt

#endif  // TPOPT_APPS_JOB_IO_H_
