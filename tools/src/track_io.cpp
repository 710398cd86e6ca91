// The files of `lacrima track`; see track_io.hpp.
#include "track_io.hpp"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>

#include "atomic_write.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/scenes/shot.hpp"

namespace lacrima::cli {

namespace {

using Json = nlohmann::json;

double number(const Json& object, const char* key, const std::filesystem::path& file, double low, double high) {
  if (!object.contains(key) || !object[key].is_number())
    throw InputError(fmt::format("{}: '{}' must be a number", file.string(), key));
  const double value = object[key].get<double>();
  if (!(value >= low && value <= high))
    throw InputError(fmt::format("{}: '{}' is {}, expected a number in [{}, {}]", file.string(), key, value, low, high));
  return value;
}

}  // namespace

PerformanceManifest readPerformanceManifest(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("cannot open the performance '{}'", file.string()));
  Json json;
  try {
    json = Json::parse(in, nullptr, true, true);
  } catch (const Json::parse_error& e) {
    throw InputError(fmt::format("{}: not JSON: {}", file.string(), e.what()));
  }
  if (!json.is_object()) throw InputError(fmt::format("{}: expected a JSON object", file.string()));
  PerformanceManifest m;
  m.file = file;
  m.fps = json.contains("fps") ? number(json, "fps", file, 1, 1000) : 30.0;
  if (!json.contains("frames") || !json["frames"].is_object())
    throw InputError(fmt::format("{}: 'frames' must be {{\"start\": first, \"end\": last}}", file.string()));
  m.firstFrame = int(number(json["frames"], "start", file, -1e6, 1e6));
  m.lastFrame = int(number(json["frames"], "end", file, m.firstFrame, 1e6));
  if (!json.contains("camera") || !json["camera"].is_object())
    throw InputError(fmt::format("{}: 'camera' must give width, height, fx, fy, cx and cy", file.string()));
  const Json& c = json["camera"];
  m.camera.width = int(number(c, "width", file, 8, 16384));
  m.camera.height = int(number(c, "height", file, 8, 16384));
  m.camera.fx = number(c, "fx", file, 1, 1e6);
  m.camera.fy = number(c, "fy", file, 1, 1e6);
  m.camera.cx = number(c, "cx", file, 0, m.camera.width);
  m.camera.cy = number(c, "cy", file, 0, m.camera.height);
  if (!json.contains("depth") || !json["depth"].is_string())
    throw InputError(fmt::format("{}: 'depth' must be the depth EXRs' path pattern, e.g. \"depth.####.exr\"", file.string()));
  m.depthPattern = (file.parent_path() / json["depth"].get<std::string>()).string();
  if (json.contains("landmarks")) {
    if (!json["landmarks"].is_string())
      throw InputError(fmt::format("{}: 'landmarks' must be a file name (CSV or JSON)", file.string()));
    m.landmarks = file.parent_path() / json["landmarks"].get<std::string>();
  }
  return m;
}

void writePerformanceManifest(const PerformanceManifest& m) {
  const Json json = {{"version", 1},
                     {"fps", m.fps},
                     {"frames", {{"start", m.firstFrame}, {"end", m.lastFrame}}},
                     {"camera", {{"width", m.camera.width}, {"height", m.camera.height}, {"fx", m.camera.fx},
                                 {"fy", m.camera.fy}, {"cx", m.camera.cx}, {"cy", m.camera.cy}}},
                     {"depth", std::filesystem::path(m.depthPattern).filename().string()},
                     {"landmarks", m.landmarks.filename().string()}};
  writeFileAtomically(m.file, "the performance", [&](std::ostream& out) { out << json.dump(2) << "\n"; });
}

tracking::DepthFrame readDepthExr(const std::filesystem::path& file, const tracking::PinholeCamera& camera) {
  auto input = OIIO::ImageInput::open(file.string());
  if (!input) throw InputError(fmt::format("cannot read the depth map '{}': {}", file.string(), OIIO::geterror()));
  const OIIO::ImageSpec& spec = input->spec();
  if (spec.width != camera.width || spec.height != camera.height)
    throw InputError(fmt::format("{}: {}x{} pixels, but the performance's camera is {}x{}", file.string(), spec.width,
                                 spec.height, camera.width, camera.height));
  int channel = 0;
  for (int c = 0; c < spec.nchannels; ++c)
    if (spec.channelnames[size_t(c)] == "Z") channel = c;
  std::vector<float> pixels(size_t(spec.width) * size_t(spec.height));
  if (!input->read_image(0, 0, channel, channel + 1, OIIO::TypeDesc::FLOAT, pixels.data()))
    throw InputError(fmt::format("cannot read the depth map '{}': {}", file.string(), input->geterror()));
  tracking::DepthFrame frame(camera);
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) {
      const float z = pixels[size_t(y) * size_t(camera.width) + size_t(x)];
      frame.setDepth(x, y, std::isfinite(z) && z > 0.0f ? z : 0.0f);
    }
  return frame;
}

void writeDepthExr(const std::filesystem::path& file, const tracking::DepthFrame& frame) {
  const tracking::PinholeCamera& camera = frame.camera();
  OIIO::ImageSpec spec(camera.width, camera.height, 1, OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"Z"};
  std::filesystem::create_directories(file.parent_path());
  const std::string temporary = file.string() + ".tmp.exr";
  auto output = OIIO::ImageOutput::create(temporary);
  if (!output || !output->open(temporary, spec) || !output->write_image(OIIO::TypeDesc::FLOAT, frame.depths().data()) ||
      !output->close())
    throw InputError(fmt::format("cannot write the depth map '{}': {}", file.string(), OIIO::geterror()));
  std::filesystem::rename(temporary, file);
}

void writeWeightsCsv(const std::filesystem::path& file, const std::vector<std::string>& names, int firstFrame,
                     const tracking::WeightSequence& weights) {
  writeFileAtomically(file, "the weight track", [&](std::ostream& out) {
    out << "frame";
    for (const std::string& n : names) out << "," << n;
    out << "\n";
    for (size_t i = 0; i < weights.size(); ++i) {
      out << firstFrame + int(i);
      for (long k = 0; k < weights[i].size(); ++k) out << fmt::format(",{:.5f}", weights[i][k]);
      out << "\n";
    }
  });
}

const std::vector<std::string>& headChannelNames() {
  static const std::vector<std::string> names = {"head.rx", "head.ry", "head.rz", "head.tx", "head.ty", "head.tz"};
  return names;
}

Eigen::VectorXd channelsOfHeadMotion(const Eigen::Isometry3d& motion, const Vec3d& pivot) {
  const double degree = 180.0 / std::numbers::pi;
  const Eigen::Matrix3d& r = motion.linear();
  // R = Rz Ry Rx: x in (-180, 180], y in [-90, 90], z in (-180, 180].
  Eigen::VectorXd channels(6);
  channels << std::atan2(r(2, 1), r(2, 2)) * degree, std::asin(std::clamp(-r(2, 0), -1.0, 1.0)) * degree,
      std::atan2(r(1, 0), r(0, 0)) * degree, motion.translation() + r * pivot - pivot;
  return channels;
}

Eigen::Isometry3d headMotionOfChannels(const Eigen::VectorXd& channels, const Vec3d& pivot) {
  const double radian = std::numbers::pi / 180.0;
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  motion.linear() = (Eigen::AngleAxisd(channels[2] * radian, Vec3d::UnitZ()) *
                     Eigen::AngleAxisd(channels[1] * radian, Vec3d::UnitY()) *
                     Eigen::AngleAxisd(channels[0] * radian, Vec3d::UnitX()))
                        .toRotationMatrix();
  motion.translation() = pivot + channels.segment<3>(3) - motion.linear() * pivot;
  return motion;
}

tracking::WeightSequence headChannels(const std::vector<Eigen::Isometry3d>& poses, const Vec3d& pivot,
                                      const Eigen::Isometry3d& start) {
  tracking::WeightSequence out;
  if (poses.empty()) return out;
  const Eigen::Isometry3d first = poses.front();
  for (const Eigen::Isometry3d& pose : poses) out.push_back(channelsOfHeadMotion(start * first.inverse() * pose, pivot));
  return out;
}

}  // namespace lacrima::cli
