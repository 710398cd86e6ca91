#pragma once
// Runs a shell command for command-line tests and captures its exit status and output.
//
// A command that dies of a signal (a segfault, an abort, an uncaught exception's terminate) fails
// the running test here, with the signal named, whatever the caller then checks of the status: a
// test that only asks for `exitStatus <= 1` or `!= 0` must not pass because the program crashed.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <string>
#include <sys/wait.h>

namespace lacrima::test {

struct CommandResult {
  int exitStatus = -1;  // the exit status; 128 + N when killed by signal N (as a shell reports it)
  int signal = 0;       // the signal that ended the command, 0 when it exited by itself
  std::string output;   // stdout and stderr interleaved
};

// lacrima's own exit status after Ctrl-C or SIGTERM (it catches them, finishes and exits 130).
constexpr int kInterruptedExitStatus = 130;

// The signal behind a wait status. popen's shell turns a child's death by signal N into its own
// exit status 128 + N, so that counts as the signal too, except 130, which lacrima exits with
// itself when interrupted.
inline int terminatingSignal(int waitStatus) {
  if (WIFSIGNALED(waitStatus)) return WTERMSIG(waitStatus);
  if (!WIFEXITED(waitStatus)) return 0;
  const int status = WEXITSTATUS(waitStatus);
  if (status > 128 && status <= 128 + 64 && status != kInterruptedExitStatus) return status - 128;
  return 0;
}

inline CommandResult runCommand(const std::string& command) {
  CommandResult result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) {
    ADD_FAILURE() << "cannot start `" << command << "`: " << std::strerror(errno);
    return result;
  }
  std::array<char, 4096> buffer;
  while (size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) result.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  result.signal = terminatingSignal(status);
  result.exitStatus = result.signal ? 128 + result.signal : WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (result.signal)
    ADD_FAILURE() << "`" << command << "` was killed by signal " << result.signal << " (" << strsignal(result.signal)
                  << ")\n"
                  << result.output;
  return result;
}

inline std::string shellQuote(const std::string& s) {
  std::string quoted = "'";
  for (char c : s) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace lacrima::test
