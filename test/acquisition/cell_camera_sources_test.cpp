// A cell file's camera sources: each camera's `source:` opened as the backend it names, with the
// camera's image size; real PNG files in a folder come out as that camera's frames, a folder that
// is not there leaves that view unknown, and a camera without a source is named in the error.

#include "safecell/acquisition/cell_camera_sources.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "safecell/acquisition/frame_set_acquirer.hpp"
#include "safecell/cell/cell_error.hpp"
#include "safecell/cell/cell_file.hpp"
#include "safecell/test/scratch_folder.hpp"

namespace safecell {
namespace {

// A cell of two 64 x 48 cameras; `sources` is each camera's source line.
std::string cell_yaml(const std::string& source0, const std::string& source1) {
  const auto camera = [](const std::string& name, double x, const std::string& source) {
    return "  - name: " + name + "\n    look_at: {position_m: [" + std::to_string(x) +
           ", 1.9, 2.9], target_m: [0, 0, 0.8], horizontal_fov_deg: 75, size_px: [64, 48]}\n" +
           (source.empty() ? "" : "    source: " + source + "\n");
  };
  return "name: two cameras\nm_max_m: 0.2\njoints:\n  - {name: a, range_deg: [-90, 90], l_m: 1}\n"
         "feature_grid: {columns: 8, rows: 8}\ncameras:\n" +
         camera("cam0", 1.9, source0) + camera("cam1", -1.9, source1);
}

TEST(CellCameraSources, FramesOfAFolderOfPngFilesAndAnUnknownViewForAMissingFolder) {
  const test::ScratchFolder scratch;
  std::filesystem::create_directories(scratch.path() / "frames" / "cam0");
  for (int i = 0; i < 3; ++i) {
    const std::string file = "frame_" + std::to_string(i) + ".png";
    ASSERT_TRUE(cv::imwrite((scratch.path() / "frames" / "cam0" / file).string(),
                            cv::Mat(48, 64, CV_8UC1, cv::Scalar(40 + 10 * i))));
  }
  const CellModel cell = load_cell_model(parse_cell_yaml(
      cell_yaml("{folder: frames/cam0}", "{folder: frames/cam1}"), "cell.yaml", scratch.path()));
  ASSERT_EQ(cell.config.cameras[0].source->spec, (scratch.path() / "frames/cam0").string());
  FrameSetAcquirer acquirer(cell_camera_sources(cell));
  ASSERT_EQ(acquirer.camera_count(), 2U);
  EXPECT_EQ(acquirer.source(1).name(), "cam1");
  EXPECT_EQ(acquirer.source(0).frame_size(), cv::Size(64, 48));
  for (int i = 0; i < 3; ++i) {
    const FrameSet set = acquirer.acquire();
    ASSERT_TRUE(set.frames[0].known()) << set.frames[0].view.detail;
    EXPECT_EQ(set.frames[0].image.at<std::uint8_t>(10, 10), 40 + 10 * i);
    EXPECT_FALSE(set.frames[1].known());
    EXPECT_EQ(set.frames[1].view.fault, CameraFault::kUnavailable);
  }
  EXPECT_FALSE(acquirer.acquire().frames[0].known()) << "the folder has run out";
}

// A folder of three frames recorded at `first_s`, + 0.1 s, + 0.2 s, with its frame_times.csv.
void record_folder(const std::filesystem::path& folder, double first_s) {
  std::filesystem::create_directories(folder);
  std::ofstream csv(folder / "frame_times.csv");
  csv << "file,time_s\n";
  for (int i = 0; i < 3; ++i) {
    const std::string file = "frame_" + std::to_string(i) + ".png";
    ASSERT_TRUE(
        cv::imwrite((folder / file).string(), cv::Mat(48, 64, CV_8UC1, cv::Scalar(40 + 10 * i))));
    csv << file << ',' << first_s + 0.1 * i << '\n';
  }
}

double steady_now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

TEST(CellCameraSources, RecordingsPlayedLiveKeepTheirPaceOnTheSteadyClock) {
  const test::ScratchFolder scratch;
  record_folder(scratch.path() / "frames" / "cam0", 1000.0);
  record_folder(scratch.path() / "frames" / "cam1", 1000.01);  // 10 ms after cam0
  const CellModel cell = load_cell_model(parse_cell_yaml(
      cell_yaml("{folder: frames/cam0}", "{folder: frames/cam1}"), "cell.yaml", scratch.path()));

  // Control: read as fast as possible, the frames carry the recording's own times.
  FrameSetAcquirer as_read(cell_camera_sources(cell));
  EXPECT_DOUBLE_EQ(as_read.acquire().frames[1].exposure_s, 1000.01);

  FrameSetAcquirer live(cell_camera_sources(cell, Recordings::kLive));
  const double started_s = steady_now_s();
  std::vector<FrameSet> sets;
  sets.reserve(3);
  for (int i = 0; i < 3; ++i) sets.push_back(live.acquire());
  const double ended_s = steady_now_s();
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t c = 0; c < 2; ++c) {
      const CameraFrame& frame = sets[i].frames[c];
      ASSERT_TRUE(frame.known()) << frame.view.detail;
      // On the steady clock, during the replay, at the recorded offsets to the first frame.
      EXPECT_GE(frame.exposure_s, started_s) << "set " << i << " camera " << c;
      EXPECT_LE(frame.exposure_s, ended_s) << "set " << i << " camera " << c;
      const double recorded_offset_s = 0.1 * static_cast<double>(i) + 0.01 * static_cast<double>(c);
      EXPECT_NEAR(frame.exposure_s - sets[0].frames[0].exposure_s, recorded_offset_s, 1e-6)
          << "set " << i << " camera " << c;
    }
  }
  // The replay waited for the last frame's recorded time: 0.21 s after the first.
  EXPECT_GE(ended_s - started_s, 0.21 - 1e-3);
}

TEST(CellCameraSources, AVideoFileIsOpenedAsAFileWhateverItsName) {
  // "0" would read as device 0, and a '!' as a GStreamer pipeline: the cell file says "video".
  const test::ScratchFolder scratch;
  const CellModel cell = load_cell_model(parse_cell_yaml(
      cell_yaml("{video: '0'}", "{video: 'take!1.mp4'}"), "cell.yaml", scratch.path()));
  std::vector<std::unique_ptr<CameraSource>> sources = cell_camera_sources(cell);
  ASSERT_EQ(sources.size(), 2U);
  for (const auto& source : sources) {
    const HealthReport grabbed = source->grab();
    EXPECT_EQ(grabbed.fault, CameraFault::kUnavailable);
    EXPECT_NE(grabbed.detail.find("video file"), std::string::npos) << grabbed.detail;
    EXPECT_NE(grabbed.detail.find("no such file"), std::string::npos) << grabbed.detail;
  }
}

TEST(CellCameraSources, ACameraWithoutASourceIsNamed) {
  const CellModel cell =
      load_cell_model(parse_cell_yaml(cell_yaml("", "{device: 0}"), "cell.yaml", "/tmp"));
  try {
    static_cast<void>(cell_camera_sources(cell));
    FAIL() << "expected a CellError";
  } catch (const CellError& error) {
    EXPECT_EQ(std::string(error.what()),
              "cell.yaml:7: cameras[0].source: missing; on real cameras each camera needs one "
              "(device, video, folder, gstreamer or url)");
  }
}

}  // namespace
}  // namespace safecell
