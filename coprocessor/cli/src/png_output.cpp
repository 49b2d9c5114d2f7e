#include "png_output.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "safecell/files/atomic_write.hpp"

namespace safecell {

void write_png(const std::filesystem::path& path, const cv::Mat& image) {
  std::vector<unsigned char> bytes;
  if (!cv::imencode(".png", image, bytes)) {
    throw std::runtime_error(path.string() + ": the PNG encoder refused the image");
  }
  write_file_atomically(
      path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

cv::Mat labelled(const cv::Mat& image, double scale, const std::string& label) {
  cv::Mat tile;
  cv::resize(image, tile, cv::Size(), scale, scale,
             scale < 1.0 ? cv::INTER_AREA : cv::INTER_NEAREST);
  const cv::Scalar white = tile.channels() == 1 ? cv::Scalar(255) : cv::Scalar(255, 255, 255);
  cv::putText(tile, label, {8, 24}, cv::FONT_HERSHEY_SIMPLEX, 0.7, white, 2);
  return tile;
}

cv::Mat contact_sheet(std::vector<cv::Mat> tiles, std::size_t columns) {
  while (tiles.size() % columns != 0)
    tiles.push_back(cv::Mat::zeros(tiles.front().size(), tiles.front().type()));
  std::vector<cv::Mat> rows;
  for (std::size_t i = 0; i < tiles.size(); i += columns) {
    cv::Mat row;
    cv::hconcat(std::vector<cv::Mat>(tiles.begin() + static_cast<std::ptrdiff_t>(i),
                                     tiles.begin() + static_cast<std::ptrdiff_t>(i + columns)),
                row);
    rows.push_back(row);
  }
  cv::Mat sheet;
  cv::vconcat(rows, sheet);
  return sheet;
}

}  // namespace safecell
