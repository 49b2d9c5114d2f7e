#include "safecell/campaign/fault_campaign.hpp"

#include <algorithm>
#include <chrono>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "safecell/campaign/camera_fault_injector.hpp"
#include "safecell/closed_loop/controller_session.hpp"
#include "safecell/closed_loop/demo_world.hpp"
#include "safecell/closed_loop/live_simulated_cameras.hpp"
#include "safecell/cspace/map_hash.hpp"
#include "safecell/faultproxy/fault_proxy.hpp"
#include "safecell/link/link_errors.hpp"
#include "safecell/protocol/frame.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr double kMovingGrace_s = 5.0;    // the most a trial waits past settle_s for motion
constexpr double kLinkLimits_ms = 250.0;  // the watchdog and the maximum data age: the demo's

std::uint64_t ns_of(Clock::time_point at) {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(at.time_since_epoch()).count());
}

Clock::duration seconds(double s) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

ControllerSetup campaign_controller_setup(const CampaignSensing& sensing, const DemoWorld& world,
                                          const CampaignSettings& settings) {
  ControllerSetup setup = controller_setup_of(sensing.cell, sensing.grid);
  setup.start_rad = world.start_rad();
  setup.goals_rad = world.goals_rad();
  setup.repeat = true;
  const double limits = settings.test_only_controller_limits_ms > 0.0
                            ? settings.test_only_controller_limits_ms
                            : kLinkLimits_ms;
  setup.watchdog_ms = limits;
  setup.max_data_age_ms = limits;
  return setup;
}

TrialBounds campaign_bounds(const ControllerSetup& setup, const CampaignSettings& settings) {
  TrialBounds bounds;
  bounds.stop_ms = kLinkLimits_ms + setup.max_period_ms;
  bounds.latched_stop_ms = setup.max_period_ms + 2.0;
  bounds.moving_map_age_ms =
      kLinkLimits_ms + kLinkLimits_ms + setup.max_period_ms + setup.max_clock_lead_ms;
  bounds.recover_s = settings.recover_s;
  bounds.period_ms = setup.period_ms;
  bounds.max_period_ms = setup.max_period_ms;
  bounds.frame_period_ms = 1e3 / settings.fps;
  return bounds;
}

std::uint64_t faults_injected(const FaultCounts& c) {
  return c.dropped + c.duplicated + c.reordered + c.delayed + c.flipped + c.inserted +
         c.foreign_session + c.resealed_flipped + c.cut;
}

// The proxy's rates for a link class while it lasts.
FaultRates rates_for(FaultClass fault, const CampaignSettings& settings,
                     const ControllerSetup& setup) {
  FaultRates rates;
  const double rate = settings.link_fault_rate;
  switch (fault) {
    case FaultClass::kCorruption:
      rates.flip = rate;
      break;
    case FaultClass::kResealedCorruption:
      rates.resealed_flip = rate;
      break;
    case FaultClass::kRepetition:
      rates.duplicate = rate;
      break;
    case FaultClass::kReorder:
      rates.reorder = rate;
      break;
    case FaultClass::kLoss:
      rates.drop = rate;
      break;
    case FaultClass::kInsertion:
      rates.insert = rate;
      break;
    case FaultClass::kForeignSession:
      rates.foreign_session = rate;
      break;
    case FaultClass::kDelay:
      rates.delay = 1.0;  // every datagram, older than the controller accepts when it arrives
      rates.delay_by = std::chrono::milliseconds(static_cast<int>(setup.max_data_age_ms) + 150);
      break;
    case FaultClass::kLinkCut:
      rates.drop = 1.0;
      break;
    default:
      break;
  }
  return rates;
}

// One trial: everything it starts lives here and ends with it.
class Trial {
 public:
  // Its folder: <index + 1>-<fault><suffix> in the campaign's.
  Trial(FaultClass fault, std::size_t index, const std::string& suffix,
        const CampaignSensing& sensing, const CampaignSettings& settings, std::ostream& log)
      : fault_(fault),
        sensing_(sensing),
        settings_(settings),
        log_(log),
        folder_(settings.folder / (std::to_string(index + 1) + "-" + to_string(fault) + suffix)),
        world_(sensing.cell, sensing.grid, 1e9),  // nobody walks in: the faults are the test
        setup_(campaign_controller_setup(sensing, world_, settings)) {
    fs::create_directories(folder_);
    record_.fault = fault;
    proxy_settings_.seed = settings.seed + index;
    proxy_settings_.configuration_fingerprint =
        configuration_fingerprint(sensing.grid.fingerprint(), sensing.lut_fingerprint);
  }

  [[nodiscard]] const ControllerSetup& setup() const { return setup_; }

  TrialRecord run() {
    traces_.push_back(folder_ / "trace.jsonl");
    ControllerSessionSettings session_settings =
        real_time_session(settings_.controller_program, folder_, settings_.fps,
                          sensing_.sync_error_s, sensing_.camera_references);
    session_settings.extra_args = {"--trace", traces_.back().string()};
    session_settings.route = [this](std::uint16_t coprocessor, std::uint16_t controller) {
      proxy_settings_.peer_a = coprocessor;
      proxy_settings_.peer_b = controller;
      proxy_ = std::make_unique<FaultProxy>(proxy_settings_);
      proxy_->start();
      return LinkRoute{proxy_->port_a(), proxy_->port_b()};
    };
    if (fault_ == FaultClass::kWrongFingerprint) {
      session_settings.controller_lut_fingerprint = sensing_.lut_fingerprint ^ 0x5AFEC011u;
    }
    const Clock::time_point start = Clock::now();
    try {
      session_.emplace(sensing_.cell, sensing_.grid, sensing_.pipeline, sensing_.lut_fingerprint,
                       setup_, session_settings, log_);
    } catch (const LinkSetupError& error) {
      if (fault_ != FaultClass::kWrongFingerprint) throw;
      record_.refusal = error.what();
      record_.injected = 1;
      record_.fault_begin_ns = ns_of(start);
      record_.fault_end_ns = record_.end_ns = ns_of(Clock::now());
      return finish();
    }
    if (fault_ == FaultClass::kWrongFingerprint) {
      record_.injected = 1;
      record_.fault_begin_ns = ns_of(start);
      record_.fault_end_ns = record_.end_ns = ns_of(Clock::now());
      return finish();  // accepted: the checks say so (no refusal, the robot may move)
    }
    loop();
    return finish();
  }

 private:
  ControllerSession& session() { return *session_; }

  void listen() {
    session().link().on_joint_state(
        [this](const ReceivedJointState& received) { last_state_ = received.state.state(); });
  }

  void begin_fault() {
    switch (site_of(fault_)) {
      case FaultSite::kLink:
        proxy_->set_rates(rates_for(fault_, settings_, setup_), {});
        break;
      case FaultSite::kCameras: {
        // Enough cameras that fewer than the threshold stay healthy.
        const auto count = sensing_.cell.cameras.size();
        const auto healthy_needed = static_cast<std::size_t>(sensing_.cell.camera_threshold);
        std::vector<std::size_t> cameras;
        for (std::size_t c = 0; c + healthy_needed <= count; ++c) cameras.push_back(c);
        injector_->begin(fault_, cameras);
        break;
      }
      case FaultSite::kEnds:
        if (fault_ == FaultClass::kCoprocessorKilled) {
          silent_ = true;
        } else {
          traces_.push_back(folder_ / ("trace." + std::to_string(traces_.size()) + ".jsonl"));
          session().restart_controller({"--trace", traces_.back().string()});
        }
        record_.injected = 1;
        break;
    }
  }

  void end_fault() {
    switch (site_of(fault_)) {
      case FaultSite::kLink:
        proxy_->set_rates({}, {});
        record_.injected = faults_injected(proxy_->counts_a_to_b());
        break;
      case FaultSite::kCameras:
        injector_->end();
        record_.injected = injector_->injected();
        break;
      case FaultSite::kEnds:
        // A new session to the controller (the restarted program, or the same one).
        session().reopen_link();
        listen();
        silent_ = false;
        break;
    }
  }

  void loop() {
    listen();
    std::vector<double> rendered_q = setup_.start_rad;
    LiveSimulatedCameras cameras(sensing_.sim, [this, &rendered_q](std::uint64_t exposure_ns) {
      const JointsAtTime joints = session().service().joints().at(exposure_ns);
      if (joints.known) rendered_q = joints.position_rad;
      return SimScene{rendered_q, {}};
    });
    CameraFaultInjector injector(cameras);
    injector_ = &injector;

    const auto period = seconds(1.0 / settings_.fps);
    const Clock::time_point start = Clock::now();
    // The fault begins after the settling time once the controller reports the robot moving (a
    // fault that meets a robot already held would pass the stop check without showing anything);
    // if it never moves, after a grace period, and the checks say so.
    const Clock::time_point fault_due = start + seconds(settings_.settle_s);
    const Clock::time_point fault_due_at_latest = fault_due + seconds(kMovingGrace_s);
    Clock::time_point fault_end = Clock::time_point::max();
    Clock::time_point end = Clock::time_point::max();
    enum class Phase { kBefore, kFault, kAfter } phase = Phase::kBefore;
    Clock::time_point last_acknowledgement{};
    std::int64_t k = 0;
    while (true) {
      const Clock::time_point exposure_at = start + k * period;
      if (exposure_at >= end) break;
      if (silent_) {
        std::this_thread::sleep_until(exposure_at);
      } else {
        session().service().serve_link(exposure_at);
      }
      const Clock::time_point now = Clock::now();
      const bool moving =
          last_state_ == v1::CONTROLLER_STATE_MOVING || last_state_ == v1::CONTROLLER_STATE_SLOWED;
      if (phase == Phase::kBefore && now >= fault_due && (moving || now >= fault_due_at_latest)) {
        log_ << "  " << to_string(fault_) << ": fault on"
             << (moving ? "" : " (the robot is not moving: the trial will say so)") << "\n";
        record_.fault_begin_ns = ns_of(now);
        fault_end = now + seconds(settings_.fault_s);
        end = fault_end + seconds(settings_.recover_s);
        begin_fault();
        phase = Phase::kFault;
      } else if (phase == Phase::kFault && now >= fault_end) {
        record_.fault_end_ns = ns_of(now);
        end_fault();
        log_ << "  " << to_string(fault_) << ": fault off\n";
        phase = Phase::kAfter;
      }
      // The operator acknowledges what latched (SIGUSR1): before the fault (a late cycle on a
      // loaded machine trips the cycle's watchdog; the trial needs the robot working when the
      // fault begins), and once the fault is over; never while it lasts, which is what the
      // trial watches.
      const bool operator_on_duty =
          phase == Phase::kBefore ||
          (phase == Phase::kAfter && now - fault_end >= std::chrono::milliseconds(300));
      if (operator_on_duty && last_state_ == v1::CONTROLLER_STATE_FAULT &&
          now - last_acknowledgement >= std::chrono::milliseconds(500)) {
        session().process().acknowledge_fault();
        last_acknowledgement = now;
      }
      const auto behind = Clock::now() - exposure_at;
      if (phase != Phase::kBefore) {
        record_.service_behind_ms = std::max(
            record_.service_behind_ms, std::chrono::duration<double, std::milli>(behind).count());
      }
      if (behind > period) {
        k += behind / period;
        continue;
      }
      ++k;
      const FrameSet frames = injector.acquire();
      if (silent_) continue;
      const ServiceCycle& cycle = session().service().process(frames);
      const CellSet& map = session().service().last_map();
      record_.sent[{session().link().session_id(), cycle.map_version}] = {
          cycle.exposure_ns, map_hash(map.words().data(), sensing_.grid.cell_count())};
    }
    record_.end_ns = ns_of(Clock::now());
    injector_ = nullptr;
  }

  TrialRecord finish() {
    if (session_) (void)session_->finish("fault campaign trial over");
    session_.reset();
    if (proxy_) proxy_->stop();
    for (const fs::path& trace : traces_) {
      if (fs::exists(trace)) record_.traces.push_back(read_controller_trace(trace));
    }
    return std::move(record_);
  }

  FaultClass fault_;
  const CampaignSensing& sensing_;
  const CampaignSettings& settings_;
  std::ostream& log_;
  fs::path folder_;
  DemoWorld world_;
  ControllerSetup setup_;
  FaultProxySettings proxy_settings_;
  std::unique_ptr<FaultProxy> proxy_;
  std::optional<ControllerSession> session_;
  CameraFaultInjector* injector_ = nullptr;
  std::vector<fs::path> traces_;
  std::optional<v1::ControllerState> last_state_;
  bool silent_ = false;
  TrialRecord record_;
};

nlohmann::json json_of(const TrialResult& trial) {
  const auto host = [](const HostLateness& late) {
    return nlohmann::json{{"controller_late_ms", late.controller_late_ms},
                          {"late_cycles", late.late_cycles},
                          {"service_behind_ms", late.service_behind_ms}};
  };
  nlohmann::json out = {{"fault", to_string(trial.fault)},
                        {"passed", trial.passed()},
                        {"host", host(trial.host)},
                        {"injected", trial.injected},
                        {"detected", trial.detected},
                        {"maps_refused", trial.maps_refused},
                        {"updates_refused_without_fault", trial.refused_without_fault},
                        {"stops", trial.stops},
                        {"maps_applied", trial.maps_applied},
                        {"wrong_maps_accepted", trial.wrong_maps},
                        {"degraded_maps", trial.degraded_maps},
                        {"stale_motion_cycles", trial.stale_motion_cycles},
                        {"worst_moving_map_age_ms", trial.worst_moving_map_age_ms},
                        {"causes", trial.causes},
                        {"failures", trial.failures}};
  out["stop_ms"] = trial.stop_ms ? nlohmann::json(*trial.stop_ms) : nlohmann::json();
  out["recovered_s"] = trial.recovered_s ? nlohmann::json(*trial.recovered_s) : nlohmann::json();
  if (trial.rerun_because) {
    out["first_run"] = {{"rerun_because", *trial.rerun_because},
                        {"failures", trial.first_run_failures},
                        {"host", host(trial.first_run_host)}};
  }
  return out;
}

}  // namespace

bool CampaignResult::passed() const {
  return std::all_of(trials.begin(), trials.end(),
                     [](const TrialResult& trial) { return trial.passed(); });
}

namespace {

// One trial, checked, its outcome logged. `suffix` tells a second run's folder apart.
TrialResult run_trial(FaultClass fault, std::size_t index, const std::string& suffix,
                      const CampaignSensing& sensing, const CampaignSettings& settings,
                      CampaignResult& result, std::ostream& log) {
  Trial trial(fault, index, suffix, sensing, settings, log);
  result.bounds = campaign_bounds(trial.setup(), settings);
  TrialResult outcome = check_trial(trial.run(), result.bounds);
  log << "  " << (outcome.passed() ? "passed" : "FAILED");
  for (const std::string& failure : outcome.failures) log << "; " << failure;
  log << "\n";
  return outcome;
}

}  // namespace

CampaignResult run_fault_campaign(const CampaignSensing& sensing, const CampaignSettings& settings,
                                  std::ostream& log) {
  CampaignResult result;
  for (std::size_t i = 0; i < settings.classes.size(); ++i) {
    const FaultClass fault = settings.classes[i];
    log << "trial " << i + 1 << "/" << settings.classes.size() << ": " << to_string(fault) << "\n";
    TrialResult outcome = run_trial(fault, i, "", sensing, settings, result, log);
    if (outcome.failed_on_a_late_host(result.bounds)) {
      // A time bound broke while the host could not keep real time: the trial once more, and
      // both runs reported. Any other failure stands as it is.
      const std::string because =
          "the first run broke time bounds only, while the host was late (" +
          describe(outcome.host, result.bounds) + ")";
      log << "  " << because << ": the trial once more\n";
      TrialResult again = run_trial(fault, i, "-again", sensing, settings, result, log);
      again.rerun_because = because;
      again.first_run_failures = outcome.failures;
      again.first_run_host = outcome.host;
      outcome = std::move(again);
    }
    result.trials.push_back(std::move(outcome));
  }
  return result;
}

std::string campaign_json(const CampaignResult& result) {
  nlohmann::json trials = nlohmann::json::array();
  std::uint64_t refused_without_fault = 0;
  for (const TrialResult& trial : result.trials) {
    trials.push_back(json_of(trial));
    refused_without_fault += trial.refused_without_fault;
  }
  const nlohmann::json out = {{"passed", result.passed()},
                              {"updates_refused_without_fault", refused_without_fault},
                              {"bounds",
                               {{"stop_ms", result.bounds.stop_ms},
                                {"latched_stop_ms", result.bounds.latched_stop_ms},
                                {"moving_map_age_ms", result.bounds.moving_map_age_ms},
                                {"recover_s", result.bounds.recover_s},
                                {"period_ms", result.bounds.period_ms},
                                {"max_period_ms", result.bounds.max_period_ms},
                                {"frame_period_ms", result.bounds.frame_period_ms}}},
                              {"trials", trials}};
  return out.dump(2);
}

}  // namespace safecell
