// Flood scenario files; see lacrima/scenes/flood_scenario.hpp and docs/crowd.md.
#include "lacrima/scenes/flood_scenario.hpp"

#include <fmt/format.h>

#include <cmath>

#include "read/json_source.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/io/gltf_asset.hpp"
#include "lacrima/scenes/shot.hpp"
#include "read/shot_checker.hpp"
#include "read/text_file.hpp"

namespace lacrima {

namespace {

using namespace shotfile;
using crowd::Vec2d;

// [x, z] on the ground.
std::optional<Vec2d> groundPoint(ObjectReader& o, const std::string& key, bool required) {
  const Json* v = o.find(key);
  if (!v) {
    if (required) o.missing(key, "a ground point [x, z] in metres");
    return std::nullopt;
  }
  // Doubles, not readVec2's floats: a 0.8 m spacing read as a float puts the 25th agent 0.3 um off.
  if (!v->is_array() || v->size() != 2 || !(*v)[0].is_number() || !(*v)[1].is_number()) {
    o.error(key, fmt::format("expected a ground point [x, z] in metres, found {}", describeValue(*v)));
    return std::nullopt;
  }
  return Vec2d((*v)[0].get<double>(), (*v)[1].get<double>());
}

std::optional<crowd::GroundRect> groundRect(Checker& c, const Json& v, const std::string& pointer) {
  ObjectReader o(c, v, pointer, {"min", "max"});
  if (!o.ok()) return std::nullopt;
  const auto lo = groundPoint(o, "min", true), hi = groundPoint(o, "max", true);
  if (!lo || !hi) return std::nullopt;
  if (!(hi->x() > lo->x() && hi->y() > lo->y())) {
    o.error("max", "'max' must exceed 'min' in both x and z");
    return std::nullopt;
  }
  return crowd::GroundRect{*lo, *hi};
}

class FloodReader {
 public:
  FloodReader(Checker& c, FloodScenario& scenario, std::filesystem::path directory)
      : c_(c), s_(scenario), directory_(std::move(directory)) {}

  void read(const Json& root) {
    ObjectReader o(c_, root, "", {"version", "field", "river", "crowd", "crowds", "frameTime", "duration", "coupledDensity"});
    if (!o.ok()) return;
    if (auto v = o.integer("version", Range::closed(1, 1), true)) (void)v;
    crowd::FloodParams& p = s_.params;
    if (const Json* f = o.find("field"))
      if (auto r = groundRect(c_, *f, o.at("field"))) p.field = *r;
    if (auto x = o.number("frameTime", Range::closed(0.01, 1))) p.frameTime = *x;
    if (auto x = o.number("duration", Range::closed(1, 3600))) s_.duration = *x;
    if (auto x = o.number("coupledDensity", Range::closed(0, 1e4))) p.coupledDensity = *x;
    if (const Json* r = o.find("river")) readRiver(*r, o.at("river"));
    if (const Json* cr = o.find("crowd")) readCrowdParams(*cr, o.at("crowd"));
    if (const Json* cs = o.find("crowds")) {
      if (!cs->is_array() || cs->empty())
        c_.error(o.at("crowds"), Anchor::Value, fmt::format("expected a non-empty array of crowds, found {}", describeValue(*cs)));
      else
        for (size_t i = 0; i < cs->size(); ++i) readCrowd((*cs)[i], childPointer(o.at("crowds"), i));
    } else {
      o.missing("crowds", "an array of crowds, each with 'name' and 'groups' of agents");
    }
  }

 private:
  void readRiver(const Json& v, const std::string& pointer) {
    ObjectReader o(c_, v, pointer,
                   {"zMin", "width", "depth", "length", "speed", "particleRadius", "bankHeight", "obstacles", "obstacleHeight", "start"});
    if (!o.ok()) return;
    crowd::RiverParams& r = s_.params.river;
    if (auto x = o.number("zMin", Range::any())) r.zMin = *x;
    if (auto x = o.number("width", Range::above(0))) r.width = *x;
    if (auto x = o.number("depth", Range::above(0))) r.depth = *x;
    if (auto x = o.number("length", Range::above(0))) r.length = *x;
    if (auto x = o.number("speed", Range::closed(0, 20))) r.speed = *x;
    if (auto x = o.number("particleRadius", Range::closed(0.05, 2))) r.particleRadius = *x;
    if (auto x = o.number("bankHeight", Range::above(0))) r.bankHeight = *x;
    if (auto x = o.number("obstacleHeight", Range::above(0))) r.obstacleHeight = *x;
    if (auto start = o.string("start")) {
      if (*start == "full" || *start == "empty") r.startsFull = *start == "full";
      else o.error("start", fmt::format("unknown start '{}' (expected 'full': the river flowing at the start, or 'empty': "
                                        "a dry bed the water enters at the upstream end)", *start));
    }
    if (const Json* obstacles = o.find("obstacles")) {
      if (!obstacles->is_array()) {
        o.error("obstacles", fmt::format("expected an array of {{\"min\": [x, z], \"max\": [x, z]}}, found {}", describeValue(*obstacles)));
      } else {
        for (size_t i = 0; i < obstacles->size(); ++i)
          if (auto b = groundRect(c_, (*obstacles)[i], childPointer(o.at("obstacles"), i))) r.obstacles.push_back(*b);
      }
    }
    // The river's particles: Schaffer et al.'s 100k at 0.15 m is the largest tried (docs/crowd.md).
    const double particles = r.width * r.depth * r.length / std::pow(2.0 * r.particleRadius, 3);
    if (particles > 2e5)
      o.error("particleRadius", fmt::format("the river would hold {:.3g} particles at particleRadius {} m, more than the "
                                            "200,000 allowed (about 100 s of computing a simulated second)",
                                            particles, r.particleRadius));
  }

  void readCrowdParams(const Json& v, const std::string& pointer) {
    ObjectReader o(c_, v, pointer, {"markerDensity", "personalSpace", "goalRadius", "obstacleMargin", "seed"});
    if (!o.ok()) return;
    crowd::CrowdParams& p = s_.params.crowd;
    if (auto x = o.number("markerDensity", Range::closed(0.1, 100))) p.markerDensity = *x;
    if (auto x = o.number("personalSpace", Range::closed(0.2, 10))) p.personalSpace = *x;
    if (auto x = o.number("goalRadius", Range::closed(0.1, 20))) p.goalRadius = *x;
    if (auto x = o.number("obstacleMargin", Range::closed(0, 10))) p.obstacleMargin = *x;
    if (auto x = o.unsignedInteger("seed")) p.seed = *x;
  }

  void readCrowd(const Json& v, const std::string& pointer) {
    ObjectReader o(c_, v, pointer, {"name", "label", "mass", "endurance", "groups", "figure"});
    if (!o.ok()) return;
    const size_t before = c_.errorCount();
    crowd::FloodCrowd crowd;
    if (auto name = o.string("name", true)) crowd.name = *name;
    std::string label = crowd.name;
    if (auto l = o.string("label")) label = *l;
    if (auto x = o.number("mass", Range::closed(1, 500))) crowd.agentMass = *x;
    TriangleMesh figure;
    if (auto file = o.string("figure")) figure = readFigure(o, *file);
    if (const Json* e = o.find("endurance")) readEndurance(*e, o.at("endurance"), crowd);
    if (const Json* g = o.find("groups")) {
      if (!g->is_array() || g->empty())
        o.error("groups", fmt::format("expected a non-empty array of agent groups, found {}", describeValue(*g)));
      else
        for (size_t i = 0; i < g->size(); ++i) readGroup((*g)[i], childPointer(o.at("groups"), i), crowd);
    } else {
      o.missing("groups", "an array of agent groups: 'count', 'first', 'along', 'across', 'perRow' and a goal");
    }
    if (c_.errorCount() != before) return;
    s_.params.crowds.push_back(std::move(crowd));
    s_.labels.push_back(label);
    s_.figures.push_back(std::move(figure));
  }

  // A glTF figure (relative to the scenario file): every primitive of the file in one mesh.
  TriangleMesh readFigure(ObjectReader& o, const std::string& file) {
    const std::filesystem::path path = directory_ / file;
    TriangleMesh figure;
    try {
      const GltfAsset asset = loadGltfAsset(path);
      bool allNormals = true;
      for (const GltfPrimitive& primitive : asset.primitives) {
        const TriangleMesh& part = primitive.mesh;
        const uint32_t base = uint32_t(figure.positions.size());
        figure.positions.insert(figure.positions.end(), part.positions.begin(), part.positions.end());
        figure.normals.insert(figure.normals.end(), part.normals.begin(), part.normals.end());
        allNormals = allNormals && part.normals.size() == part.positions.size();
        for (uint32_t i : part.indices) figure.indices.push_back(base + i);
      }
      if (figure.indices.empty()) o.error("figure", fmt::format("the figure '{}' has no triangles", path.string()));
      if (!allNormals) computeSmoothNormals(figure);
    } catch (const InputError& e) {
      o.error("figure", fmt::format("cannot load the figure: {}", e.what()));
    }
    figure.name = "figure";
    return figure;
  }

  // [[seconds, tau], ...], seconds increasing, tau in [0, 1].
  void readEndurance(const Json& v, const std::string& pointer, crowd::FloodCrowd& crowd) {
    const auto fail = [&](const std::string& at, const std::string& message) { c_.error(at, Anchor::Value, message); };
    if (!v.is_array() || v.empty()) {
      fail(pointer, fmt::format("expected keys [[seconds, tau], ...], found {}", describeValue(v)));
      return;
    }
    crowd.endurance.clear();
    for (size_t i = 0; i < v.size(); ++i) {
      const std::string at = childPointer(pointer, i);
      const Json& key = v[i];
      if (!key.is_array() || key.size() != 2 || !key[0].is_number() || !key[1].is_number()) {
        fail(at, fmt::format("expected a key [seconds, tau], found {}", describeValue(key)));
        continue;
      }
      const double time = key[0].get<double>(), tau = key[1].get<double>();
      if (!(tau >= 0.0 && tau <= 1.0)) fail(childPointer(at, size_t(1)), fmt::format("expected tau in [0, 1], found {}", tau));
      if (!crowd.endurance.empty() && !(time > crowd.endurance.back().first))
        fail(childPointer(at, size_t(0)), fmt::format("key times must increase: {} after {}", time, crowd.endurance.back().first));
      crowd.endurance.emplace_back(time, tau);
    }
  }

  // Agents on a grid: the n-th at first + (n % perRow) along + (n / perRow) across, walking at
  // `speed` to `goal` (one point for all) or to their start + `goalOffset`.
  void readGroup(const Json& v, const std::string& pointer, crowd::FloodCrowd& crowd) {
    ObjectReader o(c_, v, pointer, {"count", "first", "along", "across", "perRow", "goal", "goalOffset", "speed"});
    if (!o.ok()) return;
    const auto count = o.integer("count", Range::closed(1, 10000), true);
    const auto first = groundPoint(o, "first", true);
    const Vec2d along = groundPoint(o, "along", false).value_or(Vec2d(1, 0));
    const Vec2d across = groundPoint(o, "across", false).value_or(Vec2d(0, 1));
    int64_t perRow = count.value_or(1);
    if (auto x = o.integer("perRow", Range::closed(1, 10000))) perRow = *x;
    double speed = 1.3;
    if (auto x = o.number("speed", Range::above(0))) speed = *x;
    const auto goal = groundPoint(o, "goal", false), goalOffset = groundPoint(o, "goalOffset", false);
    if (goal.has_value() == goalOffset.has_value()) {
      o.error(goal ? "goalOffset" : "goal", "give one of 'goal' (a point [x, z] for every agent) and 'goalOffset' (from each "
                                            "agent's start)", Anchor::Key);
      return;
    }
    if (!count || !first) return;
    for (int64_t n = 0; n < *count; ++n) {
      crowd::Agent agent;
      agent.position = *first + double(n % perRow) * along + double(n / perRow) * across;
      agent.goal = goal ? *goal : agent.position + *goalOffset;
      agent.maxSpeed = speed;
      if (!s_.params.field.contains(agent.position)) {
        o.error("first", fmt::format("agent {} of the group starts at [{}, {}], outside the field", n, agent.position.x(),
                                     agent.position.y()));
        return;
      }
      crowd.agents.push_back(agent);
    }
  }

  Checker& c_;
  FloodScenario& s_;
  std::filesystem::path directory_;  // the scenario file's: figures are found relative to it
};

}  // namespace

FloodScenario loadFloodScenario(const std::filesystem::path& path) {
  FloodScenario scenario;
  scenario.name = path.stem().string();
  const ParsedJsonFile parsed = readJsonFile(path, "the flood scenario");
  Checker checker(path, parsed.source);
  FloodReader(checker, scenario, path.parent_path()).read(parsed.json);
  if (checker.errorCount() > 0) throw ShotError(checker.diagnostics());
  return scenario;
}

}  // namespace lacrima
