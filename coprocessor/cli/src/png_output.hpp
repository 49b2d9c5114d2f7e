#pragma once
// Pictures for people: PNG files written atomically, labelled tiles and contact sheets.
// Private to the CLI.

#include <filesystem>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace safecell {

// Encodes and writes atomically; throws FileError or std::runtime_error naming the path.
void write_png(const std::filesystem::path& path, const cv::Mat& image);

// The image scaled by `scale` with `label` written in its top-left corner.
cv::Mat labelled(const cv::Mat& image, double scale, const std::string& label);

// Tiles of one size and type in rows of `columns`, the last row padded with black.
cv::Mat contact_sheet(std::vector<cv::Mat> tiles, std::size_t columns);

}  // namespace safecell
