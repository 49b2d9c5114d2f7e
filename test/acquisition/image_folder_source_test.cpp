#include "safecell/acquisition/image_folder_source.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "safecell/acquisition/acquisition_error.hpp"
#include "safecell/acquisition/frame_set_acquirer.hpp"
#include "safecell/test/scratch_folder.hpp"

namespace safecell {
namespace {

using test::ScratchFolder;

cv::Size frame_size() { return {64, 48}; }

void write_image(const std::filesystem::path& path, int level, cv::Size size = frame_size(),
                 int type = CV_8UC1) {
  ASSERT_TRUE(cv::imwrite(path.string(), cv::Mat(size, type, cv::Scalar::all(level)))) << path;
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

FrameSetAcquirer over(const std::filesystem::path& folder) {
  std::vector<std::unique_ptr<CameraSource>> sources;
  sources.push_back(std::make_unique<ImageFolderSource>("cam0", frame_size(), folder));
  return FrameSetAcquirer(std::move(sources));
}

// The message of the AcquisitionError the folder's source throws, or "" when none.
std::string error_of(const std::filesystem::path& folder) {
  try {
    const ImageFolderSource source("cam0", frame_size(), folder);
  } catch (const AcquisitionError& error) {
    return error.what();
  }
  return "";
}

void expect_has(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "'" << part << "' in: " << text;
}

TEST(ImageFolderSource, PlaysTheImagesInNameOrderWithTheCsvTimesThenStops) {
  const ScratchFolder folder;
  write_image(folder / "b.png", 20);
  write_image(folder / "a.png", 10);
  write_image(folder / "c.PGM", 30);
  write_text(folder / "notes.txt", "not an image");
  write_text(folder / kFrameTimesFile, "file,time_s\r\na.png,1.25\n\nb.png,1.5\nc.PGM,2\n");
  FrameSetAcquirer acquirer = over(folder.path());
  const std::vector<double> times_s{1.25, 1.5, 2.0};
  for (int frame = 0; frame < 3; ++frame) {
    const CameraFrame got = acquirer.acquire().frames.at(0);
    ASSERT_TRUE(got.known()) << got.view.detail;
    EXPECT_EQ(got.image.at<std::uint8_t>(7, 7), 10 * (frame + 1)) << "frame " << frame;
    EXPECT_EQ(got.stamp_source, StampSource::kBackend);
    EXPECT_EQ(got.exposure_s, times_s[static_cast<std::size_t>(frame)]);
    EXPECT_EQ(got.counter, static_cast<std::uint64_t>(frame + 1));
  }
  const CameraFrame after = acquirer.acquire().frames.at(0);
  EXPECT_EQ(after.view.fault, CameraFault::kStopped);
  expect_has(after.view.detail, "camera 'cam0': camera stopped delivering");
  expect_has(after.view.detail, "exhausted after 3 frames");
}

TEST(ImageFolderSource, WithoutACsvTheFileTimesStampTheFrames) {
  using namespace std::chrono_literals;
  const ScratchFolder folder;
  const std::vector<std::chrono::sys_seconds> times{std::chrono::sys_seconds(1'700'000'000s),
                                                    std::chrono::sys_seconds(1'700'000'007s)};
  for (std::size_t i = 0; i < times.size(); ++i) {
    const auto path = folder / ("frame" + std::to_string(i) + ".png");
    write_image(path, 50);
    std::filesystem::last_write_time(path, std::chrono::file_clock::from_sys(times[i]));
  }
  FrameSetAcquirer acquirer = over(folder.path());
  EXPECT_NEAR(acquirer.acquire().frames.at(0).exposure_s, 1'700'000'000.0, 1e-3);
  EXPECT_NEAR(acquirer.acquire().frames.at(0).exposure_s, 1'700'000'007.0, 1e-3);
}

TEST(ImageFolderSource, MalformedCsvRowsAreNamedByFileLineAndValue) {
  const ScratchFolder folder;
  write_image(folder / "a.png", 10);
  write_image(folder / "b.png", 20);
  const auto csv = (folder / kFrameTimesFile).string();
  const std::vector<std::pair<std::string, std::string>> cases{
      {"file,time\na.png,1\nb.png,2\n",
       csv + ":1: header: expected 'file,time_s', got 'file,time'"},
      {"file,time_s\na.png,1\nb.png,soon\n", csv + ":3: time_s: 'soon' is not a number of seconds"},
      {"file,time_s\na.png,1\nb.png,2x\n", csv + ":3: time_s: '2x'"},
      {"file,time_s\na.png,1\nb.png\n", csv + ":3: row: expected 'file,time_s', got 'b.png'"},
      {"file,time_s\na.png,1\nb.png,2,3\n", csv + ":3: row:"},
      {"file,time_s\na.png,1\na.png,2\nb.png,3\n", csv + ":3: file: 'a.png' is named twice"},
      {"file,time_s\na.png,1\n", csv + ": file: no row for image 'b.png'"},
      {"file,time_s\na.png,1\nb.png,2\nc.png,3\n", csv + ":4: file: 'c.png' is not a PNG or PGM"},
      {"file,time_s\na.png,2\nb.png,2\n",
       csv + ":3: time_s: 2 of 'b.png' is not after 2 of line 2"},
      // A row no image name needs: refused before it is taken apart.
      {"file,time_s\na.png,1\n" + std::string(5000, 'b') + ".png,2\n",
       csv + ":3: row: 5006 bytes, expected at most 4096"},
  };
  for (const auto& [text, message] : cases) {
    write_text(csv, text);
    expect_has(error_of(folder.path()), message);
  }
  write_text(csv, "file,time_s\na.png,1\nb.png,2\n");
  EXPECT_EQ(error_of(folder.path()), "");
}

TEST(ImageFolderSource, TruncatedAndGarbageFilesAreCorruptFramesNamingTheFile) {
  const ScratchFolder folder;
  write_image(folder / "1.png", 10);
  // A real PNG cut in half.
  write_image(folder / "2.png", 20);
  const auto truncated = folder / "2.png";
  std::filesystem::resize_file(truncated, std::filesystem::file_size(truncated) / 2);
  write_text(folder / "3.png", "this is not a PNG file at all");
  write_image(folder / "4.png", 40);
  FrameSetAcquirer acquirer = over(folder.path());
  EXPECT_TRUE(acquirer.acquire().frames.at(0).known());
  for (const char* name : {"2.png", "3.png"}) {
    const CameraFrame bad = acquirer.acquire().frames.at(0);
    EXPECT_EQ(bad.view.fault, CameraFault::kCorruptFrame) << name;
    expect_has(bad.view.detail, "camera 'cam0': corrupt frame (cannot decode image file '" +
                                    (folder / name).string() + "'");
    EXPECT_TRUE(bad.image.empty());
  }
  // The folder goes on after a bad file.
  const CameraFrame next = acquirer.acquire().frames.at(0);
  ASSERT_TRUE(next.known()) << next.view.detail;
  EXPECT_EQ(next.image.at<std::uint8_t>(0, 0), 40);
}

TEST(ImageFolderSource, ImagesOfTheWrongSizeOrDepthAreTheWrongFormatNamingTheFile) {
  const ScratchFolder folder;
  write_image(folder / "1.png", 10, {32, 24});
  write_image(folder / "2.png", 1000, frame_size(), CV_16UC1);
  write_image(folder / "3.png", 60, frame_size(), CV_8UC3);
  FrameSetAcquirer acquirer = over(folder.path());
  const CameraFrame small = acquirer.acquire().frames.at(0);
  EXPECT_EQ(small.view.fault, CameraFault::kWrongFormat);
  expect_has(small.view.detail, "got 32 x 24 8-bit gray, expected 8-bit gray 64 x 48, from '" +
                                    (folder / "1.png").string() + "'");
  const CameraFrame deep = acquirer.acquire().frames.at(0);
  EXPECT_EQ(deep.view.fault, CameraFault::kWrongFormat);
  expect_has(deep.view.detail, "got 64 x 48 16-bit 1-channel");
  expect_has(deep.view.detail, (folder / "2.png").string());
  const CameraFrame colour = acquirer.acquire().frames.at(0);
  ASSERT_TRUE(colour.known()) << colour.view.detail;
  EXPECT_EQ(colour.image.at<std::uint8_t>(1, 1), 60);
}

TEST(ImageFolderSource, AMissingFolderIsUnavailableByName) {
  const ScratchFolder folder;
  const auto missing = folder / "no-such-folder";
  const ImageFolderSource source("cam0", frame_size(), missing);
  EXPECT_FALSE(source.opened());
  const CameraFrame got = over(missing).acquire().frames.at(0);
  EXPECT_EQ(got.view.fault, CameraFault::kUnavailable);
  expect_has(got.view.detail,
             "camera 'cam0': camera unavailable (cannot open image folder '" + missing.string());
}

}  // namespace
}  // namespace safecell
