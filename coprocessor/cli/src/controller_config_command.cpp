#include "safecell/cli/controller_config_command.hpp"

#include <CLI/CLI.hpp>
#include <iomanip>
#include <memory>
#include <sstream>

#include "command_line.hpp"
#include "lut_loading.hpp"
#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_grid.hpp"
#include "safecell/closed_loop/controller_setup.hpp"
#include "safecell/files/atomic_write.hpp"
#include "udp_address.hpp"

namespace safecell {

void run_controller_config(const ControllerConfigOptions& options, std::ostream& out,
                           std::ostream& err) {
  const UdpEndpoint listen = udp_address("--listen", options.listen, 1);
  const UdpEndpoint coprocessor = udp_address("--coprocessor", options.coprocessor, 1);
  const CellModel cell = load_cell_model(load_cell_file_or_default(options.cell_path));
  const CspaceGrid grid = make_grid(cell.config);
  const CachedLuts luts = cell_luts(cell, grid, ModelLutOptions{}, options.lut_cache, err);

  ControllerSetup setup = controller_setup_of(cell, grid);
  setup.start_rad = inside_grid(grid, std::vector<double>(grid.joint_count(), 0.0));
  setup.listen_address = listen.address;
  setup.listen_port = listen.port;
  setup.coprocessor_address = coprocessor.address;
  setup.coprocessor_port = coprocessor.port;
  setup.lut_fingerprint = luts.set.fingerprint;
  write_file_atomically(options.out, controller_config_yaml(grid, setup));
  std::ostringstream fingerprints;
  fingerprints << std::hex << std::setfill('0') << "grid " << std::setw(16) << grid.fingerprint()
               << ", LUTs " << std::setw(16) << luts.set.fingerprint;
  out << "wrote " << options.out << " for '" << cell.config.name << "' (" << fingerprints.str()
      << "); link " << options.listen << " <- " << options.coprocessor
      << ". Its robot, timing and task sections are the simulated robot's: set your robot's.\n";
}

void add_controller_config_command(CLI::App& controller, CommandLine& line) {
  const auto controller_config = std::make_shared<ControllerConfigOptions>();
  CLI::App* config_command = controller.add_subcommand(
      "config",
      "Write a safecell-controller configuration for a cell: its grid to the last bit, the LUT "
      "fingerprint of its tables, the link's addresses; the robot, timing and task sections are "
      "the simulated robot's, to be set for a real one");
  config_command->add_option("--cell", controller_config->cell_path,
                             "Cell file (YAML); without it the built-in default cell");
  config_command->add_option("--lut-cache", controller_config->lut_cache,
                             "Folder of cached look-up tables; default $SAFECELL_CACHE or "
                             "~/.cache/safecell");
  config_command
      ->add_option("--listen", controller_config->listen,
                   "The controller's UDP address, HOST:PORT (safecell run's --controller)")
      ->capture_default_str();
  config_command
      ->add_option("--coprocessor", controller_config->coprocessor,
                   "The coprocessor's UDP address, HOST:PORT (safecell run's --listen)")
      ->capture_default_str();
  config_command->add_option("--out", controller_config->out, "The file to write")
      ->capture_default_str();
  config_command->callback([=, &line] {
    line.action = [=, &line] { run_controller_config(*controller_config, line.out, line.err); };
  });
}

}  // namespace safecell
