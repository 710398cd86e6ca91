// `lacrima farm`: the pure parts (chunks, the sbatch script, Slurm's output, where each frame
// stands), the job files of --dry-run, and a real single-node Slurm cluster (tools/slurm/cluster.sh)
// rendering a 6-frame shot in 3 array tasks bitwise like a local render.
#include <gtest/gtest.h>
#include <pwd.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "farm_job.hpp"
#include "farm_status.hpp"
#include "support/test_directory.hpp"
#include "tools/lacrima_cli_support.hpp"

namespace lacrima {
namespace farm_test {

namespace fs = std::filesystem;
using namespace cli;
using test::bytesWithoutRenderTime;
using test::lacrima;
using test::writeSphereShot;

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

std::string readText(const fs::path& path) { return test::readBytes(path); }

TEST(FarmJob, ChunksAreConsecutiveRunsOfTheFramesInOrder) {
  const std::vector<std::vector<int>> expected = {{1, 3, 5}, {7, 9, 11}, {13}};
  EXPECT_EQ(chunkFrames({1, 3, 5, 7, 9, 11, 13}, 3), expected);
  EXPECT_EQ(chunkFrames({4, 5}, 10), (std::vector<std::vector<int>>{{4, 5}}));
  EXPECT_TRUE(chunkFrames({}, 2).empty());
}

TEST(FarmJob, ScriptIsAnArrayJobWhoseTasksRenderTheirChunkWithResume) {
  FarmJob job;
  job.shot = "/shots/my shot.json";
  job.lacrima = "/opt/lacrima/bin/lacrima";
  job.cpusPerTask = 4;
  job.partition = "render";
  job.render.spp = 64;
  job.render.outputPattern = "/out/shot.####.exr";
  job.submissions.push_back({"", {{1, 2}, {3, 4}, {5}}, "job-1.sh"});
  const std::string script = sbatchScript(job, 0, "/out/shot.farm");
  EXPECT_TRUE(contains(script, "#SBATCH --array=0-2\n")) << script;
  EXPECT_TRUE(contains(script, "#SBATCH --cpus-per-task=4\n")) << script;
  EXPECT_TRUE(contains(script, "#SBATCH --partition=render\n")) << script;
  EXPECT_TRUE(contains(script, "#SBATCH --output=/out/shot.farm/logs/%A_%a.log\n")) << script;
  EXPECT_TRUE(contains(script, "#SBATCH --job-name=lacrima:my_shot\n")) << script;
  EXPECT_TRUE(contains(script, "'/opt/lacrima/bin/lacrima' render '/shots/my shot.json' --frames \"$frames\" --resume"))
      << script;
  EXPECT_TRUE(contains(script, "'--spp' '64' '--out' '/out/shot.####.exr'")) << script;
  EXPECT_TRUE(contains(script, "/out/shot.farm/status/${SLURM_ARRAY_JOB_ID}_${task}.exit")) << script;
  job.cpusPerTask = 0;
  EXPECT_TRUE(contains(sbatchScript(job, 0, "/out/shot.farm"), "#SBATCH --exclusive\n"));
}

TEST(FarmStatus, ReadsJobIdsAndQueuedArrayTasks) {
  EXPECT_EQ(parseSbatchJobId("12\n"), "12");
  EXPECT_EQ(parseSbatchJobId("345;farm\n"), "345");
  EXPECT_EQ(parseSbatchJobId("Submitted batch job 12\n"), std::nullopt);
  EXPECT_EQ(parseSbatchJobId(""), std::nullopt);

  const auto queue = parseSqueue(
      "12_0 RUNNING None\n12_[2-3,5%2] PENDING Resources\n13 RUNNING None\ngarbage\n"
      "14_1 PENDING launch failed requeued held\n");
  ASSERT_EQ(queue.size(), 5u);
  EXPECT_EQ(queue[0].jobId, "12");
  EXPECT_EQ(queue[0].task, 0u);
  EXPECT_EQ(queue[0].state, "RUNNING");
  EXPECT_EQ(queue[1].task, 2u);
  EXPECT_EQ(queue[2].task, 3u);
  EXPECT_EQ(queue[3].task, 5u);
  EXPECT_EQ(queue[3].state, "PENDING");
  EXPECT_EQ(queue[3].reason, "Resources");
  EXPECT_FALSE(queue[3].held());
  EXPECT_EQ(queue[4].reason, "launch failed requeued held");
  EXPECT_TRUE(queue[4].held());
}

// Frames 1-8: a first job (7) of chunks {1,2} {3,4} {5,6}, then a resubmission (9) of {3,4} and {7}.
TEST(FarmStatus, EachFrameTakesTheWordOfTheNewestTaskThatRendersIt) {
  FarmJob job;
  job.frames = {1, 2, 3, 4, 5, 6, 7, 8};
  job.submissions.push_back({"7", {{1, 2}, {3, 4}, {5, 6}}, "job-1.sh"});
  job.submissions.push_back({"9", {{3, 4}, {7}}, "job-2.sh"});
  const std::vector<QueuedTask> queue = {
      {"9", 0, "RUNNING", "None"}, {"9", 1, "PENDING", "Priority"}, {"7", 2, "RUNNING", "None"}};
  // Job 7's task 2 shows as running in the queue, but its frames are already on disk.
  const std::map<std::pair<std::string, size_t>, int> exits = {{{"7", 0}, 0}, {{"7", 1}, 1}};
  const auto reports = classifyFrames(job, "/jobs/x.farm", {1, 2, 5}, queue, exits);
  ASSERT_EQ(reports.size(), 8u);
  const std::vector<FrameState> expected = {FrameState::Done,    FrameState::Done,    FrameState::Running,
                                            FrameState::Running, FrameState::Done,    FrameState::Running,
                                            FrameState::Pending, FrameState::Missing};
  for (size_t i = 0; i < reports.size(); ++i) EXPECT_EQ(reports[i].state, expected[i]) << "frame " << reports[i].frame;

  // Without the queue: job 9's tasks left no exit status (cancelled or lost); frame 6's task
  // (job 7, task 2) neither.
  const auto after = classifyFrames(job, "/jobs/x.farm", {1, 2, 5}, {}, exits);
  EXPECT_EQ(after[2].state, FrameState::Failed);
  EXPECT_EQ(after[2].why, "task 0 of job 9 ended without an exit status (cancelled, killed or lost); log "
                          "/jobs/x.farm/logs/9_0.log");
  EXPECT_EQ(after[7].why, "not in any submission (submit again)");
  const auto failed = classifyFrames(job, "/jobs/x.farm", {}, {}, {{{"7", 0}, 2}, {{"9", 0}, 0}});
  EXPECT_EQ(failed[0].why, "task 0 of job 7 exited 2; log /jobs/x.farm/logs/7_0.log");
  EXPECT_EQ(failed[3].why, "task 0 of job 9 exited 0 but the frame is not complete on disk; log /jobs/x.farm/logs/9_0.log");
  const auto held = classifyFrames(job, "/jobs/x.farm", {}, {{"9", 1, "PENDING", "launch failed requeued held"}}, {});
  EXPECT_EQ(held[6].state, FrameState::Failed);
  EXPECT_EQ(held[6].why, "task 1 of job 9 is held by Slurm (launch failed requeued held): see the slurmd log; "
                         "`scancel 9` and submit again");
}

// `status --wait` waits for the job's tasks, not only its frames: a task whose frames are on disk
// records its exit status after the render returns (the race a cluster run once lost).
TEST(FarmStatus, TheJobHasQueuedTasksUntilItsOwnTasksLeaveTheQueue) {
  FarmJob job;
  job.frames = {1, 2};
  job.submissions.push_back({"7", {{1, 2}}, "job-1.sh"});
  job.submissions.push_back({"", {{2}}, "job-2.sh"});  // a --dry-run: no job id
  EXPECT_TRUE(jobHasQueuedTasks(job, {{"7", 0, "COMPLETING", "None"}}));
  EXPECT_TRUE(jobHasQueuedTasks(job, {{"12", 0, "RUNNING", "None"}, {"7", 0, "RUNNING", "None"}}));
  EXPECT_FALSE(jobHasQueuedTasks(job, {}));
  EXPECT_FALSE(jobHasQueuedTasks(job, {{"12", 0, "RUNNING", "None"}})) << "another job's task";
  EXPECT_FALSE(jobHasQueuedTasks(job, {{"7", 0, "PENDING", "launch failed requeued held"}})) << "held: never ends";
}

TEST(FarmCommand, DryRunWritesTheJobAndSubmitsNothing) {
  const fs::path dir = test::testDirectory("farm", /*fresh=*/true);
  const fs::path shot = writeSphereShot(dir, 5);
  const auto run = lacrima({"farm", "submit", shot.string(), "--chunk", "2", "--spp", "3", "--aov", "lightGroups",
                            "--region", "2,1,20,9", "--dry-run"});
  ASSERT_EQ(run.exitStatus, 0) << run.output;
  EXPECT_TRUE(contains(run.output, "--dry-run: 3 task(s) for frames 1-5 (0 complete frames skipped), not submitted"))
      << run.output;
  const fs::path jobDir = dir / "out" / "spheres.farm";
  EXPECT_EQ(readText(jobDir / "chunks-1.txt"), "1-2\n3-4\n5\n");
  EXPECT_TRUE(contains(readText(jobDir / "job-1.sh"), "#SBATCH --array=0-2\n"));
  const FarmJob job = readFarmJob(jobDir);
  EXPECT_EQ(job.frames, (std::vector<int>{1, 2, 3, 4, 5}));
  EXPECT_EQ(job.render.spp, 3);
  EXPECT_EQ(job.render.aovs, (std::vector<std::string>{"lightGroups"})) << "each task renders with the --aov";
  EXPECT_TRUE(contains(readText(jobDir / "job-1.sh"), "'--aov' 'lightGroups'")) << readText(jobDir / "job-1.sh");
  EXPECT_EQ(job.render.region, (std::vector<int>{2, 1, 20, 9})) << "each task renders the --region";
  EXPECT_TRUE(contains(readText(jobDir / "job-1.sh"), "'--region' '2,1,20,9'")) << readText(jobDir / "job-1.sh");
  EXPECT_EQ(job.render.outputPattern, (dir / "out" / "spheres.####.exr").string());
  ASSERT_EQ(job.submissions.size(), 1u);
  EXPECT_EQ(job.submissions[0].jobId, "");

  const auto status = lacrima({"farm", "status", shot.string()});
  EXPECT_EQ(status.exitStatus, 1) << status.output;
  EXPECT_TRUE(contains(status.output, "5 frames: 0 done, 0 running, 0 pending, 0 failed, 5 missing")) << status.output;
  EXPECT_TRUE(contains(status.output, "frames 1-5 missing: only a --dry-run job was written")) << status.output;
}

// The overrides are applied right after loading: a --region outside the shot's 32x18 frame is
// refused before any frame is checked or any job written, not by every task on the farm.
TEST(FarmCommand, ARegionOutsideTheFrameIsRefusedBeforeAJobIsWritten) {
  const fs::path dir = test::testDirectory("farm_region", /*fresh=*/true);
  const fs::path shot = writeSphereShot(dir, 3);
  const auto run = lacrima({"farm", "submit", shot.string(), "--region", "30,0,4,4", "--dry-run"});
  EXPECT_EQ(run.exitStatus, 2) << run.output;
  EXPECT_TRUE(contains(run.output, "--region 30,0,4,4: the region does not lie within the 32x18 frame (it ends at "
                                   "pixel (33, 3))"))
      << run.output;
  EXPECT_FALSE(fs::exists(dir / "out" / "spheres.farm")) << "no job written";
}

TEST(FarmCommand, NothingIsSubmittedWhenEveryFrameIsComplete) {
  const fs::path dir = test::testDirectory("farm", /*fresh=*/true);
  const fs::path shot = writeSphereShot(dir, 2);
  ASSERT_EQ(lacrima({"render", shot.string(), "--quiet"}).exitStatus, 0);
  const auto run = lacrima({"farm", "submit", shot.string()});  // no sbatch is needed for this
  EXPECT_EQ(run.exitStatus, 0) << run.output;
  EXPECT_TRUE(contains(run.output, "all 2 frames of " + shot.string() + " are complete; nothing to submit")) << run.output;
  const auto other = lacrima({"farm", "submit", shot.string(), "--spp", "5", "--dry-run"});  // other settings
  EXPECT_TRUE(contains(other.output, "1 task(s) for frames 1-2 (0 complete frames skipped)")) << other.output;
}

TEST(FarmCommand, StatusWithoutAJobSaysHowToSubmitOne) {
  const fs::path dir = test::testDirectory("farm", /*fresh=*/true);
  const fs::path shot = writeSphereShot(dir, 2);
  const auto run = lacrima({"farm", "status", shot.string()});
  EXPECT_EQ(run.exitStatus, 2);
  EXPECT_EQ(run.output, (dir / "out" / "spheres.farm" / "job.json").string() +
                            ": no farm job here (submit one with `lacrima farm submit`)\n");
}

// ---- a real cluster ------------------------------------------------------------------------------

// Starts tools/slurm/cluster.sh in `dir` and stops exactly its daemons when it goes out of scope.
class SlurmCluster {
 public:
  explicit SlurmCluster(const fs::path& dir) : dir_(dir) {
    const auto start = test::runCommand(script() + " start " + test::shellQuote(dir_.string()));
    started_ = start.exitStatus == 0;
    log_ = start.output;
    if (started_) setenv("SLURM_CONF", (dir_ / "slurm.conf").c_str(), 1);
  }
  ~SlurmCluster() {
    if (started_) test::runCommand(script() + " stop " + test::shellQuote(dir_.string()));
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
  bool started() const { return started_; }
  const std::string& log() const { return log_; }

 private:
  static std::string script() { return test::shellQuote(std::string(LACRIMA_SOURCE_DIR) + "/tools/slurm/cluster.sh"); }
  fs::path dir_;
  bool started_ = false;
  std::string log_;
};

std::string frameName(int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "spheres.%04d.exr", frame);
  return name;
}

// What the single-node cluster needs and is missing on this machine ("" when nothing is).
std::string missingClusterPrerequisites() {
  std::vector<std::string> missing;
  if (geteuid() != 0) missing.push_back("root (slurmd runs jobs as their owner)");
  for (const char* daemon : {"/usr/sbin/slurmctld", "/usr/sbin/slurmd", "/usr/sbin/munged"})
    if (access(daemon, X_OK) != 0) missing.push_back(daemon);
  if (getpwnam("munge") == nullptr) missing.push_back("the user 'munge'");
  std::string list;
  for (const std::string& m : missing) list += (list.empty() ? "" : ", ") + m;
  return list;
}

// Under CI (CI=true) a missing prerequisite fails the cluster test instead of skipping it: a skip
// there would hide that the farm was never tested.
bool underCi() {
  const char* ci = std::getenv("CI");
  return ci && std::string(ci) == "true";
}

// The acceptance test: 6 frames in 3 chunks on a single-node Slurm cluster equal a local
// render bitwise; a lost frame and a task that cannot write show up in `farm status`, and a
// resubmission renders only what is missing. Needs root and slurm-wlm + munge (tools/bootstrap.sh
// test installs them); skipped without them, except under CI.
TEST(FarmCluster, SixFramesInThreeChunksMatchALocalRenderBitwise) {
  if (const std::string missing = missingClusterPrerequisites(); !missing.empty()) {
    const std::string why = "the single-node Slurm cluster cannot start: missing " + missing +
                            ". Install slurm-wlm and munge (apt-get install slurm-wlm munge, or tools/bootstrap.sh test) "
                            "and run as root";
    if (underCi()) FAIL() << why << " (CI=true: never skipped under CI)";
    GTEST_SKIP() << why;
  }
  const fs::path dir = test::testDirectory("farm_cluster", /*fresh=*/true);
  char clusterDir[] = "/tmp/lacrima-slurm-XXXXXX";  // short: slurmd's socket paths must fit 107 bytes
  ASSERT_NE(mkdtemp(clusterDir), nullptr);
  SlurmCluster cluster(clusterDir);
  ASSERT_TRUE(cluster.started()) << cluster.log();
  const fs::path shot = writeSphereShot(dir, 6);
  const std::vector<std::string> overrides = {"--width", "48", "--height", "27", "--spp", "4"};
  std::vector<std::string> local = {"render", shot.string(), "--quiet", "--out", (dir / "local/spheres.####.exr").string()};
  local.insert(local.end(), overrides.begin(), overrides.end());
  ASSERT_EQ(lacrima(local).exitStatus, 0);

  std::vector<std::string> submit = {"farm", "submit", shot.string(), "--chunk", "2", "--cpus-per-task", "1"};
  submit.insert(submit.end(), overrides.begin(), overrides.end());
  const auto first = lacrima(submit);
  ASSERT_EQ(first.exitStatus, 0) << first.output;
  EXPECT_TRUE(contains(first.output, "3 task(s) of up to 2 frames for frames 1-6")) << first.output;
  // A stuck cluster must fail the test, not hang CI.
  const std::string wait =
      "timeout 300 " + test::commandLine({"farm", "status", shot.string(), "--wait", "--poll", "0.2"});
  const auto done = test::runCommand(wait);
  ASSERT_EQ(done.exitStatus, 0) << done.output;
  EXPECT_TRUE(contains(done.output, "6 frames: 6 done, 0 running, 0 pending, 0 failed, 0 missing")) << done.output;
  for (int f = 1; f <= 6; ++f)
    EXPECT_TRUE(bytesWithoutRenderTime(dir / "out" / frameName(f)) == bytesWithoutRenderTime(dir / "local" / frameName(f)))
        << "frame " << f;
  const fs::path jobDir = dir / "out" / "spheres.farm";
  const FarmJob job = readFarmJob(jobDir);
  ASSERT_EQ(job.submissions.size(), 1u);
  for (size_t task = 0; task < 3; ++task) {
    EXPECT_EQ(readText(taskStatusPath(jobDir, job.submissions[0].jobId, task)), "0\n") << "task " << task;
    EXPECT_TRUE(fs::exists(taskLogPath(jobDir, job.submissions[0].jobId, task))) << "task " << task;
  }

  // Frame 3 lost, frame 5 unwritable (a directory in its place): the resubmission renders only
  // those two (in one task), frame 5 cannot be written (lacrima render exits 1), and status says
  // which frame, why, and where the log is.
  fs::remove(dir / "out" / frameName(3));
  fs::remove(dir / "out" / frameName(5));
  fs::create_directory(dir / "out" / frameName(5));
  const auto second = lacrima(submit);
  ASSERT_EQ(second.exitStatus, 0) << second.output;
  EXPECT_TRUE(contains(second.output, "1 task(s) of up to 2 frames for frames 3,5 (4 complete frames skipped)"))
      << second.output;
  const auto partial = test::runCommand(wait);
  EXPECT_EQ(partial.exitStatus, 1) << partial.output;
  EXPECT_TRUE(contains(partial.output, "6 frames: 5 done, 0 running, 0 pending, 1 failed, 0 missing")) << partial.output;
  const std::string secondId = readFarmJob(jobDir).submissions[1].jobId;
  EXPECT_TRUE(contains(partial.output, "frames 5 failed: task 0 of job " + secondId + " exited 1; log " +
                                           taskLogPath(jobDir, secondId, 0).string()))
      << partial.output;
  EXPECT_TRUE(bytesWithoutRenderTime(dir / "out" / frameName(3)) == bytesWithoutRenderTime(dir / "local" / frameName(3)));

  fs::remove(dir / "out" / frameName(5));
  ASSERT_EQ(lacrima(submit).exitStatus, 0);
  const auto last = test::runCommand(wait);
  EXPECT_EQ(last.exitStatus, 0) << last.output;
  EXPECT_TRUE(bytesWithoutRenderTime(dir / "out" / frameName(5)) == bytesWithoutRenderTime(dir / "local" / frameName(5)));
}

}  // namespace farm_test
}  // namespace lacrima
