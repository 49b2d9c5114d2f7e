#pragma once
// The end-to-end figures of `safecell bench`: frame exposure -> map applied in the controller, on
// loopback, with the default cell's 4 cameras and safecell-controller as its own process, at 30
// frames/s; and the frame rate the service sustains back to back. The frames are rendered before
// the clock starts (the camera's readout is the camera's); the exposure is the moment a frame set
// is handed to the service, the end the controller's own report of when it swapped the map in.
// Private to the CLI.

#include <cstddef>
#include <ostream>

namespace safecell {

struct EndToEndFigures {
  std::size_t frames = 0;       // at 30 frames/s
  double latency_p50_ms = 0.0;  // exposure -> applied in the controller
  double latency_p99_ms = 0.0;
  double latency_max_ms = 0.0;
  double to_sent_p50_ms = 0.0;  // exposure -> the update's last frame sent (the pipeline)
  double to_sent_p99_ms = 0.0;
  // Where to_sent goes, per frame: the features (frames to blocked masks, all cameras), the
  // fusion (robot removal, separation check, vote), and the rest (the camera health checks, the
  // robot's pose at the exposure, the map's coding and sending).
  double features_p50_ms = 0.0;
  double fusion_p50_ms = 0.0;
  double rest_p50_ms = 0.0;
  std::size_t updates_not_applied = 0;  // of those frames, maps the controller never held
  // Updates the controller refused (its repair requests), with no fault on the link: must be 0.
  std::uint64_t updates_refused_without_fault = 0;
  // The age of the map the controller held, at each of its joint states while the frames came at
  // 30 frames/s: now - the exposure of the held map (what the watchdog and the data-age check
  // see, and what a refused update raises).
  double map_age_p50_ms = 0.0;
  double map_age_p99_ms = 0.0;
  double map_age_max_ms = 0.0;
  // Over the updates applied: the least of (applied in the controller - sending began), the
  // controller's clock brought onto the coprocessor's. Below 0 by more than the clock offset's
  // error means a map was applied before it was sent: the latency figures would be wrong.
  double sent_to_applied_min_ms = 0.0;
  // The clock offset's error bound, the largest while the joint states came in (half the echo's
  // round trip: under load a few milliseconds).
  double clock_uncertainty_max_ms = 0.0;
  // Frames whose map was all forbidden (the robot's pose unknown): must be 0, or the figures
  // measured a shortcut, not the pipeline.
  std::size_t all_forbidden_frames = 0;
  double service_fps = 0.0;  // frame sets per second the service takes, back to back
  // Of those, the maps the controller applied per second: the rate sustained end to end.
  double sustained_fps = 0.0;
};

// Throws what the closed loop's setup throws (the controller program missing, no session).
EndToEndFigures measure_end_to_end(bool quick, std::ostream& log);

}  // namespace safecell
