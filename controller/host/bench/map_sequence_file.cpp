#include "map_sequence_file.hpp"

#include <cstring>
#include <fstream>
#include <stdexcept>

#include "safecell/cspace/cell_bits.hpp"
#include "safecell/cspace/cspace_grid.hpp"

namespace safecell {
namespace {

constexpr char kMagic[8] = {'S', 'C', 'M', 'A', 'P', 'S', '1', '\0'};

template <typename T>
T get(std::ifstream& in, const std::string& path) {
  T value{};
  if (!in.read(reinterpret_cast<char*>(&value), sizeof value)) {
    throw std::runtime_error(path + ": map sequence file ends early");
  }
  return value;
}

}  // namespace

MapSequence read_map_sequence(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot be read");
  char magic[8];
  if (!in.read(magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof magic) != 0) {
    throw std::runtime_error(path + ": not a safecell map sequence (magic SCMAPS1)");
  }
  MapSequence sequence;
  sequence.grid.m_max_m = get<double>(in, path);
  sequence.grid.joint_count = get<std::uint32_t>(in, path);
  if (sequence.grid.joint_count == 0 || sequence.grid.joint_count > kMaxJoints) {
    throw std::runtime_error(path + ": joint count outside 1.." + std::to_string(kMaxJoints));
  }
  for (std::uint32_t j = 0; j < sequence.grid.joint_count; ++j) {
    JointSpec& joint = sequence.grid.joints[j];
    joint.lo_rad = get<double>(in, path);
    joint.hi_rad = get<double>(in, path);
    joint.l_m = get<double>(in, path);
    joint.discretised = get<std::uint8_t>(in, path) != 0;
  }
  const auto grid = CspaceGrid::create(sequence.grid);
  if (!grid.ok()) throw std::runtime_error(path + ": the grid is refused");
  const auto map_count = get<std::uint32_t>(in, path);
  sequence.cell_count = get<std::uint32_t>(in, path);
  if (sequence.cell_count != grid.value().cell_count() || map_count == 0 || map_count > 100000) {
    throw std::runtime_error(path + ": cell count or map count does not fit the grid");
  }
  const std::uint32_t words = cell_bits::words_for(sequence.cell_count);
  for (std::uint32_t m = 0; m < map_count; ++m) {
    std::vector<std::uint64_t> map(words);
    for (std::uint64_t& word : map) word = get<std::uint64_t>(in, path);
    sequence.maps.push_back(std::move(map));
  }
  return sequence;
}

}  // namespace safecell
