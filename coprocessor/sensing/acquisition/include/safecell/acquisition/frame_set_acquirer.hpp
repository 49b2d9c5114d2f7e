#pragma once
// Takes the frames of all cameras together: grab() on every source, then retrieve() on every
// source, so the exposures lie as close together as the backends allow. Each frame is checked
// and stamped here, once for all backends: colour frames are converted to gray; a frame of
// another size or depth makes that camera's view unknown (kWrongFormat) with the sizes and the
// frame's origin in the detail. Not thread-safe.

#include <memory>
#include <vector>

#include "safecell/acquisition/camera_source.hpp"
#include "safecell/acquisition/frame_set.hpp"

namespace safecell {

class FrameSetAcquirer {
 public:
  // Throws std::invalid_argument when there is no source, a source is null, or two sources
  // share a name.
  explicit FrameSetAcquirer(std::vector<std::unique_ptr<CameraSource>> sources);

  [[nodiscard]] std::size_t camera_count() const { return sources_.size(); }
  [[nodiscard]] const CameraSource& source(std::size_t index) const { return *sources_.at(index); }

  // The next frame set, one entry per source in the order given.
  FrameSet acquire();
  // Sets acquired so far (those in which no camera delivered a frame included), and sets the
  // sources passed over between them (per set, the most any of its cameras passed over). For
  // a recording: sets acquired with a frame + sets passed over = the sets it holds, when read
  // to its end.
  [[nodiscard]] std::uint64_t sets_acquired() const { return sets_; }
  [[nodiscard]] std::uint64_t sets_passed_over() const { return sets_passed_over_; }

 private:
  CameraFrame retrieve_one(std::size_t index, const HealthReport& grabbed, double grab_time_s);

  std::vector<std::unique_ptr<CameraSource>> sources_;
  std::vector<std::uint64_t> counters_;
  std::uint64_t sets_ = 0;
  std::uint64_t sets_passed_over_ = 0;
};

}  // namespace safecell
