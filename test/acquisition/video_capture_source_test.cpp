#include "safecell/acquisition/video_capture_source.hpp"

#include <gtest/gtest.h>

#include <opencv2/videoio.hpp>

#include "safecell/acquisition/frame_set_acquirer.hpp"
#include "safecell/test/scratch_folder.hpp"

namespace safecell {
namespace {

cv::Size frame_size() { return {64, 48}; }
constexpr int kFrames = 5;
constexpr double kFps = 10.0;

int level_of(int frame) { return 30 + 40 * frame; }

// A small Motion-JPEG AVI whose frame n is flat gray at level_of(n).
void write_video(const std::filesystem::path& path) {
  cv::VideoWriter writer(path.string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), kFps,
                         frame_size(), false);
  ASSERT_TRUE(writer.isOpened()) << "cannot write " << path;
  for (int frame = 0; frame < kFrames; ++frame) {
    writer.write(cv::Mat(frame_size(), CV_8UC1, cv::Scalar(level_of(frame))));
  }
}

FrameSetAcquirer single(const std::string& spec, cv::Size size = frame_size()) {
  std::vector<std::unique_ptr<CameraSource>> sources;
  sources.push_back(std::make_unique<VideoCaptureSource>("cam0", size, spec));
  return FrameSetAcquirer(std::move(sources));
}

TEST(VideoCaptureSource, PlaysAVideoFileWithItsMediaTimesThenStops) {
  const test::ScratchFolder folder;
  const auto video = folder / "cam0.avi";
  write_video(video);
  FrameSetAcquirer acquirer = single(video.string());
  for (int frame = 0; frame < kFrames; ++frame) {
    const CameraFrame got = acquirer.acquire().frames.at(0);
    ASSERT_TRUE(got.known()) << got.view.detail;
    EXPECT_EQ(got.image.type(), CV_8UC1);
    EXPECT_EQ(got.image.size(), frame_size());
    EXPECT_NEAR(cv::mean(got.image)[0], level_of(frame), 3.0) << "frame " << frame;
    EXPECT_EQ(got.counter, static_cast<std::uint64_t>(frame + 1));
    EXPECT_EQ(got.stamp_source, StampSource::kBackend);
    EXPECT_NEAR(got.exposure_s, frame / kFps, 1e-6);
  }
  const CameraFrame after = acquirer.acquire().frames.at(0);
  EXPECT_EQ(after.view.fault, CameraFault::kStopped);
  EXPECT_NE(after.view.detail.find("camera 'cam0': camera stopped delivering"), std::string::npos)
      << after.view.detail;
  EXPECT_NE(after.view.detail.find("after 5 frames"), std::string::npos) << after.view.detail;
  EXPECT_EQ(after.counter, static_cast<std::uint64_t>(kFrames));
}

TEST(VideoCaptureSource, AVideoOfAnotherSizeIsTheWrongFormat) {
  const test::ScratchFolder folder;
  const auto video = folder / "cam0.avi";
  write_video(video);
  const CameraFrame got = single(video.string(), {704, 576}).acquire().frames.at(0);
  EXPECT_EQ(got.view.fault, CameraFault::kWrongFormat);
  EXPECT_NE(got.view.detail.find("got 64 x 48"), std::string::npos) << got.view.detail;
  EXPECT_NE(got.view.detail.find("cam0.avi, frame 1"), std::string::npos) << got.view.detail;
}

TEST(VideoCaptureSource, AMissingFileOrDeviceIsUnavailableByName) {
  const test::ScratchFolder folder;
  const std::string missing = (folder / "no-such-video.avi").string();
  const VideoCaptureSource source("cam0", frame_size(), missing);
  EXPECT_FALSE(source.opened());
  const CameraFrame file = single(missing).acquire().frames.at(0);
  EXPECT_EQ(file.view.fault, CameraFault::kUnavailable);
  EXPECT_NE(file.view.detail.find("camera 'cam0': camera unavailable (cannot open video file '" +
                                  missing + "': no such file)"),
            std::string::npos)
      << file.view.detail;

  const CameraFrame device = single("57").acquire().frames.at(0);
  EXPECT_EQ(device.view.fault, CameraFault::kUnavailable);
  EXPECT_NE(device.view.detail.find("camera 'cam0': camera unavailable (cannot open device 57"),
            std::string::npos)
      << device.view.detail;
}

TEST(VideoCaptureSource, ABrokenGStreamerPipelineIsUnavailableByName) {
  const VideoCaptureSource source("cam0", frame_size(), "safecellnosuchelement ! appsink");
  EXPECT_FALSE(source.opened());
  EXPECT_NE(source.open_problem().find("cannot open GStreamer pipeline 'safecellnosuchelement"),
            std::string::npos)
      << source.open_problem();
}

}  // namespace
}  // namespace safecell
