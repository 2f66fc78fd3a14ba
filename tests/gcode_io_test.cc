// G-code out and in, checked by LinuxCNC's own interpreter (rs274 from
// Debian's linuxcnc-uspace) where it is installed.
#include "model/io/gcode_io.h"

#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "model/io/json_io.h"
#include "model/path/link_moves.h"
#include "model/eval/path_metrics.h"
#include "model/path/path_generator.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

constexpr char kRs274[] = "/usr/bin/rs274";
constexpr char kImpellerNgc[] =
    "/usr/share/doc/linuxcnc/examples/sample-configs/sim/axis/vismach/5axis/"
    "table-rotary-tilting/demos/impeller-7bl-xyzac.ngc";

struct CanonMove {
  bool feed;
  double v[5];  // x y z a c
};

// Runs rs274 with `arguments` on `file` and calls `on_call(name, args)` for
// each canonical call it prints; fails the test, naming `source`, on any
// other line (an interpreter error) and on a non-zero exit.
void ForEachCanonCall(const std::string& file, const std::string& source,
                      const std::string& arguments,
                      const std::function<void(const std::string&, const std::string&)>& on_call) {
  const testing::CommandResult r =
      testing::RunCommand(std::string(kRs274) + " " + arguments + " -g " + file);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  std::istringstream lines(r.output);
  const std::regex canon(R"(^\s*\d+ N\.\.\.\.\. ([A-Z_0-9]+)\((.*)\)\s*$)");
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (line == "executing") continue;
    if (!std::regex_match(line, m, canon)) {
      ADD_FAILURE() << source << ": interpreter said: " << line;
      continue;
    }
    on_call(m[1], m[2]);
  }
}

// The moves rs274 prints for `file`.
std::vector<CanonMove> Interpret(const std::string& file) {
  std::vector<CanonMove> moves;
  ForEachCanonCall(file, file, "", [&moves](const std::string& call, const std::string& args) {
    if (call != "STRAIGHT_FEED" && call != "STRAIGHT_TRAVERSE") return;
    CanonMove move{call == "STRAIGHT_FEED", {}};
    double b = 0;
    std::sscanf(args.c_str(), "%lf, %lf, %lf, %lf, %lf, %lf", &move.v[0], &move.v[1],
                &move.v[2], &move.v[3], &b, &move.v[4]);
    moves.push_back(move);
  });
  return moves;
}

// `file` without its M428/M429 lines (LinuxCNC remaps that need the sim's
// HAL pins, which rs274 alone has not), as `copy`.
void WithoutTcpSwitchCopy(const std::string& file, const std::string& copy) {
  std::ifstream in(file);
  std::ofstream out(copy);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("M428", 0) != 0 && line.rfind("M429", 0) != 0) out << line << "\n";
  }
}

// The rapids of `moves` (STRAIGHT_TRAVERSE), in order.
std::vector<CanonMove> Traverses(const std::vector<CanonMove>& moves) {
  std::vector<CanonMove> rapids;
  for (const CanonMove& m : moves) {
    if (!m.feed) rapids.push_back(m);
  }
  return rapids;
}

class GcodeIoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(ReadMachineJson(
                    testing::SourcePath("data/machines/linuxcnc_xyzac_trt_sim.json"), &machine_)
                    .ok());
    RuledSurface surface;
    ASSERT_TRUE(
        ReadSurfaceJson(testing::SourcePath("data/surfaces/impeller_blade.json"), &surface).ok());
    FlankPathOptions g;
    g.poses = 40;
    ASSERT_TRUE(GenerateFlankPath(surface, g, &path_).ok());
    path_.poses[20].rapid = true;  // a rapid in the middle stays a rapid
    path_.poses[30].link = true;   // and a link a link (kLinkComment)
  }

  Machine machine_;
  ToolPath path_;
  testing::TempDir dir_;
};

TEST_F(GcodeIoTest, RoundTripsInBothStylesAndFeedModes) {
  for (GcodeStyle style : {GcodeStyle::kTcp, GcodeStyle::kJoint}) {
    for (bool inverse_time : {false, true}) {
      GcodeOptions o;
      o.style = style;
      o.inverse_time = inverse_time;
      const std::string file = dir_.File("rt.ngc");
      ASSERT_TRUE(WriteGcode(file, path_, machine_, o).ok());
      ToolPath back;
      std::vector<std::string> warnings;
      ASSERT_TRUE(ReadGcode(file, machine_, style, &back, &warnings).ok());
      EXPECT_TRUE(warnings.empty()) << warnings.front();
      ASSERT_EQ(back.poses.size(), path_.poses.size());
      for (size_t i = 0; i < back.poses.size(); ++i) {
        EXPECT_LT((back.poses[i].p_w_tip - path_.poses[i].p_w_tip).norm(), 2e-4) << i;
        EXPECT_LT((back.poses[i].a_w - path_.poses[i].a_w).norm(), 1e-5) << i;
        EXPECT_EQ(back.poses[i].rapid, path_.poses[i].rapid || i == 0) << i;
        EXPECT_EQ(back.poses[i].link, path_.poses[i].link) << i;
        if (!back.poses[i].rapid) {
          EXPECT_NEAR(back.poses[i].feed_mm_per_min, 1000.0, 0.5) << i;
        }
      }
    }
  }
}

TEST_F(GcodeIoTest, LinuxCncInterpreterAcceptsEveryStyleAndMatchesTheMoves) {
  if (!testing::FileExists(kRs274)) GTEST_SKIP() << "rs274 (linuxcnc-uspace) not installed";
  for (GcodeStyle style : {GcodeStyle::kTcp, GcodeStyle::kJoint}) {
    for (bool inverse_time : {false, true}) {
      GcodeOptions o;
      o.style = style;
      o.inverse_time = inverse_time;
      path_.title = "check (with parentheses) for rs274";
      const std::string file = dir_.File("lcnc.ngc");
      ASSERT_TRUE(WriteGcode(file, path_, machine_, o).ok());
      const std::vector<CanonMove> moves = Interpret(file);
      std::vector<JointVector> joints;
      ASSERT_TRUE(machine_.AssignJoints(path_, &joints).ok());
      ASSERT_EQ(moves.size(), path_.poses.size());
      for (size_t i = 0; i < moves.size(); ++i) {
        const Eigen::Vector3d xyz = style == GcodeStyle::kTcp
                                        ? path_.poses[i].p_w_tip
                                        : Eigen::Vector3d(joints[i].head<3>());
        EXPECT_EQ(moves[i].feed, !(path_.poses[i].rapid || i == 0)) << i;
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(moves[i].v[k], xyz[k], 1e-4) << i;
        EXPECT_NEAR(moves[i].v[3], joints[i][kA] * 180 / M_PI, 1e-4) << i;
        EXPECT_NEAR(moves[i].v[4], joints[i][kC] * 180 / M_PI, 1e-4) << i;
      }
    }
  }
}

TEST_F(GcodeIoTest, BadProgramsNameTheLine) {
  auto error_of = [&](const std::string& text) {
    std::istringstream in(text);
    ToolPath p;
    std::vector<std::string> w;
    const Status s = ReadGcodeStream(in, "bad.ngc", machine_, GcodeStyle::kTcp, &p, &w);
    return s.ok() ? std::string() : s.message();
  };
  EXPECT_NE(error_of("X1 Y2\n").find("bad.ngc:1: axis words with no motion mode"),
            std::string::npos);
  EXPECT_NE(error_of("G1 X1 (open\n").find("bad.ngc:1: unbalanced"), std::string::npos);
  EXPECT_NE(error_of("G1 X-\n").find("bad.ngc:1: word X: no valid number at '-'"),
            std::string::npos);
  EXPECT_NE(error_of("G1 X2000000\n").find("bad.ngc:1: word X value 2e+06 is out of range"),
            std::string::npos);
  EXPECT_NE(error_of("(only a comment)\n").find("no G0/G1 move"), std::string::npos);
  EXPECT_NE(error_of("G1 X1 F0\n").find("bad.ngc:1: F0 must be > 0"), std::string::npos);
  // A word LinuxCNC does not have is refused (X1e5 reads as X1 and E5).
  EXPECT_NE(error_of("G1 X1e5\n").find("bad.ngc:1: word 'E' is not LinuxCNC G-code"),
            std::string::npos);
  // Inches, incremental moves, modal motion and comments.
  std::istringstream in(
      "G20 G90 G0 X0 Y0 Z0 A0 C0\nG91 ; inches, relative\nG1 X1 F10 (one inch)\nY1\n"
      "G90 G21 G0 Z5\n");
  ToolPath p;
  std::vector<std::string> w;
  ASSERT_TRUE(ReadGcodeStream(in, "ok.ngc", machine_, GcodeStyle::kTcp, &p, &w).ok());
  ASSERT_EQ(p.poses.size(), 4u);
  EXPECT_LT((p.poses[2].p_w_tip - Eigen::Vector3d(25.4, 25.4, 0)).norm(), 1e-12);
  EXPECT_NEAR(p.poses[2].feed_mm_per_min, 254.0, 1e-9);
  EXPECT_TRUE(p.poses[3].rapid);
  EXPECT_EQ(p.poses[3].p_w_tip.z(), 5.0);
  // Incremental moves are kept as written: only absolute G1s are replaced.
  ASSERT_TRUE(p.program != nullptr);
  EXPECT_FALSE(p.program->blocks[p.poses[2].source_block].replaceable);
  EXPECT_EQ(p.program->blocks[p.poses[2].source_block].mm_per_unit, 25.4);
}

TEST_F(GcodeIoTest, PosesKeepTheirProgrammedRotaryJoints) {
  // C's winding (350, -400) and C at A = 0 are not in the tool axis.
  for (GcodeStyle style : {GcodeStyle::kTcp, GcodeStyle::kJoint}) {
    std::istringstream in("G0 X0 Y0 Z5 A-30 C350\nG1 X1 A0 C-400 F100\n");
    ToolPath p;
    std::vector<std::string> w;
    ASSERT_TRUE(ReadGcodeStream(in, "p.ngc", machine_, style, &p, &w).ok());
    ASSERT_EQ(p.poses.size(), 2u);
    ASSERT_TRUE(p.poses[0].programmed && p.poses[1].programmed);
    EXPECT_NEAR(p.poses[0].programmed->a_rad * 180 / M_PI, -30.0, 1e-12);
    EXPECT_NEAR(p.poses[0].programmed->c_rad * 180 / M_PI, 350.0, 1e-12);
    EXPECT_EQ(p.poses[1].programmed->a_rad, 0.0);
    EXPECT_NEAR(p.poses[1].programmed->c_rad * 180 / M_PI, -400.0, 1e-12);
  }
}

TEST_F(GcodeIoTest, ReadsLinuxCncsImpellerProgram) {
  if (!testing::FileExists(kImpellerNgc)) {
    GTEST_SKIP() << kImpellerNgc << " absent (Debian package linuxcnc-uspace)";
  }
  ToolPath p;
  std::vector<std::string> warnings;
  const Status s = ReadGcode(kImpellerNgc, machine_, GcodeStyle::kJoint, &p, &warnings);
  ASSERT_TRUE(s.ok()) << s.message();
  // Every G0/G1 line with an axis word is one pose: count them independently.
  std::ifstream in(kImpellerNgc);
  std::string line;
  size_t moves = 0, rapids = 0;
  while (std::getline(in, line)) {
    const bool move = std::regex_search(line, std::regex(R"(^G[01]\s.*[XYZAC]\s*-?[0-9.])"));
    moves += move;
    rapids += move && line.rfind("G0", 0) == 0;
  }
  EXPECT_EQ(p.poses.size(), moves);
  size_t read_rapids = 0;
  for (const ToolPose& pose : p.poses) read_rapids += pose.rapid;
  EXPECT_EQ(read_rapids, rapids);
  // M428 switched the program to TCP: the first pose's tip is its X Y Z.
  EXPECT_LT((p.poses[0].p_w_tip - Eigen::Vector3d(16.339, -25.409, 33.353)).norm(), 1e-9);
  EXPECT_GT(p.poses.size(), 1000u);
}

}  // namespace
}  // namespace tpopt

namespace tpopt {
namespace {

TEST(GcodeCliTest, SmoothedProgramsLoadInLinuxCnc) {
  if (!testing::FileExists(kRs274)) GTEST_SKIP() << "rs274 (linuxcnc-uspace) not installed";
  testing::TempDir dir;
  const std::string blade = testing::SourcePath("data/surfaces/impeller_blade.json");
  const std::string sim = testing::SourcePath("data/machines/linuxcnc_xyzac_trt_sim.json");
  const std::string tpopt = testing::TpoptBinary();
  auto r = testing::RunCommand(tpopt + " generate --surface=" + blade +
                               " --cutter_radius=4 --poses=60 --uv_distortion=0.03 --machine=" +
                               sim + " --out=" + dir.File("cam.ngc"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(Interpret(dir.File("cam.ngc")).size(), 60u);
  for (const std::string style : {"tcp", "joint"}) {
    const std::string out = dir.File("smooth_" + style + ".ngc");
    r = testing::RunCommand(tpopt + " smooth --in=" + dir.File("cam.ngc") + " --out=" + out +
                            " --surface=" + blade + " --machine=" + sim +
                            " --cutter_radius=4 --mode=high_accuracy --quiet --gcode_inverse_time"
                            // 60 poses are too coarse to hold 0.01 mm between them; this
                            // test is about what the interpreter reads.
                            " --accept_over_tolerance --gcode_style=" + style);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(Interpret(out).size(), 60u) << style;
  }
}

}  // namespace
}  // namespace tpopt

namespace tpopt {
namespace {

TEST(GcodeCliTest, SurfaceFreeSmoothingOfLinuxCncsImpellerProgram) {
  if (!testing::FileExists(kImpellerNgc) || !testing::FileExists(kRs274)) {
    GTEST_SKIP() << kImpellerNgc << " or rs274 absent (Debian package linuxcnc-uspace)";
  }
  testing::TempDir dir;
  const std::string sim = testing::SourcePath("data/machines/linuxcnc_xyzac_trt_sim.json");
  const std::string out = dir.File("impeller_smooth.ngc"), report = dir.File("r.json");
  const auto r = testing::RunCommand(
      testing::TpoptBinary() + " smooth --flagfile=" +
      testing::SourcePath("data/presets/surface_free.flags") + " --in=" + kImpellerNgc +
      " --out=" + out + " --machine=" + sim + " --cutter_radius=3 --quiet --report=" + report);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  Machine machine;
  ASSERT_TRUE(ReadMachineJson(sim, &machine).ok());
  ToolPath before, after;
  std::vector<std::string> warnings;
  ASSERT_TRUE(ReadGcode(kImpellerNgc, machine, GcodeStyle::kJoint, &before, &warnings).ok());
  ASSERT_TRUE(ReadGcode(out, machine, GcodeStyle::kTcp, &after, &warnings).ok());
  ASSERT_EQ(after.poses.size(), before.poses.size());
  const size_t n = before.poses.size();
  for (size_t i = 0; i < n; ++i) {
    const ToolPose &b = before.poses[i], &a = after.poses[i];
    // Rapids unchanged (to the written precision).
    if (b.rapid || (i + 1 < n && before.poses[i + 1].rapid) || i == 0) {
      EXPECT_LT((a.p_w_tip - b.p_w_tip).norm(), 2e-6) << i;
      continue;
    }
    const size_t lo = i - 1, hi = i + 1;
    const Eigen::Vector3d t = (before.poses[hi].p_w_tip - before.poses[lo].p_w_tip).normalized();
    const Eigen::Vector3d d = a.p_w_tip - b.p_w_tip;
    // Within the tolerances, plus the 1e-6 rounding of the written program.
    EXPECT_LE((d - d.dot(t) * t).norm(), 0.01 + 2e-6) << i;
    EXPECT_LE(std::acos(std::min(1.0, a.a_w.dot(b.a_w))) * 180 / M_PI, 0.5 + 1e-5) << i;
  }
  const std::string out_for_rs274 = dir.File("impeller_smooth_without_m428.ngc");
  WithoutTcpSwitchCopy(out, out_for_rs274);
  EXPECT_EQ(Interpret(out_for_rs274).size(), n);
  // The six G1s that index from one blade to the next (at 40 times the
  // median feed) are links, their targets written as programmed and marked
  // (kLinkComment, as the feeds were scheduled down). The written program
  // has at most half the input's peak d2A/ds2 and d2C/ds2 over the cuts.
  EXPECT_EQ(MarkLinkMoves(LinkMoveOptions(), &before), 6);
  for (size_t i = 0; i < n; ++i) {
    EXPECT_EQ(after.poses[i].link, before.poses[i].link) << i;
    if (!before.poses[i].link) continue;
    EXPECT_LT((after.poses[i].p_w_tip - before.poses[i].p_w_tip).norm(), 1e-6) << i;
    EXPECT_LT(std::acos(std::min(1.0, after.poses[i].a_w.dot(before.poses[i].a_w))), 1e-7) << i;
  }
  PathMetrics m_before, m_after;
  ASSERT_TRUE(EvaluatePath(before, machine, nullptr, Cutter(), DeviationOptions(),
                           MotionOptions(), &m_before).ok());
  ASSERT_TRUE(EvaluatePath(after, machine, nullptr, Cutter(), DeviationOptions(),
                           MotionOptions(), &m_after).ok());
  for (int axis : {kA, kC}) {
    EXPECT_LE(m_after.motion.axes[axis].peak_second_derivative_per_mm2,
              0.5 * m_before.motion.axes[axis].peak_second_derivative_per_mm2)
        << axis;
  }
  // The report agrees: six links, and the sim machine's limits kept as written.
  const nlohmann::json j = testing::ReadJson(report);
  EXPECT_EQ(j["input"]["link_moves"], 6);
  EXPECT_EQ(j["output"]["link_moves"], 6);
  EXPECT_EQ(j["input"]["limit_violations"], 18);
  EXPECT_EQ(j["output"]["limit_violations"], 0);
  // Every rapid as programmed, as LinuxCNC reads both programs: the same
  // X Y Z A C to the written precision, C's winding and C at A = 0 included
  // (M428/M429, which both keep, need the sim's HAL pins, so copies leave
  // them out).
  const std::string original = dir.File("impeller_without_m428.ngc");
  WithoutTcpSwitchCopy(kImpellerNgc, original);
  const std::vector<CanonMove> programmed = Traverses(Interpret(original));
  const std::vector<CanonMove> written = Traverses(Interpret(out_for_rs274));
  ASSERT_EQ(written.size(), programmed.size());
  EXPECT_EQ(programmed.size(), 186u);
  for (size_t i = 0; i < written.size(); ++i) {
    for (int k = 0; k < 5; ++k) {
      EXPECT_NEAR(written[i].v[k], programmed[i].v[k], 5e-5) << "rapid " << i << " axis " << k;
    }
  }
}

}  // namespace
}  // namespace tpopt

namespace tpopt {
namespace {

// The G0/G1 moves of a program whose every move line is written in full,
// "G<0|1> X.. Y.. Z.. A.. C..", as tpopt writes them (read without the
// reader under test).
std::vector<CanonMove> FullMoveLines(const std::string& text) {
  std::vector<CanonMove> moves;
  std::istringstream lines(text);
  const std::regex move(R"(^G([01]) X(\S+) Y(\S+) Z(\S+) A(\S+) C(\S+).*$)");
  std::smatch m;
  for (std::string line; std::getline(lines, line);) {
    if (!std::regex_match(line, m, move)) continue;
    CanonMove c{m[1] == "1", {}};
    for (int k = 0; k < 5; ++k) c.v[k] = std::stod(m[k + 2]);
    moves.push_back(c);
  }
  return moves;
}

// A program with what a flank program does with C: a rapid to C 350, a cut
// that winds C across 360 (to 390) with A wavering, a rapid that re-winds
// the table by a whole turn (to C 30, the same axis), a cut straight over
// A = 0 with C programmed there, and the park at A 0 C 0.
std::string WindingProgram() {
  std::ostringstream p;
  p << std::fixed << std::setprecision(3) << "G21 G90 G94\n";
  auto move = [&](int g, double x, double y, double z, double a, double c) {
    p << "G" << g << " X" << x << " Y" << y << " Z" << z << " A" << a << " C" << c
      << (g == 1 ? " F600" : "") << "\n";
  };
  move(0, -20, 0, 30, -30, 350);
  move(0, -20, 0, 5, -30, 350);
  for (int i = 1; i <= 40; ++i) move(1, -20 + i, 0, 5, -30 - 3 * std::sin(0.7 * i), 350 + i);
  move(0, 20, 0, 30, -30 - 3 * std::sin(28.0), 390);
  move(0, -20, 10, 30, -30, 30);
  move(0, -20, 10, 5, -10, 30);
  for (int i = 1; i <= 40; ++i) {
    move(1, -20 + i, 10, 5, -10 + 0.5 * i + (i % 2 == 0 && i != 20 ? 0.3 : 0.0), 30);
  }
  move(0, 20, 10, 30, 0, 0);
  move(0, 0, 0, 40, 0, 0);
  p << "M2\n";
  return p.str();
}

TEST(GcodeCliTest, SmoothingWritesEveryRapidAsProgrammedAndCutsFollowOn) {
  testing::TempDir dir;
  const std::string in = dir.File("winding.ngc");
  {
    std::ofstream(in) << WindingProgram();
  }
  const std::vector<CanonMove> program = FullMoveLines(WindingProgram());
  ASSERT_EQ(program.size(), 87u);
  const std::string sim = testing::SourcePath("data/machines/linuxcnc_xyzac_trt_sim.json");
  const std::string common = testing::TpoptBinary() + " smooth --in=" + in + " --machine=" + sim +
                             " --cutter_radius=3 --quiet --out=" + dir.File("out.ngc") + " ";
  const std::string runs[] = {
      "--flagfile=" + testing::SourcePath("data/presets/surface_free.flags"),
      "--flagfile=" + testing::SourcePath("data/presets/surface_free.flags") +
          " --gcode_style=joint",
      "--mode=spline",
      "--mode=spline --resample_step_mm=0.4",
  };
  for (const std::string& flags : runs) {
    SCOPED_TRACE(flags);
    const auto r = testing::RunCommand(common + flags);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::vector<CanonMove> written =
        FullMoveLines(testing::ReadFileText(dir.File("out.ngc")));
    const bool joint = flags.find("joint") != std::string::npos;
    size_t k = 0;  // the programmed move the written one belongs to
    for (size_t i = 0; i < written.size(); ++i) {
      const CanonMove& w = written[i];
      if (w.feed) {
        // A cut goes on from where the rapid left C, not a turn away.
        ASSERT_GT(i, 0u);
        EXPECT_LT(std::abs(w.v[4] - written[i - 1].v[4]), 10.0) << "move " << i;
        continue;
      }
      while (k < program.size() && program[k].feed) ++k;
      ASSERT_LT(k, program.size()) << "more rapids than programmed";
      for (int axis = joint ? 3 : 0; axis < 5; ++axis) {
        EXPECT_NEAR(w.v[axis], program[k].v[axis], 5e-5) << "move " << i << " axis " << axis;
      }
      ++k;
    }
    while (k < program.size() && program[k].feed) ++k;
    EXPECT_EQ(k, program.size()) << "fewer rapids than programmed";
  }
}

}  // namespace
}  // namespace tpopt

namespace tpopt {
namespace {

constexpr char kDemoDir[] = "/usr/share/doc/linuxcnc/examples/sample-configs/sim/";
constexpr char kToolTable[] =
    "/usr/share/doc/linuxcnc/examples/sample-configs/sim/axis/vismach/5axis/"
    "table-rotary-tilting/xyzac-trt.tbl";

// LinuxCNC's A/C demo programs that tpopt reads (the others are refused:
// see ProgramsForOtherMachinesAndSubroutinesAreRefused).
std::vector<std::string> LinuxCncAcDemos() {
  std::vector<std::string> demos;
  for (const char* dir : {"axis/vismach/5axis/table-rotary-tilting/demos/",
                          "gmoccapy/non_trivial_kinematics/table-rotary-tilting/examples/"}) {
    for (const char* name :
         {"boat-xyzac.ngc", "impeller-7bl-xyzac.ngc", "xyzac_switchkins_test_1.ngc",
          "xyzac_switchkins_test_2.ngc", "xyzac_switchkins_test_3.ngc"}) {
      const std::string path = std::string(kDemoDir) + dir + name;
      if (testing::FileExists(path)) demos.push_back(path);
    }
  }
  return demos;
}

std::vector<std::string> Corpus() {
  std::vector<std::string> files;
  for (const char* name : {"arcs.ngc", "g53_tool_change.ngc", "parameters.ngc", "tcp_switch.ngc"}) {
    files.push_back(testing::SourcePath(std::string("tests/data/gcode/") + name));
  }
  return files;
}

// rs274's canonical calls for `file`, without their sequence numbers, split
// into the feed moves (STRAIGHT_FEED, SET_FEED_RATE, SET_FEED_MODE) and all
// the others: rapids, arcs, spindle, coolant, tool changes, comments, end.
struct Canon {
  std::vector<std::string> feeds;
  std::vector<std::string> others;
};

Canon InterpretAll(const std::string& file, const testing::TempDir& dir) {
  const std::string copy = dir.File("rs274_input.ngc");
  WithoutTcpSwitchCopy(file, copy);
  Canon canon;
  ForEachCanonCall(copy, file, std::string("-t ") + kToolTable,
                   [&canon](const std::string& name, const std::string& args) {
                     const bool feed = name == "STRAIGHT_FEED" || name == "SET_FEED_RATE" ||
                                       name == "SET_FEED_MODE";
                     (feed ? canon.feeds : canon.others).push_back(name + "(" + args + ")");
                   });
  return canon;
}

TEST(GcodeProgramTest, ModeNoneWritesEveryProgramBackAsItCame) {
  std::vector<std::string> programs = Corpus();
  for (const std::string& demo : LinuxCncAcDemos()) programs.push_back(demo);
  testing::TempDir dir;
  const std::string sim = testing::SourcePath("data/machines/linuxcnc_xyzac_trt_sim.json");
  for (const std::string& in : programs) {
    SCOPED_TRACE(in);
    const std::string out = dir.File("none.ngc");
    const auto r =
        testing::RunCommand(testing::TpoptBinary() + " smooth --mode=none --in=" + in +
                            " --out=" + out + " --machine=" + sim + " --cutter_radius=3 --quiet");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    // Block for block, text for text: every move to its written decimals.
    EXPECT_EQ(testing::ReadFileText(out), testing::ReadFileText(in));
  }
}

// Whether `line` is at most a feed move: axis words (numbers, parameters
// or [expressions]), F and an optional G1, nothing else.
bool AtMostAFeedMove(std::string line) {
  for (size_t open; (open = line.rfind('[')) != std::string::npos;) {
    const size_t close = line.find(']', open);
    if (close == std::string::npos) return false;
    line.erase(open, close - open + 1);
  }
  return std::regex_match(line, std::regex(R"(^(G0?1\s*)?([XYZACF]\s*[-+0-9.]*(#<?\w+>?)?\s*)+$)"));
}

// Checks that the lines of `out_text` other than the moves and F lines
// tpopt writes are the lines of `in_text` in order, and that the lines
// left out are at most feed moves.
void ExpectSourceLinesKept(const std::string& in_text, const std::string& out_text) {
  const std::regex written(
      R"(^G1 X-?\d+\.\d{6} Y\S+ Z\S+ A\S+ C\S+( F\S+)?( \(link\))?$|^F\d+\.\d{4}$)");
  std::vector<std::string> in_lines;
  std::istringstream in(in_text), out(out_text);
  for (std::string line; std::getline(in, line);) in_lines.push_back(line);
  size_t k = 0;
  for (std::string line; std::getline(out, line);) {
    if (std::regex_match(line, written)) continue;
    while (k < in_lines.size() && in_lines[k] != line) {
      EXPECT_TRUE(AtMostAFeedMove(in_lines[k])) << "dropped: " << in_lines[k];
      ++k;
    }
    ASSERT_LT(k, in_lines.size()) << "not in the source, or out of order: " << line;
    ++k;
  }
  for (; k < in_lines.size(); ++k) EXPECT_TRUE(AtMostAFeedMove(in_lines[k])) << in_lines[k];
}

TEST(GcodeProgramTest, SmoothingChangesOnlyTheCuttingMoves) {
  if (!testing::FileExists(kRs274)) GTEST_SKIP() << "rs274 (linuxcnc-uspace) not installed";
  std::vector<std::string> programs = Corpus();
  for (const std::string& demo : LinuxCncAcDemos()) {
    if (demo.find("boat-xyzac") != std::string::npos) programs.push_back(demo);
  }
  testing::TempDir dir;
  const std::string sim = testing::SourcePath("data/machines/linuxcnc_xyzac_trt_sim.json");
  const std::string resampled = "--mode=spline --resample_step_mm=0.4";
  const std::string ceres = "--flagfile=" + testing::SourcePath("data/presets/surface_free.flags");
  for (const std::string& in : programs) {
    for (const std::string& mode : {resampled, ceres}) {
      // The boat's 1800 poses in the spline mode only: Ceres under the
      // sanitizers would take minutes.
      if (mode == ceres && in.find("boat") != std::string::npos) continue;
      SCOPED_TRACE(in + " " + mode);
      const std::string out = dir.File("smoothed.ngc");
      const auto r =
          testing::RunCommand(testing::TpoptBinary() + " smooth " + mode + " --in=" + in +
                              " --out=" + out + " --machine=" + sim + " --cutter_radius=3 --quiet");
      ASSERT_EQ(r.exit_code, 0) << r.output;
      const Canon before = InterpretAll(in, dir), after = InterpretAll(out, dir);
      // Rapids, arcs, G53 moves, spindle, coolant, tool changes, comments and
      // the program end, in order, as LinuxCNC reads them.
      EXPECT_EQ(after.others, before.others);
      // And the cuts did change (the test is not of a program left alone).
      EXPECT_NE(after.feeds, before.feeds);
      // Every block that is not a plain cutting move is in the output as
      // written.
      const std::string in_text = testing::ReadFileText(in), out_text = testing::ReadFileText(out);
      ExpectSourceLinesKept(in_text, out_text);
      EXPECT_EQ(out_text.back(), in_text.back());  // ends as the input ends
    }
  }
}

TEST(GcodeProgramTest, ParametersAndExpressionsReadAsLinuxCncReadsThem) {
  if (!testing::FileExists(kRs274)) GTEST_SKIP() << "rs274 (linuxcnc-uspace) not installed";
  const std::string file = testing::SourcePath("tests/data/gcode/parameters.ngc");
  ToolPath path;
  std::vector<std::string> warnings;
  ASSERT_TRUE(ReadGcode(file, Machine(), GcodeStyle::kTcp, &path, &warnings).ok());
  const std::vector<CanonMove> moves = Interpret(file);
  ASSERT_EQ(path.poses.size(), moves.size());
  for (size_t i = 0; i < moves.size(); ++i) {
    const ToolPose& p = path.poses[i];
    EXPECT_EQ(p.rapid, !moves[i].feed) << i;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.p_w_tip[k], moves[i].v[k], 1e-4) << i << " " << k;
    EXPECT_NEAR(p.programmed->a_rad * 180 / M_PI, moves[i].v[3], 1e-4) << i;
    EXPECT_NEAR(p.programmed->c_rad * 180 / M_PI, moves[i].v[4], 1e-4) << i;
  }
  // F#<FRATE> and F[#<FRATE> * 2].
  EXPECT_EQ(path.poses[1].feed_mm_per_min, 300.0);
  EXPECT_EQ(path.poses[7].feed_mm_per_min, 600.0);
}

TEST(GcodeProgramTest, BlocksThatAreNotCutsBreakTheRunsAndHoldTheirPoses) {
  const std::string file = testing::SourcePath("tests/data/gcode/g53_tool_change.ngc");
  ToolPath path;
  std::vector<std::string> warnings;
  ASSERT_TRUE(ReadGcode(file, Machine(), GcodeStyle::kTcp, &path, &warnings).ok());
  ASSERT_TRUE(path.program != nullptr);
  const Program& program = *path.program;
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(program.blocks.size(), lines.size());
  for (size_t b = 0; b < lines.size(); ++b) {
    const ProgramBlock& block = program.blocks[b];
    EXPECT_EQ(block.text, lines[b]);
    EXPECT_EQ(block.line, static_cast<int>(b) + 1);
    // G53 moves, and "G0 X0 Y0 A10 C0" after a tool change (Z unknown), have
    // no pose; every plain G1 with all axes has one and may be replaced.
    const bool g53 = lines[b].rfind("G53", 0) == 0;
    const bool before_z = lines[b].find("A10 C0") != std::string::npos ||
                          lines[b].find("A-25 C30") != std::string::npos;
    if (g53 || before_z) {
      EXPECT_EQ(block.pose, -1) << lines[b];
    }
    const bool plain_cut =
        std::regex_match(lines[b], std::regex(R"(^G1( [XYZAC][-0-9.]+)+( F\d+)?$)"));
    EXPECT_EQ(block.replaceable, plain_cut) << lines[b];
    if (block.pose >= 0) {
      EXPECT_EQ(path.poses[block.pose].source_block, static_cast<int>(b));
    }
  }
  // The first pose is "G0 Z10" after the tool change: X Y A C from the line
  // before it, Z its own.
  EXPECT_EQ(path.poses[0].source_line, 11);
  EXPECT_LT((path.poses[0].p_w_tip - Eigen::Vector3d(0, 0, 10)).norm(), 1e-12);
  // The move after a block without a pose (M9, T2 M6, ...) is held.
  for (const ToolPose& p : path.poses) {
    const int b = p.source_block;
    const bool after_other = b > 0 && program.blocks[b - 1].pose < 0;
    if (after_other) {
      EXPECT_TRUE(IsPositioningMove(p)) << lines[b];
    }
  }
}

TEST(GcodeProgramTest, ProgramsForOtherMachinesAndSubroutinesAreRefused) {
  auto error_of = [](const std::string& text) {
    std::istringstream in(text);
    ToolPath p;
    std::vector<std::string> w;
    const Status s = ReadGcodeStream(in, "bad.ngc", Machine(), GcodeStyle::kTcp, &p, &w);
    return s.ok() ? std::string("ok") : s.message();
  };
  const std::string start = "G0 X0 Y0 Z5 A0 C0\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {start + "G1 X1 B10 F100\n", "bad.ngc:2: word 'B': the machine has no B axis"},
      {start + "G1 U1 F100\n", "bad.ngc:2: word 'U'"},
      {start + "o100 sub\nG1 X1 F100\no100 endsub\n", "bad.ngc:2: o-word 'sub'"},
      {start + "o<probe> call [1]\n", "bad.ngc:2: o-word 'call'"},
      {start + "o1 if [#1 GT 0]\n", "bad.ngc:2: o-word 'if'"},
      {start + "G1 X#<FRATE> F100\n", "bad.ngc:2: word X: named parameter #<FRATE> is read before"},
      {start + "G1 X#<_x> F100\n", "predefined parameters are machine state"},
      {start + "G1 X#5221 F100\n", "bad.ngc:2: word X: parameter #5221 is LinuxCNC machine state"},
      {start + "G1 X[1 + ] F100\n", "bad.ngc:2: word X:"},
      {start + "G1 X[FOO[1]] F100\n", "unknown function 'FOO'"},
      {start + "/G1 X1 F100\n", "bad.ngc:2: block delete"},
      {start + "G7\n", "bad.ngc:2: G7 (lathe"},
      {start + "G12 X1\n", "bad.ngc:2: G12 is not a G code tpopt reads"},
      {start + "M72\n", "bad.ngc:2: M72"},
      {start + "G1 X" + std::string(300, '[') + "1" + std::string(300, ']') + "\n",
       "bad.ngc:2: the block has 300 brackets and parameters"},
  };
  for (const auto& [program, message] : cases) {
    EXPECT_NE(error_of(program).find(message), std::string::npos)
        << program << " -> " << error_of(program);
  }
  // LinuxCNC's own program for a B/C machine: exit 1 naming line and word.
  const std::string boat_bc =
      std::string(kDemoDir) + "axis/vismach/5axis/table-rotary-tilting/demos/boat-xyzbc.ngc";
  if (testing::FileExists(boat_bc)) {
    testing::TempDir dir;
    const auto r =
        testing::RunCommand(testing::TpoptBinary() + " smooth --mode=none --in=" + boat_bc +
                            " --out=" + dir.File("o.ngc") + " --cutter_radius=3 --quiet");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.output.find("boat-xyzbc.ngc:11: word 'B'"), std::string::npos) << r.output;
    EXPECT_FALSE(testing::FileExists(dir.File("o.ngc")));
  }
}

TEST(GcodeProgramTest, AxesNeverSetStayUnsetAndTheEndStaysTheEnd) {
  // The boat's opening: Z5 alone, then a tool change; nothing after M30 is
  // read (it would be an error), yet it is written back.
  std::istringstream in(
      "%\nG0 G17 G40 G90 G94\nZ5\nT1 M6\nG54 X-49.65 Y-23.015 A0. C0. S630 "
      "M03\n"
      "G00 Z5.0 M08\nG01 Z-6.625 F300.0\nX-49.375 "
      "F600.0\nX-15.268\nM30\nB5\n%");
  ToolPath path;
  std::vector<std::string> w;
  const Status s = ReadGcodeStream(in, "boat.ngc", Machine(), GcodeStyle::kTcp, &path, &w);
  ASSERT_TRUE(s.ok()) << s.message();
  ASSERT_EQ(path.poses.size(), 4u);
  EXPECT_EQ(path.poses[0].source_line,
            6);  // the first move that places all five axes
  EXPECT_TRUE(path.poses[0].rapid);
  EXPECT_EQ(path.program->blocks.size(), 12u);
  EXPECT_FALSE(path.program->final_newline);
  std::string text;
  ASSERT_TRUE(FormatGcodeProgram(path, path, Machine(), GcodeOptions(), &text).ok());
  EXPECT_EQ(text,
            "%\nG0 G17 G40 G90 G94\nZ5\nT1 M6\nG54 X-49.65 Y-23.015 A0. C0. "
            "S630 M03\n"
            "G00 Z5.0 M08\nG01 Z-6.625 F300.0\nX-49.375 "
            "F600.0\nX-15.268\nM30\nB5\n%");
  // A moved cut is written in full in its block's place; the F the source
  // relied on after it is restored before the next source block.
  ToolPath moved = path;
  moved.poses[2].p_w_tip.y() += 0.5;
  moved.poses[2].feed_mm_per_min = 450.0;
  ASSERT_TRUE(FormatGcodeProgram(path, moved, Machine(), GcodeOptions(), &text).ok());
  EXPECT_NE(text.find("G01 Z-6.625 F300.0\n"
                      "G1 X-49.375000 Y-22.515000 Z-6.625000 A0.000000 "
                      "C0.000000 F450.0000\n"
                      "F600.0000\nX-15.268\n"),
            std::string::npos)
      << text;
}

}  // namespace
}  // namespace tpopt

namespace tpopt {
namespace {

TEST(GcodeProgramTest, NeitherModeReturnsLinuxCncsImpellerWorse) {
  if (!testing::FileExists(kImpellerNgc)) GTEST_SKIP() << kImpellerNgc << " absent";
  testing::TempDir dir;
  const std::string sim = testing::SourcePath("data/machines/linuxcnc_xyzac_trt_sim.json");
  Machine machine;
  ASSERT_TRUE(ReadMachineJson(sim, &machine).ok());
  ToolPath before;
  std::vector<std::string> warnings;
  ASSERT_TRUE(ReadGcode(kImpellerNgc, machine, GcodeStyle::kJoint, &before, &warnings).ok());
  MarkLinkMoves(LinkMoveOptions(), &before);
  PathMetrics m_before;
  ASSERT_TRUE(EvaluatePath(before, machine, nullptr, Cutter(), DeviationOptions(),
                           MotionOptions(), &m_before).ok());
  for (const std::string mode : {"spline", "high_accuracy"}) {
    const std::string out = dir.File(mode + ".ngc"), report = dir.File(mode + ".json");
    const auto r = testing::RunCommand(testing::TpoptBinary() + " smooth --mode=" + mode +
                                       " --in=" + kImpellerNgc + " --out=" + out +
                                       " --machine=" + sim + " --cutter_radius=3 --quiet --report=" +
                                       report);
    ASSERT_EQ(r.exit_code, 0) << mode << ": " << r.output;
    // Without the put-back the spline took d2A/ds2 2.04 -> 3.14 and d2C/ds2
    // 1.92 -> 4.89 deg/mm^2; those runs are put back. High accuracy made 7
    // runs worse on one or the other while its smoothness stencils stopped
    // at every held pose; running into them, it makes none worse.
    const nlohmann::json j = testing::ReadJson(report);
    if (mode == "spline") {
      EXPECT_GT(j["runs_kept_as_input"].get<int>(), 0) << mode;
    } else {
      EXPECT_EQ(j["runs_kept_as_input"].get<int>(), 0) << mode;
    }
    // Judged on the programs as written, read back.
    ToolPath after;
    ASSERT_TRUE(ReadGcode(out, machine, GcodeStyle::kJoint, &after, &warnings).ok());
    MarkLinkMoves(LinkMoveOptions(), &after);
    PathMetrics m_after;
    ASSERT_TRUE(EvaluatePath(after, machine, nullptr, Cutter(), DeviationOptions(),
                             MotionOptions(), &m_after).ok());
    for (int axis : {kA, kC}) {
      EXPECT_LE(m_after.motion.axes[axis].peak_second_derivative_per_mm2,
                m_before.motion.axes[axis].peak_second_derivative_per_mm2 + 1e-6)
          << mode << " " << axis;
    }
  }
}

}  // namespace
}  // namespace tpopt
