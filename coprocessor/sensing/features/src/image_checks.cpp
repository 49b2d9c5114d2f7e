#include "image_checks.hpp"

#include <opencv2/core/check.hpp>
#include <stdexcept>

namespace safecell {
namespace {

std::string size_text(cv::Size size) {
  return std::to_string(size.width) + " x " + std::to_string(size.height) + " px";
}

}  // namespace

std::string image_text(const cv::Mat& image) {
  if (image.empty()) return "an empty image";
  return cv::typeToString(image.type()) + " " + size_text(image.size());
}

std::string grid_text(const FeatureGrid& grid) {
  return std::to_string(grid.columns()) + " x " + std::to_string(grid.rows()) + " cells of " +
         std::to_string(grid.cell_width_px()) + " x " + std::to_string(grid.cell_height_px()) +
         " px";
}

void throw_invalid_argument(std::string_view parameter, const std::string& problem) {
  throw std::invalid_argument(std::string(parameter) + ": " + problem);
}

void check_gray_image(const cv::Mat& image, std::string_view parameter) {
  if (image.empty() || image.type() != CV_8UC1) {
    throw_invalid_argument(parameter,
                           "expected a non-empty CV_8UC1 image, got " + image_text(image));
  }
}

void check_gray_image_of_size(const cv::Mat& image, cv::Size size, std::string_view parameter,
                              std::string_view what) {
  if (image.empty() || image.type() != CV_8UC1 || image.size() != size) {
    throw_invalid_argument(parameter, "expected CV_8UC1 " + size_text(size) + " (" +
                                          std::string(what) + "), got " + image_text(image));
  }
}

}  // namespace safecell
