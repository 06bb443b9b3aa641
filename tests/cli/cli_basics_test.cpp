#include <gtest/gtest.h>

#include "tests/test_support.h"

namespace recoil::test {

TEST(Cli, HelpAndVersion) {
  const CommandResult help = run_recoil("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("turntable"), std::string::npos);
  const CommandResult version = run_recoil("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_NE(version.out.find("recoil"), std::string::npos);
}

TEST(Cli, UnknownCommandIsBadUsage) {
  const CommandResult r = run_recoil("frobnicate");
  EXPECT_EQ(r.exit_code, 2);
}

}  // namespace recoil::test
