#include "model/cad/cad_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "model/io/json_io.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

using testing::RunCommand;
using testing::SourcePath;
using testing::TempDir;
using testing::Tpopt;

constexpr double kTolMm = 1e-9;
constexpr int kGrid = 21;

// Largest |a(u, v) - b(u, v)| over a kGrid x kGrid grid of the unit square.
template <typename A, typename B>
double MaxGridGapMm(const A& a, const B& b) {
  double worst = 0.0;
  for (int i = 0; i < kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) {
      const double u = i / (kGrid - 1.0), v = j / (kGrid - 1.0);
      worst = std::max(worst, (a.Point(u, v) - b.Point(u, v)).norm());
    }
  }
  return worst;
}

// Two cubic rails on shared knots and the ruled patch (degree 3 x 1)
// between them, poles[i][0] on rail 0.
struct Rails {
  std::vector<double> knots = {0, 0, 0, 0, 0.3, 0.55, 1, 1, 1, 1};
  std::vector<Eigen::Vector3d> c0, c1;
  Rails() {
    for (int i = 0; i < 6; ++i) {
      c0.emplace_back(12.0 * i, 3.0 * std::sin(i), 0.5 * i * i);
      c1.emplace_back(12.0 * i + 4.0 * std::cos(i), 5.0 + i, 40.0 - 0.3 * i);
    }
  }
  CadPatch Patch() const {
    CadPatch p;
    p.degree_u = 3;
    p.degree_v = 1;
    p.knots_u = knots;
    p.knots_v = {0, 0, 1, 1};
    for (size_t i = 0; i < c0.size(); ++i) p.poles.push_back({c0[i], c1[i]});
    return p;
  }
  RuledSurface Surface(CutterSide side = CutterSide::kPositive) const {
    BSplineCurve r0, r1;
    EXPECT_TRUE(BSplineCurve::Create(3, knots, c0, "rail 0", &r0).ok());
    EXPECT_TRUE(BSplineCurve::Create(3, knots, c1, "rail 1", &r1).ok());
    return RuledSurface("rails", r0, r1, side);
  }
};

CadPatch Transpose(const CadPatch& p) {
  CadPatch t = p;
  std::swap(t.degree_u, t.degree_v);
  std::swap(t.knots_u, t.knots_v);
  t.poles.assign(p.poles[0].size(),
                 std::vector<Eigen::Vector3d>(p.poles.size()));
  for (size_t i = 0; i < p.poles.size(); ++i) {
    for (size_t j = 0; j < p.poles[0].size(); ++j)
      t.poles[j][i] = p.poles[i][j];
  }
  return t;
}

class CadIoTest : public ::testing::Test {
 protected:
  std::string Write(const std::string& name,
                    const std::vector<CadPatch>& patches,
                    const std::string& unit = "MM") {
    CadWriteOptions options;
    options.length_unit = unit;
    const std::string path = dir_.File(name);
    const Status s = WriteCadPatches(path, patches, options);
    EXPECT_TRUE(s.ok()) << s.message();
    return path;
  }
  std::string ReadError(const std::string& path,
                        const CadReadOptions& options = {}) {
    RuledSurface surface;
    CadSurfaceInfo info;
    const Status s = ReadCadRuledSurface(path, options, &surface, &info);
    return s.ok() ? "" : s.message();
  }
  TempDir dir_;
};

TEST_F(CadIoTest, RuledPatchBetweenTwoRailsReadsBackExactlyInStepAndIges) {
  const Rails rails;
  for (const std::string name : {"ruled.stp", "ruled.igs"}) {
    const std::string path = Write(name, {rails.Patch()});
    RuledSurface surface;
    CadSurfaceInfo info;
    const Status s = ReadCadRuledSurface(path, {}, &surface, &info);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_LT(MaxGridGapMm(surface, rails.Surface()), kTolMm) << name;
    EXPECT_EQ(info.ruling, "v") << name;
    EXPECT_TRUE(info.exact_ruled) << name;
    EXPECT_EQ(info.ruled_deviation_mm, 0.0) << name;
    EXPECT_EQ(info.face_count, 1) << name;
    EXPECT_EQ(info.face.Describe(),
              "face 0: Geom_BSplineSurface, degree 3 x 1, 6 x 2 poles")
        << name;
    // A FORWARD face: the cutter on S_u x S_v, which is r_u x r_v here.
    EXPECT_EQ(surface.cutter_side(), CutterSide::kPositive) << name;
  }
}

TEST_F(CadIoTest, RulingAlongUIsDetectedAndTheCutterSideFollowsTheNormal) {
  const Rails rails;
  CadPatch patch = Transpose(rails.Patch());
  RuledSurface surface;
  CadSurfaceInfo info;
  ASSERT_TRUE(
      ReadCadRuledSurface(Write("u.stp", {patch}), {}, &surface, &info).ok());
  EXPECT_EQ(info.ruling, "u");
  EXPECT_LT(MaxGridGapMm(surface, rails.Surface()), kTolMm);
  // r_u x r_v = S_v x S_u = -(the face normal): the cutter on the negative
  // side.
  EXPECT_EQ(surface.cutter_side(), CutterSide::kNegative);
  patch.reversed = true;
  ASSERT_TRUE(
      ReadCadRuledSurface(Write("r.stp", {patch}), {}, &surface, &info).ok());
  EXPECT_TRUE(info.face_reversed);
  EXPECT_EQ(surface.cutter_side(), CutterSide::kPositive);
  CadReadOptions flip;
  flip.flip_cutter_side = true;
  ASSERT_TRUE(
      ReadCadRuledSurface(dir_.File("r.stp"), flip, &surface, &info).ok());
  EXPECT_EQ(surface.cutter_side(), CutterSide::kNegative);
  // Asking for the other ruling: the boundary curves along v are the two
  // straight edges, far from this twisted face.
  CadReadOptions v;
  v.ruling = "v";
  EXPECT_NE(ReadError(dir_.File("u.stp"), v).find("is not ruled"),
            std::string::npos);
}

TEST_F(CadIoTest, BezierRuledFaceIsExact) {
  const Rails rails;
  CadPatch patch;
  patch.bezier = true;
  std::vector<double> knots = {0, 0, 0, 0, 1, 1, 1, 1};
  std::vector<Eigen::Vector3d> c0(rails.c0.begin(), rails.c0.begin() + 4);
  std::vector<Eigen::Vector3d> c1(rails.c1.begin(), rails.c1.begin() + 4);
  for (int i = 0; i < 4; ++i) patch.poles.push_back({c0[i], c1[i]});
  BSplineCurve r0, r1;
  ASSERT_TRUE(BSplineCurve::Create(3, knots, c0, "0", &r0).ok());
  ASSERT_TRUE(BSplineCurve::Create(3, knots, c1, "1", &r1).ok());
  RuledSurface surface;
  CadSurfaceInfo info;
  const Status s =
      ReadCadRuledSurface(Write("bezier.stp", {patch}), {}, &surface, &info);
  ASSERT_TRUE(s.ok()) << s.message();
  // OCCT writes a Bezier face as a B_SPLINE_SURFACE_WITH_KNOTS; read, it
  // is the same surface.
  EXPECT_TRUE(info.exact_ruled);
  EXPECT_LT(
      MaxGridGapMm(surface, RuledSurface("b", r0, r1, CutterSide::kPositive)),
      kTolMm);
}

TEST_F(CadIoTest, LinearExtrusionOfABSplineIsExactlyRuled) {
  const Rails rails;
  CadPatch patch = rails.Patch();
  const Eigen::Vector3d d(3.0, -4.0, 30.0);
  patch.extrusion_mm = d;
  std::vector<Eigen::Vector3d> moved;
  for (const Eigen::Vector3d& p : rails.c0) moved.push_back(p + d);
  BSplineCurve r0, r1;
  ASSERT_TRUE(BSplineCurve::Create(3, rails.knots, rails.c0, "0", &r0).ok());
  ASSERT_TRUE(BSplineCurve::Create(3, rails.knots, moved, "1", &r1).ok());
  const RuledSurface expected("e", r0, r1, CutterSide::kPositive);
  for (const std::string name : {"extrusion.stp", "extrusion.igs"}) {
    RuledSurface surface;
    CadSurfaceInfo info;
    const Status s =
        ReadCadRuledSurface(Write(name, {patch}), {}, &surface, &info);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(info.face.surface_type, "Geom_SurfaceOfLinearExtrusion") << name;
    EXPECT_TRUE(info.exact_ruled) << name;
    EXPECT_LT(MaxGridGapMm(surface, expected), kTolMm) << name;
  }
}

TEST_F(CadIoTest, RationalFacesAreRefusedByNameUnlessTheWeightsAreEqual) {
  const Rails rails;
  CadPatch patch = rails.Patch();
  patch.weights.assign(patch.poles.size(), {1.0, 1.0});
  patch.weights[2] = {0.5, 0.5};
  for (const std::string name : {"rational.stp", "rational.igs"}) {
    const std::string error = ReadError(Write(name, {patch}));
    EXPECT_NE(
        error.find(
            name +
            ": face 0: a rational Geom_BSplineSurface (weights 0.5 to 1)"),
        std::string::npos)
        << error;
  }
  // Equal weights are no rational surface: OCCT drops them, the face is exact.
  patch.weights.assign(patch.poles.size(), {2.0, 2.0});
  RuledSurface surface;
  CadSurfaceInfo info;
  ASSERT_TRUE(
      ReadCadRuledSurface(Write("equal.stp", {patch}), {}, &surface, &info)
          .ok());
  EXPECT_LT(MaxGridGapMm(surface, rails.Surface()), kTolMm);
}

// A bicubic face over the plane z = 0 whose two inner rows along v are
// lifted by h: z = h (B1(v) + B2(v)) = 3 h v (1 - v), straight along u.
CadPatch LiftedBicubic(double h) {
  CadPatch p;
  p.degree_u = 3;
  p.degree_v = 3;
  p.knots_u = {0, 0, 0, 0, 0.5, 1, 1, 1, 1};
  p.knots_v = {0, 0, 0, 0, 1, 1, 1, 1};
  for (int i = 0; i < 5; ++i) {
    p.poles.emplace_back();
    for (int j = 0; j < 4; ++j) {
      p.poles.back().emplace_back(10.0 * i, 10.0 * j,
                                  (j == 1 || j == 2) ? h : 0.0);
    }
  }
  return p;
}

TEST_F(CadIoTest, BicubicFaceGivesItsRuledDistanceAndIsRefusedAboveTheLimit) {
  const double h = 0.4;
  const std::string path = Write("bicubic.stp", {LiftedBicubic(h)});
  // Across v its boundary rails bound the plane z = 0; the face is at most
  // 3 h / 4 above it (v = 1/2, on the grid).
  CadReadOptions options;
  options.ruling = "v";
  options.max_ruled_deviation_mm = 1.0;
  RuledSurface surface;
  CadSurfaceInfo info;
  ASSERT_TRUE(ReadCadRuledSurface(path, options, &surface, &info).ok());
  EXPECT_FALSE(info.exact_ruled);
  EXPECT_NEAR(info.ruled_deviation_mm, 0.75 * h, 1e-9);
  EXPECT_EQ(surface.Point(0.3, 0.5).z(), 0.0);
  options.max_ruled_deviation_mm = 0.2;
  const std::string error = ReadError(path, options);
  EXPECT_NE(
      error.find("bicubic.stp: face 0 is not ruled: it lies up to 0.3 mm"),
      std::string::npos)
      << error;
  // Detected: along u the face is straight, so u is the ruling, exactly in
  // distance though not in degree.
  ASSERT_TRUE(ReadCadRuledSurface(path, {}, &surface, &info).ok());
  EXPECT_EQ(info.ruling, "u");
  EXPECT_FALSE(info.exact_ruled);
  EXPECT_LT(info.ruled_deviation_mm, 1e-9);
}

TEST_F(CadIoTest, BicubicFreeformSurfaceReadsBackExactly) {
  BSplineSurface json;
  ASSERT_TRUE(
      ReadBSplineSurfaceJson(
          SourcePath("data/surfaces/propeller_blade_freeform.json"), &json)
          .ok());
  const CadPatch patch = PatchOf(json);
  for (const std::string name : {"blade.step", "blade.iges"}) {
    BSplineSurface read;
    CadSurfaceInfo info;
    double side = 0.0;
    const Status s =
        ReadCadBSplineSurface(Write(name, {patch}), {}, &read, &side, &info);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_LT(MaxGridGapMm(read, json), kTolMm) << name;
    EXPECT_EQ(side, 1.0) << name;
  }
}

TEST_F(CadIoTest, InchFilesComeBackInMm) {
  const Rails rails;
  for (const std::string name : {"inch.stp", "inch.igs"}) {
    const std::string path = Write(name, {rails.Patch()}, "INCH");
    // The file holds inches: rail 0's last pole x = 60 mm = 2.36220472440945
    // in.
    EXPECT_NE(testing::ReadFileText(path).find("2.362204724409"),
              std::string::npos)
        << name;
    RuledSurface surface;
    CadSurfaceInfo info;
    ASSERT_TRUE(ReadCadRuledSurface(path, {}, &surface, &info).ok());
    EXPECT_LT(MaxGridGapMm(surface, rails.Surface()), kTolMm) << name;
    EXPECT_NE(info.length_unit.find("IN"), std::string::npos)
        << name << ": " << info.length_unit;
  }
}

TEST_F(CadIoTest, SeveralFacesAreListedAndChosenByIndex) {
  const Rails rails;
  CadPatch plane = rails.Patch();
  plane.as_plane = true;
  const std::string path =
      Write("three.stp", {LiftedBicubic(1.0), rails.Patch(), plane});
  std::string error = ReadError(path);
  EXPECT_NE(error.find(
                "three.stp: the file holds 3 faces; choose one with --face=N:\n"
                "  face 0: Geom_BSplineSurface, degree 3 x 3, 5 x 4 poles\n"
                "  face 1: Geom_BSplineSurface, degree 3 x 1, 6 x 2 poles\n"
                "  face 2: Geom_Plane"),
            std::string::npos)
      << error;
  CadReadOptions options;
  options.face_index = 1;
  RuledSurface surface;
  CadSurfaceInfo info;
  ASSERT_TRUE(ReadCadRuledSurface(path, options, &surface, &info).ok());
  EXPECT_LT(MaxGridGapMm(surface, rails.Surface()), kTolMm);
  EXPECT_EQ(info.face_count, 3);
  options.face_index = 2;
  error = ReadError(path, options);
  EXPECT_NE(
      error.find("three.stp: face 2 is a Geom_Plane, not a B-spline, Bezier or "
                 "linear extrusion surface"),
      std::string::npos)
      << error;
  options.face_index = 3;
  error = ReadError(path, options);
  EXPECT_NE(
      error.find("three.stp: face 3 does not exist; the file holds 3 faces:"),
      std::string::npos)
      << error;
  std::vector<CadFaceSummary> faces;
  ASSERT_TRUE(ListCadFaces(path, &faces).ok());
  ASSERT_EQ(faces.size(), 3u);
  EXPECT_EQ(faces[1].poles_u, 6);
}

TEST_F(CadIoTest, TrimmedFaceUsesTheNaturalBoundsAndSaysSo) {
  const Rails rails;
  CadPatch patch = rails.Patch();
  patch.trim_u = 0.6;
  RuledSurface surface;
  CadSurfaceInfo info;
  ASSERT_TRUE(
      ReadCadRuledSurface(Write("trim.stp", {patch}), {}, &surface, &info)
          .ok());
  EXPECT_TRUE(info.trimmed);
  EXPECT_LT(MaxGridGapMm(surface, rails.Surface()), kTolMm);
  ASSERT_TRUE(ReadCadRuledSurface(Write("whole.stp", {rails.Patch()}), {},
                                  &surface, &info)
                  .ok());
  EXPECT_FALSE(info.trimmed);
}

TEST_F(CadIoTest, BadFilesNameTheFile) {
  const Rails rails;
  const std::string good = Write("good.stp", {rails.Patch()});
  const std::string text = testing::ReadFileText(good);
  const std::string igs =
      testing::ReadFileText(Write("good.igs", {rails.Patch()}));
  std::ofstream(dir_.File("empty.stp")) << "";
  std::ofstream(dir_.File("half.stp")) << text.substr(0, text.size() / 2);
  std::ofstream(dir_.File("half.igs")) << igs.substr(0, igs.size() / 2);
  std::ofstream(dir_.File("junk.step"))
      << "ISO-10303-21;\nthis is no STEP\nEND-ISO-10303-21;\n";
  Write("vertex.stp", {});
  // A control point that refers to no entity, or to one of the wrong type:
  // both crashed OCCT 7.6's STEP translator before the parser's checks
  // were read (README, "Surfaces from CAD files").
  std::string hypar =
      testing::ReadFileText(SourcePath("data/surfaces/hypar.stp"));
  const size_t net = hypar.find("(#32,#33)");
  ASSERT_NE(net, std::string::npos);
  std::ofstream(dir_.File("dangling.stp"))
      << std::string(hypar).replace(net, 9, "(#32,#99999)");
  std::ofstream(dir_.File("wrongtype.stp"))
      << std::string(hypar).replace(net, 9, "(#32,#3)");
  // An empty parameter between two rows of the net: OCCT 7.6's STEP parser
  // crashed on it (SIGSEGV, found by tests/fuzz/mutate_cad.py).
  const size_t row = hypar.find("\n    ,(");
  ASSERT_NE(row, std::string::npos);
  std::ofstream(dir_.File("gap.stp"))
      << std::string(hypar).replace(row, 7, "\n  ,  ,(");
  const std::pair<std::string, std::string> rows[] = {
      {"empty.stp", "empty.stp: the file is empty"},
      {"half.stp", "half.stp: truncated STEP file"},
      {"half.igs", "half.igs: truncated IGES file"},
      {"junk.step", "junk.step: "},
      {"vertex.stp", "vertex.stp: the file holds no surface"},
      {"dangling.stp", "dangling.stp: Unresolved Reference"},
      {"wrongtype.stp", "wrongtype.stp: entity #31: Parameter n0.2"},
      {"gap.stp", "gap.stp: line 46: an empty parameter (',,') in entity #31"},
      {"missing.stp", "missing.stp: cannot open"},
  };
  for (const auto& [name, expected] : rows) {
    const std::string error = ReadError(dir_.File(name));
    EXPECT_NE(error.find(expected), std::string::npos) << name << ": " << error;
  }
  CadReadOptions bad;
  bad.ruling = "w";
  EXPECT_NE(ReadError(good, bad).find("--ruling must be u or v (got 'w')"),
            std::string::npos);
}

// Each inconsistency the IGES pre-check finds, made by hand in a file OCCT
// wrote (README, "Hostile files"). The
// parameter counts are IGES 5.3's: a curve (126) has 6 + (K + M + 2) +
// 4 (K + 1) + 2 parameters after its type and then an optional normal (3),
// a surface (128) 9 + (K1 + M1 + 2) + (K2 + M2 + 2) + 4 (K1 + 1)(K2 + 1) + 4.
TEST_F(CadIoTest, InconsistentIgesFilesAreRefusedNamingTheEntity) {
  const Rails rails;
  const std::string good = Write("good.igs", {rails.Patch()});
  std::vector<std::string> lines;
  {
    std::istringstream in(testing::ReadFileText(good));
    for (std::string line; std::getline(in, line);) lines.push_back(line);
  }
  // The first record of an entity's parameter data (by its start), and the
  // entity's DE number from that record's columns 66-72.
  auto find = [&](const std::string& start) {
    for (size_t i = 0; i < lines.size(); ++i) {
      if (lines[i].rfind(start, 0) == 0) return i;
    }
    ADD_FAILURE() << "no record starts with " << start;
    return size_t{0};
  };
  const size_t surface = find("128,5,1,3,1,");  // K1 5, K2 1, M1 3, M2 1
  const size_t curve = find("126,5,3,");        // K 5, M 3
  const std::string surface_de =
      std::to_string(std::stoi(lines[surface].substr(65, 7)));
  const std::string curve_de =
      std::to_string(std::stoi(lines[curve].substr(65, 7)));
  size_t p_count = 0, terminate = 0, last_d = 0;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (lines[i][72] == 'P') ++p_count;
    if (lines[i][72] == 'T') terminate = i;
    if (lines[i][72] == 'D') last_d = i;
  }
  // The surface's two directory records.
  size_t surface_d = 0;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (lines[i][72] == 'D' &&
        std::stoi(lines[i].substr(73)) == std::stoi(surface_de))
      surface_d = i;
  }
  ASSERT_EQ(lines[surface_d].substr(0, 8), "     128");
  const std::string surface_p =
      std::to_string(std::stoi(lines[surface_d].substr(8, 8)));
  // Numbers as IGES right-justifies them in 8 columns.
  auto field8 = [](const std::string& text) {
    return std::string(8 - text.size(), ' ') + text;
  };
  auto with = [&](size_t line, size_t column, const std::string& text) {
    std::vector<std::string> edited = lines;
    edited[line].replace(column, text.size(), text);
    return edited;
  };
  // The last directory entry's parameter data run to the P section's end.
  const std::string last_de =
      std::to_string(std::stoi(lines[last_d].substr(73)) - 1);
  const std::string last_pointer =
      std::to_string(std::stoi(lines[last_d - 1].substr(8, 8)));
  const std::string last_count =
      std::to_string(std::stoi(lines[last_d].substr(24, 8)));
  std::vector<std::string> truncated = lines;
  truncated.erase(truncated.begin() + (terminate - 5),
                  truncated.begin() + terminate);
  const std::string short_p = std::to_string(p_count - 5);
  truncated[terminate - 5].replace(25, 7, field8(short_p).substr(1));
  struct Row {
    std::string name;
    std::vector<std::string> lines;
    std::string expected;
  };
  const std::string in_surface = "entity DE " + surface_de + " (type 128): ";
  const std::string in_curve = "entity DE " + curve_de + " (type 126): ";
  std::vector<std::string> semicolon = lines;
  semicolon[surface + 4][semicolon[surface + 4].find(',')] = ';';
  std::vector<std::string> narrow = lines;
  narrow[surface + 1].erase(64, 1);
  const Row rows[] = {
      // A knot record of the surface or the curve that points back to no
      // entity: OCCT 7.6 cuts the entity's parameters there, and Init of
      // IGESGeom_BSplineSurface / IGESGeom_BSplineCurve crashed (SIGSEGV;
      // all seven crashes of the mutation run in the README were such).
      {"surface_back_pointer", with(surface + 1, 65, "00(0003"),
       in_surface + "P line " + std::to_string(std::stoi(surface_p) + 1) +
           " (line " + std::to_string(surface + 2) +
           ") points back to directory entry '00(0003'"},
      {"curve_back_pointer", with(curve + 1, 65, "00(0021"),
       in_curve + "P line " +
           std::to_string(std::stoi(lines[curve + 1].substr(73))) + " (line " +
           std::to_string(curve + 2) +
           ") points back to directory entry '00(0021'"},
      {"k_too_large", with(curve, 0, "126,9,3,"),
       in_curve + "K = 9, M = 3 need 62 parameters, its parameter data "
                  "hold 45"},
      {"m_too_large", with(surface, 0, "128,5,1,4,1,"),
       in_surface + "K1 = 5, M1 = 4, K2 = 1, M2 = 1 need 76 parameters, its "
                    "parameter data hold 75"},
      {"record_ends_early", semicolon,
       in_surface + "K1 = 5, M1 = 3, K2 = 1, M2 = 1 need 75 parameters"},
      {"k_below_m", with(curve, 0, "126,2,3,"),
       in_curve + "K = 2, M = 3: the degree must be at least 1 and K at "
                  "least M"},
      {"not_a_number", with(surface, 39, "X"),
       in_surface + "parameter 10 '0.000000000000000X+00' is not a number"},
      {"truncated_p_section", truncated,
       "entity DE " + last_de + " (type 126): its parameter data, " +
           last_count + " lines from P line " + last_pointer +
           ", do not lie in the P section (" + short_p + " lines)"},
      {"pointer_past_the_end", with(surface_d, 8, field8("9999")),
       in_surface +
           "its parameter data, 34 lines from P line 9999, do not "
           "lie in the P section (" +
           std::to_string(p_count) + " lines)"},
      {"line_count_too_large", with(surface_d + 1, 24, field8("35")),
       in_surface + "P line " + std::to_string(std::stoi(surface_p) + 34) +
           " (line " + std::to_string(surface + 35) +
           ") points back to directory entry '"},
      {"type_differs", with(surface, 0, "126,"),
       in_surface + "its parameter data start with '126', not its type"},
      {"types_disagree", with(surface_d + 1, 0, field8("129")),
       "directory entry " + surface_de + " (line " +
           std::to_string(surface_d + 1) +
           "): entity type '128' and '129' disagree"},
      {"narrow_record", narrow,
       "line " + std::to_string(surface + 2) + ": a record of 79 columns"},
      {"sequence_number", with(surface, 79, "9"),
       "line " + std::to_string(surface + 1) + ": sequence number"},
      {"terminate_count", with(terminate, 31, "9"),
       "the Terminate record's field 'P    109' does not count the " +
           std::to_string(p_count) + " P records"},
  };
  for (const Row& row : rows) {
    const std::string path = dir_.File(row.name + ".igs");
    std::ofstream out(path, std::ios::binary);
    for (const std::string& line : row.lines) out << line << "\n";
    out.close();
    const std::string error = ReadError(path);
    EXPECT_NE(error.find(path + ": " + row.expected), std::string::npos)
        << row.name << ": " << error;
  }
  // The run refuses them as bad input (exit 1), naming the entity.
  for (const std::string name :
       {"surface_back_pointer", "curve_back_pointer", "k_too_large",
        "m_too_large", "truncated_p_section", "pointer_past_the_end"}) {
    const auto r = RunCommand(
        Tpopt("generate --quiet --cutter_radius=4 --poses=20 --surface=" +
              dir_.File(name + ".igs") + " --out=" + dir_.File("p.cls")));
    EXPECT_EQ(r.exit_code, 1) << name << ": " << r.output;
    EXPECT_NE(r.output.find(name + ".igs: entity DE "), std::string::npos)
        << r.output;
  }
  // The file itself, and with CR LF line ends, reads as before.
  std::ofstream crlf(dir_.File("crlf.igs"), std::ios::binary);
  for (const std::string& line : lines) crlf << line << "\r\n";
  crlf.close();
  for (const std::string& path : {good, dir_.File("crlf.igs")}) {
    RuledSurface read;
    CadSurfaceInfo info;
    const Status s = ReadCadRuledSurface(path, {}, &read, &info);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_LT(MaxGridGapMm(read, rails.Surface()), kTolMm) << path;
  }
}

TEST_F(CadIoTest, SharedRuledSurfacesRoundTripThroughTheirWriter) {
  for (const std::string name : {"hypar", "impeller_blade", "jcde2022"}) {
    RuledSurface json;
    ASSERT_TRUE(
        ReadSurfaceJson(SourcePath("data/surfaces/" + name + ".json"), &json)
            .ok());
    for (const std::string ext : {".stp", ".igs"}) {
      const std::string path = dir_.File(name + ext);
      ASSERT_TRUE(WriteCadRuledSurface(path, json, {}).ok()) << name;
      RuledSurface read;
      CadSurfaceInfo info;
      const Status s = ReadCadRuledSurface(path, {}, &read, &info);
      ASSERT_TRUE(s.ok()) << s.message();
      EXPECT_TRUE(info.exact_ruled) << name << ext;
      EXPECT_LT(MaxGridGapMm(read, json), kTolMm) << name << ext;
      EXPECT_EQ(read.cutter_side(), json.cutter_side()) << name << ext;
    }
  }
}

// The checked-in STEP versions of the shared surfaces (written by
// tpopt_write_step_surfaces) still match their JSON.
TEST_F(CadIoTest, CheckedInStepSurfacesMatchTheirJson) {
  for (const std::string name : {"hypar", "impeller_blade", "jcde2022"}) {
    RuledSurface json, step;
    CadSurfaceInfo info;
    ASSERT_TRUE(
        ReadSurfaceJson(SourcePath("data/surfaces/" + name + ".json"), &json)
            .ok());
    const Status s = ReadCadRuledSurface(
        SourcePath("data/surfaces/" + name + ".stp"), {}, &step, &info);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_LT(MaxGridGapMm(step, json), kTolMm) << name;
    EXPECT_EQ(step.cutter_side(), json.cutter_side()) << name;
  }
  BSplineSurface json, step;
  ASSERT_TRUE(
      ReadBSplineSurfaceJson(
          SourcePath("data/surfaces/propeller_blade_freeform.json"), &json)
          .ok());
  double side = 0.0;
  CadSurfaceInfo info;
  const Status s = ReadCadBSplineSurface(
      SourcePath("data/surfaces/propeller_blade_freeform.stp"), {}, &step,
      &side, &info);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_LT(MaxGridGapMm(step, json), kTolMm);
}

// A path file without its comment lines ($$ ...), which name the surface.
std::string Moves(const std::string& path) {
  std::istringstream in(testing::ReadFileText(path));
  std::string line, out;
  while (std::getline(in, line)) {
    if (line.rfind("$$", 0) != 0) out += line + "\n";
  }
  return out;
}

// Every number of `a` within 1e-9 (relative above 1) of `b`'s, every other
// value equal, keys in `skip` ignored; `where` names the first difference.
bool SameReport(const nlohmann::json& a, const nlohmann::json& b,
                const std::vector<std::string>& skip, std::string* where) {
  if (a.is_object() && b.is_object()) {
    for (const auto& [key, value] : a.items()) {
      if (std::find(skip.begin(), skip.end(), key) != skip.end()) continue;
      if (!b.contains(key)) {
        *where = key + " missing";
        return false;
      }
      if (!SameReport(value, b[key], skip, where)) {
        *where = key + "." + *where;
        return false;
      }
    }
    return a.size() == b.size() || (*where = "key count", false);
  }
  if (a.is_number() && b.is_number()) {
    const double x = a.get<double>(), y = b.get<double>();
    if (std::abs(x - y) <= 1e-9 * std::max(1.0, std::abs(x))) return true;
    *where = std::to_string(x) + " vs " + std::to_string(y);
    return false;
  }
  if (a.is_array() && b.is_array() && a.size() == b.size()) {
    for (size_t i = 0; i < a.size(); ++i) {
      if (!SameReport(a[i], b[i], skip, where)) {
        *where = "[" + std::to_string(i) + "]" + *where;
        return false;
      }
    }
    return true;
  }
  if (a == b) return true;
  *where = a.dump() + " vs " + b.dump();
  return false;
}

TEST(CadSurfaceCliTest, EvaluateGivesTheSameReportFromStepAndJson) {
  TempDir dir;
  const std::string json = SourcePath("data/surfaces/impeller_blade.json");
  const std::string step = SourcePath("data/surfaces/impeller_blade.stp");
  const std::string machine =
      SourcePath("data/machines/linuxcnc_xyzac_trt_sim.json");
  const std::string from_json = dir.File("j.cls"),
                    from_step = dir.File("s.cls");
  for (const auto& [surface, out] :
       {std::pair{json, from_json}, {step, from_step}}) {
    const auto r =
        RunCommand(Tpopt("generate --quiet --cutter_radius=4 --poses=120 "
                         "--uv_distortion=0.03 --surface=" +
                         surface + " --out=" + out));
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  // The same path from either file, to the 6 decimals APT keeps.
  const std::string moves = Moves(from_json);
  EXPECT_GT(moves.size(), 1000u);
  EXPECT_TRUE(moves == Moves(from_step));
  for (const auto& [surface, report] :
       {std::pair{json, dir.File("j.json")}, {step, dir.File("s.json")}}) {
    const auto r = RunCommand(
        Tpopt("evaluate --quiet --in=" + from_json + " --machine=" + machine +
              " --surface=" + surface + " --report=" + report));
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  const nlohmann::json j = testing::ReadJson(dir.File("j.json"));
  nlohmann::json s = testing::ReadJson(dir.File("s.json"));
  ASSERT_TRUE(s.contains("surface_cad"));
  EXPECT_EQ(s["surface_cad"]["ruling"], "v");
  EXPECT_EQ(s["surface_cad"]["exact_ruled"], true);
  EXPECT_EQ(s["surface_cad"]["trimmed"], false);
  EXPECT_EQ(s["surface_cad"]["length_unit"], "millimetre");
  s.erase("surface_cad");
  std::string where;
  EXPECT_TRUE(SameReport(j, s, {"surface", "command"}, &where)) << where;
  EXPECT_GT(j["max_overcut_mm"].get<double>(), 0.0);
}

TEST(CadSurfaceCliTest, StripwidthAndPencilReadStepFaces) {
  TempDir dir;
  const std::string machine = SourcePath("data/machines/jcde2022_ac.json");
  for (const std::string ext : {"json", "stp"}) {
    const auto r = RunCommand(
        Tpopt("stripwidth --quiet --method=sturz --cutter=torus:8,2 "
              "--tolerance_mm=0.01 "
              "--cc_points=6 --surface=" +
              SourcePath("data/surfaces/propeller_blade_freeform." + ext) +
              " --machine=" + machine + " --out=" + dir.File(ext + ".cls") +
              " --report=" + dir.File(ext + ".json")));
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  std::string where;
  nlohmann::json step = testing::ReadJson(dir.File("stp.json"));
  EXPECT_EQ(step["surface_cad"]["face"], 0);
  step.erase("surface_cad");
  EXPECT_TRUE(SameReport(testing::ReadJson(dir.File("json.json")), step,
                         {"surface", "command", "solve_time_s", "title"},
                         &where))
      << where;

  // The pencil surface as a STEP face; the same report as from its JSON.
  BSplineSurface json;
  const std::string pencil_json =
      SourcePath("data/pencil/surface_120x120x55.json");
  ASSERT_TRUE(ReadBSplineSurfaceJson(pencil_json, &json).ok());
  const CadPatch patch = PatchOf(json);
  ASSERT_TRUE(WriteCadPatches(dir.File("pencil.stp"), {patch}, {}).ok());
  for (const std::string& surface : {pencil_json, dir.File("pencil.stp")}) {
    const std::string name = surface == pencil_json ? "pj" : "ps";
    const auto r = RunCommand(Tpopt(
        "pencil --quiet --ball_radius=1.5 --feed=3000 --surface=" + surface +
        " --curve=" + SourcePath("data/pencil/flower_guides.json") + " --out=" +
        dir.File(name + ".cls") + " --report=" + dir.File(name + ".json")));
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  const std::string moves = Moves(dir.File("pj.cls"));
  EXPECT_GT(moves.size(), 1000u);
  EXPECT_TRUE(moves == Moves(dir.File("ps.cls")));
}

}  // namespace
}  // namespace tpopt
