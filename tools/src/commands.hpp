#pragma once
// The subcommands of `lacrima`. Each returns the process exit status:
// 0 success, 1 render failure (e.g. too many NaN samples), 2 bad input (shot, asset, options).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lacrima/renderer/frame.hpp"

namespace lacrima {
struct Shot;
}

namespace lacrima::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitRenderFailure = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitFarmInProgress = 3;  // `farm status`: frames still running or pending

struct RenderOptions {
  std::string shotPath;
  std::optional<std::string> frames;  // none: the shot's range
  std::optional<int> spp, width, height, threads, maxDepth;
  std::optional<uint64_t> seed;
  std::optional<bool> denoise;  // --denoise / --no-denoise; none: the shot's render.denoise
  std::vector<std::string> aovs;  // --aov: further layers, beside the shot's render.aovs
  std::vector<int> region;        // --region X,Y,W,H: the part of the frame rendered; empty: all of it
  std::string outputPattern;  // empty: the shot's
  bool preview = false;
  bool floatOutput = false;
  bool quiet = false;
  bool resume = false;  // skip frames whose EXR is already complete with these settings
  bool reportMemory = false;  // print the peak and current RSS after every frame and at the end
  // --performance ASSET=FILE: takes played on the shot's assets instead of their animation
  // (render only; the farm does not forward them), at --performance-fps (none: the shot's fps).
  std::vector<std::string> performances;
  std::optional<double> performanceFps;
};

struct ExportOptions {
  std::string shotPath;
  std::optional<std::string> frames;  // none: the shot's range
  std::string format = "glb";         // "glb" or "obj" (main.cpp validates)
  std::string outputPattern;          // empty: the shot's output pattern with the format's extension
  int threads = 0;                    // 0: all cores
};

struct FloodOptions {
  std::vector<std::string> scenarios;    // flood scenario files; empty: scenes/floods/*.json (Schaffer et al.'s)
  std::vector<std::string> experiments;  // of those, the ones named (file stems); empty: all
  std::string outputDirectory = "flood";
  // Overrides of every scenario's values, when given.
  std::optional<double> duration;        // simulated seconds at most
  std::optional<double> coupledDensity;  // kg/m^3 of water as eq. 5 counts it (0: the liquid's own)
  std::optional<double> particleRadius;  // metres
  std::vector<double> sceneTimes;        // simulated seconds at which to write the scene (glb + shot)
};

struct TrackOptions {
  std::string performance;          // performance.json to track
  std::string synthesize;           // instead: write a synthetic performance into this folder
  std::string asset;                // the face (glTF); empty: the ICT face
  std::string part = "M_Face";      // its primitive to track
  std::string out = "track";        // folder for weights.csv and performance.csv
  int frames = 60;                  // --synthesize: frames
  double noise = 1.0;               // --synthesize: x a Kinect's depth noise
  double landmarkNoise = 1.0;       // --synthesize: landmarks jittered by up to this (pixels)
  double contourDrift = 0.0;        // --synthesize: jaw-line landmarks wander along it by up to this (pixels)
  bool dropHiddenLandmarks = false;  // --synthesize: landmarks the camera does not see are missing
  double landmarkSigma = 1.0;       // tracking: the landmark term's unit of error (pixels)
  uint64_t seed = 1;                // --synthesize: the performance and the noise
  bool render = false;               // --synthesize: depth from lacrima's path tracer (Z AOV)
  std::string fromShot;              // --synthesize: the take is this shot's animation of an asset ...
  std::string shotAsset = "face";    // ... this one
  std::vector<double> headStart;     // the head's channels at the first frame (3 rotations, or 6)
  bool noPrior = false, noFilter = false;
};

struct FarmSubmitOptions {
  RenderOptions render;     // shot, --frames, the overrides and --out each task renders with
  int chunk = 4;            // frames per array task
  std::string partition;    // empty: the cluster's default
  int cpusPerTask = 0;      // 0: a whole node per task
  std::string jobDir;       // empty: next to the output
  bool dryRun = false;
};

struct FarmStatusOptions {
  RenderOptions render;     // shot and --out (to find the job directory)
  std::string jobDir;
  bool wait = false;        // poll until nothing runs or waits
  double pollSeconds = 2.0;
};

struct BenchOptions {
  std::string shotPath;
  int width = 320, height = 180, spp = 4, threads = 0, repetitions = 3;
  std::optional<std::string> costFrames;  // the per-frame cost report's frames (none: six from the middle)
  bool frameCostsOnly = false;
  // --flesh: the shot's simulated flesh per frame at these tetrahedron sizes (cmd_bench_flesh.cpp).
  bool flesh = false;
  std::vector<double> tetSizes = {0.005, 0.0028};
  // --sph: the SPH liquid's cost on a dam break of this many particles, stepped this often (cmd_bench_sph.cpp).
  bool sph = false;
  int sphParticles = 100000, sphSteps = 10;
  // --tracking: the face tracker's cost and accuracy on a synthetic take of this many frames,
  // with lacrima's prior and one at Weise et al.'s size (cmd_bench_tracking.cpp).
  bool tracking = false;
  int trackFrames = 120;
  // --quality: time to equal error (cmd_bench_quality.cpp).
  bool quality = false;
  std::optional<int> frame;  // default: the shot's first frame
  int referenceSpp = 1024, maxSpp = 64;
  std::vector<double> targets = {0.1, 0.05, 0.043};
  std::string cacheDir;  // default: $XDG_CACHE_HOME/lacrima/quality or ~/.cache/lacrima/quality
  bool freshReference = false;
  // --adaptive: adaptive sampling's threshold for the measured renders (0: off); none: the shot's.
  std::optional<double> adaptiveThreshold;
  // --caustics: the measured renders' caustics mode; none: the shot's. The reference keeps the shot's.
  std::optional<Caustics> caustics;
};

struct DiffOptions {
  std::string a, b;  // files, directories or frame patterns (name.####.exr)
  double fail = 1e-6, failPercent = 0.0, warn = 1e-6, warnPercent = 0.0;
  std::optional<double> maxMeanError;
  std::vector<std::string> aovs;  // channel groups to compare; empty: all
  std::string out;                // difference EXR (a directory when several pairs)
  std::string flipOut;            // FLIP error PNG (a directory when several pairs)
  bool json = false;
  bool noFlip = false;
  double ppd = 0;  // 0: FLIP's default observer
};

struct TestSuiteOptions {
  std::string directory;          // regression shots (*.json) and their thresholds.json
  std::string references;         // empty: <directory>/../references
  std::string out;                // renders, difference and FLIP images; empty: a temporary directory
  std::vector<std::string> shots;  // names to run; empty: all
  bool update = false;            // render into the references instead of comparing
};

int runRender(const RenderOptions& options);
int runDiff(const DiffOptions& options);
int runTestSuite(const TestSuiteOptions& options);
int runCheck(const std::string& shotPath, int threads = 0);
int runInfo(const std::string& path);
int runBench(const BenchOptions& options);
int runBenchQuality(const BenchOptions& options);
int runBenchFlesh(const BenchOptions& options);
int runBenchSph(const BenchOptions& options);
int runBenchTracking(const BenchOptions& options);
int runExport(const ExportOptions& options);
int runFlood(const FloodOptions& options);
int runTrack(const TrackOptions& options);
int runFarmSubmit(const FarmSubmitOptions& options);
int runFarmStatus(const FarmStatusOptions& options);

// Prints the shot's non-fatal warnings (Shot::warnings) to stderr, one per line:
// "shot.json:13:27: /environment/file: warning: ...", before any rendering.
void printShotWarnings(const Shot& shot);

// Default OCIO config and default shot, found from the source tree this binary was built from.
std::string defaultOcioConfig();
std::string defaultShot();

}  // namespace lacrima::cli
