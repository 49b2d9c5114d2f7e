#include "safecell/cli/controller_config_command.hpp"

#include <iomanip>
#include <sstream>

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

  ControllerSetup setup;
  setup.joints = comfortable_joint_limits(*cell.robot, grid);
  setup.start_rad = inside_grid(grid, std::vector<double>(grid.joint_count(), 0.0));
  setup.min_healthy_cameras = static_cast<std::uint32_t>(cell.camera_threshold);
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

}  // namespace safecell
