// Landmark files; see landmark_io.hpp.
#include "landmark_io.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

#include "atomic_write.hpp"
#include "lacrima/base/error.hpp"

namespace lacrima::cli {

namespace {

constexpr size_t kLandmarks = 68;

std::vector<Eigen::Vector2d> noLandmarks() {
  return std::vector<Eigen::Vector2d>(kLandmarks, Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN()));
}

// The cells of a CSV line, each without the spaces around it.
std::vector<std::string> csvCells(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) {
    const size_t first = cell.find_first_not_of(" \t\r"), last = cell.find_last_not_of(" \t\r");
    cells.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
  }
  return cells;
}

double finiteNumber(const std::string& cell) {
  size_t used = 0;
  const double value = std::stod(cell, &used);
  if (used != cell.size() || !std::isfinite(value)) throw std::invalid_argument(cell);
  return value;
}

// Calls readRow(cells) for every line after the header that is not blank; a row it rejects (by
// any exception) is an InputError naming the file, the line and what was `expected`.
template <class ReadRow>
void readRows(std::istream& in, const std::filesystem::path& file, const std::string& expected, ReadRow readRow) {
  std::string line;
  for (int row = 2; std::getline(in, line); ++row) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    try {
      readRow(csvCells(line));
    } catch (const std::exception&) {
      throw InputError(fmt::format("{}:{}: expected {}, found '{}'", file.string(), row, expected, line.substr(0, 80)));
    }
  }
}

LandmarkTrack readLongCsv(std::istream& in, const std::filesystem::path& file) {
  LandmarkTrack track;
  readRows(in, file, "'frame,landmark,u,v' with a landmark in 0-67", [&](const std::vector<std::string>& cells) {
    if (cells.size() != 4) throw std::invalid_argument("cells");
    const int frame = std::stoi(cells[0]), landmark = std::stoi(cells[1]);
    if (landmark < 0 || landmark >= int(kLandmarks)) throw std::out_of_range("landmark");
    auto& points = track[frame];
    if (points.empty()) points = noLandmarks();
    points[size_t(landmark)] = Eigen::Vector2d(finiteNumber(cells[2]), finiteNumber(cells[3]));
  });
  return track;
}

// OpenFace's columns by name; throws naming the first one missing.
struct OpenFaceColumns {
  size_t frame = 0;
  std::optional<size_t> success, faceId;
  std::vector<size_t> x, y;
};

OpenFaceColumns openFaceColumns(const std::vector<std::string>& header, const std::filesystem::path& file) {
  const auto find = [&](const std::string& name) -> std::optional<size_t> {
    const auto at = std::find(header.begin(), header.end(), name);
    return at == header.end() ? std::nullopt : std::optional(size_t(at - header.begin()));
  };
  const auto need = [&](const std::string& name) {
    if (const auto at = find(name)) return *at;
    throw InputError(fmt::format("{}:1: an OpenFace landmarks CSV needs the column '{}'", file.string(), name));
  };
  OpenFaceColumns c;
  c.frame = need("frame");
  c.success = find("success");
  c.faceId = find("face_id");
  for (size_t l = 0; l < kLandmarks; ++l) {
    c.x.push_back(need(fmt::format("x_{}", l)));
    c.y.push_back(need(fmt::format("y_{}", l)));
  }
  return c;
}

LandmarkTrack readOpenFaceCsv(std::istream& in, const std::vector<std::string>& header, const std::filesystem::path& file) {
  const OpenFaceColumns c = openFaceColumns(header, file);
  LandmarkTrack track;
  const std::string expected = fmt::format("{} cells (OpenFace's frame, x_0..x_67, y_0..y_67)", header.size());
  readRows(in, file, expected, [&](const std::vector<std::string>& cells) {
    if (cells.size() < header.size()) throw std::invalid_argument("cells");
    if (c.faceId && std::stoi(cells[*c.faceId]) != 0) return;
    std::vector<Eigen::Vector2d>& points = track[std::stoi(cells[c.frame])] = noLandmarks();
    if (c.success && finiteNumber(cells[*c.success]) == 0.0) return;  // OpenFace lost the face
    for (size_t l = 0; l < kLandmarks; ++l)
      points[l] = Eigen::Vector2d(finiteNumber(cells[c.x[l]]), finiteNumber(cells[c.y[l]]));
  });
  return track;
}

LandmarkTrack readJson(std::istream& in, const std::filesystem::path& file) {
  using Json = nlohmann::json;
  Json json;
  try {
    json = Json::parse(in, nullptr, true, true);
  } catch (const Json::parse_error& e) {
    throw InputError(fmt::format("{}: not JSON: {}", file.string(), e.what()));
  }
  const auto fail = [&](const std::string& pointer, const std::string& what) {
    return InputError(fmt::format("{}: {}: {}", file.string(), pointer, what));
  };
  if (!json.is_object() || !json.contains("frames") || !json["frames"].is_array())
    throw fail("/frames", "expected {\"frames\": [{\"frame\": 1, \"points\": [[u, v], ...]}, ...]}");
  LandmarkTrack track;
  for (size_t i = 0; i < json["frames"].size(); ++i) {
    const Json& entry = json["frames"][i];
    const std::string at = fmt::format("/frames/{}", i);
    if (!entry.is_object() || !entry.contains("frame") || !entry["frame"].is_number_integer())
      throw fail(at + "/frame", "expected the frame number (an integer)");
    if (!entry.contains("points") || !entry["points"].is_array() || entry["points"].size() != kLandmarks)
      throw fail(at + "/points", "expected 68 points, each [u, v] in pixels or null");
    std::vector<Eigen::Vector2d>& points = track[entry["frame"].get<int>()] = noLandmarks();
    for (size_t l = 0; l < kLandmarks; ++l) {
      const Json& p = entry["points"][l];
      if (p.is_null()) continue;
      if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
        throw fail(fmt::format("{}/points/{}", at, l), "expected [u, v] in pixels or null");
      points[l] = Eigen::Vector2d(p[0].get<double>(), p[1].get<double>());
    }
  }
  return track;
}

}  // namespace

LandmarkTrack readLandmarks(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("cannot open the landmarks '{}'", file.string()));
  if (file.extension() == ".json") return readJson(in, file);
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = csvCells(line);
  if (header == std::vector<std::string>{"frame", "landmark", "u", "v"}) return readLongCsv(in, file);
  if (std::find(header.begin(), header.end(), "x_0") != header.end()) return readOpenFaceCsv(in, header, file);
  throw InputError(fmt::format("{}:1: expected the header 'frame,landmark,u,v' or OpenFace's (frame, ..., x_0..x_67, "
                               "y_0..y_67), or a .json file",
                               file.string()));
}

void writeLandmarksCsv(const std::filesystem::path& file, const LandmarkTrack& track) {
  writeFileAtomically(file, "the landmarks", [&](std::ostream& out) {
    out << "frame,landmark,u,v\n";
    for (const auto& [frame, points] : track)
      for (size_t l = 0; l < points.size(); ++l)
        if (points[l].allFinite()) out << fmt::format("{},{},{:.3f},{:.3f}\n", frame, l, points[l].x(), points[l].y());
  });
}

}  // namespace lacrima::cli
