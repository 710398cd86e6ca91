// The command-line tests' runner (tests/support/run_command.hpp): a command that crashes fails the
// test that ran it, whatever the test checks afterwards, and says which signal it died of; a
// command that exits, with any status the tests expect (0, 1, 2, 130), does not.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <csignal>

#include "support/run_command.hpp"

namespace lacrima {
namespace run_command_test {

// EXPECT_NONFATAL_FAILURE's statement cannot see local variables, hence these.
test::CommandResult crashed;

TEST(RunCommand, ASegfaultingCommandFailsTheTestAndNamesTheSignal) {
  // A deliberately crashing command: the shell sends itself SIGSEGV.
  EXPECT_NONFATAL_FAILURE(crashed = test::runCommand("sh -c 'echo before the crash; kill -SEGV $$'"),
                          "was killed by signal 11 (Segmentation fault)");
  EXPECT_EQ(crashed.signal, SIGSEGV);
  EXPECT_EQ(crashed.exitStatus, 128 + SIGSEGV);
  EXPECT_GT(crashed.exitStatus, 1) << "a crash must not pass a check for exitStatus <= 1";
  EXPECT_NE(crashed.output.find("before the crash"), std::string::npos) << crashed.output;
}

TEST(RunCommand, ACrashInsideASubshellWithRedirectionsIsSeenToo) {
  // The form the CLI tests use to keep only stdout or stderr.
  EXPECT_NONFATAL_FAILURE(crashed = test::runCommand("(sh -c 'kill -ABRT $$' 2>/dev/null)"),
                          "was killed by signal 6 (Aborted)");
  EXPECT_EQ(crashed.signal, SIGABRT);
}

TEST(RunCommand, OrdinaryExitStatusesAreNotCrashes) {
  for (int status : {0, 1, 2, 127, test::kInterruptedExitStatus}) {
    const test::CommandResult run = test::runCommand("exit " + std::to_string(status));
    EXPECT_EQ(run.exitStatus, status);
    EXPECT_EQ(run.signal, 0);
  }
}

TEST(RunCommand, OutputIsStdoutAndStderrInterleaved) {
  const test::CommandResult run = test::runCommand("(echo out; echo err >&2)");
  EXPECT_EQ(run.output, "out\nerr\n");
  EXPECT_EQ(run.exitStatus, 0);
}

}  // namespace run_command_test
}  // namespace lacrima
