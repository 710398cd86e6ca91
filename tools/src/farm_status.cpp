#include "farm_status.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <sstream>

#include "frame_range.hpp"

namespace lacrima::cli {

std::optional<std::string> parseSbatchJobId(const std::string& output) {
  std::string id = output.substr(0, output.find_first_of(";\n"));
  if (id.empty() || !std::all_of(id.begin(), id.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return std::nullopt;
  return id;
}

namespace {

// "3" or "[3-5]" or "[3-5,7,9-10%2]" (the %N throttle) -> task numbers.
std::vector<size_t> parseTaskField(std::string field) {
  if (field.size() >= 2 && field.front() == '[' && field.back() == ']') field = field.substr(1, field.size() - 2);
  field = field.substr(0, field.find('%'));
  std::string error;
  const auto frames = parseFrameList(field, error);  // the same "1,3-5" syntax
  std::vector<size_t> tasks;
  if (frames)
    for (int t : *frames)
      if (t >= 0) tasks.push_back(size_t(t));
  return tasks;
}

}  // namespace

bool QueuedTask::held() const {
  return state == "REQUEUE_HOLD" || reason.find("held") != std::string::npos || reason.find("Held") != std::string::npos;
}

std::vector<QueuedTask> parseSqueue(const std::string& output) {
  std::vector<QueuedTask> queue;
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream fields(line);
    std::string id, state;
    if (!(fields >> id >> state)) continue;
    std::string reason;
    std::getline(fields >> std::ws, reason);
    const size_t underscore = id.find('_');
    if (underscore == std::string::npos) continue;
    for (size_t task : parseTaskField(id.substr(underscore + 1)))
      queue.push_back({id.substr(0, underscore), task, state, reason});
  }
  return queue;
}

const char* frameStateName(FrameState state) {
  switch (state) {
    case FrameState::Done: return "done";
    case FrameState::Running: return "running";
    case FrameState::Pending: return "pending";
    case FrameState::Failed: return "failed";
    case FrameState::Missing: return "missing";
  }
  return "?";
}

namespace {

// The newest submission whose chunks hold `frame`, and the task that renders it there.
std::optional<std::pair<size_t, size_t>> latestTaskOf(const FarmJob& job, int frame) {
  for (size_t s = job.submissions.size(); s-- > 0;) {
    const auto& chunks = job.submissions[s].chunks;
    for (size_t t = 0; t < chunks.size(); ++t)
      if (std::find(chunks[t].begin(), chunks[t].end(), frame) != chunks[t].end()) return std::make_pair(s, t);
  }
  return std::nullopt;
}

FrameReport reportUnfinished(const FarmJob& job, const std::filesystem::path& jobDir, int frame,
                             const std::vector<QueuedTask>& queue,
                             const std::map<std::pair<std::string, size_t>, int>& exitStatuses) {
  const auto where = latestTaskOf(job, frame);
  if (!where) return {frame, FrameState::Missing, "not in any submission (submit again)"};
  const FarmSubmission& s = job.submissions[where->first];
  const size_t task = where->second;
  if (s.jobId.empty()) return {frame, FrameState::Missing, "only a --dry-run job was written"};
  const std::string log = taskLogPath(jobDir, s.jobId, task).string();
  for (const QueuedTask& q : queue) {
    if (q.jobId != s.jobId || q.task != task) continue;
    if (q.held())
      return {frame, FrameState::Failed,
              fmt::format("task {} of job {} is held by Slurm ({}): see the slurmd log; `scancel {}` and "
                          "submit again",
                          task, s.jobId, q.reason, s.jobId)};
    return {frame, q.state == "PENDING" ? FrameState::Pending : FrameState::Running, ""};
  }
  const auto status = exitStatuses.find({s.jobId, task});
  if (status == exitStatuses.end())
    return {frame, FrameState::Failed,
            fmt::format("task {} of job {} ended without an exit status (cancelled, killed or lost); log {}", task,
                        s.jobId, log)};
  if (status->second != 0)
    return {frame, FrameState::Failed, fmt::format("task {} of job {} exited {}; log {}", task, s.jobId, status->second, log)};
  return {frame, FrameState::Failed,
          fmt::format("task {} of job {} exited 0 but the frame is not complete on disk; log {}", task, s.jobId, log)};
}

}  // namespace

std::vector<FrameReport> classifyFrames(const FarmJob& job, const std::filesystem::path& jobDir,
                                        const std::vector<int>& doneFrames, const std::vector<QueuedTask>& queue,
                                        const std::map<std::pair<std::string, size_t>, int>& exitStatuses) {
  std::vector<FrameReport> reports;
  for (int frame : job.frames) {
    if (std::find(doneFrames.begin(), doneFrames.end(), frame) != doneFrames.end())
      reports.push_back({frame, FrameState::Done, ""});
    else
      reports.push_back(reportUnfinished(job, jobDir, frame, queue, exitStatuses));
  }
  return reports;
}

bool jobHasQueuedTasks(const FarmJob& job, const std::vector<QueuedTask>& queue) {
  for (const QueuedTask& q : queue)
    for (const FarmSubmission& s : job.submissions)
      if (!s.jobId.empty() && q.jobId == s.jobId && !q.held()) return true;
  return false;
}

}  // namespace lacrima::cli
