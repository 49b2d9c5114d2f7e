#include "safecell/cli/luts_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <random>
#include <stdexcept>
#include <vector>

#include "command_line.hpp"
#include "lut_loading.hpp"
#include "progress_bar.hpp"
#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_grid.hpp"
#include "safecell/cell/cell_model.hpp"
#include "safecell/cli/cli_app.hpp"
#include "safecell/cli/text_table.hpp"
#include "safecell/errors/input_error.hpp"
#include "safecell/lut_build/pixel_table_check.hpp"
#include "safecell/lut_files/lut_cache.hpp"
#include "safecell/lut_files/lut_file.hpp"
#include "safecell/silhouettes/model_silhouettes.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;

// The paper's figure for its uncompressed tables: about 50 MB per camera (§5).
constexpr double kPaperBytesPerCamera = 50e6;

const char* const kStageNames[kLutBuildStages] = {"LUT-1 silhouettes", "LUT-2 inversion",
                                                  "static obstacles"};
// The same stages as keys of the JSON report's stage_s.
const char* const kStageKeys[kLutBuildStages] = {"lut1_silhouettes", "lut2_inversion",
                                                 "static_obstacles"};

std::string megabytes(std::uint64_t bytes) { return fixed(static_cast<double>(bytes) / 1e6, 2); }

std::vector<fs::path> lut_files_in(const fs::path& path) {
  if (!fs::is_directory(path)) return {path};
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(path)) {
    if (entry.is_regular_file() && entry.path().extension() == ".sclut")
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    throw InputError("folder '" + path.string() + "' holds no LUT file (*.sclut)");
  }
  return files;
}

nlohmann::ordered_json summary_json(const fs::path& path, const LutFileSummary& summary) {
  const std::size_t pixels =
      static_cast<std::size_t>(summary.columns) * static_cast<std::size_t>(summary.rows);
  nlohmann::ordered_json cameras = nlohmann::ordered_json::array();
  std::uint64_t stored = 0;
  std::uint64_t uncompressed = 0;
  for (const auto& camera : summary.cameras) {
    const std::uint64_t camera_stored = camera.cell_table_bytes + camera.pixel_table_bytes;
    const std::uint64_t camera_uncompressed =
        uncompressed_bytes(camera.covered_pairs, summary.cell_count, pixels);
    stored += camera_stored;
    uncompressed += camera_uncompressed;
    cameras.push_back({{"name", camera.name},
                       {"lut1_bytes", camera.cell_table_bytes},
                       {"lut2_bytes", camera.pixel_table_bytes},
                       {"lut2_block_bytes", camera.block_table_bytes},
                       {"lut2_block_levels", camera.block_levels},
                       {"lut2_strips", camera.strips},
                       {"covered_pairs", camera.covered_pairs},
                       {"uncompressed_bytes", camera_uncompressed},
                       {"compression_ratio",
                        static_cast<double>(camera_uncompressed) /
                            static_cast<double>(std::max<std::uint64_t>(camera_stored, 1))}});
  }
  const double camera_count = std::max<double>(1.0, static_cast<double>(summary.cameras.size()));
  nlohmann::ordered_json report;
  report["file"] = path.string();
  report["format_version"] = summary.version;
  report["source"] = to_string(summary.source);
  report["fingerprint"] = hex64(summary.fingerprint);
  report["grid_fingerprint"] = hex64(summary.grid_fingerprint);
  report["cells"] = summary.cell_count;
  report["feature_grid"] = {summary.columns, summary.rows};
  report["file_bytes"] = summary.file_bytes;
  nlohmann::ordered_json parts = nlohmann::ordered_json::array();
  for (const RobotPart& part : summary.parts) {
    parts.push_back({{"name", part.name}, {"bodies", {part.first_body, part.end_body}}});
  }
  report["robot_parts"] = std::move(parts);
  report["bytes_per_camera"] = static_cast<double>(stored) / camera_count;
  report["uncompressed_bytes_per_camera"] = static_cast<double>(uncompressed) / camera_count;
  report["paper_bytes_per_camera"] = kPaperBytesPerCamera;
  report["compression_ratio"] =
      static_cast<double>(uncompressed) / static_cast<double>(std::max<std::uint64_t>(stored, 1));
  report["cameras"] = std::move(cameras);
  return report;
}

void print_summary(const nlohmann::ordered_json& report, std::ostream& out) {
  out << "LUT file " << report["file"].get<std::string>() << " (format "
      << report["format_version"].get<int>() << ", " << report["source"].get<std::string>()
      << " mode)\n"
      << "  fingerprint " << report["fingerprint"].get<std::string>() << ", grid "
      << report["grid_fingerprint"].get<std::string>() << "\n"
      << "  " << grouped(report["cells"].get<unsigned long long>()) << " C-space cells, "
      << report["feature_grid"][0].get<int>() << " x " << report["feature_grid"][1].get<int>()
      << " feature cells, " << report["cameras"].size() << " cameras, "
      << megabytes(report["file_bytes"].get<std::uint64_t>()) << " MB on disk\n"
      << "  LUT-2 per robot part (the cameras vote per part):";
  for (const auto& part : report["robot_parts"]) {
    out << " " << part["name"].get<std::string>() << " [bodies "
        << part["bodies"][0].get<std::size_t>() << ".." << part["bodies"][1].get<std::size_t>() - 1
        << "];";
  }
  out << "\n";
  using Align = TextTable::Align;
  TextTable table({{"camera", Align::kLeft},
                   {"LUT-1 [MB]", Align::kRight},
                   {"LUT-2 [MB]", Align::kRight},
                   {"LUT-2 strips", Align::kRight},
                   {"uncompressed [MB]", Align::kRight},
                   {"ratio", Align::kRight}});
  for (const auto& camera : report["cameras"]) {
    table.add_row({camera["name"].get<std::string>(),
                   megabytes(camera["lut1_bytes"].get<std::uint64_t>()),
                   megabytes(camera["lut2_bytes"].get<std::uint64_t>()),
                   grouped(camera["lut2_strips"].get<unsigned long long>()),
                   megabytes(camera["uncompressed_bytes"].get<std::uint64_t>()),
                   fixed(camera["compression_ratio"].get<double>(), 1) + "x"});
  }
  table.print(out);
  out << "  per camera: " << fixed(report["bytes_per_camera"].get<double>() / 1e6, 2)
      << " MB stored, " << fixed(report["uncompressed_bytes_per_camera"].get<double>() / 1e6, 1)
      << " MB uncompressed, the paper's about "
      << fixed(report["paper_bytes_per_camera"].get<double>() / 1e6, 0) << " MB\n";
  if (report["source"] == "model") {
    out << "  (model mode: LUT-1 is computed from the robot model for the robot's cell each "
           "cycle, so the file holds LUT-2 and the static obstacles)\n";
  }
}

// Compares the tables with the silhouettes of `verify_cells` sampled cells; the report's
// "verified" field. Returns whether they agree.
bool verify_tables(const LutsBuildOptions& options, const CellModel& cell, const CspaceGrid& grid,
                   const ModelLutOptions& lut_options, const LutSet& luts, ProgressBar& bar,
                   nlohmann::ordered_json& report) {
  std::mt19937_64 rng(options.seed);
  std::uniform_int_distribution<CellIndex> any_cell(0, grid.cell_count() - 1);
  std::vector<CellIndex> sample(options.verify_cells);
  for (CellIndex& index : sample) index = any_cell(rng);
  const ModelSilhouettes silhouettes(cell, grid, lut_options);
  const auto started = std::chrono::steady_clock::now();
  const PixelTableCheck check =
      check_pixel_tables(luts, silhouettes, std::move(sample), lut_options.threads,
                         [&bar](double fraction) { bar.update("verifying LUT-2", fraction); });
  bar.finish();
  nlohmann::ordered_json first = nlohmann::ordered_json::array();
  for (const PixelTableMismatch& mismatch : check.first_mismatches) {
    first.push_back(describe(mismatch, luts));
  }
  report["verified"] = {
      {"cells", check.cells},
      {"seed", options.seed},
      {"entries", check.entries},
      {"pairs", check.pairs},
      {"mismatches", check.mismatches},
      {"first_mismatches", std::move(first)},
      {"seconds",
       std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count()}};
  return check.passed();
}

void print_verification(const nlohmann::ordered_json& verified, std::ostream& out) {
  out << "verified against the silhouettes computed directly: "
      << grouped(verified["cells"].get<unsigned long long>()) << " cells (seed "
      << verified["seed"].get<std::uint64_t>() << "), "
      << grouped(verified["entries"].get<unsigned long long>()) << " entries, "
      << grouped(verified["pairs"].get<unsigned long long>())
      << " pairs: " << grouped(verified["mismatches"].get<unsigned long long>()) << " mismatches ("
      << fixed(verified["seconds"].get<double>(), 1) << " s)\n";
  for (const auto& line : verified["first_mismatches"]) {
    out << "  " << line.get<std::string>() << "\n";
  }
}

}  // namespace

int run_luts_build(const LutsBuildOptions& options, std::ostream& out, std::ostream& err) {
  const CellModel loaded = load_cell_model(load_cell_file_or_default(options.cell_path));
  const CspaceGrid grid = make_grid(loaded.config);
  // The same tables as the commands that run the pipeline use, so that they find them cached.
  const CellModel cell = tables_cell(loaded, grid, err);
  ModelLutOptions lut_options;
  if (options.ball_radius_m > 0.0) lut_options.ball_radius_m = options.ball_radius_m;
  lut_options.padding_m = options.padding_m;
  lut_options.threads = options.threads;
  const fs::path folder =
      options.out_dir.empty() ? default_lut_cache_folder() : fs::path(options.out_dir);
  if (options.force) {
    std::error_code ignored;
    fs::remove(lut_cache_file(folder, model_lut_fingerprint(cell, grid, lut_options)), ignored);
  }
  ProgressBar bar(err, &err == &std::cerr && ProgressBar::stderr_is_terminal());
  // Where the build's time goes: the time up to each progress report (from this thread; at most
  // 0.1 s apart in LUT-1 and the static obstacles, once per band of feature rows in LUT-2) counts
  // to the stage it reports on. The stages take turns, one robot part at a time.
  std::array<double, kLutBuildStages> stage_s{};
  auto last_report = std::chrono::steady_clock::now();
  const CachedLuts luts = model_luts_cached(
      cell, grid, lut_options, folder,
      [&](int stage, double fraction) {
        const auto now = std::chrono::steady_clock::now();
        stage_s.at(static_cast<std::size_t>(stage)) +=
            std::chrono::duration<double>(now - last_report).count();
        last_report = now;
        bar.update(kStageNames[stage], fraction);
      },
      [&err, &cell, &last_report](const LutBuildEstimate& estimate) {
        err << build_estimate_line(estimate, cell.cameras.size()) << '\n';
        last_report = std::chrono::steady_clock::now();  // the build's clock starts now
      });
  bar.finish();
  if (!luts.note.empty()) err << luts.note << '\n';
  nlohmann::ordered_json report = summary_json(luts.file, read_lut_file_summary(luts.file));
  report["built"] = luts.built;
  report["build_s"] = luts.build_s;
  if (luts.built) {
    report["estimate"] = {{"seconds", luts.estimate.seconds},
                          {"peak_bytes", luts.estimate.peak_bytes},
                          {"threads", luts.estimate.threads},
                          {"drawn_cells", luts.estimate.drawn_cells},
                          {"sampled_cells", luts.estimate.sampled_cells}};
  }
  if (luts.built) {
    for (int stage = 0; stage < kLutBuildStages; ++stage) {
      report["stage_s"][kStageKeys[stage]] = stage_s.at(static_cast<std::size_t>(stage));
    }
  }
  const bool agree = options.verify_cells == 0 ||
                     verify_tables(options, cell, grid, lut_options, luts.set, bar, report);
  const int exit_code = agree ? 0 : 1;
  if (options.json) {
    out << report.dump(2) << '\n';
    return exit_code;
  }
  if (luts.built) {
    out << "built in " + fixed(luts.build_s, 1) + " s (";
    for (int stage = 0; stage < kLutBuildStages; ++stage) {
      out << (stage > 0 ? ", " : "") << kStageNames[stage] << ' '
          << fixed(stage_s.at(static_cast<std::size_t>(stage)), 1) << " s";
    }
    out << "): ";
  } else {
    out << "already built (use --force to build again): ";
  }
  out << luts.file.string() << "\n";
  print_summary(report, out);
  if (report.contains("verified")) print_verification(report["verified"], out);
  return exit_code;
}

int run_luts_info(const LutsInfoOptions& options, std::ostream& out, std::ostream& err) {
  const bool folder = fs::is_directory(options.path);
  nlohmann::ordered_json reports = nlohmann::ordered_json::array();
  std::size_t refused = 0;
  for (const auto& file : lut_files_in(options.path)) {
    LutFileSummary summary;
    try {
      summary = read_lut_file_summary(file);
    } catch (const LutFileError& error) {
      if (!folder) throw;
      err << "skipped: " << error.what() << '\n';
      ++refused;
      continue;
    }
    reports.push_back(summary_json(file, summary));
  }
  if (reports.empty()) {
    throw InputError("folder '" + options.path + "' holds no usable LUT file");
  }
  if (options.json) {
    out << (reports.size() == 1 ? reports[0] : reports).dump(2) << '\n';
  } else {
    for (const auto& report : reports) print_summary(report, out);
  }
  return refused > 0 ? kExitBadInput : 0;
}

void add_luts_build_and_info_commands(CLI::App& luts, CommandLine& line) {
  const auto build = std::make_shared<LutsBuildOptions>();
  // The padding the service's tables are built with (run, replay and the demo look them up).
  build->padding_m = ModelLutOptions{}.padding_m;
  CLI::App* build_command = luts.add_subcommand(
      "build",
      "Build the tables of a cell from its robot model and camera calibrations (model mode) into "
      "a folder, one file per fingerprint; a file already there is kept");
  build_command->add_option("--cell", build->cell_path,
                            "Cell file (YAML); without it the built-in default cell");
  build_command->add_option("--out", build->out_dir,
                            "Folder for the LUT file; without it the cache folder "
                            "($SAFECELL_CACHE or ~/.cache/safecell)");
  build_command
      ->add_option("--ball-radius", build->ball_radius_m,
                   "Size of the balls covering the robot, metres (default: the cell's)")
      ->check(CLI::Range(kMinBallRadius_m, kMaxBallRadius_m));
  build_command
      ->add_option("--padding", build->padding_m,
                   "Margin added all round the robot, metres (calibration error)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  build_command->add_option("--threads", build->threads, "Worker threads; 0: one per core")
      ->capture_default_str();
  build_command->add_flag("--force", build->force, "Build again even when the file exists");
  build_command->add_flag("--json", build->json, "Print one JSON object instead of a table");
  build_command
      ->add_option("--verify-cells", build->verify_cells,
                   "After the build, compare the tables with the silhouettes of this many random "
                   "C-space cells computed directly from the model (every feature cell, block and "
                   "difference entry); exit 1 on a mismatch")
      ->capture_default_str()
      ->check(CLI::Range(0U, 100000U));
  build_command->add_option("--seed", build->seed, "Seed of the cells --verify-cells samples")
      ->capture_default_str();
  build_command->callback([=, &line] {
    line.action = [=, &line] { line.exit_code = run_luts_build(*build, line.out, line.err); };
  });
  const auto lut_info = std::make_shared<LutsInfoOptions>();
  CLI::App* info_command = luts.add_subcommand(
      "info", "What a LUT file holds: sizes per camera, compression, cells, fingerprint");
  info_command->add_option("path", lut_info->path, "A LUT file (*.sclut) or a folder of them")
      ->required();
  info_command->add_flag("--json", lut_info->json, "Print JSON instead of a table");
  info_command->callback([=, &line] {
    line.action = [=, &line] { line.exit_code = run_luts_info(*lut_info, line.out, line.err); };
  });
}

}  // namespace safecell
