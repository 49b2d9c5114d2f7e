#include "safecell/service/sensing_service.hpp"

#include <algorithm>
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
  // A too-close verdict sends all_forbidden_: the pipeline need not make the map then.
  pipeline_.skip_map_when_too_close(!settings_.maps_of_stopped_cycles);
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
    explain_stop(received);
  });
}

void SensingService::explain_stop(const ReceivedJointState& received) {
  const v1::JointState& state = received.state;
  const bool halting =
      state.state() == v1::CONTROLLER_STATE_SLOWED || state.state() == v1::CONTROLLER_STATE_STOPPED;
  const bool begins = halting && !halting_;
  halting_ = halting;
  if (!halting || !state.has_blocking_cell() || state.blocking_cell() >= grid_.cell_count()) return;
  const CellIndex cell = state.blocking_cell();
  const std::uint64_t version = state.applied_map_version();
  // Explaining reads every obstacle pixel's LUT-2 entry (about a millisecond): once per cell
  // while the robot is held by it, at most once per map.
  if (!begins && (cell == explained_cell_ || version == explained_version_)) return;
  explained_cell_ = cell;
  explained_version_ = version;
  StopExplanation stop;
  stop.coprocessor_time_ns = received.coprocessor_time_ns;
  stop.stopped = state.state() == v1::CONTROLLER_STATE_STOPPED;
  stop.critical_joint = state.critical_joint();
  stop.begins = begins;
  stop.explanation = explain_cell(pipeline_.fusion(), views_history_.find(version), cell);
  stop.text = describe(stop.explanation, pipeline_.fusion());
  if (explanations_.size() >= kMaxPendingExplanations) explanations_.erase(explanations_.begin());
  explanations_.push_back(std::move(stop));
}

std::uint32_t speed_reduction_permille(double speed_limit) {
  // Rounded up: the controller's limit, 1 - permille / 1000, is never above the verdict's.
  const double reduction = std::ceil((1.0 - std::clamp(speed_limit, 0.0, 1.0)) * 1000.0);
  return static_cast<std::uint32_t>(reduction);
}

std::string all_forbidden_kind(const std::string& reason) {
  return reason.substr(0, reason.find(':'));
}

std::vector<StopExplanation> SensingService::take_stop_explanations() {
  std::vector<StopExplanation> taken;
  taken.swap(explanations_);
  return taken;
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
      const SeparationVerdict& separation = pipeline_.separation_verdict();
      if (separation.too_close) {
        // Someone may be near enough to meet the robot before it could stop: stop it.
        cycle.all_forbidden = describe(separation, *pipeline_.separation(), pipeline_.cell());
        cycle.speed_limit = 0.0;  // and the speed: a stop twice over
        last_map_ = &all_forbidden_;
      } else if (separation.speed_limit < 1.0) {
        // Near, but the robot stops from the reduced speed before they could reach it.
        cycle.speed_limit = separation.speed_limit;
        cycle.slowed_because = describe(separation, *pipeline_.separation(), pipeline_.cell());
      }
    } catch (const std::out_of_range& error) {
      cycle.all_forbidden = std::string("robot outside the grid: ") + error.what();
    }
  }
  cycle.forbidden_cells = last_map_->count();
  cycle.send_started_ns = steady_now_ns();
  const MapUpdate update =
      link_.send_map(*last_map_, cycle.exposure_ns != 0 ? cycle.exposure_ns : steady_now_ns(),
                     cycle.known_views, static_cast<std::uint32_t>(frames.frames.size()),
                     speed_reduction_permille(cycle.speed_limit));
  cycle.sent_ns = steady_now_ns();
  cycle.map_version = update.version;
  if (cycle.all_forbidden.empty()) {
    views_history_.record(update.version, pipeline_.fusion(), pipeline_.observations());
  } else {
    views_history_.record_all_forbidden(update.version, cycle.all_forbidden);
  }
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
