#pragma once
// Frame sets from pictures taken before (rendered once, or read from files), handed out in turn
// and stamped with the moment acquire() is called: a camera whose readout costs nothing. The
// end-to-end benchmark measures the pipeline and the link with it, not the renderer.

#include <cstdint>
#include <string>
#include <vector>

#include "safecell/service/frame_set_source.hpp"

namespace safecell {

class ReplayedFrameSets final : public FrameSetSource {
 public:
  // sets: each one frame per camera, named by `cameras`, in order. Throws std::invalid_argument
  // when there is no set or a set's camera count differs.
  ReplayedFrameSets(std::vector<std::string> cameras, std::vector<std::vector<cv::Mat>> sets);

  FrameSet acquire() override;

 private:
  std::vector<std::string> cameras_;
  std::vector<std::vector<cv::Mat>> sets_;
  std::uint64_t handed_out_ = 0;
};

}  // namespace safecell
