#include "model/io/atomic_file.h"

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

namespace tpopt {
namespace {

std::string Slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

int Entries(const std::string& dir) {
  int n = 0;
  DIR* d = opendir(dir.c_str());
  while (dirent* e = readdir(d)) n += e->d_name[0] != '.';
  closedir(d);
  return n;
}

class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    char pattern[] = "/tmp/tpopt_atomic_XXXXXX";
    dir_ = mkdtemp(pattern);
  }
  void TearDown() override {
    chmod(dir_.c_str(), 0755);
    std::system(("rm -rf " + dir_).c_str());
  }
  std::string dir_;
};

TEST_F(AtomicFileTest, ReplacesWholeFiles) {
  const std::string path = dir_ + "/out.txt";
  ASSERT_TRUE(WriteFileAtomically(path, std::string(100000, 'a')).ok());
  ASSERT_TRUE(WriteFileAtomically(path, "short\n").ok());
  EXPECT_EQ(Slurp(path), "short\n");
  EXPECT_EQ(Entries(dir_), 1);  // no temporary left behind
  struct stat st;
  ASSERT_EQ(stat(path.c_str(), &st), 0);
  EXPECT_TRUE(st.st_mode & S_IRGRP);  // not mkstemp's private 0600
}

TEST_F(AtomicFileTest, NewFilesFollowTheUmaskAndReplacedFilesKeepTheirMode) {
  const mode_t saved = umask(027);
  const std::string fresh = dir_ + "/fresh.txt";
  const Status s = WriteFileAtomically(fresh, "x");
  umask(saved);
  ASSERT_TRUE(s.ok()) << s.message();
  struct stat st;
  ASSERT_EQ(stat(fresh.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0640u);

  const std::string script = dir_ + "/run.sh";
  ASSERT_TRUE(WriteFileAtomically(script, "#!/bin/sh\n").ok());
  ASSERT_EQ(chmod(script.c_str(), 0750), 0);
  ASSERT_TRUE(WriteFileAtomically(script, "#!/bin/sh\nexit 0\n").ok());
  ASSERT_EQ(stat(script.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0750u);
  EXPECT_EQ(Slurp(script), "#!/bin/sh\nexit 0\n");
}

TEST_F(AtomicFileTest, MissingFolderFailsAndLeavesNothing) {
  const Status s = WriteFileAtomically(dir_ + "/no/such/dir/out.txt", "x");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("no/such/dir/out.txt"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("No such file"), std::string::npos) << s.message();
  EXPECT_EQ(Entries(dir_), 0);
}

TEST_F(AtomicFileTest, ReadOnlyFolderFailsAndKeepsTheOldFile) {
  if (geteuid() == 0) {
    GTEST_SKIP() << "running as root: a read-only folder is still writable";
  }
  const std::string path = dir_ + "/out.txt";
  ASSERT_TRUE(WriteFileAtomically(path, "old").ok());
  chmod(dir_.c_str(), 0555);
  EXPECT_FALSE(WriteFileAtomically(path, "new").ok());
  EXPECT_EQ(Slurp(path), "old");
}

TEST_F(AtomicFileTest, UnwritableTargetFailsWithoutPartialOutput) {
  // A directory in the way of the rename: the rename fails, the temporary
  // is removed. Works for root too.
  const std::string path = dir_ + "/taken";
  ASSERT_EQ(mkdir(path.c_str(), 0755), 0);
  ASSERT_EQ(mkdir((path + "/inside").c_str(), 0755), 0);
  const Status s = WriteFileAtomically(path, "x");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("taken"), std::string::npos) << s.message();
  EXPECT_EQ(Entries(dir_), 1);
}

}  // namespace
}  // namespace tpopt
