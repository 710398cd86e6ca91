// `lacrima flood`: Schaffer et al. 2020's flood experiments (crowds crossing a river of SPH water;
// geometry/crowd/include/lacrima/crowd/flood.hpp), with their trajectories, top-view plots and a
// table of outcomes (docs/crowd.md).
#include <fmt/format.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <algorithm>
#include <set>
#include <sstream>

#include "atomic_write.hpp"
#include "commands.hpp"
#include "lacrima/crowd/figure.hpp"
#include "lacrima/crowd/flood.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/scenes/flood_scenario.hpp"
#include "lacrima/scenes/shot.hpp"
#include "lacrima/sph/sph_surface.hpp"
#include "flood_water_map.hpp"
#include "mesh_export.hpp"

namespace lacrima::cli {

namespace {

using crowd::FloodSimulation;

constexpr int kPixelsPerMetre = 8;

// A top view of the field, x to the right (the river flows to the left), z up: the river blue,
// obstacles dark grey, the goal yellow, every agent's positions red (Schaffer et al.'s figures).
class TopView {
 public:
  explicit TopView(const crowd::FloodParams& p)
      : width_(int(std::lround((p.field.max.x() - p.field.min.x()) * kPixelsPerMetre))),
        height_(int(std::lround((p.field.max.y() - p.field.min.y()) * kPixelsPerMetre))),
        origin_(p.field.min),
        rgb_(size_t(width_) * size_t(height_) * 3) {
    for (int y = 0; y < height_; ++y)
      for (int x = 0; x < width_; ++x) {
        const crowd::Vec2d g = ground(x, y);
        const bool river = g.y() >= p.river.zMin && g.y() <= p.river.zMin + p.river.width;
        set(x, y, river ? 0.55f : 0.78f, river ? 0.7f : 0.76f, river ? 0.9f : 0.68f);
        for (const crowd::GroundRect& o : p.river.obstacles)
          if (o.contains(g)) set(x, y, 0.25f, 0.25f, 0.25f);
      }
  }
  void dot(const crowd::Vec2d& at, float r, float g, float b, int radius = 0) {
    const int cx = int((at.x() - origin_.x()) * kPixelsPerMetre), cy = height_ - 1 - int((at.y() - origin_.y()) * kPixelsPerMetre);
    for (int dy = -radius; dy <= radius; ++dy)
      for (int dx = -radius; dx <= radius; ++dx)
        if (cx + dx >= 0 && cx + dx < width_ && cy + dy >= 0 && cy + dy < height_) set(cx + dx, cy + dy, r, g, b);
  }
  void write(const std::filesystem::path& path) const { writePlotPng(path, width_, height_, rgb_, "the plot"); }

 private:
  crowd::Vec2d ground(int x, int y) const {
    return origin_ + crowd::Vec2d((x + 0.5) / kPixelsPerMetre, (height_ - 1 - y + 0.5) / kPixelsPerMetre);
  }
  void set(int x, int y, float r, float g, float b) {
    float* p = &rgb_[(size_t(y) * size_t(width_) + size_t(x)) * 3];
    p[0] = r, p[1] = g, p[2] = b;
  }
  int width_, height_;
  crowd::Vec2d origin_;
  std::vector<float> rgb_;
};

// A quad (two triangles) from four corners in order.
TriangleMesh quad(const std::string& name, const std::array<Vec3, 4>& corners) {
  TriangleMesh mesh;
  mesh.name = name;
  mesh.positions.assign(corners.begin(), corners.end());
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

// The river and the crowd at this moment as meshes for a renderer: the surfaced water in its bed,
// the banks a river's depth above the bed, each agent in its figure's pose (crowd/figure.hpp: the
// built-in articulated figure walking or carried as a ragdoll, or the crowd's glTF figure placed
// by the pose; none once arrived or lost). Written as <stem>.glb with <stem>.json, a shot that
// renders it.
void writeFloodScene(const FloodSimulation& simulation, size_t c, const crowd::FigureAnimator& figures,
                     const TriangleMesh& figureMesh, const std::filesystem::path& stem) {
  const crowd::RiverParams& river = simulation.params().river;
  const crowd::GroundRect& field = simulation.params().field;
  ExportScene scene;
  scene.materials = {{"water", Color(1.0f, 1.0f, 1.0f), 0.0f, 1.333f},
                     {"body", Color(0.55f, 0.12f, 0.1f), 0.8f, std::nullopt},
                     {"ground", Color(0.35f, 0.32f, 0.26f), 1.0f, std::nullopt}};
  sph::SurfaceParams surfacing;
  surfacing.voxelsPerRadius = 1.5;
  surfacing.smoothingIterations = 16;
  TriangleMesh water = sph::surfaceOfParticles(simulation.liquid().positions(), river.particleRadius, surfacing);
  water.name = "river";
  if (water.triangleCount() > 0) scene.meshes.push_back({std::move(water), 0});
  const float x0 = float(field.min.x()), x1 = float(field.max.x()), z0 = float(field.min.y()), z1 = float(field.max.y());
  const float nearBank = float(river.zMin), farBank = float(river.zMin + river.width), top = float(river.depth);
  const auto& agents = simulation.crowd(c).agents();
  for (size_t a = 0; a < agents.size(); ++a) {
    if (agents[a].arrived) continue;  // arrived or lost: out of the picture
    const crowd::FigurePose& pose = figures.poses()[a];
    TriangleMesh body;
    if (figureMesh.triangleCount() == 0) {
      body = crowd::articulatedFigure(pose);
    } else {
      body = figureMesh;
      transformMesh(body, Affine3(figureRootTransform(pose).cast<float>()));
    }
    body.name = fmt::format("agent {}", a);
    scene.meshes.push_back({std::move(body), 1});
  }
  // Counter-clockwise seen from above (or from the river, for the banks' faces).
  scene.meshes.push_back({quad("near bank", {Vec3(x0, top, z0), Vec3(x0, top, nearBank), Vec3(x1, top, nearBank), Vec3(x1, top, z0)}), 2});
  scene.meshes.push_back({quad("far bank", {Vec3(x0, top, farBank), Vec3(x0, top, z1), Vec3(x1, top, z1), Vec3(x1, top, farBank)}), 2});
  scene.meshes.push_back({quad("river bed", {Vec3(x0, 0, nearBank), Vec3(x0, 0, farBank), Vec3(x1, 0, farBank), Vec3(x1, 0, nearBank)}), 2});
  scene.meshes.push_back({quad("near bank face", {Vec3(x0, 0, nearBank), Vec3(x1, 0, nearBank), Vec3(x1, top, nearBank), Vec3(x0, top, nearBank)}), 2});
  scene.meshes.push_back({quad("far bank face", {Vec3(x1, 0, farBank), Vec3(x0, 0, farBank), Vec3(x0, top, farBank), Vec3(x1, top, farBank)}), 2});
  writeGlb(stem.string() + ".glb", scene);
  const std::string glb = stem.filename().string() + ".glb";
  const std::string shot = fmt::format(R"({{
  // The flood at {:.1f} s, written by `lacrima flood --scene-at`: render with `lacrima render` on this file.
  "version": 1,
  "frames": {{"start": 1, "end": 1, "fps": 24}},
  "output": "{}.####.exr",
  "render": {{"width": 960, "height": 540, "spp": 32, "maxDepth": 12}},
  "camera": {{"position": [36, 5.5, -4], "lookAt": [50, 0.5, 20], "fov": 40}},
  "environment": {{"file": "{}/scenes/assets/hdri/sunset.exr", "intensity": 1.0}},
  "materials": {{
    "water": {{"type": "water"}},
    "body": {{"type": "diffuse", "albedo": [0.55, 0.12, 0.1]}},
    "ground": {{"type": "diffuse", "albedo": [0.35, 0.32, 0.26]}}
  }},
  "assets": [{{"name": "flood", "file": "{}", "materials": {{"water": "water", "body": "body", "ground": "ground"}}}}]
}}
)",
                                       simulation.time(), stem.filename().string(), LACRIMA_SOURCE_DIR, glb);
  writeFileAtomically(stem.string() + ".json", "the scene's shot", [&](std::ostream& out) { out << shot; });
}

// What the figures of crowd c need of the frame just simulated.
std::vector<crowd::FigureAnimator::AgentFrame> figureFrame(const FloodSimulation& simulation, size_t c) {
  const crowd::RiverParams& river = simulation.params().river;
  std::vector<crowd::FigureAnimator::AgentFrame> frame;
  const auto& agents = simulation.crowd(c).agents();
  for (size_t a = 0; a < agents.size(); ++a) {
    const crowd::Vec2d& p = agents[a].position;
    const bool inRiver = p.y() > river.zMin && p.y() < river.zMin + river.width;
    frame.push_back({p, bool(simulation.ragdolls(c)[a]), simulation.hipHeights(c)[a], simulation.waterSpeeds(c)[a],
                     inRiver ? 0.0 : river.depth});
  }
  return frame;
}

struct CrowdSummary {
  std::string label;
  int agents = 0, arrived = 0, lost = 0;
  double lastArrival = -1.0;  // when every agent arrived; < 0 otherwise
};

std::string outcomeText(const CrowdSummary& s) {
  const std::string time = s.arrived == s.agents ? fmt::format("{:.1f} s", s.lastArrival) : "not reached";
  return fmt::format("{}: {} arrived, {} lost, {} still in the field", time, s.arrived, s.lost, s.agents - s.arrived - s.lost);
}

// Runs one experiment to its end (every agent arrived or lost) or the duration; writes
// <out>/<name>_<crowd>.csv (every 5th frame: time, agent, x, z, state, hip height) and
// <out>/<name>_<crowd>.png, and the water's mean speed map <out>/<name>_water.png.
struct ExperimentResult {
  std::vector<CrowdSummary> crowds;
  std::string shelter;  // shelterSummary's, "" without obstacles
};

ExperimentResult runExperiment(const FloodScenario& experiment, const FloodOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  FloodSimulation simulation(experiment.params);
  const size_t crowds = experiment.params.crowds.size();
  std::vector<TopView> plots;
  std::vector<std::ostringstream> csv(crowds);
  std::vector<crowd::FigureAnimator> figures;
  crowd::WaterSpeedField water(experiment.params.field, 0.5);
  for (size_t c = 0; c < crowds; ++c) {
    plots.emplace_back(experiment.params);
    figures.emplace_back(experiment.params.crowds[c].agents, experiment.params.crowd.seed + c);
    csv[c] << "time,agent,x,z,state,hip_height,water_speed\n";
  }
  std::fprintf(stderr, "flood: %s, %zu particles, %zu crowd(s)\n", experiment.name.c_str(),
               simulation.liquid().positions().size(), crowds);
  int frame = 0;
  while (!simulation.settled() && simulation.time() < experiment.duration - 1e-9) {
    simulation.advanceFrame();
    ++frame;
    for (size_t c = 0; c < crowds; ++c) figures[c].advance(figureFrame(simulation, c), experiment.params.frameTime);
    water.add(simulation.liquid().positions(), simulation.liquid().velocities());
    for (size_t c = 0; c < crowds; ++c) {
      const auto& agents = simulation.crowd(c).agents();
      for (size_t a = 0; a < agents.size(); ++a) {
        const crowd::AgentOutcome& o = simulation.outcomes(c)[a];
        const bool walking = o.arrivalTime < 0.0 && o.lostTime < 0.0;
        if (walking) plots[c].dot(agents[a].position, 0.85f, 0.05f, 0.05f);
        if (frame % 5 != 0) continue;
        const char* state = o.lostTime >= 0.0 ? "lost" : o.arrivalTime >= 0.0 ? "arrived"
                            : simulation.ragdolls(c)[a]  ? "ragdoll" : "walking";
        csv[c] << fmt::format("{:.2f},{},{:.3f},{:.3f},{},{:.3f},{:.3f}\n", simulation.time(), a, agents[a].position.x(),
                              agents[a].position.y(), state, simulation.hipHeights(c)[a], simulation.waterSpeeds(c)[a]);
      }
    }
    for (double at : options.sceneTimes)
      if (std::abs(simulation.time() - at) < 0.5 * experiment.params.frameTime)
        for (size_t c = 0; c < crowds; ++c)
          writeFloodScene(simulation, c, figures[c], experiment.figures[c],
                          std::filesystem::path(options.outputDirectory) /
                              fmt::format("{}_{}_t{:.0f}", experiment.name, experiment.params.crowds[c].name, at));
    if (frame % 100 == 0) {
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::fprintf(stderr, "flood: %s t = %.0f s, %zu particles, %.1f s of computing a simulated second\n",
                   experiment.name.c_str(), simulation.time(), simulation.liquid().positions().size(),
                   seconds / simulation.time());
    }
  }
  writeWaterSpeedMap(water, experiment.params, std::filesystem::path(options.outputDirectory) / (experiment.name + "_water.png"));
  ExperimentResult result;
  result.shelter = shelterSummary(water, experiment.params);
  std::vector<CrowdSummary>& summaries = result.crowds;
  for (size_t c = 0; c < crowds; ++c) {
    CrowdSummary s;
    s.label = experiment.labels[c];
    for (const crowd::AgentOutcome& o : simulation.outcomes(c)) {
      ++s.agents;
      if (o.arrivalTime >= 0.0) ++s.arrived, s.lastArrival = std::max(s.lastArrival, o.arrivalTime);
      if (o.lostTime >= 0.0) ++s.lost;
    }
    for (const crowd::Agent& a : experiment.params.crowds[c].agents) plots[c].dot(a.goal, 1.0f, 0.85f, 0.1f, 3);
    const std::string stem = experiment.name + "_" + experiment.params.crowds[c].name;
    writeFileAtomically(std::filesystem::path(options.outputDirectory) / (stem + ".csv"), "trajectories",
                        [&](std::ostream& out) { out << csv[c].str(); });
    plots[c].write(std::filesystem::path(options.outputDirectory) / (stem + ".png"));
    summaries.push_back(s);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::fprintf(stderr, "flood: %s done in %.0f s (%.0f simulated s, %.2f s a simulated second)\n", experiment.name.c_str(),
               seconds, simulation.time(), seconds / std::max(simulation.time(), 1e-9));
  return result;
}

}  // namespace

// The scenario files to run: those given, or Schaffer et al.'s (scenes/floods), sorted by name.
std::vector<std::filesystem::path> scenarioFiles(const FloodOptions& options) {
  std::vector<std::filesystem::path> files(options.scenarios.begin(), options.scenarios.end());
  if (files.empty()) {
    for (const auto& entry : std::filesystem::directory_iterator(std::string(LACRIMA_SOURCE_DIR) + "/scenes/floods"))
      if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
  }
  return files;
}

int runFlood(const FloodOptions& options) {
  try {
    std::vector<FloodScenario> scenarios;
    for (const std::filesystem::path& file : scenarioFiles(options)) scenarios.push_back(loadFloodScenario(file));
    std::set<std::string> known;
    for (const FloodScenario& e : scenarios) known.insert(e.name);
    for (const std::string& name : options.experiments)
      if (!known.count(name)) {
        std::string list;
        for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
        throw InputError(fmt::format("--experiments: unknown experiment '{}' (expected some of {})", name, list));
      }
    std::string table = "| run | lacrima |\n|---|---|\n", shelter;
    for (FloodScenario& e : scenarios) {
      if (!options.experiments.empty() && std::find(options.experiments.begin(), options.experiments.end(), e.name) == options.experiments.end())
        continue;
      if (options.duration) e.duration = *options.duration;
      if (options.coupledDensity) e.params.coupledDensity = *options.coupledDensity;
      if (options.particleRadius) e.params.river.particleRadius = *options.particleRadius;
      const ExperimentResult result = runExperiment(e, options);
      for (const CrowdSummary& s : result.crowds) {
        table += fmt::format("| {} | {} |\n", s.label, outcomeText(s));
        std::printf("%s: %s\n", s.label.c_str(), outcomeText(s).c_str());
      }
      if (!result.shelter.empty()) {
        shelter += fmt::format("- {}: {}\n", e.name, result.shelter);
        std::printf("%s: %s\n", e.name.c_str(), result.shelter.c_str());
      }
      std::fflush(stdout);
    }
    writeFileAtomically(std::filesystem::path(options.outputDirectory) / "table.md", "the table",
                        [&](std::ostream& out) { out << table << (shelter.empty() ? "" : "\nMean water speeds over the run:\n" + shelter); });
    return kExitOk;
  } catch (const ShotError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitBadInput;
  } catch (const InputError& e) {
    std::fprintf(stderr, "lacrima flood: %s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace lacrima::cli
