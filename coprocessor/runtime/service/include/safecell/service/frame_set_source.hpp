#pragma once
// Where the service's frame sets come from: the cameras (acquisition's FrameSetAcquirer) or the
// simulated cell. Exposure times (CameraFrame::exposure_s) are in seconds of the coprocessor's
// steady clock, the clock the link converts into the controller's.

#include "safecell/acquisition/frame_set.hpp"

namespace safecell {

class FrameSetSource {
 public:
  virtual ~FrameSetSource() = default;
  // The next frame set, one frame per camera of the cell, in its order.
  virtual FrameSet acquire() = 0;
};

}  // namespace safecell
