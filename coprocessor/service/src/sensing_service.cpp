#include "safecell/service/sensing_service.hpp"

#include <cmath>
#include <stdexcept>

#include "safecell/acquisition/exposure_sync.hpp"
#include "safecell/link/robot_pose_at_exposure.hpp"

namespace safecell {

std::uint64_t steady_seconds_to_ns(double seconds) {
  return seconds <= 0.0 ? 0 : static_cast<std::uint64_t>(std::llround(seconds * 1e9));
}

std::uint64_t steady_now_ns() {
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                        std::chrono::steady_clock::now().time_since_epoch())
                                        .count());
}

SensingService::SensingService(const CspaceGrid& grid, SensingPipeline& pipeline,
                               CoprocessorLink& link, SensingServiceSettings settings,
                               CameraViews views)
    : grid_(grid),
      pipeline_(pipeline),
      link_(link),
      settings_(std::move(settings)),
      views_(std::move(views)),
      joints_(settings_.joints),
      all_forbidden_(grid.cell_count()),
      last_map_(&all_forbidden_) {
  all_forbidden_.fill();
  link_.on_joint_state([this](const ReceivedJointState& received) {
    const v1::JointState& state = received.state;
    if (received.coprocessor_time_ns == 0) return;  // before the clock is synced
    const auto offset = link_.clock_sync().offset();
    const std::vector<double> position(state.position_rad().begin(), state.position_rad().end());
    const std::vector<double> velocity(state.velocity_rad_s().begin(),
                                       state.velocity_rad_s().end());
    if (position.size() != joints_.joint_count() || velocity.size() != position.size()) return;
    (void)joints_.add(received.coprocessor_time_ns, offset ? offset->uncertainty_ns : 0, position,
                      velocity);
  });
}

const ServiceCycle& SensingService::process(const FrameSet& delivered) {
  frames_ = delivered;  // the images are shared, not copied; only the views change
  views_.check(frames_);
  const FrameSet& frames = frames_;
  ServiceCycle cycle;
  cycle.index = cycle_.index + 1;
  cycle.exposure_ns = steady_seconds_to_ns(median_exposure_s(frames));
  cycle.known_views = static_cast<std::uint32_t>(frames.known_count());
  const RobotPoseAtExposure pose =
      robot_pose_at_exposure(joints_, cycle.exposure_ns, grid_, settings_.widening_budget_m);
  cycle.pose_known = pose.known;
  last_map_ = &all_forbidden_;
  if (!pose.known) {
    cycle.all_forbidden = "robot pose unknown: " + pose.unknown_because;
  } else if (cycle.exposure_ns == 0) {
    cycle.all_forbidden = "no camera delivered a frame";
  } else {
    cycle.q = pose.q;
    try {
      last_map_ = &pipeline_.process(frames, pose.q);
      cycle.times = pipeline_.times();
      for (const CameraObservation& observation : pipeline_.observations()) {
        cycle.blocked_per_camera.push_back(observation.blocked.count());
      }
      cycle.obstacle_per_camera = pipeline_.fusion().counts().obstacle_pixels;
    } catch (const std::out_of_range& error) {
      cycle.all_forbidden = std::string("robot outside the grid: ") + error.what();
    }
  }
  cycle.forbidden_cells = last_map_->count();
  const MapUpdate update =
      link_.send_map(*last_map_, cycle.exposure_ns != 0 ? cycle.exposure_ns : steady_now_ns(),
                     cycle.known_views, static_cast<std::uint32_t>(frames.frames.size()));
  cycle.sent_ns = steady_now_ns();
  cycle.map_version = update.version;
  cycle.map_frames = update.chunks.size();
  cycle_ = std::move(cycle);
  return cycle_;
}

void SensingService::serve_link(std::chrono::steady_clock::time_point until) {
  while (link_.poll(std::chrono::microseconds(0)) > 0) {
  }
  while (true) {
    const auto left = until - std::chrono::steady_clock::now();
    if (left <= std::chrono::steady_clock::duration::zero()) return;
    (void)link_.poll(std::chrono::duration_cast<std::chrono::microseconds>(left));
  }
}

}  // namespace safecell
