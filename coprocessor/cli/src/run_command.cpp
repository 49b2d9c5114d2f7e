#include "safecell/cli/run_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "camera_reference.hpp"
#include "command_line.hpp"
#include "incident_feed.hpp"
#include "lut_loading.hpp"
#include "safecell/acquisition/cell_camera_sources.hpp"
#include "safecell/acquisition/exposure_sync.hpp"
#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_grid.hpp"
#include "safecell/cli/cli_app.hpp"
#include "safecell/cli/text_table.hpp"
#include "safecell/files/atomic_write.hpp"
#include "safecell/files/read_file.hpp"
#include "safecell/link/link_errors.hpp"
#include "safecell/link/udp_transport.hpp"
#include "safecell/pipeline/sensing_pipeline.hpp"
#include "safecell/service/sensing_service.hpp"
#include "safecell/silhouettes/configuration_silhouettes.hpp"
#include "safecell/silhouettes/model_silhouettes.hpp"
#include "safecell/validation/percentile.hpp"
#include "scene_options.hpp"
#include "service_setup.hpp"
#include "service_status.hpp"
#include "stop_explanations.hpp"
#include "udp_address.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The signal that asked the service to stop (0: none yet). Written by the handler only.
volatile std::sig_atomic_t g_stop_signal = 0;

void on_stop_signal(int signal) { g_stop_signal = signal; }

// SIGINT and SIGTERM ask the loop to stop (it then sends the controller a stop request) while
// this object lives; the handlers before it come back after. Made once the session is about to
// open: before, while the tables build, Ctrl-C ends the program as usual.
class StopSignals {
 public:
  StopSignals() {
    g_stop_signal = 0;  // before the handlers: a signal from now on is kept
    previous_interrupt_ = std::signal(SIGINT, on_stop_signal);
    previous_terminate_ = std::signal(SIGTERM, on_stop_signal);
  }
  ~StopSignals() {
    std::signal(SIGINT, previous_interrupt_);
    std::signal(SIGTERM, previous_terminate_);
  }
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  [[nodiscard]] static std::optional<std::string> received() {
    const int signal = g_stop_signal;
    if (signal == 0) return std::nullopt;
    return signal == SIGINT ? "SIGINT" : "SIGTERM";
  }

 private:
  using Handler = void (*)(int);
  Handler previous_interrupt_ = nullptr;
  Handler previous_terminate_ = nullptr;
};

void check_options(const RunOptions& options) {
  if (options.cell_path.empty()) {
    bad_option("--cell", "", "a cell file whose cameras name their source: (see the README)");
  }
  if (!(options.seconds >= 0.0 && options.seconds <= 1e7)) {
    bad_option("--seconds", std::to_string(options.seconds), "0 (until stopped) or a duration");
  }
  if (!(options.fps >= 1.0 && options.fps <= 200.0)) {
    bad_option("--fps", std::to_string(options.fps), "frames per second, 1..200");
  }
  if (!(options.max_acceleration_rad_s2 >= 0.1 && options.max_acceleration_rad_s2 <= 1000.0)) {
    bad_option("--max-acceleration", std::to_string(options.max_acceleration_rad_s2),
               "rad/s^2, 0.1..1000 (the robot's data sheet; above, not below)");
  }
  if (!(options.sync_error_ms >= 0.0 && options.sync_error_ms <= 100.0)) {
    bad_option("--sync-error", std::to_string(options.sync_error_ms), "ms, 0..100");
  }
  // Never a reference recorded by default: after a restart with a person in the cell, that
  // person would become part of the empty cell and go unseen while standing there.
  if (options.reference_dir.empty() == !options.record_reference) {
    bad_option("--reference", options.reference_dir,
               "either --reference DIR (the empty cell's images, <camera>.png each) or "
               "--record-reference (record them now, nobody in the cell), not both");
  }
  if (options.record_reference && (options.reference_sets < 1 || options.reference_sets > 1000)) {
    bad_option("--reference-sets", std::to_string(options.reference_sets), "1..1000");
  }
  if (!(options.incident_seconds == 0.0 ||
        (options.incident_seconds >= 0.1 && options.incident_seconds <= 60.0))) {
    bad_option("--incident-seconds", std::to_string(options.incident_seconds),
               "0 (no incidents) or 0.1..60 s");
  }
  if (!(options.new_session_after_s >= 0.1 && options.new_session_after_s <= 60.0)) {
    bad_option("--new-session-after", std::to_string(options.new_session_after_s),
               "seconds of silence from the controller, 0.1..60");
  }
  if (!(options.connect_timeout_s > 0.0 && options.connect_timeout_s <= 3600.0)) {
    bad_option("--connect-timeout", std::to_string(options.connect_timeout_s), "s, up to 3600");
  }
}

// Opens the session, waiting while the controller does not answer (it may start after us).
// Returns false when a signal came first.
bool open_session(CoprocessorLink& link, const RunOptions& options, std::ostream& err) {
  const auto give_up = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                          std::chrono::duration<double>(options.connect_timeout_s));
  bool said_waiting = false;
  while (true) {
    try {
      link.open(std::chrono::milliseconds(500));
      return true;
    } catch (const LinkSetupError& error) {
      if (link.refused_because()) throw;
      if (Clock::now() > give_up) {
        throw LinkSetupError(std::string(error.what()) + " (--controller " + options.controller +
                             ", waited " + fixed(options.connect_timeout_s, 0) + " s)");
      }
    }
    if (StopSignals::received()) return false;
    if (!said_waiting) {
      err << "waiting for the controller at " << options.controller << " ...\n";
      said_waiting = true;
    }
  }
}

// The controller's stop request when the service ends by an error after the session opened: the
// normal end sends its own, naming its cause. One datagram; the controller's watchdog stops the
// robot anyway when the maps end, the request only names why.
class StopRequestOnError {
 public:
  explicit StopRequestOnError(CoprocessorLink& link) : link_(link) {}
  ~StopRequestOnError() {
    if (sent_ || !link_.clock_sync().offset()) return;
    try {
      link_.send_stop_request(v1::FAULT_CAUSE_OPERATOR, "safecell run ended by an error");
    } catch (...) {  // NOLINT(bugprone-empty-catch): nothing more can be done on the way out
    }
  }
  StopRequestOnError(const StopRequestOnError&) = delete;
  StopRequestOnError& operator=(const StopRequestOnError&) = delete;
  // False when no session is open (a signal came while a new one was being opened): there is
  // nobody to ask, and the controller's watchdog holds the robot.
  bool send(const std::string& why) {
    sent_ = true;
    if (!link_.clock_sync().offset()) return false;
    link_.send_stop_request(v1::FAULT_CAUSE_OPERATOR, why);
    return true;
  }

 private:
  CoprocessorLink& link_;
  bool sent_ = false;
};

// What the summary counts an all-forbidden cycle under: its reason without the figures after the
// colon ("robot pose unknown: uncertain by 23.4 mm" -> "robot pose unknown").
// Every camera has stopped delivering (the recordings have ended, the devices are gone).
std::optional<std::string> all_cameras_stopped(const FrameSet& set) {
  for (const CameraFrame& frame : set.frames) {
    if (frame.view.fault != CameraFault::kStopped) return std::nullopt;
  }
  return "every camera stopped delivering (" + set.frames.front().view.detail + ")";
}

// How far past a frame set's exposure the joint stream is taken in before the set is processed:
// two control cycles of 4 ms and the transport.
constexpr std::chrono::milliseconds kJointStreamLead{10};

Clock::time_point steady_time_point(double seconds) {
  return Clock::time_point(
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds)));
}

struct RunFigures {
  std::size_t cycles = 0;
  std::size_t all_forbidden_cycles = 0;
  std::size_t separation_slowed_cycles = 0;  // maps sent with a speed limit, not forbidden whole
  std::size_t cycles_short_of_views = 0;     // fewer known views than the camera threshold
  std::size_t incidents = 0;                 // folders the incident recorder wrote
  std::size_t incidents_not_written = 0;     // could not be written (the disk) or dropped
  std::size_t new_sessions = 0;              // opened after the controller fell silent
  std::size_t stops_explained = 0;           // slow-downs and stops the service explained
  std::map<std::string, std::size_t> all_forbidden_because;  // cycles per reason
  std::vector<double> features_ms;
  std::vector<double> fusion_ms;
};

void write_run_summary(const fs::path& file, const RunFigures& figures, double seconds,
                       const std::string& stopped_because, const FrameSetAcquirer& cameras,
                       const CoprocessorLink& link) {
  nlohmann::ordered_json summary;
  summary["cycles"] = figures.cycles;
  // Since the first set, the reference's included: a recording played live passes over the sets
  // it fell behind on (a live camera would have overwritten them).
  summary["sets_acquired"] = cameras.sets_acquired();
  summary["sets_passed_over"] = cameras.sets_passed_over();
  summary["seconds"] = seconds;
  summary["all_forbidden_cycles"] = figures.all_forbidden_cycles;
  summary["all_forbidden_because"] = figures.all_forbidden_because;
  summary["separation_slowed_cycles"] = figures.separation_slowed_cycles;
  summary["cycles_short_of_views"] = figures.cycles_short_of_views;
  summary["features_ms_p99"] = percentile(figures.features_ms, 0.99);
  summary["fusion_ms_p99"] = percentile(figures.fusion_ms, 0.99);
  summary["controller_faults"] = link.controller_faults().size();
  summary["incidents"] = figures.incidents;
  summary["incidents_not_written"] = figures.incidents_not_written;
  summary["new_sessions"] = figures.new_sessions;
  summary["stops_explained"] = figures.stops_explained;
  summary["stopped_because"] = stopped_because;
  write_file_atomically(file, summary.dump(2) + "\n");
}

}  // namespace

int run_service(const RunOptions& options, std::ostream& out, std::ostream& err) {
  check_options(options);
  const UdpEndpoint controller = udp_address("--controller", options.controller, 1);
  const UdpEndpoint listen = udp_address("--listen", options.listen, 0);
  const fs::path out_dir(options.out_dir);
  fs::create_directories(out_dir);

  const CellModel cell = load_cell_model(load_cell_file(options.cell_path));
  const CspaceGrid grid = make_grid(cell.config);
  // The cameras first: a camera without a source is named before the tables take their time.
  FrameSetAcquirer cameras(cell_camera_sources(cell, Recordings::kLive));
  const CachedLuts luts = cell_luts(cell, grid, ModelLutOptions{}, options.lut_cache, err);
  const ModelSilhouettes silhouettes(cell, grid, ModelLutOptions{}, CellDrawing::kWholeCells);

  std::vector<cv::Mat> reference;
  if (options.record_reference) {
    reference = record_reference_images(cameras, options.reference_sets, err);
    write_reference_images(out_dir / "reference", cell, reference);
    err << "reference images written to " << (out_dir / "reference").string()
        << " (check them: nobody may be in them; then give them as --reference)\n";
  } else {
    reference = read_reference_images(options.reference_dir, cell);
  }
  const FusionSettings fusion = service_fusion_settings(cell, options.sync_error_ms * 1e-3);
  SensingPipeline pipeline(cell, grid, luts.set, silhouettes, reference, {}, fusion);

  UdpTransport transport(listen, controller);
  CoprocessorLinkConfig link_config;
  link_config.cell_count = grid.cell_count();
  link_config.grid_fingerprint = grid.fingerprint();
  link_config.lut_fingerprint = luts.set.fingerprint;
  link_config.map_cycle_us = static_cast<std::uint32_t>(1e6 / options.fps);
  CoprocessorLink link(link_config, transport);
  err << "link: " << listen.address << ':' << transport.local_port() << " -> " << options.controller
      << " (grid fingerprint " << std::hex << grid.fingerprint() << ", LUT fingerprint "
      << luts.set.fingerprint << std::dec << ")\n";
  const StopSignals signals;
  if (!open_session(link, options, err)) {
    err << "stopped (" << *StopSignals::received() << ") before the controller answered\n";
    return 0;
  }
  StopRequestOnError stop_request(link);
  err << "session open: watchdog " << link.config().watchdog_us / 1000 << " ms, data age "
      << link.config().max_data_age_us / 1000 << " ms (the controller's)\n";

  SensingServiceSettings service_settings;
  service_settings.joints.max_acceleration_rad_s2.assign(grid.joint_count(),
                                                         options.max_acceleration_rad_s2);
  service_settings.widening_budget_m =
      removal_widening_m(*cell.robot, grid, 0.0, fusion.sync_error_s).value_or(0.02);
  service_settings.camera_threshold = static_cast<std::uint32_t>(cell.camera_threshold);
  SensingService service(
      grid, pipeline, link, service_settings,
      camera_views_for(cell, reference, [&err](std::string_view line) { err << line << "\n"; }));

  const std::uint64_t start_ns = steady_now_ns();
  const auto seconds_since_start = [start_ns](std::uint64_t ns) {
    return (static_cast<double>(ns) - static_cast<double>(start_ns)) * 1e-9;
  };
  // Incidents: the seconds around every stop and fault, for `safecell replay`.
  std::optional<IncidentFeed> incidents;
  if (options.incident_seconds > 0.0) {
    IncidentSetup setup{fs::absolute(options.cell_path),
                        read_file(options.cell_path, " again"),
                        grid.fingerprint(),
                        luts.set.fingerprint,
                        fusion.sync_error_s,
                        reference};
    incidents.emplace(
        IncidentSettings{out_dir / "incidents", options.incident_seconds, 1.0, 50, setup}, err);
  }
  std::optional<JointRecord> last_joints;
  AppliedMapLatency latency;
  std::uint64_t last_heard_ns = steady_now_ns();  // the controller's last joint state
  link.on_joint_state([&](const ReceivedJointState& received) {
    last_heard_ns = steady_now_ns();
    if (received.coprocessor_time_ns == 0) return;
    JointRecord sample = joint_record(received, link.clock_sync(), start_ns);
    latency.joint_state(sample, last_joints ? &*last_joints : nullptr);
    if (incidents) incidents->joint_state(sample, last_joints ? &*last_joints : nullptr);
    last_joints = std::move(sample);
  });

  const auto frame_period =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / options.fps));
  StatusPrinter status(err);
  RunFigures figures;
  std::size_t faults_reported = 0;
  std::string stopped_because;
  while (true) {
    if (const auto signal = StopSignals::received()) {
      stopped_because = *signal;
      break;
    }
    if (options.seconds > 0.0 && seconds_since_start(steady_now_ns()) >= options.seconds) {
      stopped_because = "--seconds " + fixed(options.seconds, 1) + " ran out";
      break;
    }
    // What is waiting in the socket first: a slow cycle is not the controller's silence.
    service.serve_link(Clock::now());
    const double silent_s = static_cast<double>(steady_now_ns() - last_heard_ns) * 1e-9;
    if (silent_s > options.new_session_after_s) {
      err << "the controller has sent nothing for " << fixed(silent_s, 1)
          << " s (restarted, or gone): opening a new session\n";
      link.start_new_session();
      if (!open_session(link, options, err)) {
        stopped_because = *StopSignals::received();
        break;
      }
      err << "session open again (" << ++figures.new_sessions << " since the start)\n";
      last_heard_ns = steady_now_ns();
    }
    const Clock::time_point acquired_at = Clock::now();
    const FrameSet set = cameras.acquire();
    if (const auto stopped = all_cameras_stopped(set)) {
      stopped_because = *stopped;
      break;
    }
    if (set.known_count() == 0) {
      // No camera gave a frame (devices gone, streams down): the cycle still sends its
      // all-forbidden map, at the frame rate, not as fast as failing cameras return.
      service.serve_link(acquired_at + frame_period);
    }
    // The joint stream until a little past the exposure, so that the pose there is interpolated
    // between samples rather than extrapolated (a camera's frame mostly arrives later than this
    // anyway; a recording played live is stamped as it is handed out).
    // Capped: a camera whose stamps run ahead of the steady clock must not hold the loop.
    const Clock::time_point now = Clock::now();
    service.serve_link(std::clamp(steady_time_point(median_exposure_s(set)) + kJointStreamLead, now,
                                  now + kJointStreamLead));
    const ServiceCycle& cycle = service.process(set);
    ++figures.cycles;
    if (!cycle.all_forbidden.empty()) {
      ++figures.all_forbidden_cycles;
      ++figures.all_forbidden_because[all_forbidden_kind(cycle.all_forbidden)];
    } else if (cycle.speed_limit < 1.0) {
      ++figures.separation_slowed_cycles;
    }
    if (cycle.known_views < service_settings.camera_threshold) ++figures.cycles_short_of_views;
    figures.features_ms.push_back(cycle.times.features_ms);
    figures.fusion_ms.push_back(cycle.times.fusion_ms);
    // A set without a known frame has no exposure: the cycle is then placed at the clock's now.
    const double time_s =
        seconds_since_start(cycle.exposure_ns != 0 ? cycle.exposure_ns : steady_now_ns());
    latency.sent(cycle.map_version, time_s);
    if (incidents) incidents->cycle(time_s, service.last_frames(), cycle, service.last_map());
    figures.stops_explained += report_stop_explanations(service, seconds_since_start, err,
                                                        incidents ? &*incidents : nullptr)
                                   .size();
    for (; faults_reported < link.controller_faults().size(); ++faults_reported) {
      const v1::FaultReport& fault = link.controller_faults()[faults_reported];
      const std::string text =
          std::string(v1::FaultCause_Name(fault.cause())) + ": " + fault.detail();
      err << "controller fault: " << text << '\n';
      if (incidents) incidents->fault(time_s, text);
    }
    status.cycle(time_s, [&] {
      return service_status_line(figures.cycles - 1, time_s, cycle, grid.cell_count(),
                                 last_joints ? &*last_joints : nullptr, latency.last_ms());
    });
  }
  status.finish();

  // A clean stop: the controller holds the robot on the request (latched until its operator
  // acknowledges) instead of finding the maps gone.
  const bool asked = stop_request.send("safecell run stopped: " + stopped_because);
  if (asked) service.serve_link(Clock::now() + std::chrono::milliseconds(50));
  const double seconds = seconds_since_start(steady_now_ns());
  if (incidents) {
    figures.incidents = incidents->finish();
    figures.incidents_not_written = incidents->not_written();
  }
  try {
    write_run_summary(out_dir / "run_summary.json", figures, seconds, stopped_because, cameras,
                      link);
  } catch (const FileError& error) {
    err << "error: the run's summary was not written: " << error.what() << '\n';
    return kExitEvidenceNotWritten;
  }
  out << "stopped: " << stopped_because
      << (asked ? "; the controller was asked to stop the robot\n"
                : "; no session was open to ask the controller (its watchdog holds the robot)\n")
      << "cycles " << figures.cycles << " in " << fixed(seconds, 1) << " s, all-forbidden "
      << figures.all_forbidden_cycles << ", slowed by the protective separation "
      << figures.separation_slowed_cycles << ", short of views " << figures.cycles_short_of_views
      << "; summary " << (out_dir / "run_summary.json").string() << '\n';
  if (figures.incidents_not_written > 0) {
    err << "error: " << figures.incidents_not_written
        << " incident(s) could not be written (see above); the run's evidence is incomplete\n";
    return kExitEvidenceNotWritten;
  }
  return 0;
}

void add_run_command(CLI::App& app, CommandLine& line) {
  const auto run = std::make_shared<RunOptions>();
  CLI::App* run_command = app.add_subcommand(
      "run",
      "The coprocessor service on the cell file's cameras (each camera's source: a capture "
      "device, a video file, an image folder with frame_times.csv, a GStreamer pipeline or an "
      "RTSP URL), sending its maps to a safecell-controller over UDP. Recordings play at their "
      "recorded pace. Stops on SIGINT or SIGTERM, after --seconds, or when every camera has "
      "stopped; the controller then gets a stop request and holds the robot");
  run_command->add_option("--cell", run->cell_path, "Cell file (YAML) whose cameras name a source")
      ->required();
  run_command->add_option("--lut-cache", run->lut_cache,
                          "Folder of cached look-up tables; default $SAFECELL_CACHE or "
                          "~/.cache/safecell");
  run_command
      ->add_option("--controller", run->controller,
                   "The controller's UDP address, HOST:PORT (its link.listen)")
      ->capture_default_str();
  run_command
      ->add_option("--listen", run->listen,
                   "This end's UDP address, HOST:PORT (the controller's link.coprocessor)")
      ->capture_default_str();
  run_command->add_option("--reference", run->reference_dir,
                          "Folder of reference images, <camera>.png each (the empty cell)");
  run_command->add_flag("--record-reference", run->record_reference,
                        "Record the reference images at the start instead (nobody may be in the "
                        "cell; the robot may move) and write them to <out>/reference");
  run_command
      ->add_option("--reference-sets", run->reference_sets,
                   "Frame sets whose median is the recorded reference")
      ->capture_default_str();
  run_command->add_option("--seconds", run->seconds, "Stop after this long (0: until stopped)")
      ->capture_default_str();
  run_command
      ->add_option("--out", run->out_dir,
                   "Folder for the recorded reference and "
                   "run_summary.json")
      ->capture_default_str();
  run_command
      ->add_option("--incident-seconds", run->incident_seconds,
                   "Seconds before each stop or fault the incident recorder writes into "
                   "<out>/incidents (0: none)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 60.0));
  run_command
      ->add_option("--max-acceleration", run->max_acceleration_rad_s2,
                   "The robot's largest joint acceleration, rad/s^2 (bounds the joint stream's "
                   "interpolation error)")
      ->capture_default_str();
  run_command
      ->add_option("--fps", run->fps, "The cameras' frame rate (announced to the controller)")
      ->capture_default_str();
  run_command
      ->add_option("--sync-error", run->sync_error_ms,
                   "How far apart the cameras' exposures may be, ms (hardware-triggered cameras: "
                   "a few; free-running ones up to a frame period, which widens the robot's "
                   "removal)")
      ->capture_default_str();
  run_command
      ->add_option("--new-session-after", run->new_session_after_s,
                   "Seconds without a word from the controller after which it counts as restarted "
                   "(or gone) and a new session is opened")
      ->capture_default_str();
  run_command
      ->add_option("--connect-timeout", run->connect_timeout_s,
                   "Seconds to wait for the controller's answer")
      ->capture_default_str();
  run_command->callback([=, &line] {
    line.action = [=, &line] { line.exit_code = run_service(*run, line.out, line.err); };
  });
}

}  // namespace safecell
