#pragma once
// The paper's noise filter: drop the k least significant bits of every pixel (a real frame
// grabber does it with its input look-up table). k comes per camera from the measured noise, see
// noise_bits.hpp. FeatureExtractor can apply the same cut as it reads a frame (no extra pass).

#include <cstdint>
#include <opencv2/core/mat.hpp>

namespace safecell {

// The most bits a cut may drop: 7 keeps one bit (dark / bright).
inline constexpr int kMaxNoiseBits = 7;

// The bits a cut of `noise_bits` keeps: value & mask = value with its low bits cleared (0xff for
// 0 bits, 0xf8 for 3). Throws std::invalid_argument for noise_bits outside 0..kMaxNoiseBits.
[[nodiscard]] std::uint8_t noise_cut_mask(int noise_bits);

// cut = frame with its `noise_bits` lowest bits cleared. `cut` may be `frame` itself (in place);
// otherwise it is (re)allocated only when its size or type differ, so a cut reused every cycle
// does not allocate. Throws std::invalid_argument for an empty frame, a frame that is not
// CV_8UC1, or noise_bits outside 0..kMaxNoiseBits.
void cut_noise_bits(const cv::Mat& frame, int noise_bits, cv::Mat& cut);

}  // namespace safecell
