#pragma once
// A shot rendered on a Slurm farm (`lacrima farm`): what was asked (shot, frames, render
// overrides, output), and each submission as a Slurm array job whose task i renders chunk i.
// Kept in a job directory as job.json, next to the generated sbatch scripts, the chunk lists,
// one log per task (logs/<jobid>_<task>.log) and one exit status per task
// (status/<jobid>_<task>.exit).
#include <filesystem>
#include <string>
#include <vector>

#include "commands.hpp"

namespace lacrima::cli {

struct FarmSubmission {
  std::string jobId;                      // Slurm's array job id; empty for --dry-run
  std::vector<std::vector<int>> chunks;   // task i renders chunks[i]
  std::string script;                     // file name of its sbatch script in the job directory
};

struct FarmJob {
  std::filesystem::path shot;     // absolute
  std::vector<int> frames;        // every frame asked for, in order
  RenderOptions render;           // the overrides each task passes on (output pattern absolute)
  std::string partition;          // empty: the cluster's default
  int cpusPerTask = 0;            // 0: each task gets a whole node (--exclusive)
  std::filesystem::path lacrima;  // the binary the tasks run
  std::vector<FarmSubmission> submissions;
};

// Consecutive runs of `chunkSize` frames of `frames`, in order (the last may be shorter).
std::vector<std::vector<int>> chunkFrames(const std::vector<int>& frames, int chunkSize);

// The sbatch script of submission `index` of `job`: an array job with one task per chunk; task i
// renders its frames with `lacrima render --resume` and records its exit status.
std::string sbatchScript(const FarmJob& job, size_t index, const std::filesystem::path& jobDir);

// The `lacrima render` arguments (after "render SHOT --frames F") that reproduce job.render.
std::vector<std::string> renderArguments(const RenderOptions& render);

// Default job directory: "<shot output directory>/<shot file stem>.farm".
std::filesystem::path defaultJobDirectory(const std::string& outputPattern, const std::filesystem::path& shot);

void writeFarmJob(const std::filesystem::path& jobDir, const FarmJob& job);
// Throws InputError naming job.json when it is missing or not a farm job.
FarmJob readFarmJob(const std::filesystem::path& jobDir);

std::filesystem::path taskLogPath(const std::filesystem::path& jobDir, const std::string& jobId, size_t task);
std::filesystem::path taskStatusPath(const std::filesystem::path& jobDir, const std::string& jobId, size_t task);

}  // namespace lacrima::cli
