#include "safecell/cli/bench_command.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "cell_fusion_bench.hpp"
#include "command_line.hpp"
#include "end_to_end_bench.hpp"
#include "safecell/bench/map_sequence_writer.hpp"
#include "safecell/bench/project_benchmarks.hpp"
#include "safecell/cli/text_table.hpp"
#include "safecell/closed_loop/controller_process.hpp"
#include "safecell/errors/input_error.hpp"
#include "scratch_path.hpp"

namespace safecell {
namespace {

// The figures later issues and DESIGN.md §5 name, from the benchmark that measures each.
struct NamedFigure {
  const char* benchmark;
  const char* median_key;
  const char* worst_key;
};
constexpr NamedFigure kNamedFigures[] = {
    {"four_frames_to_blocked_masks", "features_ms", "features_worst_ms"},
    {"camera_health_check_one_frame", "health_check_ms", "health_check_worst_ms"},
    {"render_four_default_cameras", "sim_render_ms", "sim_render_worst_ms"},
    {"fusion_typical_scene", "fusion_ms", "fusion_typical_worst_ms"},
    {"fusion_thirty_percent_blocked", "fusion_thirty_percent_ms", "fusion_worst_ms"},
    {"fusion_baseline_typical_scene", "fusion_baseline_ms", "fusion_baseline_worst_ms"},
    {"robot_silhouettes_of_one_cell", "lut1_model_ms", "lut1_model_worst_ms"},
    {"fusion_typical_scene_hidden_votes", "fusion_hidden_votes_ms", "fusion_hidden_votes_worst_ms"},
    {"stop_explanation_typical_scene", "stop_explanation_ms", "stop_explanation_worst_ms"},
    {"protective_separation_typical_scene", "protective_separation_ms",
     "protective_separation_worst_ms"},
};

// Counters of a benchmark that become top-level figures.
struct NamedCounter {
  const char* benchmark;
  const char* counter;
  const char* key;
};
constexpr NamedCounter kNamedCounters[] = {
    {"fusion_typical_scene", "lut_bytes_per_camera", "lut_bytes_per_camera"},
    {"fusion_typical_scene", "lut_build_s", "lut_build_s"},
    {"map_updates_of_demo_sequence", "delta_bytes_p50", "delta_bytes_p50"},
    {"map_updates_of_demo_sequence", "delta_bytes_p99", "delta_bytes_p99"},
    {"map_updates_of_demo_sequence", "delta_bytes_max", "delta_bytes_max"},
    {"map_updates_of_demo_sequence", "keyframe_bytes", "keyframe_bytes"},
};

// Figures of the link stated in microseconds: the median of a benchmark.
struct NamedMicroseconds {
  const char* benchmark;
  const char* key;
};
constexpr NamedMicroseconds kNamedMicroseconds[] = {
    {"frame_seal_full_size", "frame_encode_us"},
    {"frame_check_full_size", "frame_check_us"},
    {"map_updates_of_demo_sequence", "delta_encode_us"},
};

#ifdef SAFECELL_CONTROLLER_BENCH
// Runs the controller's benchmark program on the maps in `maps` (map_sequence_writer.hpp) with
// `arguments` added, and returns the JSON figures it prints last. Throws when it gives none.
nlohmann::ordered_json run_controller_bench(const std::filesystem::path& maps,
                                            std::vector<std::string> arguments) {
  // A child process that ends with this one, however this one ends (ControllerProcess), its
  // output into a file read once it has exited.
  const ScratchPath output_file("controller-bench-output");
  arguments.insert(arguments.begin(),
                   {"--json", "--benchmark_color=false", "--maps=" + maps.string()});
  ControllerProcess program(SAFECELL_CONTROLLER_BENCH, arguments, output_file.path());
  while (program.running()) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  std::ifstream in(output_file.path());
  const std::string output{std::istreambuf_iterator<char>(in), {}};
  if (program.exit_code().value_or(-1) != 0) {
    throw std::runtime_error("safecell-controller-bench failed (exit " +
                             std::to_string(program.exit_code().value_or(-1)) + "):\n" + output);
  }
  const std::size_t json_start = output.rfind("\n{");
  if (json_start == std::string::npos) {
    throw std::runtime_error("safecell-controller-bench gave no figures:\n" + output);
  }
  return nlohmann::ordered_json::parse(output.substr(json_start + 1));
}

#endif

// The controller's figures: its benchmark program on the demo's maps. Empty when the program is
// not built (a coprocessor-only build); a failure of the program is an error.
nlohmann::ordered_json controller_figures(bool quick, std::ostream& progress) {
#ifdef SAFECELL_CONTROLLER_BENCH
  const ScratchPath maps("demo-maps");
  write_default_cell_demo_maps(maps.path().string());
  progress << "running the controller's benchmarks (safecell-controller-bench)...\n" << std::flush;
  return run_controller_bench(
      maps.path(), quick ? std::vector<std::string>{"--benchmark_min_time=0.02", "--quick"}
                         : std::vector<std::string>{"--benchmark_min_time=0.5"});
#else
  (void)quick;
  (void)progress;
  return nlohmann::ordered_json::object();
#endif
}

// `bench --cell`: the cell's fusion, and, where the controller's benchmark program is built, its
// map store holding the cell's sampled maps (the store's default layout for the cell's grid).
CellFusionFigures cell_figures(const std::string& cell_path, const BenchOptions& options,
                               std::ostream& progress) {
#ifdef SAFECELL_CONTROLLER_BENCH
  const ScratchPath maps("cell-maps");
  CellFusionFigures figures = measure_cell_fusion(cell_path, options.lut_cache, options.frames,
                                                  maps.path().string(), progress);
  progress << "the controller's map store holding the maps (safecell-controller-bench)...\n"
           << std::flush;
  const nlohmann::ordered_json store = run_controller_bench(
      maps.path(), {"--quick", "--benchmark_filter=map_store_memory", "--benchmark_min_time=0.02"});
  const auto frames = static_cast<std::size_t>(options.frames);  // 10.. (checked before)
  figures.map_store_maps = static_cast<int>((frames + kMapSampleStride - 1) / kMapSampleStride);
  figures.map_store_bytes = store.at("map_store_bytes").get<double>();
  figures.map_store_blocks = store.at("map_store_blocks").get<double>();
  figures.map_store_mixed_blocks_max = store.at("map_store_mixed_blocks_max").get<double>();
  figures.map_store_degraded_blocks_max = store.at("map_store_degraded_blocks_max").get<double>();
  figures.map_store_inexact_maps = store.at("map_store_inexact_maps").get<double>();
  return figures;
#else
  return measure_cell_fusion(cell_path, options.lut_cache, options.frames, "", progress);
#endif
}

nlohmann::ordered_json cell_fusion_json(const CellFusionFigures& figures) {
  return {{"cell", figures.cell},
          {"cells", figures.cells},
          {"m_max_m", figures.m_max_m},
          {"lut_bytes_per_camera", figures.lut_bytes_per_camera},
          {"tables_built", figures.tables_built},
          {"tables_build_s", figures.tables_build_s},
          {"frames", figures.frames},
          {"fusion_p50_ms", figures.fusion_p50_ms},
          {"fusion_p99_ms", figures.fusion_p99_ms},
          {"fusion_max_ms", figures.fusion_max_ms},
          {"served_fusion_p50_ms", figures.served_fusion_p50_ms},
          {"served_fusion_p99_ms", figures.served_fusion_p99_ms},
          {"served_fusion_max_ms", figures.served_fusion_max_ms},
          {"frames_stopped", figures.frames_stopped},
          {"features_p50_ms", figures.features_p50_ms},
          {"forbidden_share_mean", figures.forbidden_share_mean},
          {"forbidden_share_max", figures.forbidden_share_max},
          {"map_store_maps", figures.map_store_maps},
          {"map_store_bytes", figures.map_store_bytes},
          {"map_store_blocks", figures.map_store_blocks},
          {"map_store_mixed_blocks_max", figures.map_store_mixed_blocks_max},
          {"map_store_degraded_blocks_max", figures.map_store_degraded_blocks_max},
          {"map_store_inexact_maps", figures.map_store_inexact_maps}};
}

// `bench --cell`: the cell's fusion against the default cell's, the same frames of the demo.
void run_cell_fusion_bench(const BenchOptions& options, std::ostream& out, std::ostream& progress) {
  if (options.frames < 10 || options.frames > 100000) {
    throw InputError("--frames must be 10..100000, got " + std::to_string(options.frames));
  }
  progress << "the baseline, "
           << (options.baseline_cell_path.empty() ? "the default cell" : options.baseline_cell_path)
           << ":\n"
           << std::flush;
  const CellFusionFigures baseline = cell_figures(options.baseline_cell_path, options, progress);
  progress << "the cell of " << options.cell_path << ":\n" << std::flush;
  const CellFusionFigures cell = cell_figures(options.cell_path, options, progress);
  const double ratio =
      baseline.fusion_p99_ms > 0.0 ? cell.fusion_p99_ms / baseline.fusion_p99_ms : 0.0;
  const double served_ratio = baseline.served_fusion_p99_ms > 0.0
                                  ? cell.served_fusion_p99_ms / baseline.served_fusion_p99_ms
                                  : 0.0;
  if (options.json) {
    nlohmann::ordered_json report;
    report["baseline"] = cell_fusion_json(baseline);
    report["cell"] = cell_fusion_json(cell);
    report["fusion_p99_ratio"] = ratio;
    report["served_fusion_p99_ratio"] = served_ratio;
    out << report.dump(2) << '\n';
    return;
  }
  using Align = TextTable::Align;
  TextTable table({{"cell", Align::kLeft},
                   {"m_max [m]", Align::kRight},
                   {"C-space cells", Align::kRight},
                   {"LUT-2 [MB/camera]", Align::kRight},
                   {"fusion p50 [ms]", Align::kRight},
                   {"p99 [ms]", Align::kRight},
                   {"worst [ms]", Align::kRight},
                   {"served p99 [ms]", Align::kRight},
                   {"served worst [ms]", Align::kRight},
                   {"forbidden (mean)", Align::kRight}});
  for (const CellFusionFigures* figures : {&baseline, &cell}) {
    table.add_row({figures->cell, fixed(figures->m_max_m, 3), grouped(figures->cells),
                   fixed(figures->lut_bytes_per_camera / 1e6, 1), fixed(figures->fusion_p50_ms, 3),
                   fixed(figures->fusion_p99_ms, 3), fixed(figures->fusion_max_ms, 3),
                   fixed(figures->served_fusion_p99_ms, 3), fixed(figures->served_fusion_max_ms, 3),
                   fixed(100.0 * figures->forbidden_share_mean, 1) + " %"});
  }
  table.print(out);
  out << "\n"
      << options.frames << " frames of the demo from when the person walks in, one "
      << "thread; fusion p99 " << fixed(ratio, 1) << "x the baseline's. Served: as the service "
      << "runs them, no map made in the " << cell.frames_stopped
      << " frames the protective separation stopped the robot in (every cell forbidden then); "
      << "served p99 " << fixed(served_ratio, 1) << "x the baseline's. The two passes take "
      << "turns going first, 30 frames at a time\n";
  for (const CellFusionFigures* figures : {&baseline, &cell}) {
    if (figures->map_store_maps == 0) continue;
    out << figures->cell << ": the controller's map store holds " << figures->map_store_maps
        << " of the maps (every " << kMapSampleStride << "th) in "
        << fixed(figures->map_store_bytes / 1e6, 2) << " MB, up to "
        << grouped(static_cast<std::uint64_t>(figures->map_store_mixed_blocks_max)) << " of "
        << grouped(static_cast<std::uint64_t>(figures->map_store_blocks))
        << " blocks mixed; degraded to forbidden: "
        << grouped(static_cast<std::uint64_t>(figures->map_store_degraded_blocks_max))
        << "; maps not held bit for bit: "
        << grouped(static_cast<std::uint64_t>(figures->map_store_inexact_maps)) << "\n";
  }
}

}  // namespace

void run_bench(const BenchOptions& options, std::ostream& out, std::ostream& progress) {
  if (!options.cell_path.empty()) {
    run_cell_fusion_bench(options, out, progress);
    return;
  }
  BenchmarkRunOptions run;
  if (options.quick) {
    run.min_time_s = 0.02;
    run.repetitions = 3;
  }
  progress << "running benchmarks (" << run.repetitions << " repetitions of at least "
           << run.min_time_s << " s each)...\n"
           << std::flush;
  const std::vector<BenchmarkFigure> figures = run_project_benchmarks(run);
  const EndToEndFigures e2e = measure_end_to_end(options.quick, progress);

  if (!options.json) {
    using Align = TextTable::Align;
    TextTable table({{"benchmark", Align::kLeft},
                     {"median [ms]", Align::kRight},
                     {"worst [ms]", Align::kRight}});
    for (const auto& figure : figures) {
      table.add_row({figure.name, fixed(figure.median_ms, 3), fixed(figure.max_ms, 3)});
    }
    table.print(out);
    out << "\nend to end (4 cameras, safecell-controller on loopback, " << e2e.frames
        << " frames at 30 frames/s): exposure -> applied in the controller p50 "
        << fixed(e2e.latency_p50_ms, 3) << " ms, p99 " << fixed(e2e.latency_p99_ms, 3)
        << " ms, worst " << fixed(e2e.latency_max_ms, 3) << " ms (to sent p99 "
        << fixed(e2e.to_sent_p99_ms, 3) << " ms; p50 features " << fixed(e2e.features_p50_ms, 3)
        << " ms, fusion " << fixed(e2e.fusion_p50_ms, 3) << " ms, the rest "
        << fixed(e2e.rest_p50_ms, 3) << " ms); " << e2e.updates_not_applied << " not applied, "
        << e2e.updates_refused_without_fault << " refused without a fault; map age at the "
        << "controller p50 " << fixed(e2e.map_age_p50_ms, 1) << " ms, p99 "
        << fixed(e2e.map_age_p99_ms, 1) << " ms, worst " << fixed(e2e.map_age_max_ms, 1) << " ms; "
        << e2e.all_forbidden_frames << " all forbidden; back to back the "
        << "service takes " << fixed(e2e.service_fps, 0) << " frames/s, the controller applies "
        << fixed(e2e.sustained_fps, 0) << " maps/s\n";
    return;
  }
  nlohmann::ordered_json report;
  for (const auto& named : kNamedFigures) {
    for (const auto& figure : figures) {
      if (figure.name != named.benchmark) continue;
      report[named.median_key] = figure.median_ms;
      report[named.worst_key] = figure.max_ms;
    }
  }
  for (const auto& named : kNamedCounters) {
    for (const auto& figure : figures) {
      const auto counter = figure.counters.find(named.counter);
      if (figure.name == named.benchmark && counter != figure.counters.end()) {
        report[named.key] = counter->second;
      }
    }
  }
  for (const auto& named : kNamedMicroseconds) {
    for (const auto& figure : figures) {
      if (figure.name == named.benchmark) report[named.key] = figure.median_ms * 1e3;
    }
  }
  // The safety CRC's throughput over a full frame's bytes, from its median time.
  for (const auto& figure : figures) {
    const auto bytes = figure.counters.find("bytes");
    if (figure.name == "safety_crc32_full_frame" && bytes != figure.counters.end() &&
        figure.median_ms > 0.0) {
      report["crc_mb_s"] = bytes->second / (figure.median_ms * 1e-3) / 1e6;
    }
  }
  // The ratio the fusion target is stated in: baseline time over fast time, in the same run.
  if (report.contains("fusion_ms") && report.contains("fusion_baseline_ms") &&
      report["fusion_ms"].get<double>() > 0.0) {
    report["fusion_speedup"] =
        report["fusion_baseline_ms"].get<double>() / report["fusion_ms"].get<double>();
  }
  nlohmann::ordered_json all = nlohmann::ordered_json::object();
  for (const auto& figure : figures) {
    all[figure.name] = {{"median_ms", figure.median_ms},
                        {"worst_ms", figure.max_ms},
                        {"counters", figure.counters}};
  }
  const nlohmann::ordered_json controller = controller_figures(options.quick, progress);
  for (auto figure = controller.begin(); figure != controller.end(); ++figure) {
    report[figure.key()] = figure.value();
  }
  report["e2e_frames"] = e2e.frames;
  report["e2e_latency_p50_ms"] = e2e.latency_p50_ms;
  report["e2e_latency_p99_ms"] = e2e.latency_p99_ms;
  report["e2e_latency_max_ms"] = e2e.latency_max_ms;
  report["e2e_to_sent_p50_ms"] = e2e.to_sent_p50_ms;
  report["e2e_to_sent_p99_ms"] = e2e.to_sent_p99_ms;
  report["e2e_features_p50_ms"] = e2e.features_p50_ms;
  report["e2e_fusion_p50_ms"] = e2e.fusion_p50_ms;
  report["e2e_rest_p50_ms"] = e2e.rest_p50_ms;
  report["e2e_sent_to_applied_min_ms"] = e2e.sent_to_applied_min_ms;
  report["e2e_clock_uncertainty_max_ms"] = e2e.clock_uncertainty_max_ms;
  report["e2e_updates_not_applied"] = e2e.updates_not_applied;
  report["e2e_updates_refused_without_fault"] = e2e.updates_refused_without_fault;
  report["e2e_map_age_p50_ms"] = e2e.map_age_p50_ms;
  report["e2e_map_age_p99_ms"] = e2e.map_age_p99_ms;
  report["e2e_map_age_max_ms"] = e2e.map_age_max_ms;
  report["e2e_all_forbidden_frames"] = e2e.all_forbidden_frames;
  report["service_fps"] = e2e.service_fps;
  report["sustained_fps"] = e2e.sustained_fps;
  report["repetitions"] = run.repetitions;
  report["benchmarks"] = std::move(all);
  out << report.dump(2) << '\n';
}

void add_bench_command(CLI::App& app, CommandLine& line) {
  const auto bench = std::make_shared<BenchOptions>();
  CLI::App* bench_command = app.add_subcommand(
      "bench", "Run the project's benchmarks on the default cell (median and worst case)");
  bench_command->add_flag("--json", bench->json, "Print one JSON object instead of a table");
  bench_command->add_flag("--quick", bench->quick, "Short runs: a smoke test, not a measurement");
  bench_command->add_option(
      "--cell", bench->cell_path,
      "Instead of the benchmarks: the fusion on this cell file's grid (such as a finer max-move) "
      "against the default cell's, over the same frames of the demo; its tables come from the "
      "cache (built first, with a progress bar, when missing)");
  bench_command->add_option("--baseline-cell", bench->baseline_cell_path,
                            "The cell --cell is compared with; without it the built-in default "
                            "cell");
  bench_command->add_option("--frames", bench->frames, "Frames of the demo --cell runs")
      ->capture_default_str();
  bench_command->add_option("--lut-cache", bench->lut_cache,
                            "Folder of the tables --cell uses; without it the cache folder");
  bench_command->callback(
      [=, &line] { line.action = [=, &line] { run_bench(*bench, line.out, line.err); }; });
}

}  // namespace safecell
