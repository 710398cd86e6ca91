#pragma once
// `lacrima farm status`: where each frame of a farm job stands, from the outputs on disk (the
// truth: a frame is done when its EXR is complete), Slurm's queue (running, pending) and the
// tasks' recorded exit statuses (failed). Pure functions of those inputs, for testing.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "farm_job.hpp"

namespace lacrima::cli {

enum class FrameState { Done, Running, Pending, Failed, Missing };

// One array task as squeue lists it ("12_3 RUNNING").
struct QueuedTask {
  std::string jobId;
  size_t task = 0;
  std::string state;   // Slurm's state name: PENDING, RUNNING, COMPLETING, ...
  std::string reason;  // why it waits ("Resources", "launch failed requeued held"); "None" when running
  // Held tasks (a failed launch, an administrator) never start by themselves: they count as failed.
  bool held() const;
};

// The array job id sbatch --parsable printed ("12" or "12;cluster"); nothing if it is not one.
std::optional<std::string> parseSbatchJobId(const std::string& output);
// squeue -h -r -o "%i %T %r" lines; lines of other shapes are ignored. A pending array whose tasks
// squeue folds into one line ("12_[3-5] PENDING") counts for each of its tasks.
std::vector<QueuedTask> parseSqueue(const std::string& output);

struct FrameReport {
  int frame = 0;
  FrameState state = FrameState::Missing;
  std::string why;  // failed/missing: what is known (exit status, log file)
};

// What the latest submission that rendered each frame says about it. doneFrames: the frames
// whose output is complete; exitStatus(jobId, task): the task's recorded exit status, if any.
std::vector<FrameReport> classifyFrames(const FarmJob& job, const std::filesystem::path& jobDir,
                                        const std::vector<int>& doneFrames, const std::vector<QueuedTask>& queue,
                                        const std::map<std::pair<std::string, size_t>, int>& exitStatuses);

// Whether a task of one of the job's submissions is still queued or running (held tasks aside:
// they never end by themselves). A task whose frames are all on disk may still be running: its
// script records the exit status after the render returns, so `status --wait` waits for this too.
bool jobHasQueuedTasks(const FarmJob& job, const std::vector<QueuedTask>& queue);

const char* frameStateName(FrameState state);

}  // namespace lacrima::cli
