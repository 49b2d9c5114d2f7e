#pragma once
// Choosing the robot configurations for the reference images (paper, Section 5: "in each camera
// image and for all configurations the robot covers as few common pixels as possible").

#include <cstddef>
#include <opencv2/core.hpp>
#include <vector>

namespace safecell {

// coverage[k][c]: the pixels (CV_8UC1, non-zero = covered) the robot covers in camera c when in
// candidate configuration k. Returns `count` candidate indices, chosen greedily: each next one
// adds the least to the sum over pixels of (times covered)^2, so the chosen configurations share
// as few pixels as they can. The median of the frames shows the background wherever fewer than
// half of them cover the pixel; the robot's base, covered in every configuration, stays (it is
// part of the empty cell's view). Throws std::invalid_argument for count 0 or above the
// candidates, or masks of differing numbers, types or sizes.
std::vector<std::size_t> choose_reference_configurations(
    const std::vector<std::vector<cv::Mat>>& coverage, std::size_t count);

// Per camera, how many of the chosen configurations cover each pixel (CV_16UC1).
std::vector<cv::Mat> coverage_counts(const std::vector<std::vector<cv::Mat>>& coverage,
                                     const std::vector<std::size_t>& chosen);

}  // namespace safecell
