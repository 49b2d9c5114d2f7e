#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "cli_run.hpp"

namespace safecell {
namespace {

TEST(ImagesShowCommand, WritesTheFourPicturesOfEveryCamera) {
  const auto out = std::filesystem::temp_directory_path() / "safecell-images-show";
  std::filesystem::remove_all(out);
  const test::CliRun run = test::safecell_cli({"images", "show", "--out", out.string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* camera : {"cam0", "cam1", "cam2", "cam3"}) {
    for (const char* picture : {"_frame.png", "_features.png", "_reference.png", "_blocked.png"}) {
      const auto path = out / (std::string(camera) + picture);
      EXPECT_FALSE(cv::imread(path.string()).empty()) << path;
    }
    // The human and the arm away from its reference poses are seen; the rest of the view is not.
    const std::string line = run.out.substr(run.out.find(std::string(camera) + ": "));
    const int blocked = std::stoi(line.substr(line.find("bits, ") + 6));
    EXPECT_GT(blocked, 50) << line;
    EXPECT_LT(blocked, 1000) << line;
  }
  EXPECT_EQ(test::safecell_cli({"images", "show", "--out", out.string(), "--reference-frames", "0"})
                .exit_code,
            2);
  std::filesystem::remove_all(out);
}

}  // namespace
}  // namespace safecell
