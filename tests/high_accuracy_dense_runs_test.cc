// Dense runs beside a sharp turn in high accuracy (issue 17): on the
// LinuxCNC sim machine, 0.05 mm moves next to a reversal or a standing move
// (model/path/standing_moves.h) were refused with exit 3, "worse than its spline
// starting point": the free pose beside a held one (the last of the program,
// the start of a standing move) had no smoothness stencil across its move
// into it, so the solve jumped it by a few degrees of C within the band, and
// on a 0.05 mm move that broke axis limits the input kept. Each program here
// must come out smoothed (exit 0), load in rs274, and no cutting run of it may
// be worse than the input's on peak d2A/ds2, d2C/ds2 or limit violations at
// the input's feeds.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "model/machine/axis_metrics.h"
#include "model/io/gcode_io.h"
#include "model/io/json_io.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

const char kMachine[] = "data/machines/linuxcnc_xyzac_trt_sim.json";

std::string Cut(double x_mm, double c_deg) {
  std::ostringstream line;
  line << std::fixed << std::setprecision(4) << "G1 X" << x_mm << " Y0 Z0 A10 C" << c_deg;
  return line.str();
}

// A rapid to (X0 Z10, A = a0_deg), then `moves` at F500, then M2: the
// program's last pose is held (the block after it is not a cut).
std::string Program(std::vector<std::string> moves, double a0_deg) {
  moves[0] += " F500";
  std::ostringstream text;
  text << "G21 G90 G94\nG0 X0 Y0 Z10 A" << a0_deg << " C0\n";
  for (const std::string& m : moves) text << m << "\n";
  text << "M2\n";
  return text.str();
}

struct Case {
  std::string name, text;
};

// 0.05 mm moves with C turning 1 deg/mm, or standing still with the rapid
// coming in at A 0 (a corner at the run's first pose), beside a standing
// move (G1 C90) or a reversal of the tip.
std::vector<Case> Cases() {
  constexpr double kStep = 0.05;
  std::vector<Case> cases;
  for (const bool turning : {true, false}) {
    const double dc = turning ? 0.05 : 0.0, a0 = turning ? 10.0 : 0.0;
    const std::string tag = turning ? "_c_turning" : "_corner_at_start";
    std::vector<std::string> standing, reversal;
    for (int i = 0; i < 40; ++i) standing.push_back(Cut(i * kStep, i * dc));
    standing.push_back("G1 C90");
    for (int i = 39; i < 80; ++i) standing.push_back(Cut(i * kStep, 90 + (i - 39) * dc));
    for (int i = 0; i < 40; ++i) reversal.push_back(Cut(i * kStep, i * dc));
    for (int i = 38; i >= 0; --i) reversal.push_back(Cut(i * kStep, (78 - i) * dc));
    cases.push_back({"standing" + tag + ".ngc", Program(standing, a0)});
    cases.push_back({"reversal" + tag + ".ngc", Program(reversal, a0)});
  }
  return cases;
}

ToolPath Read(const std::string& file, const Machine& machine) {
  ToolPath path;
  std::vector<std::string> warnings;
  const Status s = ReadGcode(file, machine, GcodeStyle::kTcp, &path, &warnings);
  EXPECT_TRUE(s.ok()) << s.message();
  return path;
}

struct RunFigures {
  std::array<double, 2> peak_d2 = {0, 0};  // A, C, rad/mm^2
  int limit_violations = 0;
};

// Each cutting run of `path` (as RunEnd splits them), with the pose before
// it, evaluated alone at the feeds it has.
std::vector<RunFigures> PerRun(const ToolPath& path, const Machine& machine) {
  std::vector<RunFigures> runs;
  for (size_t first = 0; first < path.poses.size(); first = RunEnd(path, first)) {
    ToolPath run = WithoutPoses(path);
    const size_t from = first > 0 ? first - 1 : 0;
    run.poses.assign(path.poses.begin() + from, path.poses.begin() + RunEnd(path, first));
    std::vector<JointVector> joints;
    EXPECT_TRUE(machine.AssignJoints(run, &joints).ok());
    const MotionReport m = EvaluateMotion(machine, run, joints, MotionOptions());
    runs.push_back({{m.axes[kA].peak_second_derivative_per_mm2,
                     m.axes[kC].peak_second_derivative_per_mm2},
                    m.limit_violations});
  }
  return runs;
}

TEST(HighAccuracyDenseRunsTest, DenseRunsBesideASharpTurnComeOutNoWorseThanTheyCame) {
  Machine machine;
  ASSERT_TRUE(ReadMachineJson(testing::SourcePath(kMachine), &machine).ok());
  testing::TempDir dir;
  for (const Case& c : Cases()) {
    SCOPED_TRACE(c.name);
    const std::string in = dir.File(c.name), out = dir.File("out_" + c.name);
    std::ofstream(in) << c.text;
    const auto r = testing::RunCommand(testing::TpoptBinary() +
                                       " smooth --mode=high_accuracy --in=" + in + " --out=" +
                                       out + " --cutter_radius=3 --quiet --machine=" +
                                       testing::SourcePath(kMachine));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const ToolPath input = Read(in, machine);
    ToolPath output = Read(out, machine);
    ASSERT_EQ(output.poses.size(), input.poses.size());
    // Judged at the input's feeds: the geometry, not the feed schedule.
    for (size_t i = 0; i < input.poses.size(); ++i) {
      output.poses[i].feed_mm_per_min = input.poses[i].feed_mm_per_min;
    }
    const std::vector<RunFigures> before = PerRun(input, machine), after = PerRun(output, machine);
    ASSERT_EQ(after.size(), before.size());
    bool moved = false;
    for (size_t k = 0; k < before.size(); ++k) {
      EXPECT_LE(after[k].peak_d2[0], before[k].peak_d2[0] + 1e-9) << "run " << k;
      EXPECT_LE(after[k].peak_d2[1], before[k].peak_d2[1] + 1e-9) << "run " << k;
      EXPECT_LE(after[k].limit_violations, before[k].limit_violations) << "run " << k;
    }
    for (size_t i = 0; i < input.poses.size(); ++i) {
      moved = moved || (output.poses[i].a_w - input.poses[i].a_w).norm() > 1e-6;
    }
    EXPECT_TRUE(moved) << "nothing was smoothed";

    constexpr char kRs274[] = "/usr/bin/rs274";
    if (!testing::FileExists(kRs274)) continue;
    const auto loaded = testing::RunCommand(std::string(kRs274) + " -g " + out);
    EXPECT_EQ(loaded.exit_code, 0) << loaded.output;
    EXPECT_EQ(loaded.output.find("rror"), std::string::npos) << loaded.output;
  }
}

// Where the solve still breaks more limits than its start and the input,
// the runs that do go back as programmed instead of the program being
// refused. Here a link (F20000 between two dense runs) stops the
// smoothness stencils, so the free pose before it follows the tilt the
// solve gives the run (from the corner at its start) and the link move then
// turns A faster than the input's did: with the d2 rule off, only the limits
// rule keeps it. Refused with exit 3 before.
TEST(HighAccuracyDenseRunsTest, RunsThatBreakMoreLimitsGoBackAsProgrammedNotRefused) {
  std::vector<std::string> moves;
  for (int i = 0; i < 40; ++i) moves.push_back(Cut(i * 0.05, 0));
  moves.push_back("G1 X10 Y0 Z0 A10 C0 F20000");
  for (int i = 1; i < 40; ++i) moves.push_back(Cut(10 + i * 0.05, 0) + (i == 1 ? " F500" : ""));
  testing::TempDir dir;
  const std::string in = dir.File("link.ngc"), out = dir.File("out.ngc");
  const std::string report = dir.File("report.json");
  std::ofstream(in) << Program(moves, 0.0);
  const auto r = testing::RunCommand(
      testing::TpoptBinary() + " smooth --mode=high_accuracy --in=" + in + " --out=" + out +
      " --cutter_radius=3 --quiet --keep_runs_no_worse=false --report=" + report +
      " --machine=" + testing::SourcePath(kMachine));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = testing::ReadJson(report);
  EXPECT_GT(j["runs_kept_as_input"].get<int>(), 0);
  EXPECT_LE(j["output_at_input_feed"]["limit_violations"].get<int>(),
            j["input"]["limit_violations"].get<int>());
}

}  // namespace
}  // namespace tpopt
