#pragma once
// `lacrima bench`'s frame report: per frame of a shot, where the time before the first ray goes.
#include <cmath>
#include <string>
#include <vector>

#include "lacrima/renderer/film.hpp"
#include "lacrima/renderer/frame.hpp"

namespace lacrima {
struct Shot;
}

namespace lacrima::cli {

// What the report measures of one frame, in seconds (steady_clock).
struct FrameCost {
  int frame = 0;
  double rig = 0, flesh = 0, details = 0, liquid = 0, eyes = 0, otherGeometry = 0, geometry = 0;  // buildFrame
  double liquidSimulation = 0;  // beside rig, flesh and details (FrameBuildTimes)
  SceneUpdate sceneUpdateKind = SceneUpdate::Build;  // how the renderer's scene followed the frame
  double upload = 0, bvh = 0;  // the scene update's parts (SceneUpdateProbe)
  double beforeFirstRay = 0;   // the renderer's time up to its first ray (scene update included)
  // Raw Embree's refit of the same triangles from the frame before (NaN: not measured, the layout
  // changed).
  double rawRefit = std::nan(""), rawRefitOneStep = std::nan("");
  double sceneUpdate() const { return upload + bvh; }
  double setUp() const { return beforeFirstRay - sceneUpdate(); }  // lights, integrator, checks
  double total() const { return geometry + beforeFirstRay; }       // everything before the first ray
};

// Builds and prepares `frames` of the shot in order, as `lacrima render` does (one renderer, its
// scene kept between frames), with `settings`' size, samples and threads; measures each.
std::vector<FrameCost> measureFrameCosts(const Shot& shot, const std::vector<int>& frames, const RenderSettings& settings);

// The report's table: a row per frame, then the medians, in milliseconds.
std::string formatFrameCosts(const std::vector<FrameCost>& costs);

// The frames the report measures by default: six in a row from the middle of the shot's range
// (fewer in a shorter shot).
std::vector<int> defaultFrameCostFrames(const Shot& shot);

}  // namespace lacrima::cli
