#pragma once
// How many low bits the noise cut drops for one camera, from frames of a still scene.
//
// The rule: s = each pixel's temporal sample standard deviation over the N frames (N - 1 in the
// denominator); sigma = the lower median of s over all pixels; k = the smallest k with
// 2^k >= sqrt(2) * sigma, at most kMaxNoiseBits. sqrt(2) * sigma is the spread of the difference
// of two readings of the same still pixel, so after the cut one quantisation step is at least
// that difference's standard deviation. k covers sigma in (2^(k-1), 2^k] / sqrt(2): sigma 0
// gives 0 bits, 1 gives 1, 2 gives 2, 4 gives 3, 8 gives 4 (band edges 0.71, 1.41, 2.83, 5.66,
// 11.3 gray levels; k = 0 also for sigma = 0). Computed in exact integer arithmetic
// (4^k N (N - 1) >= 2 (N sum(x^2) - sum(x)^2) at the median pixel), so the same frames always
// give the same k.
//
// Saturated pixels (0 or 255) show less noise than they have; a still scene lit into the middle of
// the range measures best. The median makes a few moving or flickering pixels harmless.

#include <opencv2/core/mat.hpp>
#include <span>

namespace safecell {

// Throws std::invalid_argument for fewer than 2 frames, or a frame that is empty, not CV_8UC1,
// or of another size than the first.
[[nodiscard]] int choose_noise_bits(std::span<const cv::Mat> still_frames);

}  // namespace safecell
