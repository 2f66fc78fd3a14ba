// Standing moves (model/path/standing_moves.h): which moves are marked, and the
// programs of issue 17, item 7 (a pure rotary move, then the same pose
// again; repeats at a run's ends; a run of rotary moves only), which both
// modes must smooth, in both formats, into programs that load.
#include "model/path/standing_moves.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "model/io/apt_io.h"
#include "model/io/gcode_io.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

ToolPose At(double x, double a_deg, bool rapid = false) {
  ToolPose p;
  p.p_w_tip = Eigen::Vector3d(x, 0.0, 0.0);
  const double a = a_deg * M_PI / 180.0;
  p.a_w = Eigen::Vector3d(0.0, std::sin(a), std::cos(a));
  p.rapid = rapid;
  return p;
}

TEST(StandingMovesTest, MarksBothPosesOfEveryFeedMoveThatLeavesTheTipStanding) {
  ToolPath path;
  path.poses = {At(0, 0, /*rapid=*/true), At(1, 10), At(1, 20),    // a pure rotation
                At(1, 20),                                        // the same pose again
                At(2, 20), At(2, 20, /*rapid=*/true),             // a rapid that stands
                At(3, 20), At(3 + 0.5e-3, 20), At(3 + 2.5e-3, 20)};  // 0.5 and 2 um
  EXPECT_EQ(MarkStandingMoves(&path), 3);
  const std::vector<bool> held = {false, true, true, true, false, false, true, true, false};
  for (size_t i = 0; i < held.size(); ++i) EXPECT_EQ(path.poses[i].held, held[i]) << i;
  EXPECT_TRUE(path.poses[5].rapid);
}

// A G-code program: a rapid to the start, then the feed moves.
std::string Gcode(const std::vector<std::string>& moves) {
  std::string text = "G21 G90 G94\nG0 X0 Y0 Z10 A0 C0\n";
  for (const std::string& m : moves) text += m + "\n";
  return text + "M2\n";
}

std::string Cut(double x_mm, double c_deg, double step = 1.0) {
  std::ostringstream line;
  line << "G1 X" << x_mm * step << " Y0 Z0 A10 C" << c_deg;
  return line.str();
}

struct Program {
  std::string name, text;
  std::vector<std::string> standing;  // lines that must come out as written
};

std::vector<Program> GcodePrograms() {
  std::vector<Program> p;
  auto run = [](int from, int to, double c, double step = 1.0) {
    std::vector<std::string> moves;
    for (int i = from; i < to; ++i) moves.push_back(Cut(i, c, step));
    return moves;
  };
  auto join = [](std::vector<std::vector<std::string>> parts) {
    std::vector<std::string> all;
    for (auto& part : parts) all.insert(all.end(), part.begin(), part.end());
    all[0] += " F500";
    return all;
  };
  // The program: G1 C90, then the same point again.
  p.push_back({"rotary_then_same.ngc",
               Gcode(join({run(0, 4, 0), {"G1 C90"}, run(3, 7, 90)})), {"G1 C90"}});
  // The same on 10 mm moves: this one made the spline's banded system
  // singular ("smoothing spline: the banded system is singular").
  p.push_back({"rotary_then_same_10mm.ngc",
               Gcode(join({run(0, 12, 0, 10), {"G1 C90"}, run(11, 24, 90, 10)})),
               {"G1 C90", Cut(11, 90, 10)}});
  p.push_back({"rotary_at_start.ngc", Gcode(join({run(0, 1, 0), {"G1 C90"}, run(0, 7, 90)})),
               {"G1 C90"}});
  p.push_back({"rotary_at_end.ngc", Gcode(join({run(0, 6, 0), {"G1 C90"}, run(5, 6, 90)})),
               {"G1 C90"}});
  p.push_back({"two_rotary.ngc", Gcode(join({run(0, 4, 0), {"G1 C45", "G1 C90"}, run(3, 7, 90)})),
               {"G1 C45", "G1 C90"}});
  p.push_back({"three_same.ngc", Gcode(join({run(0, 4, 0), run(3, 4, 0), run(3, 8, 0)})), {}});
  p.push_back({"same_at_start.ngc", Gcode(join({run(0, 1, 0), run(0, 6, 0)})), {}});
  p.push_back({"same_at_end.ngc", Gcode(join({run(0, 6, 0), run(5, 6, 0)})), {}});
  std::vector<std::string> rotary_only = {Cut(0, 0) + " F500"};
  for (int k = 1; k < 10; ++k) rotary_only.push_back("G1 C" + std::to_string(10 * k));
  p.push_back({"rotary_only.ngc", Gcode(rotary_only), {"G1 C50"}});
  return p;
}

// APT: GOTOs with the axis at A = 10 deg, C = c_deg.
std::string Goto(double x_mm, double c_deg) {
  const double a = 10.0 * M_PI / 180.0, c = c_deg * M_PI / 180.0;
  std::ostringstream line;
  line.precision(9);
  line << "GOTO/" << x_mm << ",0,0," << std::sin(a) * std::sin(c) << ","
       << std::sin(a) * std::cos(c) << "," << std::cos(a);
  return line.str();
}

std::vector<Program> AptPrograms() {
  auto apt = [](const std::vector<std::string>& gotos) {
    std::string text = "UNITS/MM\nMULTAX/ON\nFEDRAT/MMPM,500\n";
    for (const std::string& g : gotos) text += g + "\n";
    return text + "FINI\n";
  };
  std::vector<Program> p;
  std::vector<std::string> mid, start, end, only;
  for (int i = 0; i < 4; ++i) mid.push_back(Goto(i, 0));
  mid.push_back(Goto(3, 90));
  mid.push_back(Goto(3, 90));
  for (int i = 4; i < 7; ++i) mid.push_back(Goto(i, 90));
  p.push_back({"rotary_then_same.cls", apt(mid), {Goto(3, 90)}});
  start = {Goto(0, 0), Goto(0, 90)};
  for (int i = 1; i < 7; ++i) start.push_back(Goto(i, 90));
  p.push_back({"rotary_at_start.cls", apt(start), {Goto(0, 90)}});
  for (int i = 0; i < 6; ++i) end.push_back(Goto(i, 0));
  end.push_back(Goto(5, 90));
  p.push_back({"rotary_at_end.cls", apt(end), {Goto(5, 90)}});
  for (int k = 0; k < 10; ++k) only.push_back(Goto(0, 10 * k));
  p.push_back({"rotary_only.cls", apt(only), {Goto(0, 50)}});
  return p;
}

// Whether `text` has `line` as one of its lines.
bool HasLine(const std::string& text, const std::string& line) {
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) {
    if (l == line) return true;
  }
  return false;
}

size_t CountPoses(const std::string& file, bool apt) {
  ToolPath path;
  std::vector<std::string> warnings;
  const Status s = apt ? ReadApt(file, &path, &warnings)
                       : ReadGcode(file, Machine(), GcodeStyle::kTcp, &path, &warnings);
  EXPECT_TRUE(s.ok()) << s.message();
  return path.poses.size();
}

TEST(StandingMovesTest, BothModesSmoothPureRotaryAndRepeatedPosesInBothFormats) {
  constexpr char kRs274[] = "/usr/bin/rs274";
  testing::TempDir dir;
  std::vector<std::pair<Program, bool>> programs;
  for (const Program& p : GcodePrograms()) programs.push_back({p, false});
  for (const Program& p : AptPrograms()) programs.push_back({p, true});
  for (const auto& [program, apt] : programs) {
    const std::string in = dir.File(program.name);
    std::ofstream(in) << program.text;
    for (const std::string mode : {"spline", "high_accuracy"}) {
      SCOPED_TRACE(program.name + " " + mode);
      const std::string out = dir.File("out_" + mode + "_" + program.name);
      const auto r = testing::RunCommand(testing::TpoptBinary() + " smooth --mode=" + mode +
                                         " --in=" + in + " --out=" + out +
                                         " --cutter_radius=3 --quiet");
      ASSERT_EQ(r.exit_code, 0) << r.output;
      const std::string text = testing::ReadFileText(out);
      for (const std::string& line : program.standing) {
        EXPECT_TRUE(HasLine(text, line)) << "standing move not as programmed: " << line;
      }
      EXPECT_EQ(CountPoses(out, apt), CountPoses(in, apt));
      if (apt || !testing::FileExists(kRs274)) continue;
      const auto loaded = testing::RunCommand(std::string(kRs274) + " -g " + out);
      EXPECT_EQ(loaded.exit_code, 0) << loaded.output;
      std::istringstream lines(loaded.output);
      int feeds = 0;
      for (std::string line; std::getline(lines, line);) {
        EXPECT_EQ(line.find("rror"), std::string::npos) << line;
        feeds += line.find("STRAIGHT_FEED") != std::string::npos;
      }
      EXPECT_EQ(feeds + 1, static_cast<int>(CountPoses(in, apt)));  // all but the rapid
    }
  }
}

}  // namespace
}  // namespace tpopt
