#include "safecell/acquisition/frame_set.hpp"

#include <algorithm>

namespace safecell {

std::size_t FrameSet::known_count() const {
  return static_cast<std::size_t>(
      std::count_if(frames.begin(), frames.end(), [](const CameraFrame& f) { return f.known(); }));
}

}  // namespace safecell
