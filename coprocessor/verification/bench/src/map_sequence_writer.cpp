#include "safecell/bench/map_sequence_writer.hpp"

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "default_cell_tables.hpp"

namespace safecell {
namespace {

template <typename T>
void put(std::ofstream& out, T value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof value);  // little-endian hosts only
}

}  // namespace

void write_map_sequence_file(const std::string& path, const CspaceGrid& grid,
                             const std::vector<CellSet>& maps) {
  const std::string temporary = path + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(temporary + ": cannot be written");
    const char magic[8] = {'S', 'C', 'M', 'A', 'P', 'S', '1', '\0'};
    out.write(magic, sizeof magic);
    const GridSpec& spec = grid.spec();
    put(out, spec.m_max_m);
    put(out, spec.joint_count);
    for (std::uint32_t j = 0; j < spec.joint_count; ++j) {
      put(out, spec.joints[j].lo_rad);
      put(out, spec.joints[j].hi_rad);
      put(out, spec.joints[j].l_m);
      put(out, static_cast<std::uint8_t>(spec.joints[j].discretised ? 1 : 0));
    }
    put(out, static_cast<std::uint32_t>(maps.size()));
    put(out, grid.cell_count());
    for (const CellSet& map : maps) {
      for (const std::uint64_t word : map.words()) put(out, word);
    }
    if (!out.flush()) throw std::runtime_error(temporary + ": write failed");
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    throw std::runtime_error(path + ": cannot be written (rename failed)");
  }
}

void write_default_cell_demo_maps(const std::string& path) {
  write_map_sequence_file(path, default_cell_tables().grid, default_cell_demo_maps());
}

}  // namespace safecell
