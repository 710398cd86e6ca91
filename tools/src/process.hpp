#pragma once
// Runs another program (sbatch, squeue) and captures what it prints.
#include <optional>
#include <string>
#include <vector>

namespace lacrima::cli {

struct ProcessResult {
  int exitStatus = -1;  // 128 + signal when a signal ended it
  std::string out;      // standard output
  std::string err;      // standard error
};

// Runs argv[0] (looked up on PATH) with the arguments, waits for it. Nothing when it cannot be
// started (not installed, not executable); `why` then says so.
std::optional<ProcessResult> runProcess(const std::vector<std::string>& argv, std::string& why);

// `text` quoted for a POSIX shell: 'it'\''s'.
std::string shellQuote(const std::string& text);

}  // namespace lacrima::cli
