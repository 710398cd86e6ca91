// Performance-capture weight tracks: CSV reading with exact error locations, resampling, and
// Weise et al. (2011)'s adaptive temporal filter.
#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "geometry/glb_support.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/io/performance_track.hpp"

namespace lacrima {
namespace performance_track_test {

const std::vector<std::string> kNames = {"jawOpen", "eyeBlink_L", "eyeBlink_R"};

std::filesystem::path writeCsv(const std::string& text) {
  const std::filesystem::path path = test::testOutputDir() / "track.csv";
  std::ofstream(path) << text;
  return path;
}

std::string errorOf(const std::string& csv, const PerformanceCsvOptions& options = {}) {
  const std::filesystem::path path = writeCsv(csv);
  try {
    readPerformanceCsv(path, kNames, options);
  } catch (const InputError& e) {
    std::string message = e.what();
    return message.substr(path.string().size());  // the file is named first; keep the rest
  }
  return "no error";
}

TEST(PerformanceCsv, ReadsTimeOrFrameColumnsAndMapsNames) {
  const std::filesystem::path path = writeCsv("frame,JawOpen,eyeBlink_L\n0,0.1,0\n1,0.2,0.5\n3,0.4,1\n");
  PerformanceCsvOptions options;
  options.sourceFps = 60.0f;
  options.nameMap = {{"JawOpen", "jawOpen"}};  // e.g. a tracker's capitalisation
  const PerformanceTrack track = readPerformanceCsv(path, kNames, options);
  EXPECT_EQ(track.names, (std::vector<std::string>{"jawOpen", "eyeBlink_L"}));
  ASSERT_EQ(track.times.size(), 3u);
  EXPECT_FLOAT_EQ(track.times[2], 3.0f / 60.0f);
  EXPECT_EQ(track.frames[1], (std::vector<float>{0.2f, 0.5f}));
  const PerformanceTrack seconds = readPerformanceCsv(writeCsv("eyeBlink_R, time\n1, 0.5\n0, 0.75\n\n"), kNames);
  EXPECT_EQ(seconds.times, (std::vector<float>{0.5f, 0.75f}));
  EXPECT_EQ(seconds.frames[0], std::vector<float>{1.0f});
}

TEST(PerformanceCsv, ErrorsNameTheFileLineAndColumn) {
  EXPECT_EQ(errorOf("t,jawOpen\n0,1\n"), ":1:1: no 'time' (seconds) or 'frame' column in the header 't,jawOpen'");
  EXPECT_EQ(errorOf("time,jawOpen,eyeBlinkL\n"), ":1:3: unknown blendshape 'eyeBlinkL' (did you mean 'eyeBlink_L'?)");
  EXPECT_EQ(errorOf("time,jawOpen\n0,0.1\n0.1,nan\n"), ":3:2: 'nan' in column 'jawOpen' is not a finite number");
  EXPECT_EQ(errorOf("time,jawOpen\n0,0.1\n0.1,0.2x\n"), ":3:2: '0.2x' in column 'jawOpen' is not a finite number");
  EXPECT_EQ(errorOf("jawOpen,time\n0,0.1\n0.2,0.1\n"), ":3:2: time 0.1 s is not after the previous row's 0.1 s");
  EXPECT_EQ(errorOf("time,jawOpen\n0,0.1\n0.1\n"), ":3:1: 1 fields, the header has 2");
  EXPECT_EQ(errorOf("time,jawOpen\n,0.1\n"), ":2:1: '' in column 'time' is not a finite number");
}

TEST(PerformanceTrack, ResamplesLinearlyToTheTargetRate) {
  PerformanceTrack track;
  track.names = {"jawOpen"};
  track.times = {0.0f, 0.1f, 0.3f};
  track.frames = {{0.0f}, {1.0f}, {0.0f}};
  const PerformanceTrack out = resampleTrack(track, 20.0f);
  ASSERT_EQ(out.times.size(), 7u);  // 0, 0.05, ..., 0.3
  const float expected[] = {0.0f, 0.5f, 1.0f, 0.75f, 0.5f, 0.25f, 0.0f};
  for (size_t i = 0; i < 7; ++i) EXPECT_NEAR(out.frames[i][0], expected[i], 1e-5f) << i;
  EXPECT_THROW(resampleTrack(track, 0.0f), InputError);
}

// Found by fuzzing (tools/hardening.sh): a far-off time used to allocate until std::bad_alloc.
TEST(PerformanceTrack, RefusesToResampleATrackOfMoreThanAMillionFrames) {
  PerformanceTrack track;
  track.names = {"jawOpen"};
  track.times = {0.0f, 1e7f};
  track.frames = {{0.0f}, {1.0f}};
  try {
    resampleTrack(track, 24.0f);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "the track spans 1e+07 s, 2.4e+08 frames at 24 fps: more than 1e+06 (are the times in "
                           "seconds and the fps right?)");
  }
  track.times = {0.0f, 41666.0f};  // 999985 frames: the longest track still resampled
  EXPECT_EQ(resampleTrack(track, 24.0f).times.size(), 999985u);
}

float sampleVariance(const std::vector<float>& v) {
  double mean = 0.0, m2 = 0.0;
  for (float x : v) mean += x;
  mean /= double(v.size());
  for (float x : v) m2 += (x - mean) * (x - mean);
  return float(m2 / double(v.size() - 1));
}

TEST(AdaptiveFilter, FollowsAFastStepWithLittleLag) {
  std::vector<std::vector<float>> frames(100, std::vector<float>{0.0f});
  for (size_t i = 50; i < frames.size(); ++i) frames[i][0] = 1.0f;
  const auto filtered = adaptiveTemporalFilter(frames);
  EXPECT_GT(filtered[50][0], 0.99f);  // the frame of the step itself: a box filter would give 1/6
  EXPECT_EQ(filtered[10][0], 0.0f);
  EXPECT_NEAR(filtered[99][0], 1.0f, 1e-6f);
}

TEST(AdaptiveFilter, ReducesTheVarianceOfJitterOnAStillFace) {
  std::mt19937 rng(11);
  std::normal_distribution<float> noise(0.0f, 0.01f);  // tracker jitter on a held expression
  std::vector<std::vector<float>> frames;
  for (int i = 0; i < 2000; ++i) frames.push_back({0.5f + noise(rng), 0.2f + noise(rng)});
  const auto filtered = adaptiveTemporalFilter(frames);
  for (size_t c = 0; c < 2; ++c) {
    std::vector<float> before, after;
    for (size_t i = 5; i < frames.size(); ++i) before.push_back(frames[i][c]), after.push_back(filtered[i][c]);
    const float ratio = sampleVariance(after) / sampleVariance(before);
    std::printf("[ info     ] channel %zu: filtered/raw variance %.3f\n", c, ratio);
    EXPECT_LT(ratio, 0.5f);
  }
  EXPECT_THROW(adaptiveTemporalFilter(frames, {-1, 20.0f}), InputError);
}

}  // namespace performance_track_test
}  // namespace lacrima
