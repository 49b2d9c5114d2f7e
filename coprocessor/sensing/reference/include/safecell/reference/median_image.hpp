#pragma once
// The per-pixel median of frames: a pixel the robot covers in fewer than half of the frames
// shows the background in the median.

#include <opencv2/core.hpp>
#include <span>

namespace safecell {

// The lower median of each pixel over the frames (CV_8UC1, all of one size). Throws
// std::invalid_argument naming the frame when there is none, or a frame of another type or size.
cv::Mat median_image(std::span<const cv::Mat> frames);

}  // namespace safecell
