// lacrima: render film-quality tear shots. See `lacrima --help` and README.md.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "commands.hpp"
#include "lacrima/base/allocator_tuning.hpp"
#include "lacrima/renderer/frame.hpp"

using namespace lacrima::cli;

namespace {

const char* kDescription =
    "lacrima - a physically based path tracer for realistic human tears.\n"
    "\n"
    "Examples:\n"
    "  lacrima render scenes/shots/tear_closeup.json --preview\n"
    "      render the shot's frames to EXR (and an sRGB PNG preview next to each)\n"
    "  lacrima render shot.json --frames 1-48x2 --spp 64 --width 640 --height 360\n"
    "      every 2nd frame of 1-48, at a quick preview quality\n"
    "  lacrima check shot.json         validate a shot file, report every problem\n"
    "  lacrima export shot.json --frames 1-48 --format obj\n"
    "      the face, shape, tear and SPH liquid meshes of each frame, for other tools\n"
    "  lacrima info face.glb           list primitives, blendshapes and cameras of a glTF\n"
    "  lacrima info frame.0001.exr     list channels and lacrima metadata of a rendered frame\n"
    "  lacrima bench                   renderer and raw Embree throughput on the default shot\n"
    "  lacrima bench --quality         samples and seconds to reach an RMSE, against a converged reference\n"
    "  lacrima diff a.exr b.exr        compare two images (or directories, or frame sequences)\n"
    "  lacrima test-suite tests/data/regression\n"
    "      render the regression shots and compare them with their reference images\n"
    "  lacrima farm submit shot.json --chunk 6\n"
    "      the shot's frames as a Slurm array job; `lacrima farm status shot.json` follows it\n"
    "  lacrima flood --out flood      Schaffer et al.'s flood experiments: crowds crossing SPH water\n"
    "  lacrima track perf/performance.json --out track\n"
    "      a face performance (depth + landmarks) to a weight track a shot plays (Weise et al. 2011)\n"
    "\n"
    "Exit status: 0 success, 1 render failure, 2 bad input (shot file, asset or options);\n"
    "diff and test-suite: 0 pass, 1 warn, 2 fail or bad input; farm status: 3 frames still running.";

// An option value as the error message shows it: numbers bare, anything else quoted.
// --caustics' values, spelt as in shot files.
std::map<std::string, lacrima::Caustics> causticsByName() {
  std::map<std::string, lacrima::Caustics> byName;
  for (lacrima::Caustics mode : lacrima::kCausticsModes) byName[lacrima::causticsName(mode)] = mode;
  return byName;
}

std::string describeArgument(const std::string& text) {
  char* end = nullptr;
  if (!text.empty()) std::strtod(text.c_str(), &end);
  const bool numeric = !text.empty() && end == text.c_str() + text.size();
  return numeric ? text : "'" + text + "'";
}

// Whole numbers in [lo, hi] (hi = the type's maximum: no upper bound), with messages in the
// style of the shot-file diagnostics: "--spp: expected an integer >= 1, found 0". CLI11's own
// PositiveNumber/NonNegativeNumber print "not in range 0.000000 to 1797693134862315..." instead.
template <typename T>
CLI::Validator integerIn(T lo, T hi) {
  const std::string bound =
      hi == std::numeric_limits<T>::max() ? fmt::format(">= {}", lo) : fmt::format("in [{}, {}]", lo, hi);
  return CLI::Validator(
      [lo, hi, bound](std::string& text) -> std::string {
        T value{};
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, value);
        if (ec == std::errc() && ptr == end && value >= lo && value <= hi) return std::string();
        const bool tooLarge = ec == std::errc::result_out_of_range && ptr == end && text[0] != '-';
        return fmt::format("expected an integer {}, found {}{}", bound, describeArgument(text),
                           tooLarge ? " (too large)" : "");
      },
      "INT " + bound);
}

const char* kRenderExamples =
    "Examples:\n"
    "  lacrima render scenes/shots/tear_closeup.json --preview\n"
    "      all frames of the shot, to the shot's output pattern, with a PNG preview next to each EXR\n"
    "  lacrima render shot.json --frames 1-48x2 --spp 64 --width 640 --height 360\n"
    "      every 2nd frame of 1-48 at a quick preview quality\n"
    "  lacrima render shot.json --frames 12 --out /tmp/look.####.exr --seed 3\n"
    "      one frame to another place, with another seed\n"
    "  lacrima render scenes/shots/tear_closeup.json --frames 46 --region 780,400,480,500 --preview\n"
    "      the tear at 1:1 and full quality: a 480x500 crop window of the 1080p frame, its pixels the frame's\n"
    "  lacrima render scenes/shots/tear_closeup.json --performance face=track/performance.csv --out /tmp/t.####.exr\n"
    "      the crying shot played by a tracked performance (lacrima track) instead of its keyed one\n"
    "\n"
    "Overrides replace the shot file's render settings for this run only. Frames are written to a\n"
    "temporary name and renamed when complete, so an interrupted render never leaves a partial EXR.\n"
    "Ctrl-C (or SIGTERM) once: the current frame is finished and written, then the render stops and says\n"
    "how to continue (--resume); twice: the current frame is abandoned at once.\n"
    "Exit status: 0 success, 1 render failure (e.g. NaN samples), 2 bad input (shot, asset, options),\n"
    "130 interrupted with frames left to render.";

// The shot and the options that change what a render writes, shared by `render` and `farm submit`.
void addShotAndOverrides(CLI::App& command, RenderOptions& o) {
  // No CLI::ExistingFile: loadShot reports a missing shot file as `check` does.
  command.add_option("shot", o.shotPath, "Shot file (JSON)")->required();
  command.add_option("--spp,-s", o.spp, "Samples per pixel")->check(integerIn(1, INT_MAX));
  auto* width = command.add_option("--width", o.width, "Image width in pixels")->check(integerIn(1, 16384));
  auto* height = command.add_option("--height", o.height, "Image height in pixels")->check(integerIn(1, 16384));
  width->needs(height);
  height->needs(width);
  command.add_option("--seed", o.seed, "Random seed (same seed, same pixels)")
      ->check(integerIn<uint64_t>(0, std::numeric_limits<uint64_t>::max()));
  command.add_option("--max-depth", o.maxDepth, "Maximum path depth")->check(integerIn(0, 1000));
  command.add_option("--out,-o", o.outputPattern, "Output path pattern, #### = frame number (e.g. out/shot.####.exr)");
  command.add_flag("--preview", o.preview, "Also write an sRGB PNG preview (OCIO, ACES SDR view) next to each EXR");
  command.add_flag("--float", o.floatOutput, "Write the beauty as 32-bit float instead of half");
  auto* denoise = command.add_flag_callback("--denoise", [&o] { o.denoise = true; },
                                            "Denoise each frame: a denoised.R/G/B layer beside the raw beauty, shown "
                                            "by the preview (needs spp >= 2)");
  auto* noDenoise = command.add_flag_callback("--no-denoise", [&o] { o.denoise = false; },
                                              "Do not denoise, whatever the shot's render.denoise says");
  denoise->excludes(noDenoise);
  command.add_option("--aov", o.aovs,
                     "A further EXR layer, beside the shot's render.aovs (repeatable): CryptoObject, CryptoMaterial "
                     "(Cryptomatte ID mattes), lightGroups (a beauty layer per light group), lightPaths (diffuse, "
                     "specular and transmission direct/indirect, subsurface, emission, environment: adding up to the "
                     "beauty) or one of those passes by its layer name (diffuse_direct, ...); docs/compositing.md")
      ->check(CLI::IsMember(lacrima::aovNames()));
  command
      .add_option("--region", o.region,
                  "X,Y,W,H: render only the W x H pixels whose top left is pixel (X, Y) of the frame (a crop "
                  "window): the same pixels as in the whole frame, in an EXR whose data window they are (1:1 "
                  "looks at the tear in a fraction of the time)")
      ->delimiter(',')
      ->expected(4)
      ->check(integerIn(0, 16384));
}

void addRender(CLI::App& app, RenderOptions& o) {
  auto* render = app.add_subcommand("render", "Render a shot to an OpenEXR sequence");
  render->footer(kRenderExamples);
  addShotAndOverrides(*render, o);
  render->add_option("--frames,-f", o.frames, "Frames to render: 12, 1-48, 1-48x2 or lists like 1,5,10-12");
  render->add_option("--threads,-t", o.threads,
                     "Worker threads for everything: loading the shot, each frame's geometry and its path tracing "
                     "(0 = all cores; the image is the same for any count)")->check(integerIn(0, INT_MAX));
  render->add_flag("--quiet,-q", o.quiet, "Only print the per-frame summary lines");
  render->add_flag("--resume", o.resume,
                   "Skip frames whose EXR already exists, reads back completely and was rendered with the same "
                   "resolution, spp, seed and max depth; render the others (a truncated or corrupt file again)");
  render->add_option("--performance", o.performances,
                     "ASSET=FILE: play a performance CSV (lacrima track's performance.csv: weights and head "
                     "channels) on the shot's asset instead of its keyed blendshapes, controls and joints; tears, "
                     "flesh and eyes follow the tracked face. Repeatable; write to another --out than the shot's")
      ->type_name("ASSET=FILE");
  render->add_option("--performance-fps", o.performanceFps, "The --performance tracks' frame rate (default: the shot's)")
      ->check(CLI::PositiveNumber);
  render->add_flag("--report-memory", o.reportMemory,
                   "After every frame and at the end, print the process's peak and current resident memory "
                   "and malloc's heap in use / held (also after building and after rendering each frame); a "
                   "peak that grows frame after frame is a leak, a heap held that grows while in use stays "
                   "flat is fragmentation");
  render->callback([&o] { throw CLI::RuntimeError(runRender(o)); });
}

// One of a fixed set of words, with a message in the style of integerIn's.
CLI::Validator oneOf(const std::vector<std::string>& words) {
  std::string expected;
  for (size_t i = 0; i < words.size(); ++i)
    expected += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + words[i];
  return CLI::Validator(
      [words, expected](std::string& text) -> std::string {
        for (const std::string& w : words)
          if (text == w) return std::string();
        return fmt::format("expected {}, found {}", expected, describeArgument(text));
      },
      expected);
}

const char* kExportExamples =
    "Examples:\n"
    "  lacrima export scenes/shots/tear_closeup.json\n"
    "      every frame, next to the shot's EXR output with .glb (out/tear_closeup.####.glb)\n"
    "  lacrima export shot.json --frames 12-14 --format obj --out /tmp/geo/shot.####.obj\n"
    "      three frames as OBJ (each with its .mtl) to another place\n"
    "\n"
    "Each frame's file holds what the renderer gets from the shot at shutter open: the posed face\n"
    "primitives, the shapes, the tears, the SPH liquids' surfaces (simulated up to the frame, or read\n"
    "from their cache) and the spheres (tessellated), in world space and metres, each a named mesh\n"
    "(\"face/<mesh>/M_Face\", \"tear\", \"ellipsoid\", \"sph 0\", \"sphere 2\", ...) with its material's\n"
    "name and colour. glb: one node and mesh per mesh (see it with `lacrima info FILE.glb`);\n"
    "obj: one object per mesh, uvs flipped to OBJ's bottom-left origin. Files are written to a\n"
    "temporary name and renamed when complete.\n"
    "Exit status: 0 success, 2 bad input (shot, asset, options) or an output that cannot be written.";

void addExport(CLI::App& app, ExportOptions& o) {
  auto* exportCommand = app.add_subcommand("export", "Write each frame's face, shape, tear and SPH liquid meshes (glTF or OBJ)");
  exportCommand->footer(kExportExamples);
  exportCommand->add_option("shot", o.shotPath, "Shot file (JSON)")->required();
  exportCommand->add_option("--frames,-f", o.frames, "Frames to export: 12, 1-48, 1-48x2 or lists like 1,5,10-12");
  exportCommand->add_option("--format", o.format, "File format: glb (binary glTF 2.0, default) or obj (+ .mtl)")
      ->check(oneOf({"glb", "obj"}));
  exportCommand->add_option("--out,-o", o.outputPattern,
                            "Output path pattern, #### = frame number (default: the shot's output with .glb/.obj)");
  exportCommand->add_option("--threads,-t", o.threads,
                            "Worker threads for loading the shot and building each frame (0 = all cores; the files are "
                            "the same for any count)")->check(integerIn(0, INT_MAX));
  exportCommand->callback([&o] { throw CLI::RuntimeError(runExport(o)); });
}

const char* kFloodExamples =
    "Examples:\n"
    "  lacrima flood --out flood\n"
    "      Schaffer et al.'s experiments, scenes/floods/*.json (about 17 minutes on 2 cores)\n"
    "  lacrima flood --experiments table1-1.5 --duration 60 --out /tmp/flood\n"
    "      the four crowds of Table 1 at 1.5 m/s, for the first simulated minute\n"
    "  lacrima flood my_river.json --scene-at 20 --out /tmp/flood\n"
    "      a scenario file of your own, and its scene at 20 s to render\n"
    "\n"
    "Schaffer et al. 2020's flood (docs/crowd.md): a river of SPH water (27 m wide, 1 m deep and\n"
    "100 m long in theirs) streaming across a field, crowds of BioCrowds agents (65 kg, 1.3 m/s)\n"
    "crossing it, pushed by the water (their eqs. 5-9) according to their endurance tau. A\n"
    "scenario file (JSON, docs/crowd.md \"Scenario files\") gives the field, the river, the coupling\n"
    "and the crowds; theirs are table1-0.5, table1-1.5, table1-2.5 (Table 1's runs S1-S12 at one\n"
    "stream speed, tau 0, 0.2, 0.8 and 1.0 crossing the same river), counter-stream (tau 0.6, v_F\n"
    "1.5, a second group walking against the stream) and obstacle (tau 0.6, v_F 1.5, a 7 x 7 x 1 m\n"
    "block in the river). Each runs until every agent has arrived or been carried off the end, or\n"
    "its duration. Writes, in --out: <experiment>_<crowd>.csv (every half second: time, agent, x, z,\n"
    "state, hip height, the water's speed at it), <experiment>_<crowd>.png (a top view, the river\n"
    "flowing to the left, the "
    "trajectories red), <experiment>_water.png (the water's mean speed over the run: dark blue\n"
    "still, cyan the stream's speed, white twice it) and table.md (each run's time for the last\n"
    "agent, or not reached, how many arrived and were lost, and the water's speed behind each\n"
    "obstacle against beside it), and prints the table's rows as they finish. With --scene-at T,\n"
    "also each crowd's scene at T simulated seconds as <experiment>_<crowd>_tT.glb and a shot\n"
    "<experiment>_<crowd>_tT.json that renders it (`lacrima render` on the .json): the surfaced\n"
    "river, the banks and each agent as an articulated figure walking or, carried, tumbling as a\n"
    "ragdoll (or as the crowd's glTF \"figure\").\n"
    "Exit status: 0 success, 2 a bad scenario file or option, or an output that cannot be written.";

void addFlood(CLI::App& app, FloodOptions& o) {
  auto* flood = app.add_subcommand(
      "flood", "Run Schaffer et al. 2020's flood experiments: crowds crossing a river of SPH water");
  flood->footer(kFloodExamples);
  flood->add_option("scenarios", o.scenarios,
                    "Flood scenario files (JSON; default: Schaffer et al.'s, scenes/floods/*.json)");
  flood->add_option("--experiments", o.experiments, "Of the scenarios, the ones named (file stems), e.g. "
                                                    "table1-1.5,obstacle")
      ->delimiter(',');
  flood->add_option("--out,-o", o.outputDirectory, "Folder for the trajectories, plots and table (default: flood)");
  flood->add_option("--duration", o.duration, "Simulated seconds at most per experiment (default: the scenario's, 300)")
      ->check(CLI::Range(1.0, 3600.0));
  flood->add_option("--coupled-density", o.coupledDensity,
                    "kg/m^3 of water as Schaffer et al.'s eq. 5 counts it, each colliding particle weighing this "
                    "times its volume (default: the scenario's, 80 in Schaffer et al.'s; 0: water's own 1000)")
      ->check(CLI::Range(0.0, 1e4));
  flood->add_option("--particle-radius", o.particleRadius,
                    "SPH particle radius in metres (default: the scenario's, 0.25: 21,600 particles in "
                    "Schaffer et al.'s river; 0.15: 89,910)")
      ->check(CLI::Range(0.1, 1.0));
  flood->add_option("--scene-at", o.sceneTimes,
                    "Simulated seconds at which to write each crowd's scene: <experiment>_<crowd>_t<T>.glb "
                    "(the surfaced river, the agents, the ground) and a .json shot that renders it")
      ->delimiter(',')
      ->check(CLI::Range(0.0, 3600.0));
  flood->callback([&o] { throw CLI::RuntimeError(runFlood(o)); });
}

const char* kTrackExamples =
    "Examples:\n"
    "  lacrima track --synthesize /tmp/perf --frames 60\n"
    "      a synthetic performance of the ICT face: depth EXRs with a Kinect's noise, 68 landmarks,\n"
    "      and the truth it was made from (truth_weights.csv, truth_performance.csv)\n"
    "  lacrima track --synthesize /tmp/perf --render --frames 30\n"
    "      the same with the depth rendered by lacrima itself (capture.json's Z AOV)\n"
    "  lacrima track /tmp/perf/performance.json --out /tmp/track\n"
    "      track it: /tmp/track/weights.csv (play it in a shot: \"performance\": {\"file\": ...})\n"
    "      and /tmp/track/performance.csv (the weights and the head's channels, for an asset with a\n"
    "      rig); beside a synthetic performance, the errors against its truth\n"
    "  lacrima track --synthesize /tmp/cry --from-shot scenes/shots/tear_closeup.json\n"
    "  lacrima track /tmp/cry/performance.json --out /tmp/cry-track --head-start 6,0,12 --no-filter\n"
    "  lacrima render scenes/shots/tear_closeup.json --performance face=/tmp/cry-track/performance.csv -o t.####.exr\n"
    "      the crying shot's own performance captured, tracked, and the shot played by the track\n"
    "\n"
    "The realtime tracker of Weise, Bouaziz, Li & Pauly 2011 (docs/tracking.md): per frame, ICP of the\n"
    "face's upper part against the depth map (point-plane, from the last frame's pose; the first frame's\n"
    "from the inner landmarks and their depth), Weise et al.'s adaptive pose filter (--no-filter: off), then\n"
    "the blendshape weights in [0, 1] fitted to the depth and the landmarks with Weise et al.'s animation\n"
    "prior (--no-prior: off; trained on synthetic keyed blends of twelve archetypal expressions with\n"
    "spontaneous blinks).\n"
    "A performance is performance.json: {\"version\": 1, \"fps\": 30, \"frames\": {\"start\": 1, \"end\": 60},\n"
    "\"camera\": {\"width\", \"height\", \"fx\", \"fy\", \"cx\", \"cy\"} (pixels), \"depth\": \"depth.####.exr\" (one\n"
    "float channel Z in metres, 0 = none), \"landmarks\": \"landmarks.csv\" (frame,landmark,u,v in pixels,\n"
    "iBUG 68 numbering; or OpenFace 2.0's CSV, or JSON: docs/tracking.md)}. On a moving head the pose\n"
    "filter lags (--no-filter tracks it closer). performance.csv adds to the weights the head's\n"
    "motion since the first frame as the rig's channels head.rx/ry/rz (Euler degrees, x first) and\n"
    "head.tx/ty/tz (metres), turning about the ICT rig's head pivot.\n"
    "Exit status: 0 success, 2 a bad performance, asset or option.";

void addTrack(CLI::App& app, TrackOptions& o) {
  auto* track = app.add_subcommand("track", "Track a recorded face performance into a blendshape weight track");
  track->footer(kTrackExamples);
  track->add_option("performance", o.performance, "The performance to track (performance.json)");
  track->add_option("--synthesize", o.synthesize, "Instead, write a synthetic performance of the face into this folder");
  track->add_option("--asset", o.asset, "The face (glTF with morph targets and 68 landmarks; default: the ICT face)");
  track->add_option("--part", o.part, "The face's primitive to track (default: M_Face)");
  track->add_option("--out,-o", o.out, "Folder for weights.csv and performance.csv (default: track)");
  track->add_option("--frames", o.frames, "--synthesize: frames (default 60, at 30 fps)")->check(CLI::Range(1, 100000));
  track->add_option("--noise", o.noise, "--synthesize: depth noise, times a Kinect's (default 1; 0: none)")->check(CLI::Range(0.0, 100.0));
  track->add_option("--landmark-noise", o.landmarkNoise, "--synthesize: landmarks jittered by up to this many pixels (default 1)")
      ->check(CLI::Range(0.0, 100.0));
  track->add_option("--contour-drift", o.contourDrift,
                    "--synthesize: the jaw line's 17 landmarks wander along the contour by up to this many pixels, "
                    "each over 2-5 s, as a detector's do (default 0)")
      ->check(CLI::Range(0.0, 100.0));
  track->add_flag("--drop-hidden-landmarks", o.dropHiddenLandmarks,
                  "--synthesize: landmarks the camera does not see (turned away, or behind the cheek) are missing, "
                  "as a detector drops its low-confidence points");
  track->add_option("--landmark-sigma", o.landmarkSigma,
                    "The landmarks' typical error in pixels: how much the fit trusts them against the depth "
                    "(default 1, a good detector on a sharp frame; 2-4 for a phone's video)")
      ->check(CLI::Range(0.05, 1000.0));
  track->add_option("--seed", o.seed, "--synthesize: the performance's and the noise's seed (default 1)");
  track->add_flag("--render", o.render,
                  "--synthesize: the depth from lacrima's own path tracer (the Z AOV of capture.json, every part of "
                  "the face in view, the head turned through the ICT rig) instead of a z-buffer of the tracked primitive");
  track->add_option("--from-shot", o.fromShot,
                    "--synthesize: capture this shot's animation of --shot-asset (its weights and head, over the "
                    "shot's frames at its fps) instead of a keyed one");
  track->add_option("--shot-asset", o.shotAsset, "--from-shot: the asset whose animation is captured (default: face)");
  track->add_option("--head-start", o.headStart,
                    "The head's channels at the first frame, as the shot stages it: rx ry rz (degrees) [tx ty tz "
                    "(metres)]; performance.csv's head channels are this pose followed by the tracked motion "
                    "(default: at rest)")
      ->expected(3, 6)
      ->delimiter(',');
  track->add_flag("--no-prior", o.noPrior, "Fit without the animation prior");
  track->add_flag("--no-filter", o.noFilter, "Do not filter the head pose");
  track->callback([&o] { throw CLI::RuntimeError(runTrack(o)); });
}

const char* kFarmExamples =
    "Examples:\n"
    "  lacrima farm submit scenes/shots/tear_closeup.json --chunk 6 --partition render\n"
    "      the shot's frames as a Slurm array job, 6 frames per task, each task on a whole node\n"
    "  lacrima farm submit shot.json --frames 1-24 --spp 64 --cpus-per-task 8 --dry-run\n"
    "      write the sbatch script and chunk list without submitting (look, then `sbatch` it)\n"
    "  lacrima farm status shot.json --wait\n"
    "      done / running / pending / failed frames, until nothing runs any more\n"
    "\n"
    "Each task runs `lacrima render SHOT --frames <its chunk> --resume` with the overrides given to\n"
    "submit, so a node writes bitwise the frame a local render writes, and frames go to the shot's\n"
    "output (or --out) atomically. Submitting again renders only the frames not yet complete on\n"
    "disk. The job directory (default: <output dir>/<shot>.farm) holds job.json, the sbatch scripts\n"
    "(job-N.sh), chunk lists, one log per task (logs/<job>_<task>.log) and one exit status per task\n"
    "(status/<job>_<task>.exit). A single-node test cluster: tools/slurm/cluster.sh.\n"
    "Exit status: 0 submitted (or nothing to do) / every frame done; 1 sbatch failed / frames failed or\n"
    "missing; 2 bad input; 3 (status) frames still running or pending.";

void addFarm(CLI::App& app, FarmSubmitOptions& submit, FarmStatusOptions& status) {
  auto* farm = app.add_subcommand("farm", "Render a shot on a Slurm farm and follow it");
  farm->footer(kFarmExamples);
  farm->require_subcommand(1);
  auto* submitCommand = farm->add_subcommand("submit", "Submit the shot's missing frames as a Slurm array job");
  submitCommand->footer(kFarmExamples);
  addShotAndOverrides(*submitCommand, submit.render);
  submitCommand->add_option("--frames,-f", submit.render.frames, "Frames: 12, 1-48, 1-48x2 or lists like 1,5,10-12");
  submitCommand->add_option("--chunk", submit.chunk, "Frames per array task (default 4)")->check(integerIn(1, 100000));
  submitCommand->add_option("--partition,-p", submit.partition, "Slurm partition (default: the cluster's)");
  submitCommand->add_option("--cpus-per-task", submit.cpusPerTask,
                            "CPUs per task, the render's threads (default 0: a whole node per task)")
      ->check(integerIn(0, 100000));
  submitCommand->add_option("--job-dir", submit.jobDir, "Job directory (default: <output dir>/<shot>.farm)");
  submitCommand->add_flag("--dry-run", submit.dryRun, "Write the job's files but do not submit");
  submitCommand->callback([&submit] { throw CLI::RuntimeError(runFarmSubmit(submit)); });

  auto* statusCommand = farm->add_subcommand("status", "Done, running, pending and failed frames of a farm job");
  statusCommand->footer(kFarmExamples);
  statusCommand->add_option("shot", status.render.shotPath, "Shot file (JSON)")->required();
  statusCommand->add_option("--out,-o", status.render.outputPattern, "The --out given to submit, if any");
  statusCommand->add_option("--job-dir", status.jobDir, "The --job-dir given to submit, if any");
  statusCommand->add_flag("--wait", status.wait, "Poll until no frame runs or waits and the job's tasks have left the queue, then report");
  statusCommand->add_option("--poll", status.pollSeconds, "Seconds between polls with --wait (default 2)")
      ->check(CLI::Range(0.05, 3600.0));
  statusCommand->callback([&status] { throw CLI::RuntimeError(runFarmStatus(status)); });
}

void addCheck(CLI::App& app, std::string& shot, int& threads) {
  auto* check = app.add_subcommand("check", "Validate a shot file and its assets without rendering");
  check->add_option("shot", shot, "Shot file (JSON)")->required();
  check->add_option("--threads,-t", threads, "Worker threads for loading the shot and building its first frame (0 = all cores)")
      ->check(integerIn(0, INT_MAX));
  check->callback([&shot, &threads] { throw CLI::RuntimeError(runCheck(shot, threads)); });
}

void addInfo(CLI::App& app, std::string& file) {
  auto* info = app.add_subcommand("info", "Describe a glTF asset (.glb/.gltf) or an EXR frame");
  info->add_option("file", file, "A .glb, .gltf or .exr file")->required();
  info->callback([&file] { throw CLI::RuntimeError(runInfo(file)); });
}

// Non-negative real numbers, with a message in the style of integerIn's.
CLI::Validator nonNegativeNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = text.empty() ? -1.0 : std::strtod(text.c_str(), &end);
        if (!text.empty() && end == text.c_str() + text.size() && value >= 0.0 && std::isfinite(value))
          return std::string();
        return fmt::format("expected a number >= 0, found {}", describeArgument(text));
      },
      "NUMBER >= 0");
}

void addBench(CLI::App& app, BenchOptions& o) {
  auto* bench = app.add_subcommand("bench", "Measure render and raw Embree throughput (not a test)");
  bench->footer(
      "Renders the default shot (or SHOT) at a fixed small size and reports medians of the repetitions,\n"
      "then per frame (--frames) the milliseconds before the first ray: geometry stages, scene update, set-up.\n"
      "With --sph, the SPH liquid's particle updates per second on a dam break; with --tracking, the face\n"
      "tracker's milliseconds a frame against Weise et al. 2011's 20 Hz.\n"
      "With --quality, reports time to equal error, e.g.\n"
      "  lacrima bench --quality --width 160 --height 90 --max-spp 64 --target 0.05");
  bench->add_option("shot", o.shotPath, "Shot file (default: scenes/shots/tear_closeup.json)");
  bench->add_option("--width", o.width, "Width")->check(integerIn(8, 4096));
  bench->add_option("--height", o.height, "Height")->check(integerIn(8, 4096));
  bench->add_option("--spp", o.spp, "Samples per pixel")->check(integerIn(1, 4096));
  bench->add_option("--threads", o.threads, "Threads (0 = all cores); in the frame report, for the geometry too")->check(integerIn(0, INT_MAX));
  bench->add_option("--repetitions", o.repetitions, "Repetitions (median reported)")->check(integerIn(1, 50));
  bench->add_option("--frames", o.costFrames,
                    "The frames of the per-frame cost report, in order (default: six from the middle of the shot)");
  bench->add_flag("--frame-costs-only", o.frameCostsOnly, "Only the per-frame cost report (no throughput)");
  bench->add_flag("--quality", o.quality,
                  "Time to equal error instead: RMSE at 1, 2, 4 ... --max-spp samples against a converged reference, "
                  "the RMSE-vs-spp slope, and the samples and seconds to reach each --target");
  bench->add_flag("--flesh", o.flesh,
                  "The simulated flesh's milliseconds per frame instead, its volume rebuilt at each --tet-size "
                  "(simulated from the shot's first frame through --frame, default the shot's last)");
  bench->add_option("--tet-size", o.tetSizes,
                    "--flesh: tetrahedron edge bounds in metres (repeatable; default 0.005 0.0028: about 20k and "
                    "100k tetrahedra on the default shot)")
      ->check(CLI::PositiveNumber);
  bench->add_flag("--sph", o.sph,
                  "The SPH liquid's cost instead: a dam break of --particles particles (2.5 mm) stepped --steps "
                  "times; median step, particle updates per second, solver iterations, surfacing milliseconds");
  bench->add_option("--particles", o.sphParticles, "--sph: particles (default 100000)")->check(integerIn(100, 10000000));
  bench->add_option("--steps", o.sphSteps, "--sph: measured steps (default 10)")->check(integerIn(1, 10000));
  bench->add_flag("--tracking", o.tracking,
                  "The face tracker's cost instead (lacrima track): per frame the rigid and non-rigid stages' "
                  "milliseconds and the frames a second on a synthetic take of the ICT face, with lacrima's prior "
                  "and one trained at Weise et al.'s size (20 analysers, 50 starts), against the take's truth");
  bench->add_option("--track-frames", o.trackFrames, "--tracking: frames of the take (default 120, at 30 fps)")
      ->check(integerIn(5, 100000));
  bench->add_option("--frame", o.frame, "--quality: the frame (default: the shot's first); --flesh: the last frame");
  bench->add_option("--reference-spp", o.referenceSpp,
                    "--quality: samples of the reference (its own noise adds in quadrature: 1024 against 64 spp "
                    "raises the RMSE by 3 %)")
      ->check(integerIn(16, 1 << 20));
  bench->add_option("--max-spp", o.maxSpp, "--quality: the largest measured sample count")->check(integerIn(1, 1 << 16));
  bench->add_option("--target", o.targets, "--quality: RMSE targets (repeatable; default 0.1 0.05 0.043)")
      ->check(CLI::PositiveNumber);
  bench->add_option("--cache", o.cacheDir,
                    "--quality: folder of cached references (default $XDG_CACHE_HOME/lacrima/quality or "
                    "~/.cache/lacrima/quality); a reference is keyed by the shot file's contents, frame, size, "
                    "max depth, pixel filter and spp");
  bench->add_flag("--fresh-reference", o.freshReference,
                  "--quality: render the reference again (after a change of assets or of what the renderer converges to)");
  bench->add_option("--adaptive", o.adaptiveThreshold,
                    "--quality: adaptive sampling for the measured renders with this threshold, 0 = off (default: "
                    "as the shot says); each count is then the pixels' maximum, and the mean is reported")
      ->check(nonNegativeNumber());
  bench->add_option("--caustics", o.caustics,
                    "--quality: the measured renders' caustics, mnee, straight or off (default: as the shot says; "
                    "the reference keeps the shot's): e.g. MNEE against brute force on "
                    "scenes/shots/caustic_drop.json")
      ->transform(CLI::CheckedTransformer(causticsByName()));
  bench->callback(
      [&o] {
        throw CLI::RuntimeError(o.quality ? runBenchQuality(o)
                                : o.flesh ? runBenchFlesh(o)
                                : o.sph   ? runBenchSph(o)
                                : o.tracking ? runBenchTracking(o)
                                          : runBench(o));
      });
}


const char* kDiffExamples =
    "A and B are two images (OpenEXR with all its AOV channels, PNG, ...), two directories (images\n"
    "paired by file name) or two frame patterns (shot.####.exr: frames paired by number). A frame on\n"
    "one side only fails the comparison.\n"
    "\n"
    "Metrics, per channel group (beauty = R,G,B,A; each AOV such as N, albedo, Z): mean absolute\n"
    "error, RMS, the largest difference with its pixel and channel, PSNR (peak 1.0) and the pixels\n"
    "over the thresholds. FLIP (NVIDIA's perceptual error, 0 = identical, 1 = as different as\n"
    "possible) of the beauty: HDR-FLIP for float images, LDR-FLIP for 8-bit ones.\n"
    "\n"
    "Thresholds work as in OIIO's idiff: a pixel fails when any channel differs by more than --fail,\n"
    "and the comparison FAILS when more than --failpercent % of the pixels fail (or the mean error\n"
    "exceeds --max-mean); it WARNS when more than --warnpercent % differ by more than --warn.\n"
    "The defaults (1e-6, 0 %) ask for identical images.\n"
    "\n"
    "Examples:\n"
    "  lacrima diff ref.exr new.exr\n"
    "      the table of every channel group, FLIP, PASS/WARN/FAIL\n"
    "  lacrima diff ref.exr new.exr --fail 0.05 --failpercent 0.5 --warn 0.005 --aov beauty\n"
    "      tolerate noise: fail when over 0.5 % of the beauty's pixels differ by more than 0.05\n"
    "  lacrima diff old/shot.####.exr new/shot.####.exr --out diffs --flip-out diffs --json\n"
    "      a whole sequence: per frame and overall, |A-B| EXRs and FLIP maps into diffs/, JSON report\n"
    "\n"
    "Exit status: 0 pass, 1 warn, 2 fail (also: a missing frame, an unreadable file, different sizes\n"
    "or channels, bad options). See docs/diff.md.";

void addDiff(CLI::App& app, DiffOptions& o) {
  auto* diff = app.add_subcommand("diff", "Compare two images, directories or frame sequences (metrics, FLIP)");
  diff->footer(kDiffExamples);
  diff->add_option("a", o.a, "Reference: an image, a directory or a frame pattern (name.####.exr)")->required();
  diff->add_option("b", o.b, "Test: the same kind as A")->required();
  diff->add_option("--fail", o.fail, "A pixel fails when a channel differs by more than this (default 1e-6)")
      ->check(nonNegativeNumber());
  diff->add_option("--failpercent", o.failPercent, "Fail when more than this % of pixels fail (default 0)")
      ->check(nonNegativeNumber());
  diff->add_option("--warn", o.warn, "A pixel warns when a channel differs by more than this (default 1e-6)")
      ->check(nonNegativeNumber());
  diff->add_option("--warnpercent", o.warnPercent, "Warn when more than this % of pixels warn (default 0)")
      ->check(nonNegativeNumber());
  diff->add_option("--max-mean", o.maxMeanError, "Also fail when a group's mean absolute error exceeds this")
      ->check(nonNegativeNumber());
  diff->add_option("--aov", o.aovs, "Compare only this channel group (beauty, N, albedo, Z, ...); repeatable");
  diff->add_option("--out,-o", o.out, "Write |A-B| as a float EXR here (a directory for several pairs)");
  diff->add_option("--flip-out", o.flipOut, "Write the FLIP error map (magma colours) as PNG here (a directory for several pairs)");
  diff->add_option("--ppd", o.ppd, "FLIP observer: pixels per degree (0 or unset: 67.02, 0.7 m from a 0.7 m wide 3840-pixel monitor)")
      ->check(nonNegativeNumber());
  diff->add_flag("--no-flip", o.noFlip, "Skip FLIP (it is the slow part on large images)");
  diff->add_flag("--json", o.json, "Print the report as JSON instead of tables");
  diff->callback([&o] { throw CLI::RuntimeError(runDiff(o)); });
}

const char* kTestSuiteExamples =
    "Renders every shot file DIR/*.json (in-process, as `lacrima render` does) and compares the\n"
    "render with REFDIR/<shot>.exr using DIR/thresholds.json (per-shot thresholds over a default;\n"
    "see docs/diff.md). Shots that do not pass leave their render, |A-B| EXR and FLIP PNG in --out.\n"
    "\n"
    "Examples:\n"
    "  lacrima test-suite tests/data/regression\n"
    "      the project's image regression (references in tests/data/references)\n"
    "  lacrima test-suite tests/data/regression --shot face_liquid_tear --out /tmp/suite\n"
    "      one shot, its images kept in /tmp/suite\n"
    "  lacrima test-suite tests/data/regression --update\n"
    "      render new references (with PNG previews) instead; tools/update_references.sh records why\n"
    "\n"
    "Exit status: 0 all pass, 1 a shot warns, 2 a shot fails (or its render fails, or bad input).";

void addTestSuite(CLI::App& app, TestSuiteOptions& o) {
  auto* suite = app.add_subcommand("test-suite", "Render regression shots and compare them with their references");
  suite->footer(kTestSuiteExamples);
  suite->add_option("directory", o.directory, "Directory of regression shots (*.json) and thresholds.json")->required();
  suite->add_option("--references,-r", o.references, "Reference images (default: DIR/../references)");
  suite->add_option("--out,-o", o.out, "Where renders and difference images go (default: a temporary directory)");
  suite->add_option("--shot", o.shots, "Run only this shot (file name without .json); repeatable");
  suite->add_flag("--update", o.update, "Render the references instead of comparing with them");
  suite->callback([&o] { throw CLI::RuntimeError(runTestSuite(o)); });
}

}  // namespace

int main(int argc, char** argv) {
  lacrima::keepFreedMemoryForReuse();
  CLI::App app(kDescription, "lacrima");
  app.set_version_flag("--version", std::string("lacrima ") + LACRIMA_VERSION);
  app.require_subcommand(1);
  RenderOptions renderOptions;
  BenchOptions benchOptions;
  ExportOptions exportOptions;
  DiffOptions diffOptions;
  TestSuiteOptions testSuiteOptions;
  FarmSubmitOptions farmSubmitOptions;
  FarmStatusOptions farmStatusOptions;
  FloodOptions floodOptions;
  TrackOptions trackOptions;
  std::string checkShot, infoFile;
  int checkThreads = 0;
  addRender(app, renderOptions);
  addCheck(app, checkShot, checkThreads);
  addInfo(app, infoFile);
  addBench(app, benchOptions);
  addExport(app, exportOptions);
  addDiff(app, diffOptions);
  addTestSuite(app, testSuiteOptions);
  addFarm(app, farmSubmitOptions, farmStatusOptions);
  addFlood(app, floodOptions);
  addTrack(app, trackOptions);
  try {
    app.parse(argc, argv);
  } catch (const CLI::RuntimeError& status) {
    return status.get_exit_code();  // a subcommand ran; its status
  } catch (const CLI::RequiredError& e) {
    // "lacrima frobnicate": CLI11 checks for the missing subcommand before it complains about
    // the extra argument, and would say only "A subcommand is required".
    const std::vector<std::string> extra = app.remaining();
    if (app.get_subcommands().empty() && !extra.empty()) {
      std::string names;
      for (const CLI::App* sub : app.get_subcommands({})) names += (names.empty() ? "" : ", ") + sub->get_name();
      const bool isOption = !extra.front().empty() && extra.front()[0] == '-';
      std::fprintf(stderr,
                   "lacrima: unknown %s '%s' (expected a subcommand: %s)\nRun with --help for more information.\n",
                   isOption ? "option" : "subcommand", extra.front().c_str(), names.c_str());
      return kExitBadInput;
    }
    return app.exit(e) == 0 ? 0 : kExitBadInput;
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : kExitBadInput;  // --help/--version are 0; usage errors are bad input
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lacrima: internal error: %s\n", e.what());
    return kExitRenderFailure;
  }
  return kExitOk;
}
