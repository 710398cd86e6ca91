// `lacrima bench`'s frame report; see bench_frame_costs.hpp and docs/performance.md.
#include "bench_frame_costs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "lacrima/renderer/bench.hpp"
#include "lacrima/renderer/render.hpp"
#include "lacrima/scenes/frame_build_times.hpp"
#include "lacrima/scenes/frame_builder.hpp"
#include "lacrima/scenes/shot.hpp"
#include "median.hpp"
#include "thread_cap.hpp"

namespace lacrima::cli {

namespace {

void applyBenchSettings(const RenderSettings& bench, RenderSettings& settings) {
  settings.width = bench.width;
  settings.height = bench.height;
  settings.samplesPerPixel = bench.samplesPerPixel;
  settings.threads = bench.threads;
}

void recordGeometry(const FrameBuildTimes& t, FrameCost& cost) {
  cost.rig = t.rigSeconds;
  cost.flesh = t.fleshSeconds;
  cost.details = t.detailSeconds;
  cost.liquidSimulation = t.liquidSimulationSeconds;
  cost.liquid = t.liquidSeconds;
  cost.eyes = t.eyeSeconds;
  cost.otherGeometry = t.otherSeconds;
  cost.geometry = t.totalSeconds;
}

// Milliseconds, or "-" for a figure not measured (NaN).
std::string ms(double seconds) { return std::isnan(seconds) ? std::string("-") : fmt::format("{:.1f}", 1e3 * seconds); }

struct Column {
  const char* title;
  std::function<double(const FrameCost&)> value;
  bool followedOnly;  // its median leaves out the built frames (a build from scratch is another cost)
};

const std::vector<Column>& columns() {
  static const std::vector<Column> all = {
      {"rig", [](const FrameCost& c) { return c.rig; }, false},
      {"flesh", [](const FrameCost& c) { return c.flesh; }, false},
      {"details", [](const FrameCost& c) { return c.details; }, false},
      {"liquid-sim", [](const FrameCost& c) { return c.liquidSimulation; }, false},
      {"liquid", [](const FrameCost& c) { return c.liquid; }, false},
      {"eyes", [](const FrameCost& c) { return c.eyes; }, false},
      {"other", [](const FrameCost& c) { return c.otherGeometry; }, false},
      {"geometry", [](const FrameCost& c) { return c.geometry; }, false},
      {"upload", [](const FrameCost& c) { return c.upload; }, true},
      {"bvh", [](const FrameCost& c) { return c.bvh; }, true},
      {"scene", [](const FrameCost& c) { return c.sceneUpdate(); }, true},
      {"set-up", [](const FrameCost& c) { return c.setUp(); }, true},
      {"total", [](const FrameCost& c) { return c.total(); }, true},
      {"raw-refit", [](const FrameCost& c) { return c.rawRefit; }, true},
      {"raw-1-step", [](const FrameCost& c) { return c.rawRefitOneStep; }, true},
  };
  return all;
}

}  // namespace

std::vector<int> defaultFrameCostFrames(const Shot& shot) {
  std::vector<int> frames;
  for (int f = (shot.frameStart + shot.frameEnd) / 2; f <= shot.frameEnd && frames.size() < 6; ++f) frames.push_back(f);
  return frames;
}

std::vector<FrameCost> measureFrameCosts(const Shot& shot, const std::vector<int>& frames, const RenderSettings& settings) {
  std::vector<FrameCost> costs;
  Renderer renderer;
  SceneUpdateProbe probe;
  Frame previous;  // raw Embree refits from its positions to the next frame's (the scenes trace no ray here)
  FrameBuilder builder(shot);  // the frames in order, as a render builds them
  for (const int f : frames) {
    FrameCost cost;
    cost.frame = f;
    FrameBuildTimes times;
    Frame frame = withThreadCap(settings.threads, [&] { return builder.build(f, &times); });
    recordGeometry(times, cost);
    applyBenchSettings(settings, frame.settings);
    const SceneUpdateSplit split = probe.update(frame);
    cost.sceneUpdateKind = split.kind;
    cost.upload = split.uploadSeconds;
    cost.bvh = split.bvhSeconds;
    cost.beforeFirstRay = secondsBeforeFirstRay(renderer, frame);
    if (split.kind == SceneUpdate::Refit) {
      const RawRefitTimes raw = measureRawEmbreeRefit(previous, frame);
      cost.rawRefit = raw.sameTimeStepsSeconds;
      cost.rawRefitOneStep = raw.oneTimeStepSeconds;
    }
    costs.push_back(cost);
    previous = std::move(frame);
  }
  return costs;
}

std::string formatFrameCosts(const std::vector<FrameCost>& costs) {
  std::string out = fmt::format("{:>8}", "frame");
  for (const Column& c : columns()) out += fmt::format(" {:>10}", c.title);
  out += "\n";
  for (const FrameCost& cost : costs) {
    const char* marker = cost.sceneUpdateKind == SceneUpdate::Build ? " B" : cost.sceneUpdateKind == SceneUpdate::Update ? " U" : "";
    out += fmt::format("{:>8}", fmt::format("{}{}", cost.frame, marker));
    for (const Column& c : columns()) out += fmt::format(" {:>10}", ms(c.value(cost)));
    out += "\n";
  }
  out += fmt::format("{:>8}", "median");
  for (const Column& c : columns()) {
    std::vector<double> values;
    for (const FrameCost& cost : costs)
      if ((!c.followedOnly || cost.sceneUpdateKind != SceneUpdate::Build) && !std::isnan(c.value(cost)))
        values.push_back(c.value(cost));
    out += fmt::format(" {:>10}", ms(median(values)));
  }
  return out + "\n";
}

}  // namespace lacrima::cli
