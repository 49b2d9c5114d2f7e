#include "end_to_end_bench.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>

#include "safecell/closed_loop/closed_loop_record.hpp"
#include "safecell/closed_loop/controller_session.hpp"
#include "safecell/closed_loop/replayed_frame_sets.hpp"
#include "safecell/sim/demo_scenario.hpp"
#include "safecell/validation/percentile.hpp"
#include "scratch_path.hpp"
#include "simulated_sensing.hpp"

namespace safecell {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double kFps = 30.0;

// The person of the demo walking through the cell past the still robot, rendered in advance.
std::vector<std::vector<cv::Mat>> rendered_sets(SimulatedSensing& sensing,
                                                const std::vector<double>& q, std::size_t count) {
  const HumanWalker person = demo_person(sensing.cell);
  std::vector<std::vector<cv::Mat>> sets;
  for (std::size_t k = 0; k < count; ++k) {
    const double t = static_cast<double>(k) / kFps;
    SimScene scene{q, {person.pose_at(t)}};
    sets.push_back(sensing.sim.render(scene, k + 1, t));
  }
  return sets;
}

}  // namespace

EndToEndFigures measure_end_to_end(bool quick, std::ostream& log) {
  const std::filesystem::path program = find_controller_program("");
  // The map path end to end: the demo's person comes within the protective separation of the
  // still robot, which would forbid those maps whole; the check's own time is in fusion_ms
  // and in the protective_separation benchmark.
  SimulatedSensing sensing("", "", 1, log, CellOverrides{0, true});
  // The controller's file and log.
  const ScratchPath folder("e2e");
  std::filesystem::create_directories(folder.path());
  ControllerSetup setup = controller_setup_of(sensing.cell, sensing.grid);
  setup.start_rad = demo_robot_at(sensing.grid, 0.0);  // held there: no task
  ControllerSession session(
      sensing.cell, sensing.grid, sensing.pipeline, sensing.luts.set.fingerprint, setup,
      real_time_session(program, folder.path(), kFps, sensing.fusion.sync_error_s,
                        sensing.reference.frames),
      log);
  const std::uint64_t start_ns = steady_now_ns();
  ClosedLoopRecord record;
  std::uint64_t clock_uncertainty_max_ns = 0;
  session.link().on_joint_state([&](const ReceivedJointState& received) {
    if (received.coprocessor_time_ns == 0) return;
    record.joints.push_back(joint_record(received, session.link().clock_sync(), start_ns));
    if (const auto offset = session.link().clock_sync().offset()) {
      clock_uncertainty_max_ns = std::max(clock_uncertainty_max_ns, offset->uncertainty_ns);
    }
  });
  log << "end to end: rendering the frames first (the camera's part)\n";
  ReplayedFrameSets frames(
      [&] {
        std::vector<std::string> names;
        for (const auto& camera : sensing.cell.cameras) names.push_back(camera.name());
        return names;
      }(),
      rendered_sets(sensing, setup.start_rad, quick ? 15 : 60));
  SensingService& service = session.service();
  // The joint stream first, so that the robot's pose at the first exposure is known.
  service.serve_link(Clock::now() + std::chrono::milliseconds(300));

  EndToEndFigures figures;
  figures.frames = quick ? 45 : 600;
  log << "end to end: " << figures.frames << " frames at 30 frames/s, then back to back\n";
  const auto period = std::chrono::nanoseconds(static_cast<std::int64_t>(1e9 / kFps));
  std::map<std::uint64_t, double> exposure_of;  // map version -> exposure (s since start)
  // map version -> when its sending began (s since start): the controller cannot have applied it
  // before. (The time it had left is no bound: this thread may lose the CPU after the send, and
  // under load the controller applied maps 5 ms "before" it.)
  std::map<std::uint64_t, double> send_started_of;
  std::vector<double> to_sent_ms;
  std::vector<double> features_ms;
  std::vector<double> fusion_ms;
  std::vector<double> rest_ms;
  auto next = Clock::now();
  for (std::size_t k = 0; k < figures.frames; ++k) {
    next += period;
    const ServiceCycle& cycle = service.process(frames.acquire());
    if (!cycle.all_forbidden.empty() && figures.all_forbidden_frames++ == 0) {
      log << "end to end: a map all forbidden (" << cycle.all_forbidden << ")\n";
    }
    const double exposure_s =
        (static_cast<double>(cycle.exposure_ns) - static_cast<double>(start_ns)) * 1e-9;
    exposure_of[cycle.map_version] = exposure_s;
    send_started_of[cycle.map_version] =
        (static_cast<double>(cycle.send_started_ns) - static_cast<double>(start_ns)) * 1e-9;
    to_sent_ms.push_back(static_cast<double>(cycle.sent_ns - cycle.exposure_ns) * 1e-6);
    features_ms.push_back(cycle.times.features_ms);
    fusion_ms.push_back(cycle.times.fusion_ms);
    rest_ms.push_back(to_sent_ms.back() - cycle.times.features_ms - cycle.times.fusion_ms);
    service.serve_link(next);
  }
  service.serve_link(Clock::now() + std::chrono::milliseconds(50));
  figures.updates_refused_without_fault = session.link().repair_requests();
  std::vector<double> map_age_ms;
  const double paced_from_s = exposure_of.empty() ? 0.0 : exposure_of.begin()->second;
  for (const JointRecord& sample : record.joints) {
    const auto exposure = exposure_of.find(sample.applied_map_version);
    if (sample.time_s < paced_from_s || exposure == exposure_of.end()) continue;
    map_age_ms.push_back((sample.time_s - exposure->second) * 1e3);
  }
  figures.map_age_p50_ms = percentile(map_age_ms, 0.5);
  figures.map_age_p99_ms = percentile(map_age_ms, 0.99);
  figures.map_age_max_ms = percentile(map_age_ms, 1.0);
  std::vector<double> latency_ms;
  std::map<std::uint64_t, double> applied_at;
  for (const JointRecord& sample : record.joints) {
    if (sample.applied_map_time_s > 0.0)
      applied_at.emplace(sample.applied_map_version, sample.applied_map_time_s);
  }
  for (const auto& [version, exposure_s] : exposure_of) {
    const auto applied = applied_at.find(version);
    if (applied == applied_at.end()) {
      ++figures.updates_not_applied;
      continue;
    }
    latency_ms.push_back((applied->second - exposure_s) * 1e3);
    const double sent_to_applied_ms = (applied->second - send_started_of.at(version)) * 1e3;
    figures.sent_to_applied_min_ms =
        latency_ms.size() == 1 ? sent_to_applied_ms
                               : std::min(figures.sent_to_applied_min_ms, sent_to_applied_ms);
  }
  figures.clock_uncertainty_max_ms = static_cast<double>(clock_uncertainty_max_ns) * 1e-6;
  figures.latency_p50_ms = percentile(latency_ms, 0.5);
  figures.latency_p99_ms = percentile(latency_ms, 0.99);
  figures.latency_max_ms = percentile(latency_ms, 1.0);
  figures.to_sent_p50_ms = percentile(to_sent_ms, 0.5);
  figures.to_sent_p99_ms = percentile(to_sent_ms, 0.99);
  figures.features_p50_ms = percentile(features_ms, 0.5);
  figures.fusion_p50_ms = percentile(fusion_ms, 0.5);
  figures.rest_p50_ms = percentile(rest_ms, 0.5);

  // Back to back: as fast as the service goes, serving the link between frames.
  const std::size_t sustained = quick ? 30 : 300;
  std::vector<std::uint64_t> versions;
  const auto begin = Clock::now();
  for (std::size_t k = 0; k < sustained; ++k) {
    const ServiceCycle& cycle = service.process(frames.acquire());
    if (!cycle.all_forbidden.empty() && figures.all_forbidden_frames++ == 0) {
      log << "end to end: a map all forbidden (" << cycle.all_forbidden << ")\n";
    }
    versions.push_back(cycle.map_version);
    service.serve_link(Clock::now());
  }
  const double elapsed_s = std::chrono::duration<double>(Clock::now() - begin).count();
  service.serve_link(Clock::now() + std::chrono::milliseconds(50));
  figures.service_fps = static_cast<double>(sustained) / elapsed_s;
  std::size_t applied = 0;
  for (const JointRecord& sample : record.joints) {
    if (sample.applied_map_time_s > 0.0)
      applied_at.emplace(sample.applied_map_version, sample.applied_map_time_s);
  }
  for (const std::uint64_t version : versions) applied += applied_at.count(version);
  figures.sustained_fps = static_cast<double>(applied) / elapsed_s;
  (void)session.finish("safecell bench finished");
  return figures;
}

}  // namespace safecell
