// `lacrima farm submit` / `lacrima farm status`: a shot's frames as a Slurm array job, and
// where its frames stand. Frames are written by `lacrima render --resume` on the nodes, so a
// node renders bitwise what a local render gives (the sampler depends on the frame, not the
// machine or its thread count), and a resubmission renders only what is missing.
#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <thread>

#include "atomic_write.hpp"
#include "commands.hpp"
#include "farm_job.hpp"
#include "farm_status.hpp"
#include "frame_range.hpp"
#include "frame_selection.hpp"
#include "lacrima/scenes/shot.hpp"
#include "process.hpp"
#include "render_plan.hpp"

namespace lacrima::cli {

namespace {

namespace fs = std::filesystem;

fs::path thisExecutable() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path("lacrima") : self;
}

fs::path jobDirectoryFor(const std::string& jobDirOption, const std::string& pattern, const fs::path& shot) {
  return jobDirOption.empty() ? defaultJobDirectory(pattern, shot) : fs::absolute(jobDirOption);
}

std::vector<int> missingFrames(const RenderOptions& render, const Shot& shot, const std::string& pattern,
                               const std::vector<int>& frames) {
  std::vector<int> missing;
  for (int f : frames)
    if (!whyFrameIsNotComplete(render, shot, pattern, f).empty()) missing.push_back(f);
  return missing;
}

// The job so far (a resubmission adds to it) with this submission's request: frames asked now
// are added to the job's, and the overrides of now apply to every frame.
FarmJob jobWithRequest(const fs::path& jobDir, const FarmSubmitOptions& o, const std::vector<int>& frames) {
  FarmJob job;
  std::error_code ec;
  if (fs::exists(jobDir / "job.json", ec)) job = readFarmJob(jobDir);
  job.shot = fs::absolute(o.render.shotPath);
  for (int f : frames)
    if (std::find(job.frames.begin(), job.frames.end(), f) == job.frames.end()) job.frames.push_back(f);
  job.render = o.render;
  job.partition = o.partition;
  job.cpusPerTask = o.cpusPerTask;
  job.lacrima = thisExecutable();
  return job;
}

void writeSubmissionFiles(const fs::path& jobDir, FarmJob& job) {
  const size_t index = job.submissions.size() - 1;
  FarmSubmission& s = job.submissions.back();
  s.script = fmt::format("job-{}.sh", index + 1);
  writeFileAtomically(jobDir / fmt::format("chunks-{}.txt", index + 1), "chunk list", [&s](std::ostream& out) {
    for (const auto& chunk : s.chunks) out << formatFrameList(chunk) << "\n";
  });
  writeFileAtomically(jobDir / s.script, "sbatch script",
                      [&](std::ostream& out) { out << sbatchScript(job, index, jobDir); });
  fs::create_directories(jobDir / "logs");
  fs::create_directories(jobDir / "status");
}

// Runs sbatch on the script; the array job's id, or a message on stderr and nothing.
std::optional<std::string> submitScript(const fs::path& script) {
  std::string why;
  const auto result = runProcess({"sbatch", "--parsable", script.string()}, why);
  if (!result) {
    std::fprintf(stderr, "lacrima farm: cannot run sbatch: %s (is Slurm installed? --dry-run writes the job "
                         "without submitting it)\n", why.c_str());
    return std::nullopt;
  }
  const auto id = parseSbatchJobId(result->out);
  if (result->exitStatus != 0 || !id) {
    std::fprintf(stderr, "lacrima farm: sbatch %s failed (exit %d): %s%s\n", script.string().c_str(),
                 result->exitStatus, result->err.c_str(), result->out.c_str());
    return std::nullopt;
  }
  return id;
}

// The `lacrima farm status` command line that finds this job again.
std::string statusCommand(const FarmSubmitOptions& o) {
  std::string command = "lacrima farm status " + shellQuote(o.render.shotPath);
  if (!o.jobDir.empty()) return command + " --job-dir " + shellQuote(o.jobDir);
  if (!o.render.outputPattern.empty()) command += " --out " + shellQuote(o.render.outputPattern);
  return command;
}

}  // namespace

int runFarmSubmit(const FarmSubmitOptions& o) {
  try {
    Shot shot = loadShot(o.render.shotPath);
    const std::vector<int> frames = selectShotFrames(o.render.frames, shot);
    RenderOptions render = o.render;
    render.outputPattern = fs::absolute(resolveOutputPattern(o.render, shot, frames.size())).string();
    const fs::path jobDir = jobDirectoryFor(o.jobDir, render.outputPattern, shot.path);
    printShotWarnings(shot);
    applyOverrides(render, shot.render);  // the settings the frames on disk are checked against

    const std::vector<int> missing = missingFrames(render, shot, render.outputPattern, frames);
    if (missing.empty()) {
      std::printf("lacrima farm: all %zu frames of %s are complete; nothing to submit\n", frames.size(),
                  o.render.shotPath.c_str());
      return kExitOk;
    }
    FarmSubmitOptions request = o;
    request.render = render;
    FarmJob job = jobWithRequest(jobDir, request, frames);
    job.submissions.push_back({"", chunkFrames(missing, o.chunk), ""});
    writeSubmissionFiles(jobDir, job);
    const fs::path script = jobDir / job.submissions.back().script;
    const size_t tasks = job.submissions.back().chunks.size();
    if (o.dryRun) {
      writeFarmJob(jobDir, job);
      std::printf("lacrima farm: --dry-run: %zu task(s) for frames %s (%zu complete frames skipped), not submitted\n"
                  "  script: %s\n  submit it with: sbatch %s\n",
                  tasks, formatFrameList(missing).c_str(), frames.size() - missing.size(), script.c_str(),
                  script.c_str());
      return kExitOk;
    }
    const auto jobId = submitScript(script);
    if (!jobId) return kExitRenderFailure;
    job.submissions.back().jobId = *jobId;
    writeFarmJob(jobDir, job);
    std::printf("lacrima farm: submitted job %s: %zu task(s) of up to %d frames for frames %s (%zu complete frames "
                "skipped)\n  logs: %s/logs\n  follow it: %s\n",
                jobId->c_str(), tasks, o.chunk, formatFrameList(missing).c_str(), frames.size() - missing.size(),
                jobDir.c_str(), statusCommand(o).c_str());
    return kExitOk;
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitBadInput;
  }
}

namespace {

std::map<std::pair<std::string, size_t>, int> recordedExitStatuses(const fs::path& jobDir) {
  std::map<std::pair<std::string, size_t>, int> statuses;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(jobDir / "status", ec)) {
    if (entry.path().extension() != ".exit") continue;
    const std::string name = entry.path().stem().string();  // "<jobid>_<task>"
    const size_t underscore = name.find('_');
    int status = 0;
    std::ifstream in(entry.path());
    if (underscore == std::string::npos || !(in >> status)) continue;
    try {
      statuses[{name.substr(0, underscore), size_t(std::stoul(name.substr(underscore + 1)))}] = status;
    } catch (const std::exception&) {
      // not a status file of ours
    }
  }
  return statuses;
}

// The array tasks Slurm still knows as queued or running; a warning when squeue cannot say.
std::vector<QueuedTask> queuedTasks(bool& warned) {
  std::string why;
  const auto result = runProcess({"squeue", "-h", "-r", "-o", "%i %T %r"}, why);
  if (result && result->exitStatus == 0) return parseSqueue(result->out);
  if (!warned)
    std::fprintf(stderr, "lacrima farm: warning: squeue %s: running tasks cannot be told from lost ones\n",
                 result ? ("failed: " + result->err).c_str() : why.c_str());
  warned = true;
  return {};
}

struct StatusCounts {
  std::map<FrameState, std::vector<int>> frames;
  size_t count(FrameState s) const { return frames.count(s) ? frames.at(s).size() : 0; }
  bool inProgress() const { return count(FrameState::Running) + count(FrameState::Pending) > 0; }
};

StatusCounts countStates(const std::vector<FrameReport>& reports) {
  StatusCounts counts;
  for (const FrameReport& r : reports) counts.frames[r.state].push_back(r.frame);
  return counts;
}

std::string summaryLine(const FarmJob& job, const StatusCounts& c) {
  return fmt::format("{}: {} frames: {} done, {} running, {} pending, {} failed, {} missing", job.shot.string(),
                     job.frames.size(), c.count(FrameState::Done), c.count(FrameState::Running),
                     c.count(FrameState::Pending), c.count(FrameState::Failed), c.count(FrameState::Missing));
}

void printDetails(const std::vector<FrameReport>& reports, const StatusCounts& c) {
  for (FrameState s : {FrameState::Running, FrameState::Pending})
    if (c.count(s)) std::printf("  %s: frames %s\n", frameStateName(s), formatFrameList(c.frames.at(s)).c_str());
  // Failed and missing frames grouped by reason (one task's frames share one).
  std::vector<std::pair<std::string, std::vector<int>>> groups;
  for (const FrameReport& r : reports) {
    if (r.state != FrameState::Failed && r.state != FrameState::Missing) continue;
    const std::string key = std::string(frameStateName(r.state)) + ": " + r.why;
    if (groups.empty() || groups.back().first != key) groups.push_back({key, {}});
    groups.back().second.push_back(r.frame);
  }
  for (const auto& [reason, frames] : groups) std::printf("  frames %s %s\n", formatFrameList(frames).c_str(), reason.c_str());
  if (c.count(FrameState::Failed) + c.count(FrameState::Missing) > 0)
    std::printf("  resubmit the same `lacrima farm submit` command: only these frames are rendered again\n");
}

}  // namespace

int runFarmStatus(const FarmStatusOptions& o) {
  try {
    Shot shot = loadShot(o.render.shotPath);
    const std::vector<int> allFrames = selectShotFrames(std::nullopt, shot);
    const std::string pattern = fs::absolute(resolveOutputPattern(o.render, shot, allFrames.size())).string();
    const fs::path jobDir = jobDirectoryFor(o.jobDir, pattern, shot.path);
    const FarmJob job = readFarmJob(jobDir);
    applyOverrides(job.render, shot.render);  // the job's tasks render with them: its frames are checked against them
    bool warned = false;
    std::string lastLine;
    for (;;) {
      const std::vector<QueuedTask> queue = queuedTasks(warned);  // before the outputs: no frame falls between
      std::vector<int> done;
      for (int f : job.frames)
        if (whyFrameIsNotComplete(job.render, shot, job.render.outputPattern, f).empty()) done.push_back(f);
      const auto reports = classifyFrames(job, jobDir, done, queue, recordedExitStatuses(jobDir));
      const StatusCounts counts = countStates(reports);
      const std::string line = summaryLine(job, counts);
      if (o.wait && (counts.inProgress() || jobHasQueuedTasks(job, queue))) {
        if (line != lastLine) std::printf("%s\n", line.c_str());
        std::fflush(stdout);
        lastLine = line;
        std::this_thread::sleep_for(std::chrono::milliseconds(int(o.pollSeconds * 1000)));
        continue;
      }
      std::printf("%s\n", line.c_str());
      printDetails(reports, counts);
      if (counts.count(FrameState::Done) == job.frames.size()) return kExitOk;
      return counts.inProgress() ? kExitFarmInProgress : kExitRenderFailure;
    }
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace lacrima::cli
