#pragma once
// A camera replayed from a folder of image files: the folder's PNG and PGM files (by extension,
// any case) in the order of their names, one per grab; when they run out the camera has stopped
// delivering. Exposure times come from the sidecar CSV `frame_times.csv` in the folder
// (frame_times_csv.hpp has its format) when there is one, else from the files' modification
// times (seconds since the Unix epoch). Images are decoded in retrieve(), as they are (so a
// 16-bit or wrongly sized file reaches the acquirer's format check with its name).

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "safecell/acquisition/camera_source.hpp"

namespace safecell {

inline constexpr const char* kFrameTimesFile = "frame_times.csv";

class ImageFolderSource final : public CameraSource {
 public:
  // A folder that does not exist leaves the source closed (see opened()); each grab() then
  // reports kUnavailable. Throws AcquisitionError when the sidecar CSV is malformed, names a
  // file that is not an image of the folder, lacks a row for one, or its times do not increase
  // in name order.
  ImageFolderSource(std::string camera_name, cv::Size frame_size, std::filesystem::path folder);

  [[nodiscard]] const std::string& name() const override { return name_; }
  [[nodiscard]] cv::Size frame_size() const override { return frame_size_; }
  [[nodiscard]] bool opened() const { return open_problem_.empty(); }
  [[nodiscard]] const std::string& open_problem() const { return open_problem_; }
  [[nodiscard]] std::size_t frame_count() const { return files_.size(); }

  HealthReport grab() override;
  HealthReport retrieve(SourceFrame& frame) override;

 private:
  void read_times_from_csv(const std::filesystem::path& csv);
  void read_times_from_files();

  std::string name_;
  cv::Size frame_size_;
  std::filesystem::path folder_;
  std::string open_problem_;
  std::vector<std::filesystem::path> files_;  // sorted by name
  std::vector<double> times_s_;               // one per file
  std::size_t next_ = 0;                      // the file the next grab() latches
};

}  // namespace safecell
