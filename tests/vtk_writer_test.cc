#include "model/io/vtk_writer.h"

#include <gtest/gtest.h>

#include "tests/test_util.h"
#include "tests/vtk_test_reader.h"

namespace tpopt {
namespace {

using testing::FileExists;
using testing::ParsedPolyData;
using testing::TempDir;

// Two quads sharing an edge, a segment and a polyline, and two arrays.
PolyData Sample() {
  PolyData data;
  for (int i = 0; i < 6; ++i) {
    data.points_w.push_back(Eigen::Vector3d(i % 3 * 1.5, i / 3 * 2.25, 0.1 * i - 0.123456789));
  }
  data.polys = {{0, 1, 4, 3}, {1, 2, 5, 4}};
  data.lines = {{0, 5}, {0, 1, 2, 5}};
  data.point_scalars = {{"deviation_mm", {-0.01, 0.0, 0.002, 1e-7, -3.5, 0.25}},
                        {"part", {0, 0, 0, 1, 1, 2}}};
  return data;
}

void ExpectSameAs(const PolyData& data, const ParsedPolyData& parsed) {
  ASSERT_EQ(parsed.point_count(), data.points_w.size());
  for (size_t i = 0; i < data.points_w.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(parsed.points[3 * i + k], data.points_w[i][k], 1e-9) << i << " " << k;
    }
  }
  EXPECT_EQ(parsed.lines, data.lines);
  EXPECT_EQ(parsed.polys, data.polys);
  ASSERT_EQ(parsed.point_scalars.size(), data.point_scalars.size());
  for (const auto& [name, values] : data.point_scalars) {
    ASSERT_EQ(parsed.point_scalars.count(name), 1u) << name;
    const std::vector<double>& back = parsed.point_scalars.at(name);
    ASSERT_EQ(back.size(), values.size()) << name;
    for (size_t i = 0; i < values.size(); ++i) EXPECT_NEAR(back[i], values[i], 1e-12) << name;
  }
}

TEST(VtkWriterTest, BothFormatsReadBackTheSame) {
  PolyData lines_only = Sample();  // a scene without a surface
  lines_only.polys.clear();
  for (const PolyData& data : {Sample(), lines_only}) {
    std::string error;
    ExpectSameAs(data, testing::ParseVtp(VtpText(data), &error));
    EXPECT_EQ(error, "") << "vtp";
    ExpectSameAs(data, testing::ParseLegacyVtk(LegacyVtkText(data), &error));
    EXPECT_EQ(error, "") << "legacy vtk";
  }
  EXPECT_EQ(VtpText(lines_only).find("<Polys>"), std::string::npos);
  EXPECT_NE(VtpText(lines_only).find("NumberOfPolys=\"0\""), std::string::npos);
}

TEST(VtkWriterTest, TheReaderCatchesBrokenFiles) {
  // The parse-back tests are only as good as the reader's objections.
  EXPECT_NE(testing::XmlWellFormedError("<a><b></a></b>"), "");
  EXPECT_NE(testing::XmlWellFormedError("<a x=1></a>"), "");
  EXPECT_NE(testing::XmlWellFormedError("<a></a><b/>"), "");
  EXPECT_NE(testing::XmlWellFormedError("<a>"), "");
  EXPECT_EQ(testing::XmlWellFormedError("<?xml version=\"1.0\"?>\n<a x=\"1\"><b/>t</a>\n"), "");
  std::string vtp = VtpText(Sample());
  vtp.replace(vtp.find("NumberOfLines=\"2\""), 17, "NumberOfLines=\"3\"");
  std::string error;
  testing::ParseVtp(vtp, &error);
  EXPECT_NE(error, "");
  std::string legacy = LegacyVtkText(Sample());
  legacy.replace(legacy.find("LINES 2 8"), 9, "LINES 2 9");
  error.clear();
  testing::ParseLegacyVtk(legacy, &error);
  EXPECT_NE(error, "");
}

TEST(VtkWriterTest, FormatFollowsTheExtension) {
  VtkFormat format;
  ASSERT_TRUE(VtkFormatOf("out/scene.VTP", &format));
  EXPECT_EQ(format, VtkFormat::kXmlPolyData);
  ASSERT_TRUE(VtkFormatOf("scene.vtk", &format));
  EXPECT_EQ(format, VtkFormat::kLegacy);
  EXPECT_FALSE(VtkFormatOf("scene.vtu", &format));
  EXPECT_FALSE(VtkFormatOf("dir.vtp/scene", &format));
}

TEST(VtkWriterTest, WritesWholeFilesAndNothingOnFailure) {
  TempDir dir;
  const PolyData data = Sample();
  ASSERT_TRUE(WritePolyData(dir.File("s.vtp"), data).ok());
  ASSERT_TRUE(WritePolyData(dir.File("s.vtk"), data).ok());
  EXPECT_EQ(testing::ReadFileText(dir.File("s.vtp")), VtpText(data));
  EXPECT_EQ(testing::ReadFileText(dir.File("s.vtk")), LegacyVtkText(data));

  Status s = WritePolyData(dir.File("missing/s.vtp"), data);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("missing/s.vtp"), std::string::npos) << s.message();
  s = WritePolyData(dir.File("s.obj"), data);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("s.obj"), std::string::npos) << s.message();
  EXPECT_FALSE(FileExists(dir.File("s.obj")));
}

}  // namespace
}  // namespace tpopt
