// G-code out and in, checked by LinuxCNC's own interpreter (rs274 from
// Debian's linuxcnc-uspace) where it is installed.
#include "model/gcode_io.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "model/json_io.h"
#include "model/link_moves.h"
#include "model/path_metrics.h"
#include "model/path_generator.h"
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

// Runs rs274 on `file`; fails the test on any line that is not a canonical
// call (an interpreter error), and returns the moves it printed.
std::vector<CanonMove> Interpret(const std::string& file) {
  const testing::CommandResult r = testing::RunCommand(std::string(kRs274) + " -g " + file);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  std::vector<CanonMove> moves;
  std::istringstream lines(r.output);
  std::string line;
  const std::regex canon(R"(^\s*\d+ N\.\.\.\.\. ([A-Z_0-9]+)\((.*)\)\s*$)");
  while (std::getline(lines, line)) {
    std::smatch m;
    if (line == "executing") continue;
    if (!std::regex_match(line, m, canon)) {
      ADD_FAILURE() << file << ": interpreter said: " << line;
      continue;
    }
    const std::string call = m[1];
    if (call != "STRAIGHT_FEED" && call != "STRAIGHT_TRAVERSE") continue;
    CanonMove move{call == "STRAIGHT_FEED", {}};
    double b = 0;
    std::sscanf(m[2].str().c_str(), "%lf, %lf, %lf, %lf, %lf, %lf", &move.v[0], &move.v[1],
                &move.v[2], &move.v[3], &b, &move.v[4]);
    moves.push_back(move);
  }
  return moves;
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
  EXPECT_NE(error_of("G1 X1\nG2 X2 Y2 I1 J0\n").find("bad.ngc:2: arcs"), std::string::npos);
  EXPECT_NE(error_of("X1 Y2\n").find("bad.ngc:1: axis words before any G0/G1"), std::string::npos);
  EXPECT_NE(error_of("G1 X1 (open\n").find("bad.ngc:1: unbalanced"), std::string::npos);
  EXPECT_NE(error_of("G1 X-\n").find("bad.ngc:1: word X has no valid number"),
            std::string::npos);
  EXPECT_NE(error_of("G1 X2000000\n").find("bad.ngc:1: word X value 2000000 is out of range"),
            std::string::npos);
  EXPECT_NE(error_of("(only a comment)\n").find("no G0/G1 move"), std::string::npos);
  EXPECT_NE(error_of("G1 X1 F0\n").find("bad.ngc:1: F0 must be > 0"), std::string::npos);
  // An unknown word is warned once, not fatal (X1e5 reads as X1 and E5).
  {
    std::istringstream in("G1 X1e5\nG1 X2 E3\n");
    ToolPath p;
    std::vector<std::string> w;
    ASSERT_TRUE(ReadGcodeStream(in, "w.ngc", machine_, GcodeStyle::kTcp, &p, &w).ok());
    ASSERT_EQ(w.size(), 1u);
    EXPECT_NE(w[0].find("w.ngc:1: word 'E'"), std::string::npos) << w[0];
  }
  // Inches, incremental moves, modal motion and comments.
  std::istringstream in("G20 G91 ; inches, relative\nG1 X1 F10 (one inch)\nY1\nG90 G21 G0 Z5\n");
  ToolPath p;
  std::vector<std::string> w;
  ASSERT_TRUE(ReadGcodeStream(in, "ok.ngc", machine_, GcodeStyle::kTcp, &p, &w).ok());
  ASSERT_EQ(p.poses.size(), 3u);
  EXPECT_LT((p.poses[1].p_w_tip - Eigen::Vector3d(25.4, 25.4, 0)).norm(), 1e-12);
  EXPECT_NEAR(p.poses[1].feed_mm_per_min, 254.0, 1e-9);
  EXPECT_TRUE(p.poses[2].rapid);
  EXPECT_EQ(p.poses[2].p_w_tip.z(), 5.0);
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
  EXPECT_EQ(Interpret(out).size(), n);
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
  // (the original's M428/M429 need the sim's M-files, so a copy leaves
  // them out).
  const std::string original = dir.File("impeller_without_m428.ngc");
  std::ofstream copy(original);
  std::ifstream in(kImpellerNgc);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("M428", 0) != 0 && line.rfind("M429", 0) != 0) copy << line << "\n";
  }
  copy.close();
  const std::vector<CanonMove> programmed = Traverses(Interpret(original));
  const std::vector<CanonMove> written = Traverses(Interpret(out));
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
