#include "model/io/gcode_expression.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tpopt {
namespace {

// The value of `code` read from its start, and where reading stopped.
double ValueOf(const GcodeParameters& p, const std::string& code, size_t* end = nullptr) {
  size_t pos = 0;
  double value = 0.0;
  const Status s = p.ReadValue(code, &pos, &value);
  EXPECT_TRUE(s.ok()) << code << ": " << s.message();
  if (end != nullptr) *end = pos;
  return value;
}

std::string ErrorOf(const GcodeParameters& p, const std::string& code) {
  size_t pos = 0;
  double value = 0.0;
  const Status s = p.ReadValue(code, &pos, &value);
  return s.ok() ? "ok" : s.message();
}

TEST(GcodeExpressionTest, NumbersStopAtTheNextWord) {
  GcodeParameters p;
  size_t end = 0;
  EXPECT_EQ(ValueOf(p, "-12.5Y3", &end), -12.5);
  EXPECT_EQ(end, 5u);
  EXPECT_EQ(ValueOf(p, ".5"), 0.5);
  EXPECT_EQ(ValueOf(p, "+3."), 3.0);
  EXPECT_NE(ErrorOf(p, "0X1").find("ok"), std::string::npos);  // 0, then word X
  EXPECT_NE(ErrorOf(p, "-").find("no valid number"), std::string::npos);
  EXPECT_NE(ErrorOf(p, "1.2.3").find("no valid number"), std::string::npos);
}

TEST(GcodeExpressionTest, PrecedenceAsTheLinuxCncManualGivesIt) {
  GcodeParameters p;
  // ** before * / MOD before + - before comparisons before AND OR XOR.
  EXPECT_EQ(ValueOf(p, "[1+2*3]"), 7.0);
  EXPECT_EQ(ValueOf(p, "[2*3**2]"), 18.0);
  EXPECT_EQ(ValueOf(p, "[10-4-3]"), 3.0);  // left to right
  EXPECT_EQ(ValueOf(p, "[12/3/2]"), 2.0);
  EXPECT_EQ(ValueOf(p, "[7MOD3+1]"), 2.0);
  EXPECT_EQ(ValueOf(p, "[-7MOD3]"),
            2.0);  // MOD is never negative for a positive divisor
  EXPECT_EQ(ValueOf(p, "[1+1EQ2]"), 1.0);
  EXPECT_EQ(ValueOf(p, "[1LT2AND3GT4]"), 0.0);
  EXPECT_EQ(ValueOf(p, "[1LT2OR3GT4]"), 1.0);
  EXPECT_EQ(ValueOf(p, "[1XOR1]"), 0.0);
  EXPECT_EQ(ValueOf(p, "[[1+2]*[3+4]]"), 21.0);
  EXPECT_EQ(ValueOf(p, "-[2*3]"), -6.0);
}

TEST(GcodeExpressionTest, FunctionsInDegrees) {
  GcodeParameters p;
  EXPECT_NEAR(ValueOf(p, "SIN[30]"), 0.5, 1e-15);
  EXPECT_NEAR(ValueOf(p, "COS[60]"), 0.5, 1e-15);
  EXPECT_NEAR(ValueOf(p, "TAN[45]"), 1.0, 1e-15);
  EXPECT_NEAR(ValueOf(p, "ASIN[0.5]"), 30.0, 1e-12);
  EXPECT_NEAR(ValueOf(p, "ACOS[0.5]"), 60.0, 1e-12);
  EXPECT_NEAR(ValueOf(p, "ATAN[1]/[-1]"), 135.0, 1e-12);
  EXPECT_EQ(ValueOf(p, "ABS[-3]"), 3.0);
  EXPECT_EQ(ValueOf(p, "SQRT[16]"), 4.0);
  EXPECT_EQ(ValueOf(p, "FIX[-2.5]"), -3.0);
  EXPECT_EQ(ValueOf(p, "FUP[2.1]"), 3.0);
  EXPECT_EQ(ValueOf(p, "ROUND[2.5]"), 3.0);
  EXPECT_NEAR(ValueOf(p, "LN[EXP[2]]"), 2.0, 1e-15);
  EXPECT_NE(ErrorOf(p, "FOO[1]").find("unknown function 'FOO'"), std::string::npos);
  EXPECT_NE(ErrorOf(p, "SQRT[-1]").find("not finite"), std::string::npos);
  EXPECT_NE(ErrorOf(p, "[1/0]").find("division by zero"), std::string::npos);
  EXPECT_NE(ErrorOf(p, "[1+2").find("closing ']'"), std::string::npos);
}

TEST(GcodeExpressionTest, ParametersNumberedNamedAndIndirect) {
  GcodeParameters p;
  size_t pos = 0;
  std::pair<std::string, double> a;
  ASSERT_TRUE(p.ReadAssignment("#<FRATE>=[100*3]", &pos, &a).ok());
  EXPECT_EQ(a.first, "#<FRATE>");
  EXPECT_EQ(a.second, 300.0);
  p.Set(a.first, a.second);
  p.Set("#2", 7.0);
  EXPECT_EQ(ValueOf(p, "#<FRATE>"), 300.0);
  EXPECT_EQ(ValueOf(p, "[#2*2+1]"), 15.0);
  EXPECT_EQ(ValueOf(p, "#[1+1]"), 7.0);
  p.Set("#7", 42.0);
  EXPECT_EQ(ValueOf(p, "##2"), 42.0);  // #2 is 7: the value of #7
  EXPECT_EQ(ValueOf(p, "-#2"), -7.0);
  EXPECT_EQ(ValueOf(p, "#31"), 0.0);  // numbered parameters start at 0
  EXPECT_EQ(ValueOf(p, "EXISTS[#<FRATE>]"), 1.0);
  EXPECT_EQ(ValueOf(p, "EXISTS[#<NONE>]"), 0.0);
  EXPECT_NE(ErrorOf(p, "#<NONE>").find("#<NONE> is read before the program sets it"),
            std::string::npos);
  EXPECT_NE(ErrorOf(p, "#<_X>").find("predefined"), std::string::npos);
  EXPECT_NE(ErrorOf(p, "#5221").find("machine state"), std::string::npos);
  EXPECT_NE(ErrorOf(p, "#0.5").find("not an integer"), std::string::npos);
  pos = 0;
  EXPECT_NE(p.ReadAssignment("#1+2", &pos, &a).message().find("not followed by '='"),
            std::string::npos);
}

}  // namespace
}  // namespace tpopt
