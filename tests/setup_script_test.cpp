// scripts/setup.sh as the README runs it: what it asks cmake to build, with and without `tests`,
// and what it says to an argument it does not know. A stand-in cmake on PATH records its
// arguments, so that nothing is configured or built.
#include "test_support.hpp"

#include <sstream>

#include <gtest/gtest.h>

namespace ecoview::test {
namespace {

// Runs setup.sh with `args`, the package step skipped and cmake a stand-in that appends each call's
// arguments, one line per call, to cmake_calls.txt in `dir`.
CommandResult run_setup(const TempDir& dir, const std::string& args) {
  write_text(dir / "cmake", "#!/bin/sh\necho \"$*\" >>" + shell_quote((dir / "cmake_calls.txt").string()) + "\n");
  return run_shell("chmod +x " + shell_quote((dir / "cmake").string()) + " && PATH=" + shell_quote(dir.path().string()) +
                   ":$PATH ECOVIEW_SKIP_APT=1 " + shell_quote((source_dir() / "scripts" / "setup.sh").string()) + " " + args);
}

// The last line setup.sh with `args` called cmake with: the build.
std::string build_call(const std::string& args) {
  const TempDir dir;
  const CommandResult r = run_setup(dir, args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::istringstream calls(read_bytes(dir / "cmake_calls.txt"));
  std::string line, last;
  while (std::getline(calls, line)) last = line;
  return last;
}

TEST(SetupScript, BuildsOnlyTheEcoviewBinaryByDefault) {
  const std::string build = build_call("");
  EXPECT_EQ(build.rfind("--build build ", 0), 0u) << build;
  EXPECT_TRUE(build.ends_with("--target ecoview")) << build;
}

TEST(SetupScript, BuildsEveryTargetGivenTests) {
  const std::string build = build_call("tests");
  EXPECT_EQ(build.rfind("--build build ", 0), 0u) << build;
  EXPECT_TRUE(build.ends_with("--target all")) << build;
}

TEST(SetupScript, AnUnknownArgumentGetsTheUsageAndExitCode2BeforeAnyBuild) {
  const TempDir dir;
  const CommandResult r = run_setup(dir, "--test");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("usage: scripts/setup.sh [tests]"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--test"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "cmake_calls.txt"));
  const CommandResult help = run_setup(dir, "--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_EQ(help.out.rfind("usage: scripts/setup.sh [tests]", 0), 0u) << help.out;
}

}  // namespace
}  // namespace ecoview::test
