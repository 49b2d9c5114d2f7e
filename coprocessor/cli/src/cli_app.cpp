#include "safecell/cli/cli_app.hpp"

#include <CLI/CLI.hpp>
#include <functional>

#include "safecell/cell/cell_error.hpp"
#include "safecell/cli/cell_info_command.hpp"

namespace safecell {
namespace {

constexpr const char* kDescription =
    "safecell: cameras watch a robot cell; a coprocessor turns every set of frames into the\n"
    "robot configurations that are forbidden right now, and the controller core slows or stops\n"
    "the robot before it reaches one.";

}  // namespace

int run_safecell(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App app{kDescription, "safecell"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "safecell 0.1.0");
  std::function<void()> action;

  CLI::App* cell = app.add_subcommand("cell", "Inspect a cell description");
  cell->require_subcommand(1);
  CellInfoOptions cell_info;
  CLI::App* info = cell->add_subcommand(
      "info", "Show the C-space grid of a cell: per joint range, l_i, dq_i and cell count");
  info->add_option("--cell", cell_info.cell_path,
                   "Cell file (YAML); without it the built-in default cell of the paper");
  info->add_flag("--json", cell_info.json, "Print one JSON object instead of a table");
  info->callback([&] { action = [&] { run_cell_info(cell_info, out); }; });

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error, out, err);
  }
  try {
    action();
    return 0;
  } catch (const CellError& error) {
    err << "error: " << error.what() << '\n';
    return kExitBadInput;
  } catch (const std::exception& error) {
    err << "internal error: " << error.what() << '\n';
    return kExitInternalError;
  }
}

}  // namespace safecell
