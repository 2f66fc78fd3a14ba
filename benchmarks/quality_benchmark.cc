// The spline-vs-Ceres quality table: for every case of the suite (the three
// shared surfaces x {clean SPO, distorted CAM path} x both shared machines,
// plus LinuxCNC's impeller program surface-free when linuxcnc-uspace is
// installed) run the plain spline method and the high-accuracy mode and
// print one Markdown table; `--out=FILE.csv` also writes it as CSV.
//
//   ./build/benchmarks/quality_benchmark [--out=quality.csv] [--poses=300]
//
// Deviation is judged against a clean double-point-offset (DPO) path on the
// same surface, the best classical offset method. Axis motion is given both
// at the input's programmed feed (what the geometry alone demands) and as
// written, after feed scheduling (what the machine will run).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "apps/huge_page_malloc.h"
#include "model/io/gcode_io.h"
#include "model/io/json_io.h"
#include "model/path/link_moves.h"
#include "model/path/path_generator.h"
#include "model/base/units.h"
#include "solver/smooth/smoothing_pipeline.h"

namespace tpopt {
namespace {

constexpr double kNoValue = std::nan("");

// LinuxCNC's own 7-blade impeller program for the xyzac-trt sim machine
// (Debian linuxcnc-uspace); not copied into the repository (its licence).
constexpr char kLinuxCncImpeller[] =
    "/usr/share/doc/linuxcnc/examples/sample-configs/sim/axis/vismach/5axis/"
    "table-rotary-tilting/demos/impeller-7bl-xyzac.ngc";

struct Row {
  std::string surface, machine, path, mode;
  // NaN for a surface-free case (no surface to measure against).
  double dpo_mm = 0, overcut_mm = 0, undercut_mm = 0, rms_mm = 0;
  double a_acc_input_feed = 0, c_acc_input_feed = 0;
  double a_vel = 0, c_vel = 0, a_acc = 0, c_acc = 0, a_jerk = 0, c_jerk = 0;
  int violations_input = 0, violations = 0;
  double machining_time_s = 0, solve_time_s = 0;
};

std::string Data(const std::string& relative) {
  return std::string(TPOPT_SOURCE_DIR) + "/data/" + relative;
}

void Fill(const SmoothingResult& r, double wall_s, Row* row) {
  const PathMetrics& out = r.output_metrics;
  row->overcut_mm = out.deviation ? out.deviation->max_overcut_mm : kNoValue;
  row->undercut_mm = out.deviation ? out.deviation->max_undercut_mm : kNoValue;
  row->rms_mm = out.deviation ? out.deviation->rms_deviation_mm : kNoValue;
  row->a_acc_input_feed = r.output_at_input_feed.motion.axes[kA].peak_acceleration * kRadToDeg;
  row->c_acc_input_feed = r.output_at_input_feed.motion.axes[kC].peak_acceleration * kRadToDeg;
  row->a_vel = out.motion.axes[kA].peak_velocity * kRadToDeg;
  row->c_vel = out.motion.axes[kC].peak_velocity * kRadToDeg;
  row->a_acc = out.motion.axes[kA].peak_acceleration * kRadToDeg;
  row->c_acc = out.motion.axes[kC].peak_acceleration * kRadToDeg;
  row->a_jerk = out.motion.axes[kA].peak_jerk * kRadToDeg;
  row->c_jerk = out.motion.axes[kC].peak_jerk * kRadToDeg;
  row->violations_input = r.input_metrics.motion.limit_violations;
  row->violations = out.motion.limit_violations;
  row->machining_time_s = out.motion.machining_time_s;
  row->solve_time_s = wall_s;
}

double WorstMm(const RuledSurface& surface, const Machine& machine, const ToolPath& path) {
  PathMetrics m;
  if (!EvaluatePath(path, machine, &surface, *path.cutter, DeviationOptions(), MotionOptions(), &m)
           .ok()) {
    return -1;
  }
  return WorstDeviationMm(m);
}

// Adds one row per mode for `input`; `base` names the case.
void RunBothModes(const ToolPath& input, const RuledSurface* surface, const Cutter& cutter,
                  const Machine& machine, const SmoothingSettings& preset, const Row& base,
                  double dpo_mm, std::vector<Row>* rows) {
  for (const SmoothingMode mode : {SmoothingMode::kSpline, SmoothingMode::kHighAccuracy}) {
    SmoothingSettings settings = preset;
    settings.mode = mode;
    SmoothingResult result;
    const auto start = std::chrono::steady_clock::now();
    const Status s = RunSmoothing({&input, surface, &cutter, &machine}, settings, &result);
    const double wall_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Row row = base;
    row.mode = mode == SmoothingMode::kSpline ? "spline" : "high_accuracy";
    row.dpo_mm = dpo_mm;
    if (s.ok()) {
      Fill(result, wall_s, &row);
    } else {
      std::fprintf(stderr, "%s %s %s: %s\n", base.surface.c_str(), base.machine.c_str(),
                   row.mode.c_str(), s.message().c_str());
      row.violations = -1;
    }
    rows->push_back(row);
    std::fprintf(stderr, ".");
  }
}

// LinuxCNC's impeller program smoothed without a surface, with the settings
// of data/presets/surface_free.flags and a 3 mm cutter (as in the README).
void RunLinuxCncImpeller(std::vector<Row>* rows) {
  Machine machine;
  ToolPath input;
  std::vector<std::string> warnings;
  if (!ReadMachineJson(Data("machines/linuxcnc_xyzac_trt_sim.json"), &machine).ok() ||
      !ReadGcode(kLinuxCncImpeller, machine, GcodeStyle::kTcp, &input, &warnings).ok()) {
    std::fprintf(stderr, "\n%s not readable (linuxcnc-uspace not installed?): case skipped\n",
                 kLinuxCncImpeller);
    return;
  }
  MarkLinkMoves(LinkMoveOptions(), &input);  // as tpopt does by default: the six blade indexes
  SmoothingSettings preset;
  preset.high_accuracy.tolerance_mm = 0.01;
  preset.high_accuracy.angle_tolerance_deg = 0.5;
  preset.high_accuracy.w_second = 1e6;
  preset.high_accuracy.w_third = 0;
  preset.high_accuracy.w_tip_second = 0;
  Cutter cutter;
  cutter.radius_mm = 3.0;
  const Row base{"(none) impeller-7bl-xyzac.ngc", "linuxcnc_xyzac_trt_sim", "LinuxCNC program", ""};
  RunBothModes(input, nullptr, cutter, machine, preset, base, kNoValue, rows);
}

std::vector<Row> RunSuite(int poses) {
  std::vector<Row> rows;
  // The table reports every result, within the tolerance or not.
  SmoothingSettings settings;
  settings.accept_over_tolerance = true;
  // Input and output judged on the input's covered range (the default).
  settings.judge_on_input_range = true;
  for (const char* surface_name : {"jcde2022", "hypar", "impeller_blade"}) {
    RuledSurface surface;
    if (!ReadSurfaceJson(Data("surfaces/") + surface_name + ".json", &surface).ok()) continue;
    for (const char* machine_name : {"jcde2022_ac", "linuxcnc_xyzac_trt_sim"}) {
      Machine machine;
      if (!ReadMachineJson(Data("machines/") + machine_name + ".json", &machine).ok()) continue;
      FlankPathOptions g;
      g.poses = poses;
      g.strategy = FlankStrategy::kDoublePointOffset;
      ToolPath dpo;
      GenerateFlankPath(surface, g, &dpo);
      const double dpo_mm = WorstMm(surface, machine, dpo);
      g.strategy = FlankStrategy::kSinglePointOffset;
      for (const bool distorted : {false, true}) {
        g.uv_distortion = distorted ? 0.03 : 0.0;
        g.axis_noise_deg = distorted ? 0.3 : 0.0;
        ToolPath input;
        GenerateFlankPath(surface, g, &input);
        const Row base{surface_name, machine_name,
                       distorted ? "CAM (uv 0.03, 0.3 deg)" : "clean SPO", ""};
        RunBothModes(input, &surface, *input.cutter, machine, settings, base, dpo_mm, &rows);
      }
    }
  }
  RunLinuxCncImpeller(&rows);
  std::fprintf(stderr, "\n");
  return rows;
}

void PrintMarkdown(const std::vector<Row>& rows) {
  std::printf(
      "| surface | machine | input path | mode | max overcut mm | max undercut mm | RMS mm | "
      "max dev / DPO | A, C peak acc at input feed deg/s^2 | A, C peak vel deg/s | A, C peak acc "
      "deg/s^2 | A, C peak jerk deg/s^3 | violations in -> out | machining time s | wall s |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  // A number, or a dash where there is none (surface-free cases).
  auto cell = [](double v, const char* format) {
    if (std::isnan(v)) return std::string("—");
    char text[64];
    std::snprintf(text, sizeof(text), format, v);
    return std::string(text);
  };
  for (const Row& r : rows) {
    std::printf(
        "| %s | %s | %s | %s | %s | %s | %s | %s | %.1f, %.1f | %.2f, %.2f | %.1f, %.1f | "
        "%.0f, %.0f | %d -> %d | %.1f | %.3f |\n",
        r.surface.c_str(), r.machine.c_str(), r.path.c_str(), r.mode.c_str(),
        cell(r.overcut_mm, "%.4f").c_str(), cell(r.undercut_mm, "%.4f").c_str(),
        cell(r.rms_mm, "%.4f").c_str(),
        cell(std::max(r.overcut_mm, r.undercut_mm) / r.dpo_mm, "%.2f").c_str(),
        r.a_acc_input_feed, r.c_acc_input_feed, r.a_vel, r.c_vel, r.a_acc, r.c_acc, r.a_jerk,
        r.c_jerk, r.violations_input, r.violations, r.machining_time_s, r.solve_time_s);
  }
}

std::string Csv(const std::vector<Row>& rows) {
  std::ostringstream out;
  out << "surface,machine,input_path,mode,dpo_max_dev_mm,max_overcut_mm,max_undercut_mm,rms_mm,"
         "a_acc_input_feed,c_acc_input_feed,a_vel,c_vel,a_acc,c_acc,a_jerk,c_jerk,"
         "violations_input,violations,machining_time_s,solve_time_s\n";
  for (const Row& r : rows) {
    out << r.surface << ',' << r.machine << ',' << r.path << ',' << r.mode << ',' << r.dpo_mm
        << ',' << r.overcut_mm << ',' << r.undercut_mm << ',' << r.rms_mm << ','
        << r.a_acc_input_feed << ',' << r.c_acc_input_feed << ',' << r.a_vel << ',' << r.c_vel
        << ',' << r.a_acc << ',' << r.c_acc << ',' << r.a_jerk << ',' << r.c_jerk << ','
        << r.violations_input << ',' << r.violations << ',' << r.machining_time_s << ','
        << r.solve_time_s << '\n';
  }
  return out.str();
}

}  // namespace
}  // namespace tpopt

int main(int argc, char** argv) {
  tpopt::RestartWithHugePageMalloc(argv);
  std::string out;
  int poses = 300;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--out=", 6) == 0) {
      out = argv[i] + 6;
    } else if (std::strncmp(argv[i], "--poses=", 8) == 0) {
      poses = std::atoi(argv[i] + 8);
    } else {
      std::fprintf(stderr, "usage: quality_benchmark [--out=FILE.csv] [--poses=N]\n");
      return 2;
    }
  }
  if (poses < 4) {
    std::fprintf(stderr, "quality_benchmark: --poses=%d must be >= 4\n", poses);
    return 2;
  }
  const std::vector<tpopt::Row> rows = tpopt::RunSuite(poses);
  tpopt::PrintMarkdown(rows);
  if (!out.empty()) {
    std::ofstream file(out);
    file << tpopt::Csv(rows);
    if (!file) {
      std::fprintf(stderr, "quality_benchmark: cannot write %s\n", out.c_str());
      return 1;
    }
  }
  return 0;
}
