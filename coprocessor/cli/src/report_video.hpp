#pragma once
// A short film of a run for the report: frames kept as JPEG during the run (a few milliseconds
// each, so the loop keeps its pace), written at the end as MP4 (H.264, which browsers play) or,
// where this OpenCV cannot, as WebM (VP8). Private to the CLI.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

namespace safecell {

class ReportVideo {
 public:
  explicit ReportVideo(double frames_per_second) : fps_(frames_per_second) {}

  // Keeps a frame (CV_8UC3; every frame of a film has the first one's size, others are resized).
  void add(const cv::Mat& frame);
  [[nodiscard]] std::size_t frames() const { return jpeg_.size(); }

  // Writes `stem`.mp4 (or `stem`.webm) into `folder`, through a temporary file renamed when
  // whole; returns the file's name, or empty when no writer could open (the report goes on
  // without the film).
  std::string write(const std::filesystem::path& folder, const std::string& stem) const;

 private:
  double fps_;
  cv::Size size_;
  std::vector<std::vector<std::uint8_t>> jpeg_;
};

}  // namespace safecell
