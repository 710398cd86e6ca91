#include "farm_job.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cctype>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "atomic_write.hpp"
#include "frame_range.hpp"
#include "lacrima/base/error.hpp"
#include "process.hpp"

namespace lacrima::cli {

namespace fs = std::filesystem;
using nlohmann::json;

std::vector<std::vector<int>> chunkFrames(const std::vector<int>& frames, int chunkSize) {
  std::vector<std::vector<int>> chunks;
  for (size_t i = 0; i < frames.size(); i += size_t(chunkSize))
    chunks.emplace_back(frames.begin() + long(i), frames.begin() + long(std::min(frames.size(), i + chunkSize)));
  return chunks;
}

std::vector<std::string> renderArguments(const RenderOptions& r) {
  std::vector<std::string> args;
  auto add = [&args](const char* flag, const auto& value) {
    if (value) {
      args.push_back(flag);
      args.push_back(std::to_string(*value));
    }
  };
  add("--spp", r.spp);
  add("--width", r.width);
  add("--height", r.height);
  add("--seed", r.seed);
  add("--max-depth", r.maxDepth);
  if (!r.outputPattern.empty()) args.insert(args.end(), {"--out", r.outputPattern});
  if (r.preview) args.push_back("--preview");
  if (r.floatOutput) args.push_back("--float");
  if (r.denoise) args.push_back(*r.denoise ? "--denoise" : "--no-denoise");
  for (const std::string& aov : r.aovs) args.insert(args.end(), {"--aov", aov});
  if (!r.region.empty()) args.insert(args.end(), {"--region", fmt::format("{}", fmt::join(r.region, ","))});
  return args;
}

std::filesystem::path taskLogPath(const fs::path& jobDir, const std::string& jobId, size_t task) {
  return jobDir / "logs" / fmt::format("{}_{}.log", jobId, task);
}

std::filesystem::path taskStatusPath(const fs::path& jobDir, const std::string& jobId, size_t task) {
  return jobDir / "status" / fmt::format("{}_{}.exit", jobId, task);
}

namespace {

// "lacrima:<shot stem>" with only characters an #SBATCH line takes without quoting.
std::string jobName(const FarmJob& job) {
  std::string name = "lacrima:" + job.shot.stem().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != ':' && c != '-' && c != '_' && c != '.') c = '_';
  return name;
}

}  // namespace

// Task i reads its frames from line i + 1 of the chunk list, so the script stays the same size
// whatever the number of tasks. The exit status goes to a temporary name first: `farm status`
// never reads half a number.
std::string sbatchScript(const FarmJob& job, size_t index, const fs::path& jobDir) {
  const FarmSubmission& s = job.submissions[index];
  const fs::path chunkList = jobDir / fmt::format("chunks-{}.txt", index + 1);
  std::ostringstream out;
  out << "#!/bin/bash\n"
      << "# Written by `lacrima farm submit`: task i renders the frames on line i+1 of\n"
      << "# " << chunkList.string() << ". See `lacrima farm status --help`.\n"
      << "#SBATCH --job-name=" << jobName(job) << "\n"
      << "#SBATCH --array=0-" << s.chunks.size() - 1 << "\n"
      << "#SBATCH --output=" << (jobDir / "logs" / "%A_%a.log").string() << "\n";
  if (job.cpusPerTask > 0)
    out << "#SBATCH --cpus-per-task=" << job.cpusPerTask << "\n";
  else
    out << "#SBATCH --exclusive\n";
  if (!job.partition.empty()) out << "#SBATCH --partition=" << job.partition << "\n";
  out << "set -u\n"
      << "task=\"${SLURM_ARRAY_TASK_ID:?not started as a Slurm array task}\"\n"
      << "frames=\"$(sed -n \"$((task + 1))p\" " << shellQuote(chunkList.string()) << ")\"\n"
      << "echo \"lacrima farm: job ${SLURM_ARRAY_JOB_ID} task ${task} on $(hostname): frames ${frames}\"\n"
      << shellQuote(job.lacrima.string()) << " render " << shellQuote(job.shot.string())
      << " --frames \"$frames\" --resume --quiet --threads \"${SLURM_CPUS_PER_TASK:-0}\"";
  for (const std::string& a : renderArguments(job.render)) out << ' ' << shellQuote(a);
  const std::string status = (jobDir / "status").string() + "/${SLURM_ARRAY_JOB_ID}_${task}.exit";
  out << "\nstatus=$?\n"
      << "mkdir -p " << shellQuote((jobDir / "status").string()) << "\n"
      << "echo \"$status\" > \"" << status << ".tmp\" && mv \"" << status << ".tmp\" \"" << status << "\"\n"
      << "exit \"$status\"\n";
  return out.str();
}

fs::path defaultJobDirectory(const std::string& outputPattern, const fs::path& shot) {
  return fs::absolute(fs::path(outputPattern).parent_path()) / (shot.stem().string() + ".farm");
}

namespace {

json renderToJson(const RenderOptions& r) {
  json j = json::object();
  if (r.spp) j["spp"] = *r.spp;
  if (r.width) j["width"] = *r.width;
  if (r.height) j["height"] = *r.height;
  if (r.seed) j["seed"] = *r.seed;
  if (r.maxDepth) j["maxDepth"] = *r.maxDepth;
  j["output"] = r.outputPattern;
  j["preview"] = r.preview;
  j["float"] = r.floatOutput;
  if (r.denoise) j["denoise"] = *r.denoise;
  if (!r.aovs.empty()) j["aovs"] = r.aovs;
  if (!r.region.empty()) j["region"] = r.region;
  return j;
}

RenderOptions renderFromJson(const json& j, const fs::path& shot) {
  RenderOptions r;
  r.shotPath = shot.string();
  if (j.contains("spp")) r.spp = j["spp"].get<int>();
  if (j.contains("width")) r.width = j["width"].get<int>();
  if (j.contains("height")) r.height = j["height"].get<int>();
  if (j.contains("seed")) r.seed = j["seed"].get<uint64_t>();
  if (j.contains("maxDepth")) r.maxDepth = j["maxDepth"].get<int>();
  r.outputPattern = j.at("output").get<std::string>();
  r.preview = j.at("preview").get<bool>();
  r.floatOutput = j.at("float").get<bool>();
  if (j.contains("denoise")) r.denoise = j["denoise"].get<bool>();
  if (j.contains("aovs")) r.aovs = j["aovs"].get<std::vector<std::string>>();
  if (j.contains("region")) r.region = j["region"].get<std::vector<int>>();
  return r;
}

}  // namespace

void writeFarmJob(const fs::path& jobDir, const FarmJob& job) {
  json j;
  j["version"] = 1;
  j["shot"] = job.shot.string();
  j["frames"] = job.frames;
  j["render"] = renderToJson(job.render);
  j["partition"] = job.partition;
  j["cpusPerTask"] = job.cpusPerTask;
  j["lacrima"] = job.lacrima.string();
  j["submissions"] = json::array();
  for (const FarmSubmission& s : job.submissions)
    j["submissions"].push_back({{"jobId", s.jobId}, {"chunks", s.chunks}, {"script", s.script}});
  writeFileAtomically(jobDir / "job.json", "farm job", [&j](std::ostream& out) { out << j.dump(2) << "\n"; });
}

FarmJob readFarmJob(const fs::path& jobDir) {
  const fs::path file = jobDir / "job.json";
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("{}: no farm job here (submit one with `lacrima farm submit`)", file.string()));
  try {
    const json j = json::parse(in);
    if (j.at("version").get<int>() != 1) throw InputError(fmt::format("{}: unknown farm job version", file.string()));
    FarmJob job;
    job.shot = j.at("shot").get<std::string>();
    job.frames = j.at("frames").get<std::vector<int>>();
    job.render = renderFromJson(j.at("render"), job.shot);
    job.partition = j.at("partition").get<std::string>();
    job.cpusPerTask = j.at("cpusPerTask").get<int>();
    job.lacrima = j.at("lacrima").get<std::string>();
    for (const json& s : j.at("submissions"))
      job.submissions.push_back({s.at("jobId").get<std::string>(), s.at("chunks").get<std::vector<std::vector<int>>>(),
                                 s.at("script").get<std::string>()});
    return job;
  } catch (const json::exception& e) {
    throw InputError(fmt::format("{}: not a readable farm job: {}", file.string(), e.what()));
  }
}

}  // namespace lacrima::cli
