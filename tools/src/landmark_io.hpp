#pragma once
// The 2D facial landmarks of a recorded performance (iBUG 68-point numbering, pixels), in the
// forms a capture pipeline gives them:
// * lacrima's CSV, one landmark a row: "frame,landmark,u,v";
// * OpenFace 2.0's CSV (Baltrusaitis et al. 2018), one frame a row: columns "frame", "x_0".."x_67",
//   "y_0".."y_67" (spaces after the commas allowed); rows whose "success" is 0 give no landmarks,
//   and with a "face_id" column only face 0 is read;
// * JSON: {"frames": [{"frame": 1, "points": [[u, v], ..., null, ...]}, ...]}: 68 points a
//   frame, null where one is missing.
#include <filesystem>
#include <map>
#include <vector>

#include "lacrima/base/math.hpp"

namespace lacrima::cli {

// Per frame, 68 points (NaN where a landmark is missing).
using LandmarkTrack = std::map<int, std::vector<Eigen::Vector2d>>;

// Reads any of the forms above (JSON by the .json extension, a CSV by its header). Throws
// InputError naming the file and the line or JSON pointer.
LandmarkTrack readLandmarks(const std::filesystem::path& file);

// Writes lacrima's CSV (the missing landmarks left out).
void writeLandmarksCsv(const std::filesystem::path& file, const LandmarkTrack& track);

}  // namespace lacrima::cli
