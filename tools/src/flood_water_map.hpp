#pragma once
// `lacrima flood`'s map of the water: its mean ground speed per half-metre cell over a run
// (crowd/water_speed_field.hpp) as a top view like the trajectories' (the river flowing to the
// left), and each obstacle's shelter as numbers.
#include <filesystem>
#include <string>
#include <vector>

#include "lacrima/crowd/flood.hpp"
#include "lacrima/crowd/water_speed_field.hpp"

namespace lacrima::cli {

// Writes an RGB float image (rows from the top, values in [0, 1]) as an 8-bit PNG, atomically
// (a temporary file renamed into place). Throws InputError naming `what` and the path.
void writePlotPng(const std::filesystem::path& path, int width, int height, const std::vector<float>& rgb, const char* what);

// Writes the map as a PNG: dry ground beige, obstacles dark grey, the water from dark blue (still)
// through cyan (the stream's speed v_F) to white (twice v_F and faster).
void writeWaterSpeedMap(const crowd::WaterSpeedField& field, const crowd::FloodParams& params,
                        const std::filesystem::path& path);

// Per obstacle: "obstacle k: water in its lee X m/s, beside it Y m/s" ("" without obstacles).
std::string shelterSummary(const crowd::WaterSpeedField& field, const crowd::FloodParams& params);

}  // namespace lacrima::cli
