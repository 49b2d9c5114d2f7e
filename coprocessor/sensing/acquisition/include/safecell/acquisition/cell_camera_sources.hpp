#pragma once
// The cameras of a cell file as sources, for the service on real cameras: each camera's
// `source:` (cell_config.hpp) opened as the backend it names, with the camera's calibrated image
// size as the size every frame must have.

#include <memory>
#include <vector>

#include "safecell/acquisition/camera_source.hpp"
#include "safecell/cell/cell_model.hpp"

namespace safecell {

// How a camera recorded into an image folder or a video file is played.
enum class Recordings {
  kAsFastAsRead,  // each frame as soon as it is asked for, stamped with its recorded time
  kLive,          // at its recorded pace, stamped on the steady clock (live_replay_source.hpp)
};

// One source per camera, in the cell's order. A source that cannot be opened stays closed and
// reports kUnavailable on each grab (the view is unknown; the service carries on and the
// controller stops when too few views are known). Throws CellError naming the file and line of a
// camera without a `source:`.
[[nodiscard]] std::vector<std::unique_ptr<CameraSource>> cell_camera_sources(
    const CellModel& cell, Recordings recordings = Recordings::kAsFastAsRead);

}  // namespace safecell
