#pragma once
// One map cycle of the coprocessor service: a frame set -> the robot's pose at its exposure (the
// smart buffer, fed by the link's joint stream) -> the sensing pipeline -> the map update to the
// controller. Between cycles serve_link() takes in the joint stream and the acknowledgements.
//
// When the pose at the exposure is unknown (no recent joints, too uncertain: see
// robot_pose_at_exposure.hpp), or the pipeline refuses the frames, the cycle sends an
// all-forbidden map and names why: the controller then stops the robot. A frame set with fewer
// known views than the camera threshold is sent as it is, with its healthy-camera count, and the
// controller stops on that.
//
// Stop explanations: when the controller's joint stream says it slows down or stops for a
// forbidden cell in its way (has_blocking_cell), the service explains that cell with the views of
// the map the controller held (cell_explanation.hpp): which robot part, cameras and feature cells
// made it critical, or that it was static or the whole map was forbidden. One explanation when a
// slow-down or stop begins and whenever its blocking cell changes, at most one per map version.
// Thread context: one thread (the service's); not synchronised.

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "safecell/acquisition/camera_views.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/explain/cell_explanation.hpp"
#include "safecell/link/coprocessor_link.hpp"
#include "safecell/link/joint_buffer.hpp"
#include "safecell/pipeline/sensing_pipeline.hpp"

namespace safecell {

struct SensingServiceSettings {
  JointBufferLimits joints;        // the robot's acceleration limits, the buffer's bounds
  double widening_budget_m = 0.0;  // what the removal allows for timing (removal_widening_m)
  std::uint32_t camera_threshold = 2;
  // Whether the pipeline makes the map of a cycle the protective separation stops the robot in,
  // which the service sends all forbidden. Off: it skips it (sensing_pipeline.hpp), the service's
  // slowest cycles being those; on for figures of the map itself (the demo's near-person share).
  bool maps_of_stopped_cycles = false;
};

// What one cycle did, for the status line, the report and the incident recorder.
struct ServiceCycle {
  std::uint64_t index = 0;        // cycles so far, this one included
  std::uint64_t exposure_ns = 0;  // the set's median exposure, coprocessor clock
  // When sending the map update began, and when it had left (send_map returned): whatever is
  // read of the update elsewhere happened after the first; the second may be late by however long
  // this thread was not scheduled after the send.
  std::uint64_t send_started_ns = 0;
  std::uint64_t sent_ns = 0;
  bool pose_known = false;
  std::vector<double> q;      // the robot at the exposure, when known
  std::string all_forbidden;  // why the whole map was forbidden this cycle; empty: it was not
  // The speed the map was sent with (a fraction of the top speed, MapChunk's reduction) and why
  // it is below 1: someone within the protective separation distance at full speed.
  double speed_limit = 1.0;
  std::string slowed_because;
  std::uint32_t known_views = 0;
  std::vector<std::size_t> blocked_per_camera;   // blocked feature cells
  std::vector<std::size_t> obstacle_per_camera;  // after robot removal
  std::size_t forbidden_cells = 0;
  std::uint64_t map_version = 0;
  std::size_t map_frames = 0;  // frames the update took
  CycleTimes times;
};

// Why the controller slowed down or stopped, explained.
struct StopExplanation {
  std::uint64_t coprocessor_time_ns = 0;  // when the joint state that asked for it arrived
  bool stopped = false;                   // stopped, else slowed down
  std::uint32_t critical_joint = 0;       // counted from 1 (0: none)
  bool begins = false;                    // the slow-down or stop began with this joint state
  CellExplanation explanation;
  std::string text;  // describe(explanation)
};

class SensingService {
 public:
  // Keeps references to grid, pipeline and link. Registers itself for the link's joint states.
  // Sets the pipeline to skip the map when its separation check stops the robot (the service
  // then sends every cell forbidden) unless settings.maps_of_stopped_cycles; the pipeline keeps
  // that setting after the service is gone.
  // views: the cameras' health checks (camera_views_for), which every frame set passes before
  // the pipeline sees it: a frozen, blinded, black, moved or relit camera's view is unknown.
  SensingService(const CspaceGrid& grid, SensingPipeline& pipeline, CoprocessorLink& link,
                 SensingServiceSettings settings, CameraViews views);
  SensingService(const SensingService&) = delete;
  SensingService& operator=(const SensingService&) = delete;

  // One map cycle on the frames `delivered` (exposures in the coprocessor's steady clock), after
  // their health checks. Throws std::invalid_argument when the set's cameras are not the cell's.
  const ServiceCycle& process(const FrameSet& delivered);
  // Serves the link (joint states, echoes) until `until` passes, and at least takes in what is
  // already waiting (so a loop that runs behind still hears the joint stream).
  void serve_link(std::chrono::steady_clock::time_point until);

  [[nodiscard]] const ServiceCycle& last_cycle() const { return cycle_; }
  [[nodiscard]] const JointBuffer& joints() const { return joints_; }
  [[nodiscard]] const CellSet& last_map() const { return *last_map_; }
  // The last frame set as the pipeline saw it: each camera's view after its health check (for
  // incidents and pictures).
  [[nodiscard]] const FrameSet& last_frames() const { return frames_; }
  // The stop explanations made since the last call (at most kMaxPendingExplanations, the newest).
  std::vector<StopExplanation> take_stop_explanations();

  static constexpr std::size_t kMaxPendingExplanations = 64;

 private:
  const CspaceGrid& grid_;
  SensingPipeline& pipeline_;
  CoprocessorLink& link_;
  SensingServiceSettings settings_;
  CameraViews views_;
  FrameSet frames_;
  JointBuffer joints_;
  CellSet all_forbidden_;
  const CellSet* last_map_;
  ServiceCycle cycle_;
  FusedViewsHistory views_history_;
  std::vector<StopExplanation> explanations_;
  // The last joint state's: slowed or stopped, and the blocking cell and map last explained.
  bool halting_ = false;
  CellIndex explained_cell_ = 0;
  std::uint64_t explained_version_ = 0;

  void explain_stop(const ReceivedJointState& received);
};

// MapChunk.speed_reduction_permille for a speed limit (a fraction of the top speed, 0..1).
std::uint32_t speed_reduction_permille(double speed_limit);

// The kind of a reason the whole map was forbidden (ServiceCycle::all_forbidden): its text before
// the first colon ("robot pose unknown", "an obstacle within the protective separation
// distance"), for counting cycles per reason.
std::string all_forbidden_kind(const std::string& reason);

// Seconds of the steady clock as its nanoseconds (exposure stamps to the link's clock).
std::uint64_t steady_seconds_to_ns(double seconds);
std::uint64_t steady_now_ns();

}  // namespace safecell
