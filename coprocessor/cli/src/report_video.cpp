#include "report_video.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <system_error>

namespace safecell {
namespace {

constexpr int kJpegQuality = 85;

struct Container {
  const char* extension;
  int fourcc;
};

}  // namespace

void ReportVideo::add(const cv::Mat& frame) {
  if (frame.empty()) return;
  if (jpeg_.empty()) size_ = {frame.cols - frame.cols % 2, frame.rows - frame.rows % 2};
  cv::Mat sized;
  cv::resize(frame, sized, size_, 0.0, 0.0, cv::INTER_AREA);
  std::vector<std::uint8_t> bytes;
  cv::imencode(".jpg", sized, bytes, {cv::IMWRITE_JPEG_QUALITY, kJpegQuality});
  jpeg_.push_back(std::move(bytes));
}

std::string ReportVideo::write(const std::filesystem::path& folder, const std::string& stem) const {
  if (jpeg_.empty()) return "";
  const Container containers[] = {{".mp4", cv::VideoWriter::fourcc('a', 'v', 'c', '1')},
                                  {".webm", cv::VideoWriter::fourcc('V', 'P', '8', '0')}};
  for (const Container& container : containers) {
    std::string name = stem + container.extension;
    const std::filesystem::path partial = folder / (".partial-" + name);
    cv::VideoWriter writer(partial.string(), cv::CAP_FFMPEG, container.fourcc, fps_, size_);
    if (!writer.isOpened()) continue;
    for (const std::vector<std::uint8_t>& bytes : jpeg_)
      writer.write(cv::imdecode(bytes, cv::IMREAD_COLOR));
    writer.release();
    std::error_code error;
    std::filesystem::rename(partial, folder / name, error);
    if (!error) return name;
    std::filesystem::remove(partial, error);
  }
  return "";
}

}  // namespace safecell
