#pragma once
// The checks of the features module's inputs and the text of their messages. Every error is a
// std::invalid_argument reading "parameter: what it is, what was expected".

#include <opencv2/core/mat.hpp>
#include <string>
#include <string_view>

#include "safecell/camera/feature_grid.hpp"

namespace safecell {

// "CV_8UC1 704 x 576 px", or "an empty image".
[[nodiscard]] std::string image_text(const cv::Mat& image);

// "64 x 64 cells of 11 x 9 px".
[[nodiscard]] std::string grid_text(const FeatureGrid& grid);

// Throws "parameter: problem".
[[noreturn]] void throw_invalid_argument(std::string_view parameter, const std::string& problem);

// A non-empty CV_8UC1 image of any size.
void check_gray_image(const cv::Mat& image, std::string_view parameter);

// A CV_8UC1 image of exactly `size` (width x height); `what` says where the size comes from.
void check_gray_image_of_size(const cv::Mat& image, cv::Size size, std::string_view parameter,
                              std::string_view what);

}  // namespace safecell
