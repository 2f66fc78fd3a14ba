// The bad-input matrix, end to end through the tpopt command: every row
// gives a clear message and no partial output file; rows that are errors
// give exit 1 and name the file and the line, pose or key.
#include <sys/resource.h>
#include <sys/stat.h>

#include <cstdio>
#include <fstream>

#include <gtest/gtest.h>

#include "model/cad/cad_io.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

using testing::FileExists;
using testing::RunCommand;
using testing::SourcePath;
using testing::TempDir;

const std::string kBlade = SourcePath("data/surfaces/impeller_blade.json");
const std::string kSim = SourcePath("data/machines/linuxcnc_xyzac_trt_sim.json");

struct Row {
  std::string name;       // the file the row writes
  std::string contents;
  std::string args;       // beyond --in/--out
  std::string expected;   // in the message
};

class BadInputMatrixTest : public ::testing::Test {
 protected:
  testing::CommandResult Smooth(const std::string& in, const std::string& args) {
    std::remove(dir_.File("out.cls").c_str());
    std::remove(dir_.File("r.json").c_str());
    return RunCommand(testing::TpoptBinary() + " smooth --quiet --mode=spline --in=" + in +
                      " --out=" + dir_.File("out.cls") + " --report=" + dir_.File("r.json") + " " +
                      args);
  }
  std::string Write(const std::string& name, const std::string& text) {
    std::ofstream(dir_.File(name)) << text;
    return dir_.File(name);
  }
  TempDir dir_;
};

TEST_F(BadInputMatrixTest, ErrorsExitOneNamingTheFileAndPlaceWithNoOutput) {
  const std::string good_rail =
      "{\"degree\": 1, \"knots\": [0, 0, 1, 1], \"control_points\": [[0,0,0],[50,0,0]]}";
  const Row rows[] = {
      {"trunc.cls", "CUTTER/8\nGOTO/1,2,3\nGOTO/4,5,", "", "trunc.cls:3: GOTO needs 3 or 6"},
      {"cont.cls", "CUTTER/8\nGOTO/1,2,3\nGOTO/4,5,$\n", "", "cont.cls:3: statement continued"},
      {"nan.cls", "CUTTER/8\nGOTO/1,2,3\nGOTO/nan,5,6\n", "", "nan.cls:3: GOTO argument 1 'nan'"},
      {"inf.cls", "CUTTER/8\nGOTO/1,2,3\nGOTO/4,-inf,6\n", "", "inf.cls:3: GOTO argument 2"},
      {"huge.cls", "CUTTER/8\nGOTO/1,2,3\nGOTO/4,5,1e308\n", "", "huge.cls:3: GOTO argument 3"},
      {"negr.cls", "TLDATA/MILL,-8,0,30\nGOTO/1,2,3\nGOTO/4,5,6\n", "", "negr.cls:1: cutter radius -4"},
      {"zero.cls", "CUTTER/8\nGOTO/1,2,3,0,0,0\nGOTO/4,5,6\n", "", "zero.cls:2: zero-length tool axis"},
      {"one.cls", "CUTTER/8\nGOTO/18,-4,41.7,0.97,0,0.24\n", "", "one.cls: the path has no cutting move"},
      {"trunc.ngc", "G21 G90\nG1 X1 Y2 Z3 F100\nG1 X", "", "trunc.ngc:3: word X: a value is missing"},
      {"beyond.cls", "CUTTER/8\nGOTO/0,0,0,0,-0.9396926,-0.3420201\nGOTO/1,0,0\n",
       "--machine=" + kSim, "pose 0 (line 2): A = "},
      {"ok.cls", "CUTTER/8\nGOTO/0,0,0\nGOTO/1,0,0\nGOTO/2,0,0\n", "--cutter_radius=-4",
       "cutter radius -4"},
  };
  for (const Row& row : rows) {
    const auto r = Smooth(Write(row.name, row.contents), row.args);
    EXPECT_EQ(r.exit_code, 1) << row.name << ": " << r.output;
    EXPECT_NE(r.output.find(row.expected), std::string::npos) << row.name << ": " << r.output;
    EXPECT_FALSE(FileExists(dir_.File("out.cls"))) << row.name;
    EXPECT_FALSE(FileExists(dir_.File("r.json"))) << row.name;
  }
  // Surface and machine files: truncated, 1e308, non-monotone knots.
  const std::string path = Write("p.cls", "CUTTER/8\nGOTO/0,0,0\nGOTO/1,0,0\nGOTO/2,0,0\n");
  const Row files[] = {
      {"trunc.json", "{\"rails\": [\n" + good_rail + ",\n", "--surface=", "trunc.json:3: malformed JSON"},
      {"big.json",
       "{\"rails\": [" + good_rail +
           ", {\"degree\": 1, \"knots\": [0,0,1,1], \"control_points\": [[0,0,9],[1e308,0,9]]}]}",
       "--surface=", "big.json: rails[1].control_points[1][0] = 1e+308 is out of range"},
      {"knots.json",
       "{\"rails\": [" + good_rail +
           ", {\"degree\": 1, \"knots\": [0,0.6,0.4,1,1], \"control_points\": "
           "[[0,0,9],[1,0,9],[2,0,9]]}]}",
       "--surface=", "knots.json: rails[1]: knots decrease at index 2"},
      {"machine.json", "{\"kinematics\": \"xyzac-trt\", \"axes\": {\"A\": {\"max_velocity\": -1}}}",
       "--machine=", "machine.json: axes.A"},
  };
  for (const Row& row : files) {
    const auto r = Smooth(path, row.args + Write(row.name, row.contents));
    EXPECT_EQ(r.exit_code, 1) << row.name << ": " << r.output;
    EXPECT_NE(r.output.find(row.expected), std::string::npos) << row.name << ": " << r.output;
    EXPECT_FALSE(FileExists(dir_.File("out.cls"))) << row.name;
  }
}

// STEP and IGES surfaces: exit 1 naming the file (and the face), nothing
// written.
TEST_F(BadInputMatrixTest, CadSurfaceErrorsExitOneNamingTheFileAndFace) {
  if (!CadIoAvailable()) GTEST_SKIP() << "built without OpenCASCADE";
  CadPatch ruled;
  ruled.knots_u = {0, 0, 0, 0, 1, 1, 1, 1};
  ruled.knots_v = {0, 0, 1, 1};
  for (int i = 0; i < 4; ++i) {
    ruled.poles.push_back(
        {Eigen::Vector3d(10.0 * i, 0, 0), Eigen::Vector3d(10.0 * i, 5.0 + i * i, 30)});
  }
  CadPatch plane = ruled;
  plane.as_plane = true;
  const std::string good = dir_.File("good.stp"), two = dir_.File("two.stp");
  ASSERT_TRUE(WriteCadPatches(good, {ruled}, {}).ok());
  ASSERT_TRUE(WriteCadPatches(two, {ruled, plane}, {}).ok());
  ASSERT_TRUE(WriteCadPatches(dir_.File("none.stp"), {}, {}).ok());
  ASSERT_TRUE(WriteCadPatches(dir_.File("plane.igs"), {plane}, {}).ok());
  const std::string text = testing::ReadFileText(good);
  Write("cut.stp", text.substr(0, text.size() / 2));
  // An IGES surface (128) whose K1 asks for more poles than it holds
  // (tpopt's IGES pre-check, model/cad/cad_io.cc).
  ASSERT_TRUE(WriteCadPatches(dir_.File("good.igs"), {ruled}, {}).ok());
  std::string iges = testing::ReadFileText(dir_.File("good.igs"));
  const size_t k1 = iges.find("\n128,3,1,3,1,");
  ASSERT_NE(k1, std::string::npos);
  Write("k1.igs", iges.replace(k1 + 5, 1, "9"));
  Write("empty.step", "");
  const std::string path = Write("p.cls", "CUTTER/8\nGOTO/0,0,0\nGOTO/1,0,0\nGOTO/2,0,0\n");
  const Row rows[] = {
      {"cut.stp", "", "--surface=" + dir_.File("cut.stp"), "cut.stp: truncated STEP file"},
      {"empty.step", "", "--surface=" + dir_.File("empty.step"), "empty.step: the file is empty"},
      {"none.stp", "", "--surface=" + dir_.File("none.stp"),
       "none.stp: the file holds no surface"},
      {"two.stp", "", "--surface=" + two, "two.stp: the file holds 2 faces; choose one"},
      {"two.stp", "", "--surface=" + two + " --face=2", "two.stp: face 2 does not exist"},
      {"two.stp", "", "--surface=" + two + " --face=1",
       "two.stp: face 1 is a Geom_Plane, not a B-spline"},
      {"plane.igs", "", "--surface=" + dir_.File("plane.igs"),
       "plane.igs: face 0 is a Geom_Plane"},
      {"k1.igs", "", "--surface=" + dir_.File("k1.igs"),
       "k1.igs: entity DE 3 (type 128): K1 = 9, M1 = 3, K2 = 1, M2 = 1 need "},
      {"good.stp", "", "--surface=" + good + " --ruling=u --max_ruled_deviation_mm=0.001",
       "good.stp: face 0 is not ruled"},
  };
  for (const Row& row : rows) {
    const auto r = Smooth(path, row.args);
    EXPECT_EQ(r.exit_code, 1) << row.args << ": " << r.output;
    EXPECT_NE(r.output.find(row.expected), std::string::npos) << row.args << ": " << r.output;
    EXPECT_FALSE(FileExists(dir_.File("out.cls"))) << row.args;
    EXPECT_FALSE(FileExists(dir_.File("r.json"))) << row.args;
  }
  // A bad --ruling is a usage error of the flags, but reaches the reader as
  // bad input naming the file.
  const auto r = Smooth(path, "--surface=" + good + " --ruling=w");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("good.stp: --ruling must be u or v (got 'w')"), std::string::npos) << r.output;
}

TEST_F(BadInputMatrixTest, UnwritableOutputsExitOneAndLeaveNothing) {
  const std::string path = Write("p.cls", "CUTTER/8\nGOTO/0,0,0\nGOTO/1,0,0\nGOTO/2,0,0\n");
  auto r = RunCommand(testing::TpoptBinary() + " smooth --quiet --mode=spline --in=" + path +
                      " --out=" + dir_.File("missing/out.cls"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("missing/out.cls"), std::string::npos) << r.output;
  // A folder where the output file should go stands in for a read-only
  // target (root can write anywhere): the rename fails, nothing is left.
  ASSERT_EQ(mkdir(dir_.File("taken.cls").c_str(), 0755), 0);
  ASSERT_EQ(mkdir(dir_.File("taken.cls/x").c_str(), 0755), 0);
  r = RunCommand(testing::TpoptBinary() + " smooth --quiet --mode=spline --in=" + path +
                 " --out=" + dir_.File("taken.cls"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("taken.cls"), std::string::npos) << r.output;
}

// A degenerate but legal path smoothed in both modes: no crash, a message
// when refused, and never a partial file. Repeated poses (common in CAM
// files) and a path that stands on one ruling (`must_smooth`) must smooth
// normally: the latter was once refused as the solver's failure, exit 3,
// for its zero-width u range.
void ExpectNoCrashNorHalfFile(const TempDir& dir, const std::string& in, const std::string& name,
                              bool must_smooth) {
  for (const std::string mode : {"spline", "high_accuracy"}) {
    const std::string out = dir.File(name + "_" + mode + ".out.cls");
    // Without split moves: their re-solves (tested on random cases) took
    // these paths from 14 s to 126 s in Release, past the sanitizer run's
    // time, and add no handling of bad input.
    const auto r = RunCommand(testing::TpoptBinary() + " smooth --quiet --mode=" + mode +
                              " --split_moves_for_tolerance=1 --in=" + in + " --out=" + out +
                              " --surface=" + kBlade);
    EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1 || r.exit_code == 3)
        << name << " " << mode << ": exit " << r.exit_code << " " << r.output;
    if (must_smooth) {
      EXPECT_EQ(r.exit_code, 0) << name << " " << mode << ": " << r.output;
    }
    if (r.exit_code == 0) {
      EXPECT_TRUE(FileExists(out)) << name;
    } else {
      EXPECT_FALSE(FileExists(out)) << name;
      EXPECT_FALSE(r.output.empty()) << name;
    }
  }
}

TEST_F(BadInputMatrixTest, DegeneratePathsNeverCrashOrLeaveHalfFiles) {
  std::string same = "CUTTER/8\n", repeated = "CUTTER/8\n";
  for (int i = 0; i < 6; ++i) same += "GOTO/18,-4,41.7,0.97,0,0.24\n";
  for (int i = 0; i < 20; ++i) {
    const std::string g = "GOTO/" + std::to_string(18 + 0.1 * i) + ",-4,41.7,0.97,0,0.24\n";
    repeated += g + g;
  }
  ExpectNoCrashNorHalfFile(
      dir_,
      Write("two.cls", "CUTTER/8\nGOTO/18,-4,41.7,0.97,0,0.24\nGOTO/18.1,-4,41.5,0.97,0,0.24\n"),
      "two.cls", false);
  ExpectNoCrashNorHalfFile(dir_, Write("same.cls", same), "same.cls", true);
  ExpectNoCrashNorHalfFile(dir_, Write("repeated.cls", repeated), "repeated.cls", true);
  ExpectNoCrashNorHalfFile(
      dir_,
      Write("pole.cls",
            "CUTTER/8\nGOTO/0,0,0,0,0,1\nGOTO/1,0,0,0,0,1\nGOTO/2,0,0,0.01,0,1\nGOTO/3,0,0\n"),
      "pole.cls", false);
}

// C winding 4 turns at A = 20 deg, 30 deg a move, 4 mm off the blade, as
// DegeneratePathsNeverCrashOrLeaveHalfFiles. Its high-accuracy solve takes
// about 20 s in Release (3 s when it was cut from 11 turns to 4) and 4 min
// under the sanitizers, so CI's sanitizer run leaves it to the Release run.
TEST_F(BadInputMatrixTest, AWindingPathNeverCrashesOrLeavesHalfFiles) {
  std::string winding = "CUTTER/8\n";
  for (int i = 0; i <= 48; ++i) {
    const double c = i * 30 * M_PI / 180, a = 20 * M_PI / 180;
    winding += "GOTO/" + std::to_string(i * 0.1) + ",0,0," + std::to_string(std::sin(a) * std::sin(c)) +
               "," + std::to_string(std::sin(a) * std::cos(c)) + "," + std::to_string(std::cos(a)) +
               "\n";
  }
  ExpectNoCrashNorHalfFile(dir_, Write("winding.cls", winding), "winding.cls", false);
}

// A very large program (600,000 moves, about 30 MB) with one bad number on
// its last line: the reader streams it, so the error names that line, the
// whole run stays within a memory bound far below what a quadratic reader
// would need, and nothing is written.
TEST_F(BadInputMatrixTest, VeryLargeInputStreamsToTheErrorOnItsLastLine) {
  constexpr int kMoves = 600000;
  const std::string in = dir_.File("large.cls");
  {
    std::ofstream out(in);
    out << "CUTTER/8\n";
    for (int i = 0; i < kMoves; ++i) {
      out << "GOTO/" << 0.001 * i << ",-4,41.7,0.97,0,0.2431049\n";
    }
    out << "GOTO/1,2,nan,0,0,1\n";
  }
  const auto r = RunCommand(testing::TpoptBinary() + " evaluate --quiet --in=" + in +
                            " --report=" + dir_.File("large.json"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("large.cls"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(std::to_string(kMoves + 2)), std::string::npos) << r.output;
  EXPECT_FALSE(FileExists(dir_.File("large.json")));
  struct rusage usage {};
  ASSERT_EQ(getrusage(RUSAGE_CHILDREN, &usage), 0);
  // ru_maxrss is in KiB on Linux. 600,000 poses hold about 60 MB, and the
  // program's blocks (model/path/program.h: each line's text, so that a written
  // program is the user's own) about as much again; the sanitizer build
  // roughly triples that.
  EXPECT_LT(usage.ru_maxrss, 800 * 1024) << "peak memory of the largest child, KiB";
}

}  // namespace
}  // namespace tpopt
