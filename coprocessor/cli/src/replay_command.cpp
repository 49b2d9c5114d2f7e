#include "safecell/cli/replay_command.hpp"

#include <CLI/CLI.hpp>
#include <bit>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "camera_reference.hpp"
#include "command_line.hpp"
#include "cspace_pictures.hpp"
#include "demo_report.hpp"
#include "lut_loading.hpp"
#include "png_output.hpp"
#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_grid.hpp"
#include "safecell/cell/default_cell.hpp"
#include "safecell/cli/text_table.hpp"
#include "safecell/closed_loop/report_page.hpp"
#include "safecell/closed_loop/timeline_plot.hpp"
#include "safecell/errors/input_error.hpp"
#include "safecell/files/atomic_write.hpp"
#include "safecell/files/read_file.hpp"
#include "safecell/pipeline/sensing_pipeline.hpp"
#include "safecell/service/incident_folder.hpp"
#include "safecell/silhouettes/model_silhouettes.hpp"
#include "service_setup.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;

// The replay must run on what the service ran with, or its maps mean nothing: first the cell
// file's text (before it is loaded, so a file that moved is named as such).
// An empty path: the built-in default cell (the demo's without --cell).
void check_cell_text(const Incident& incident, const fs::path& cell_path) {
  const std::string text = cell_path.empty()
                               ? std::string(default_cell_yaml())
                               : read_file(cell_path,
                                           ": the cell file the incident was recorded with; "
                                           "give it as --cell if it has moved");
  if (text != incident.setup.cell_text) {
    throw InputError(cell_path.string() +
                     " is not the cell file the incident was recorded with (its text "
                     "is in the incident's cell.yaml); give that one as --cell");
  }
}

// Then what the cell makes of it: the cameras, the grid.
void check_setup(const Incident& incident, const fs::path& cell_path, const CellModel& cell,
                 const CspaceGrid& grid) {
  std::vector<std::string> names;
  for (const PinholeCamera& camera : cell.cameras) names.push_back(camera.name());
  if (names != incident.cameras) {
    throw InputError(cell_path.string() + ": its cameras are not the incident's");
  }
  if (grid.fingerprint() != incident.setup.grid_fingerprint) {
    throw InputError(cell_path.string() + ": grid fingerprint " +
                     fingerprint_hex(grid.fingerprint()) + ", the incident was recorded with " +
                     fingerprint_hex(incident.setup.grid_fingerprint) +
                     " (a file the cell names has changed: the robot?)");
  }
}

std::size_t differing_cells(const CellSet& a, const CellSet& b) {
  std::size_t count = 0;
  for (std::size_t w = 0; w < a.words().size(); ++w) {
    count += static_cast<std::size_t>(std::popcount(a.words()[w] ^ b.words()[w]));
  }
  return count;
}

// The controller's joint stream and the maps sent, as the demo's timeline draws them.
ClosedLoopRecord incident_record(const Incident& incident) {
  ClosedLoopRecord record;
  for (const IncidentJointState& joint : incident.joints) {
    JointRecord sample;
    sample.time_s = joint.time_s;
    sample.q = joint.q;
    sample.velocity = joint.velocity;
    sample.state = state_named(joint.state).value_or(v1::CONTROLLER_STATE_UNSPECIFIED);
    sample.speed_scale = joint.speed_scale;
    record.joints.push_back(std::move(sample));
  }
  for (const IncidentCycle& cycle : incident.cycles) {
    CycleRecord entry;
    entry.exposure_s = cycle.exposure_s;
    entry.forbidden_cells = cycle.forbidden_cells;
    entry.all_forbidden = cycle.all_forbidden;
    record.cycles.push_back(std::move(entry));
  }
  return record;
}

struct ReplayedCycle {
  std::uint64_t cycle = 0;
  double exposure_s = 0.0;
  std::string outcome;  // "identical", "differs", "all forbidden as sent", ...
  std::size_t differing_cells = 0;
};

}  // namespace

int run_replay(const ReplayOptions& options, std::ostream& out, std::ostream& err) {
  const fs::path folder(options.incident_dir);
  const Incident incident = read_incident(folder);
  const fs::path cell_path =
      options.cell_path.empty() ? incident.setup.cell_file : fs::path(options.cell_path);
  check_cell_text(incident, cell_path);
  const CellModel cell = load_cell_model(load_cell_file_or_default(cell_path.string()));
  const CspaceGrid grid = make_grid(cell.config);
  check_setup(incident, cell_path, cell, grid);
  const CachedLuts luts = cell_luts(cell, grid, ModelLutOptions{}, options.lut_cache, err);
  if (luts.set.fingerprint != incident.setup.lut_fingerprint) {
    throw InputError("the tables for " + cell_path.string() + " have fingerprint " +
                     fingerprint_hex(luts.set.fingerprint) + ", the incident was recorded with " +
                     fingerprint_hex(incident.setup.lut_fingerprint));
  }
  const ModelSilhouettes silhouettes(cell, grid, ModelLutOptions{}, CellDrawing::kWholeCells);
  const std::vector<cv::Mat> reference = read_reference_images(folder / "reference", cell);
  SensingPipeline pipeline(cell, grid, luts.set, silhouettes, reference, {},
                           service_fusion_settings(cell, incident.setup.sync_error_s));
  const fs::path out_dir = options.out_dir.empty() ? folder / "replay" : fs::path(options.out_dir);
  fs::create_directories(out_dir);

  // The cycle the pictures show: of those the pipeline ran on, the first exposed at or after the
  // trigger, else the last before it.
  std::optional<std::size_t> shown;
  for (std::size_t i = 0; i < incident.cycles.size(); ++i) {
    if (!incident.cycles[i].all_forbidden.empty()) continue;
    shown = i;
    if (incident.cycles[i].exposure_s >= incident.trigger_s) break;
  }
  std::vector<ReplayedCycle> replayed;
  std::vector<CellIndex> path;
  std::vector<ReportPicture> pictures;
  std::size_t differing = 0;
  for (std::size_t i = 0; i < incident.cycles.size(); ++i) {
    const IncidentCycle& cycle = incident.cycles[i];
    const CellSet sent = read_incident_map(folder, cycle, grid.cell_count());
    ReplayedCycle result{cycle.index, cycle.exposure_s, "identical", 0};
    if (!cycle.all_forbidden.empty()) {
      // The service sent all forbidden without a map of the pipeline's: nothing to run again.
      result.outcome = "all forbidden as sent (" + cycle.all_forbidden + ")";
      result.differing_cells = grid.cell_count() - sent.count();
    } else {
      const FrameSet frames = incident_frame_set(folder, incident, cycle);
      try {
        const CellSet& map = pipeline.process(frames, cycle.q);
        result.differing_cells = differing_cells(map, sent);
        path.push_back(pipeline.robot_cell());
        if (i == shown) {
          std::vector<cv::Mat> images;
          for (std::size_t c = 0; c < frames.frames.size(); ++c) {
            const cv::Mat& image = frames.frames[c].image;
            images.push_back(image.empty() ? cv::Mat(reference[c].size(), CV_8UC1, cv::Scalar(0))
                                           : image);
          }
          write_png(out_dir / "views.png", demo_views_picture(images, pipeline, cell, "replayed"));
          pictures.push_back({"views.png", "The cameras at cycle " + std::to_string(cycle.index) +
                                               ": what they saw, the robot removed"});
          write_png(out_dir / "slice_j1_j2.png",
                    forbidden_slice(grid, map, luts.set.static_cells, pipeline.robot_cell(), 0, 1,
                                    "joints 1 x 2 at cycle " + std::to_string(cycle.index), path));
          pictures.push_back({"slice_j1_j2.png",
                              "The forbidden map replayed, joints 1 x 2, "
                              "with the robot's path up to then"});
        }
      } catch (const std::out_of_range& error) {
        result.outcome = std::string("refused by the pipeline: ") + error.what();
        result.differing_cells = grid.cell_count() - sent.count();
      }
    }
    if (result.differing_cells != 0) {
      result.outcome = "differs in " + std::to_string(result.differing_cells) + " cells";
      ++differing;
      err << "cycle " << cycle.index << ": the replayed map " << result.outcome << '\n';
    }
    replayed.push_back(result);
  }

  // The forbidden share of the maps sent, and the incident's seconds after its trigger shaded.
  TimelineCurve forbidden{"C-space forbidden by the maps sent", "%", {}, {}};
  for (const IncidentCycle& cycle : incident.cycles) {
    forbidden.time_s.push_back(cycle.exposure_s);
    forbidden.values.push_back(100.0 * static_cast<double>(cycle.forbidden_cells) /
                               static_cast<double>(grid.cell_count()));
  }
  const double begin_s =
      incident.cycles.empty() ? incident.trigger_s - 1.0 : incident.cycles.front().exposure_s;
  const double end_s = incident.joints.empty() ? incident.trigger_s : incident.joints.back().time_s;
  write_png(out_dir / "timeline.png", timeline_plot(incident_record(incident), forbidden,
                                                    {incident.trigger_s, end_s}, begin_s));
  pictures.push_back({"timeline.png", "The controller's joint stream around the incident"});

  nlohmann::ordered_json summary;
  summary["incident"] = fs::absolute(folder).string();
  summary["causes"] = incident.causes;
  summary["trigger_s"] = incident.trigger_s;
  summary["cycles"] = incident.cycles.size();
  summary["cycles_differing"] = differing;
  summary["per_cycle"] = nlohmann::ordered_json::array();
  for (const ReplayedCycle& result : replayed) {
    summary["per_cycle"].push_back({{"cycle", result.cycle},
                                    {"exposure_s", result.exposure_s},
                                    {"outcome", result.outcome},
                                    {"differing_cells", result.differing_cells}});
  }
  write_file_atomically(out_dir / "replay.json", summary.dump(2) + "\n");

  ReportPage page;
  page.title = "safecell replay: " + folder.filename().string();
  page.passed = differing == 0;
  page.verdict = differing == 0
                     ? "Every replayed map equals the map the service sent."
                     : std::to_string(differing) + " of " + std::to_string(incident.cycles.size()) +
                           " replayed maps differ from those sent.";
  std::string causes;
  for (const std::string& cause : incident.causes) causes += (causes.empty() ? "" : "; ") + cause;
  page.story = "The incident began at " + fixed(incident.trigger_s, 2) + " s: " + causes + ".";
  page.figures = {{"cycles", std::to_string(incident.cycles.size())},
                  {"cycles differing", std::to_string(differing)},
                  {"joint states", std::to_string(incident.joints.size())}};
  page.pictures = pictures;
  write_file_atomically(out_dir / "index.html", report_page_html(page));

  out << "replayed " << incident.cycles.size() << " cycles of " << folder.string() << ": "
      << (differing == 0 ? "every map as sent" : std::to_string(differing) + " differ")
      << "; report " << (out_dir / "index.html").string() << '\n';
  return differing == 0 ? 0 : 1;
}

void add_replay_command(CLI::App& app, CommandLine& line) {
  const auto replay = std::make_shared<ReplayOptions>();
  CLI::App* replay_command = app.add_subcommand(
      "replay",
      "Run the sensing pipeline again on an incident folder that safecell run recorded: every "
      "cycle's recorded frames and robot pose give a forbidden map, compared bit for bit with "
      "the map sent then; the report (cameras, C-space slice, timeline, index.html) goes into "
      "<incident>/replay. Exit 1 when a map differs");
  replay_command->add_option("incident", replay->incident_dir, "The incident folder")
      ->required()
      ->check(CLI::ExistingDirectory);
  replay_command->add_option("--cell", replay->cell_path,
                             "The cell file (default: the one the incident names; its text must "
                             "be the recorded one)");
  replay_command->add_option("--lut-cache", replay->lut_cache,
                             "Folder of cached look-up tables; default $SAFECELL_CACHE or "
                             "~/.cache/safecell");
  replay_command->add_option("--out", replay->out_dir,
                             "Folder for the report (default: <incident>/replay)");
  replay_command->callback([=, &line] {
    line.action = [=, &line] { line.exit_code = run_replay(*replay, line.out, line.err); };
  });
}

}  // namespace safecell
