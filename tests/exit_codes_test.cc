// The one mapping from a Status's code to the tpopt command's exit code.
#include "apps/exit_codes.h"

#include <gtest/gtest.h>

namespace tpopt {
namespace {

TEST(ExitCodesTest, EachStatusCodeMapsToTheDocumentedExitCode) {
  EXPECT_EQ(ExitCodeOf(Status::Ok()), 0);
  EXPECT_EQ(ExitCodeOf(Status::Error("bad input")), 1);
  EXPECT_EQ(ExitCodeOf(Status::IoError("disk full")), 1);
  EXPECT_EQ(ExitCodeOf(Status::Usage("unknown flag")), 2);
  EXPECT_EQ(ExitCodeOf(Status::SolverFailure("no solution")), 3);
}

}  // namespace
}  // namespace tpopt
