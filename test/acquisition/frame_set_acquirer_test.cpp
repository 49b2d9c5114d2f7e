#include "safecell/acquisition/frame_set_acquirer.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <opencv2/imgproc.hpp>

#include "scripted_source.hpp"

namespace safecell {
namespace {

using test::ScriptedSource;

cv::Size frame_size() { return {64, 48}; }

cv::Mat gray(int level, cv::Size size = frame_size()) { return {size, CV_8UC1, cv::Scalar(level)}; }

std::unique_ptr<CameraSource> flat_source(const std::string& name, int level,
                                          std::vector<std::string>* calls = nullptr) {
  return std::make_unique<ScriptedSource>(
      name, frame_size(), [level](int) { return gray(level); }, calls);
}

FrameSetAcquirer acquirer_of(std::vector<std::unique_ptr<CameraSource>> sources) {
  return FrameSetAcquirer(std::move(sources));
}

template <typename... Sources>
std::vector<std::unique_ptr<CameraSource>> list(Sources... sources) {
  std::vector<std::unique_ptr<CameraSource>> result;
  (result.push_back(std::move(sources)), ...);
  return result;
}

TEST(FrameSetAcquirer, GrabsEveryCameraBeforeRetrievingAny) {
  std::vector<std::string> calls;
  FrameSetAcquirer acquirer =
      acquirer_of(list(flat_source("cam0", 10, &calls), flat_source("cam1", 20, &calls),
                       flat_source("cam2", 30, &calls)));
  const FrameSet set = acquirer.acquire();
  EXPECT_EQ(calls, (std::vector<std::string>{"grab cam0", "grab cam1", "grab cam2", "retrieve cam0",
                                             "retrieve cam1", "retrieve cam2"}));
  ASSERT_EQ(set.frames.size(), 3U);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(set.frames[i].camera, "cam" + std::to_string(i));
    EXPECT_TRUE(set.frames[i].known()) << set.frames[i].view.detail;
    EXPECT_EQ(set.frames[i].image.at<std::uint8_t>(5, 5), 10 * (i + 1));
  }
}

TEST(FrameSetAcquirer, CountsFramesPerCameraAndSkipsTheCountWhenNoFrameCame) {
  // cam1 fails its second grab: it keeps its count in that set and goes on from there.
  FrameSetAcquirer acquirer = acquirer_of(
      list(flat_source("cam0", 10),
           std::make_unique<ScriptedSource>(
               "cam1", frame_size(), [](int) { return gray(20); }, nullptr,
               [](int grab) { return grab == 1 ? CameraFault::kStopped : CameraFault::kNone; })));
  const std::vector<std::vector<std::uint64_t>> expected{{1, 1}, {2, 1}, {3, 2}, {4, 3}};
  for (std::size_t cycle = 0; cycle < expected.size(); ++cycle) {
    const FrameSet set = acquirer.acquire();
    EXPECT_EQ(set.index, cycle + 1);
    EXPECT_EQ(set.frames[0].counter, expected[cycle][0]) << "set " << set.index;
    EXPECT_EQ(set.frames[1].counter, expected[cycle][1]) << "set " << set.index;
    EXPECT_EQ(set.frames[1].known(), cycle != 1) << "set " << set.index;
  }
}

TEST(FrameSetAcquirer, AMissingCameraIsUnknownByNameAndTheOthersStayKnown) {
  std::vector<std::string> calls;
  FrameSetAcquirer acquirer =
      acquirer_of(list(flat_source("left", 10, &calls),
                       std::make_unique<ScriptedSource>(
                           "gone", frame_size(), [](int) { return gray(20); }, &calls,
                           [](int) { return CameraFault::kUnavailable; }),
                       flat_source("right", 30, &calls)));
  const FrameSet set = acquirer.acquire();
  ASSERT_EQ(set.frames.size(), 3U);
  EXPECT_EQ(set.known_count(), 2U);
  EXPECT_TRUE(set.frames[0].known());
  EXPECT_TRUE(set.frames[2].known());
  const CameraFrame& gone = set.frames[1];
  EXPECT_EQ(gone.camera, "gone");
  EXPECT_EQ(gone.view.fault, CameraFault::kUnavailable);
  EXPECT_NE(gone.view.detail.find("camera 'gone': camera unavailable"), std::string::npos)
      << gone.view.detail;
  EXPECT_TRUE(gone.image.empty());
  EXPECT_EQ(gone.counter, 0U);
  // A camera whose grab failed is not asked to retrieve.
  EXPECT_EQ(std::count(calls.begin(), calls.end(), "retrieve gone"), 0);
}

TEST(FrameSetAcquirer, AWrongSizedFrameMakesThatViewUnknownNamingCameraAndSizes) {
  FrameSetAcquirer acquirer = acquirer_of(
      list(flat_source("cam0", 10), std::make_unique<ScriptedSource>("cam1", frame_size(), [](int) {
             return gray(20, {32, 24});
           })));
  const FrameSet set = acquirer.acquire();
  EXPECT_TRUE(set.frames[0].known());
  const CameraFrame& wrong = set.frames[1];
  EXPECT_EQ(wrong.view.fault, CameraFault::kWrongFormat);
  EXPECT_TRUE(wrong.image.empty());
  for (const char* part : {"camera 'cam1': wrong frame format", "got 32 x 24 8-bit gray",
                           "expected 8-bit gray 64 x 48", "from 'script'"}) {
    EXPECT_NE(wrong.view.detail.find(part), std::string::npos)
        << part << " in " << wrong.view.detail;
  }
}

TEST(FrameSetAcquirer, ColourBecomesGrayAndOtherDepthsAreWrong) {
  FrameSetAcquirer acquirer = acquirer_of(
      list(std::make_unique<ScriptedSource>(
               "colour", frame_size(),
               [](int) { return cv::Mat(frame_size(), CV_8UC3, cv::Scalar(50, 50, 50)); }),
           std::make_unique<ScriptedSource>("deep", frame_size(), [](int) {
             return cv::Mat(frame_size(), CV_16UC1, cv::Scalar(1000));
           })));
  const FrameSet set = acquirer.acquire();
  ASSERT_TRUE(set.frames[0].known()) << set.frames[0].view.detail;
  EXPECT_EQ(set.frames[0].image.type(), CV_8UC1);
  EXPECT_EQ(set.frames[0].image.at<std::uint8_t>(3, 3), 50);
  EXPECT_EQ(set.frames[1].view.fault, CameraFault::kWrongFormat);
  EXPECT_NE(set.frames[1].view.detail.find("got 64 x 48 16-bit 1-channel"), std::string::npos)
      << set.frames[1].view.detail;
}

TEST(FrameSetAcquirer, StampsWithTheBackendTimeOrElseTheGrabClock) {
  auto timed =
      std::make_unique<ScriptedSource>("timed", frame_size(), [](int) { return gray(10); });
  timed->set_exposure_s(12.5);
  FrameSetAcquirer acquirer = acquirer_of(list(std::move(timed), flat_source("untimed", 10)));
  const auto now_s = [] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
  };
  const double before_s = now_s();
  const FrameSet set = acquirer.acquire();
  const double after_s = now_s();
  EXPECT_EQ(set.frames[0].stamp_source, StampSource::kBackend);
  EXPECT_EQ(set.frames[0].exposure_s, 12.5);
  EXPECT_EQ(set.frames[1].stamp_source, StampSource::kGrabClock);
  EXPECT_GE(set.frames[1].exposure_s, before_s);
  EXPECT_LE(set.frames[1].exposure_s, after_s);
}

TEST(FrameSetAcquirer, RefusesNoSourcesANullSourceAndTwinNames) {
  EXPECT_THROW(acquirer_of({}), std::invalid_argument);
  EXPECT_THROW(acquirer_of(list(flat_source("cam0", 1), std::unique_ptr<CameraSource>())),
               std::invalid_argument);
  EXPECT_THROW(acquirer_of(list(flat_source("cam0", 1), flat_source("cam0", 2))),
               std::invalid_argument);
}

}  // namespace
}  // namespace safecell
