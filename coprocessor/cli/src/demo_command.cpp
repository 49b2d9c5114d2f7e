#include "safecell/cli/demo_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <random>

#include "command_line.hpp"
#include "demo_report.hpp"
#include "incident_feed.hpp"
#include "safecell/cell/default_cell.hpp"
#include "safecell/cli/cli_app.hpp"
#include "safecell/cli/text_table.hpp"
#include "safecell/cli/validate_command.hpp"
#include "safecell/closed_loop/controller_session.hpp"
#include "safecell/closed_loop/live_simulated_cameras.hpp"
#include "safecell/files/atomic_write.hpp"
#include "safecell/files/read_file.hpp"
#include "safecell/robot/kinematics.hpp"
#include "safecell/separation/protective_separation.hpp"
#include "safecell/sim/ground_truth.hpp"
#include "safecell/validation/configuration_strata.hpp"
#include "safecell/validation/scene_check.hpp"
#include "scene_options.hpp"
#include "service_status.hpp"
#include "simulated_sensing.hpp"
#include "stop_explanations.hpp"

namespace safecell {
namespace {

// The near-person figures of one cycle whose map the pipeline made (not one forbidden whole for
// want of the robot's pose).
void add_near_person_figures(const SimulatedSensing& sensing, const SimScene& scene,
                             const ServiceCycle& cycle, NearPersonFreeSpace& figures) {
  const bool separation = all_forbidden_kind(cycle.all_forbidden) == kSeparationStopKind;
  if (scene.humans.empty() || !cycle.pose_known || (!cycle.all_forbidden.empty() && !separation)) {
    return;
  }
  const double distance_m = GroundTruth(moving_bodies(scene))
                                .min_distance_m(collision_shapes_at(sensing.sim.robot(), scene.q));
  if (distance_m >= NearPersonFreeSpace::kNear_m) return;
  const auto cells = static_cast<double>(sensing.grid.cell_count());
  ++figures.frames;
  figures.separation_frames += separation ? 1 : 0;
  figures.slowed_frames += !separation && cycle.speed_limit < 1.0 ? 1 : 0;
  figures.speed_limit_sum += cycle.speed_limit;
  figures.map_free_sum +=
      1.0 - static_cast<double>(sensing.pipeline.fusion().forbidden().count()) / cells;
  figures.sent_free_sum += 1.0 - static_cast<double>(cycle.forbidden_cells) / cells;
}

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr double kWatchdog_ms = 250.0;  // a few frame periods: a late frame is not yet a fault

ControllerSetup demo_controller_setup(const CellModel& cell, const CspaceGrid& grid,
                                      const DemoWorld& world) {
  ControllerSetup setup = controller_setup_of(cell, grid);
  setup.start_rad = world.start_rad();
  setup.goals_rad = world.goals_rad();
  setup.repeat = true;
  setup.watchdog_ms = kWatchdog_ms;
  setup.max_data_age_ms = kWatchdog_ms;
  return setup;
}

void check_options(const DemoOptions& options) {
  if (!(options.seconds >= 5.0 && options.seconds <= 3600.0)) {
    bad_option("--seconds", std::to_string(options.seconds), "a duration of 5..3600 s");
  }
  if (!(options.fps >= 2.0 && options.fps <= 60.0)) {
    bad_option("--fps", std::to_string(options.fps), "a frame rate of 2..60 per second");
  }
  if (!(options.views_every_s >= 0.0)) {
    bad_option("--views-every", std::to_string(options.views_every_s), "seconds >= 0");
  }
  if (!(options.incident_seconds == 0.0 ||
        (options.incident_seconds >= 0.1 && options.incident_seconds <= 60.0))) {
    bad_option("--incident-seconds", std::to_string(options.incident_seconds),
               "0 (no incidents) or 0.1..60 s");
  }
}

}  // namespace

int run_demo(const DemoOptions& options, std::ostream& out, std::ostream& err) {
  check_options(options);
  const fs::path program = find_controller_program(options.controller_program);
  SimulatedSensing sensing(options.cell_path, options.lut_cache, options.seed, err);
  const fs::path out_dir(options.out_dir);
  for (const char* sub : {"views", "slices"}) fs::create_directories(out_dir / sub);

  // The person comes in once the robot has done a few moves alone (the productivity baseline)
  // and leaves with time to spare for moves after.
  const DemoWorld world(sensing.cell, sensing.grid, 0.3 * options.seconds);
  ControllerSessionSettings session_settings = real_time_session(
      program, out_dir, options.fps, sensing.fusion.sync_error_s, sensing.reference.frames);
  // The near-person figures show the map's free share beside the sent one: every map is made.
  session_settings.maps_of_stopped_cycles = true;
  ControllerSession session(
      sensing.cell, sensing.grid, sensing.pipeline, sensing.luts.set.fingerprint,
      demo_controller_setup(sensing.cell, sensing.grid, world), session_settings, err);
  SensingService& service = session.service();

  const std::uint64_t start_ns = steady_now_ns();
  const auto seconds_since_start = [start_ns](std::uint64_t ns) {
    return (static_cast<double>(ns) - static_cast<double>(start_ns)) * 1e-9;
  };
  DemoRun run;
  run.seconds = options.seconds;
  run.fps = options.fps;
  ClosedLoopRecord& record = run.record;
  AppliedMapLatency latency;  // for the status line
  // Incidents as safecell run records them, for `safecell replay` (the built-in cell: no file).
  std::optional<IncidentFeed> incidents;
  if (options.incident_seconds > 0.0) {
    IncidentSetup setup{options.cell_path.empty() ? fs::path() : fs::absolute(options.cell_path),
                        options.cell_path.empty() ? std::string(default_cell_yaml())
                                                  : read_file(options.cell_path, " again"),
                        sensing.grid.fingerprint(),
                        sensing.luts.set.fingerprint,
                        sensing.fusion.sync_error_s,
                        sensing.reference.frames};
    incidents.emplace(
        IncidentSettings{out_dir / "incidents", options.incident_seconds, 1.0, 50, setup}, err);
  }
  session.link().on_joint_state([&](const ReceivedJointState& received) {
    if (received.coprocessor_time_ns == 0) return;
    JointRecord sample = joint_record(received, session.link().clock_sync(), start_ns);
    const JointRecord* previous = record.joints.empty() ? nullptr : &record.joints.back();
    latency.joint_state(sample, previous);
    if (incidents) incidents->joint_state(sample, previous);
    record.joints.push_back(std::move(sample));
  });

  // The cameras see the robot where the controller's joint stream puts it at the exposure.
  std::vector<double> rendered_q = session.setup().start_rad;
  LiveSimulatedCameras cameras(sensing.sim, [&](std::uint64_t exposure_ns) {
    const JointsAtTime joints = service.joints().at(exposure_ns);
    if (joints.known) rendered_q = joints.position_rad;
    SimScene scene{rendered_q, {}};
    if (auto person = world.person_at(seconds_since_start(exposure_ns))) {
      scene.humans.push_back(*person);
    }
    return scene;
  });

  StatusPrinter status(err);
  const auto period = std::chrono::nanoseconds(static_cast<std::int64_t>(1e9 / options.fps));
  const auto start = Clock::time_point(std::chrono::nanoseconds(start_ns));
  const auto end =
      start + std::chrono::nanoseconds(static_cast<std::int64_t>(options.seconds * 1e9));
  const std::size_t views_every =
      options.views_every_s > 0.0
          ? std::max<std::size_t>(
                1, static_cast<std::size_t>(std::lround(options.views_every_s * options.fps)))
          : 0;
  const auto video_every =
      std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(options.fps / 5.0)));
  std::mt19937_64 rng(options.seed);
  std::optional<double> fault_since;  // the controller has reported a fault since then
  std::size_t cycle_count = 0;
  std::int64_t k = 0;
  while (true) {
    const auto exposure_at = start + k * period;
    if (exposure_at >= end) break;
    service.serve_link(exposure_at);
    if (!session.process().running()) {
      run.controller_died = true;
      break;
    }
    // The operator: a fault holds the robot until acknowledged; the demo's operator presses the
    // key once the fault has held for a while (a real one would look at the cause first).
    if (!record.joints.empty() && record.joints.back().state == v1::CONTROLLER_STATE_FAULT) {
      const double now_s = record.joints.back().time_s;
      if (!fault_since) fault_since = now_s;
      if (options.acknowledge_after_s > 0.0 &&
          now_s - *fault_since >= options.acknowledge_after_s) {
        session.process().acknowledge_fault();
        run.acknowledged_s.push_back(now_s);
        err << "operator: acknowledged the controller's fault at " << fixed(now_s, 1)
            << " s (it held " << fixed(now_s - *fault_since, 1) << " s)\n";
        fault_since.reset();
      }
    } else {
      fault_since.reset();
    }
    // Behind by a frame or more (a slow machine): skip to the present, as a camera would.
    const auto behind = Clock::now() - exposure_at;
    if (behind > period) {
      const auto skip = behind / period;
      run.frames_skipped += static_cast<std::size_t>(skip);
      k += skip;
      continue;
    }
    ++k;
    const FrameSet frames = cameras.acquire();
    const ServiceCycle& cycle = service.process(frames);
    const std::size_t index = cycle_count++;
    const double time_s = seconds_since_start(cycle.exposure_ns);
    if (incidents) incidents->cycle(time_s, service.last_frames(), cycle, service.last_map());
    for (IncidentExplanation& stop : report_stop_explanations(service, seconds_since_start, err,
                                                              incidents ? &*incidents : nullptr)) {
      run.stop_explanations.push_back(std::move(stop));
    }
    add_near_person_figures(sensing, cameras.last_scene(), cycle, run.near_person);
    CycleRecord cycle_record;
    cycle_record.exposure_s = time_s;
    cycle_record.sent_s = seconds_since_start(cycle.sent_ns);
    cycle_record.map_version = cycle.map_version;
    cycle_record.forbidden_cells = cycle.forbidden_cells;
    cycle_record.blocked_per_camera = cycle.blocked_per_camera;
    cycle_record.features_ms = cycle.times.features_ms;
    cycle_record.fusion_ms = cycle.times.fusion_ms;
    cycle_record.person_present = !cameras.last_scene().humans.empty();
    cycle_record.all_forbidden = cycle.all_forbidden;
    record.cycles.push_back(cycle_record);
    latency.sent(cycle.map_version, time_s);

    if (cycle.pose_known && cycle.all_forbidden.empty() && options.check_every > 0 &&
        index % static_cast<std::size_t>(options.check_every) == 0) {
      const SceneUnderTest under_test{cameras.last_scene(),
                                      cameras.last_object_ids(),
                                      service.last_map(),
                                      sensing.fusion.camera_threshold,
                                      "demo",
                                      index};
      run.checks += check_scene(sensing.cell, sensing.grid, sensing.sim, under_test,
                                options.checks_per_cycle, rng);
    }
    const JointRecord* joints = record.joints.empty() ? nullptr : &record.joints.back();
    if (index % video_every == 0 && cycle.all_forbidden.empty()) {
      run.video.add(demo_views_picture(
          cameras.last_frames(), sensing.pipeline, sensing.cell,
          fixed(time_s, 1) + " s  " + (joints ? state_name(joints->state) : "waiting")));
    }
    if (views_every > 0 && index % views_every == 0 && cycle.all_forbidden.empty()) {
      DemoSnapshot snapshot;
      snapshot.cycle = index;
      snapshot.time_s = time_s;
      snapshot.views = demo_views_picture(cameras.last_frames(), sensing.pipeline, sensing.cell,
                                          joints ? state_name(joints->state) : "waiting");
      snapshot.forbidden = service.last_map();
      snapshot.robot_cell = sensing.pipeline.robot_cell();
      for (const JointRecord& sample : record.joints) {
        if (sample.time_s >= time_s - kDemoPathSeconds) {
          snapshot.path.push_back(cell_of(sensing.grid, sample.q));
        }
      }
      run.snapshots.push_back(std::move(snapshot));
    }
    status.cycle(time_s, [&] {
      return service_status_line(index, time_s, cycle, sensing.grid.cell_count(), joints,
                                 latency.last_ms());
    });
  }
  status.finish();

  // A clean end: the controller is asked to stop (it holds the robot), then the program exits.
  // What follows the request is not part of the run.
  const double run_end_s = seconds_since_start(steady_now_ns());
  run.controller_exit = session.finish("safecell demo finished");
  if (incidents) {
    err << incidents->finish() << " incident(s) in " << (out_dir / "incidents").string()
        << " (safecell replay FOLDER runs one again)\n";
    run.incidents_not_written = incidents->not_written();
  }
  if (run.controller_died) {
    err << "the controller exited during the demo (code "
        << (run.controller_exit ? std::to_string(*run.controller_exit) : "?")
        << "); its last words:" << session.log_tail() << "\n";
  }
  while (!record.joints.empty() && record.joints.back().time_s > run_end_s) {
    record.joints.pop_back();
  }
  bool safe = false;
  try {
    safe = write_demo_report(out_dir, sensing, world, session.setup().goals_rad, run, out, err);
  } catch (const FileError& error) {
    err << "error: the demo's report was not written: " << error.what() << '\n';
    return kExitEvidenceNotWritten;
  }
  if (!safe) return kExitValidationFailed;
  if (run.incidents_not_written > 0) {
    err << "error: " << run.incidents_not_written
        << " incident(s) could not be written (see above); the run's evidence is incomplete\n";
    return kExitEvidenceNotWritten;
  }
  return 0;
}

void add_demo_command(CLI::App& app, CommandLine& line) {
  const auto demo = std::make_shared<DemoOptions>();
  CLI::App* demo_command = app.add_subcommand(
      "demo",
      "The closed loop on the simulated cell, in real time: this coprocessor and "
      "safecell-controller "
      "(the controller core on the simulated robot, a second process) over loopback UDP; the robot "
      "works through a pick-and-place task while a person walks in, reaches towards it and leaves. "
      "Writes a report folder (index.html, timeline.png, camera views, C-space slices, "
      "summary.json)");
  demo_command->add_option("--cell", demo->cell_path,
                           "Cell file (YAML); without it the built-in default cell");
  demo_command->add_option("--seconds", demo->seconds, "Duration (real time), 5..3600 s")
      ->capture_default_str();
  demo_command->add_option("--fps", demo->fps, "Camera frames per second, 2..60")
      ->capture_default_str();
  demo_command->add_option("--out", demo->out_dir, "Report folder")->capture_default_str();
  demo_command->add_option("--lut-cache", demo->lut_cache,
                           "Folder of cached look-up tables; default $SAFECELL_CACHE or "
                           "~/.cache/safecell");
  demo_command->add_option("--seed", demo->seed, "Seed of the sensor noise and the checks")
      ->capture_default_str();
  demo_command
      ->add_option("--views-every", demo->views_every_s,
                   "Seconds between saved camera views and slices (0: none)")
      ->capture_default_str();
  demo_command
      ->add_option("--checks-per-frame", demo->checks_per_cycle,
                   "Configurations checked against the map (FCL) per checked frame")
      ->capture_default_str()
      ->check(CLI::Range(0, 10000));
  demo_command
      ->add_option("--check-every", demo->check_every, "Frames between checked frames (0: none)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000000));
  demo_command
      ->add_option("--acknowledge-after", demo->acknowledge_after_s,
                   "The demo's operator acknowledges a controller fault after it held this many "
                   "seconds (0: never)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 3600.0));
  demo_command
      ->add_option("--incident-seconds", demo->incident_seconds,
                   "Seconds before each stop or fault written into <out>/incidents for safecell "
                   "replay (0: none)")
      ->capture_default_str();
  demo_command->add_option("--controller-program", demo->controller_program,
                           "The safecell-controller program; default $SAFECELL_CONTROLLER, the one "
                           "beside safecell, or the one this build made");
  demo_command->callback([=, &line] {
    line.action = [=, &line] { line.exit_code = run_demo(*demo, line.out, line.err); };
  });
}

}  // namespace safecell
