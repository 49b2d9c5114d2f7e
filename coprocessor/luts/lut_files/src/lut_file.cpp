#include "safecell/lut_files/lut_file.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <span>
#include <vector>

#include "safecell/base/crc32.hpp"
#include "safecell/files/atomic_write.hpp"

namespace safecell {
namespace {

static_assert(std::endian::native == std::endian::little,
              "LUT files are little-endian and mapped as they are");

constexpr char kMagic[8] = {'S', 'C', 'L', 'U', 'T', '\r', '\n', '\x1a'};
constexpr std::uint16_t kNoCamera = 0xFFFFU;

enum class SectionKind : std::uint32_t {
  kCameraName = 1,
  kPixelOffsets = 2,
  kPixelStrips = 3,
  kCellOffsets = 4,
  kCellRects = 5,
  kStaticCells = 6,
  kCameraStats = 7,
  kBlockOffsets = 8,
  kBlockStrips = 9,
  kLeftDifferenceOffsets = 10,  // level: 0 for the pixels, l for blocks of 2^l
  kLeftDifferenceStrips = 11,
  kUpperDifferenceOffsets = 12,  // level as for the left ones
  kUpperDifferenceStrips = 13,
  kPartBodies = 14,  // once: first and end body of every part
  kPartNames = 15,   // per part
};

// Parts a file may hold: the part number is one byte.
constexpr std::size_t kMaxParts = 255;

// The section kinds of the differences to each neighbour.
constexpr SectionKind kDifferenceOffsets[kNeighbourCount] = {SectionKind::kLeftDifferenceOffsets,
                                                             SectionKind::kUpperDifferenceOffsets};
constexpr SectionKind kDifferenceStrips[kNeighbourCount] = {SectionKind::kLeftDifferenceStrips,
                                                            SectionKind::kUpperDifferenceStrips};

// The camera statistics section: covered pairs, strips of the pixels, strips of the blocks.
constexpr std::size_t kCameraStatsWords = 3;

struct Header {
  char magic[8];
  std::uint32_t version;
  std::uint32_t header_bytes;
  std::uint64_t fingerprint;
  std::uint64_t grid_fingerprint;
  std::uint32_t source;
  std::uint32_t columns;
  std::uint32_t rows;
  std::uint32_t camera_count;
  std::uint32_t cell_count;
  std::uint32_t section_count;
  std::uint64_t section_table_offset;
  std::uint64_t file_bytes;
  std::uint32_t checksum;
  std::uint32_t reserved;
};
static_assert(sizeof(Header) == kLutHeaderBytes);
static_assert(offsetof(Header, file_bytes) == kLutFileBytesOffset);
static_assert(offsetof(Header, checksum) == kLutChecksumOffset);

struct SectionEntry {
  std::uint32_t kind;
  std::uint16_t camera;
  std::uint8_t level;  // the LUT-2 pyramid level of block and difference sections, else 0
  std::uint8_t part;   // the robot part of LUT-2 sections, statistics and part names, else 0
  std::uint64_t offset;
  std::uint64_t bytes;
};
static_assert(sizeof(SectionEntry) == 24);

// Builds the file image in memory: sections appended 8-byte aligned, then the table.
class FileImage {
 public:
  FileImage() { bytes_.resize(sizeof(Header)); }

  void add(SectionKind kind, std::uint16_t camera, const void* data, std::size_t size,
           std::uint8_t part = 0, std::uint8_t level = 0) {
    bytes_.resize((bytes_.size() + 7) & ~std::size_t{7});
    sections_.push_back(
        SectionEntry{static_cast<std::uint32_t>(kind), camera, level, part, bytes_.size(), size});
    const auto* first = static_cast<const char*>(data);
    bytes_.insert(bytes_.end(), first, first + size);
  }
  template <typename T>
  void add(SectionKind kind, std::uint16_t camera, std::span<const T> values, std::uint8_t part = 0,
           std::uint8_t level = 0) {
    add(kind, camera, values.data(), values.size_bytes(), part, level);
  }

  std::string finish(Header header) {
    bytes_.resize((bytes_.size() + 7) & ~std::size_t{7});
    header.section_count = static_cast<std::uint32_t>(sections_.size());
    header.section_table_offset = bytes_.size();
    const auto* table = reinterpret_cast<const char*>(sections_.data());
    bytes_.insert(bytes_.end(), table, table + sections_.size() * sizeof(SectionEntry));
    header.file_bytes = bytes_.size();
    header.checksum = 0;
    std::memcpy(bytes_.data(), &header, sizeof(Header));
    const std::uint32_t checksum = crc32(bytes_.data(), bytes_.size());
    std::memcpy(bytes_.data() + kLutChecksumOffset, &checksum, sizeof(checksum));
    return std::string(bytes_.begin(), bytes_.end());
  }

 private:
  std::vector<char> bytes_;
  std::vector<SectionEntry> sections_;
};

// A read-only mapping of a whole file, unmapped when the last table using it goes.
class Mapping {
 public:
  explicit Mapping(const std::filesystem::path& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw LutFileError(path, std::string("cannot open: ") + std::strerror(errno));
    struct stat info {};
    if (::fstat(fd, &info) != 0 || info.st_size < static_cast<off_t>(sizeof(Header))) {
      ::close(fd);
      throw LutFileError(
          path, "too short for a LUT file header (" + std::to_string(info.st_size) + " bytes)");
    }
    size_ = static_cast<std::size_t>(info.st_size);
    void* address = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0);
    ::close(fd);
    if (address == MAP_FAILED) {
      throw LutFileError(path, std::string("cannot map: ") + std::strerror(errno));
    }
    data_ = static_cast<const char*>(address);
  }
  ~Mapping() { ::munmap(const_cast<char*>(data_), size_); }
  Mapping(const Mapping&) = delete;
  Mapping& operator=(const Mapping&) = delete;

  [[nodiscard]] const char* data() const { return data_; }
  [[nodiscard]] std::size_t size() const { return size_; }

 private:
  const char* data_ = nullptr;
  std::size_t size_ = 0;
};

Header checked_header(const std::filesystem::path& path, const Mapping& mapping) {
  Header header{};
  std::memcpy(&header, mapping.data(), sizeof(Header));
  if (std::memcmp(header.magic, kMagic, sizeof(kMagic)) != 0) {
    throw LutFileError(path, "not a safecell LUT file (wrong magic bytes)");
  }
  if (header.version != kLutFileVersion) {
    throw LutFileError(path, "format version " + std::to_string(header.version) +
                                 ", this program reads version " + std::to_string(kLutFileVersion) +
                                 "; build the tables again");
  }
  if (header.header_bytes != sizeof(Header) || header.file_bytes != mapping.size()) {
    throw LutFileError(path, "truncated or extended: the header says " +
                                 std::to_string(header.file_bytes) + " bytes, the file has " +
                                 std::to_string(mapping.size()));
  }
  Crc32 crc;
  crc.update(mapping.data(), kLutChecksumOffset);
  const std::uint32_t zero = 0;
  crc.update(&zero, sizeof(zero));
  crc.update(mapping.data() + kLutChecksumOffset + sizeof(zero),
             mapping.size() - kLutChecksumOffset - sizeof(zero));
  if (crc.value() != header.checksum) {
    throw LutFileError(path, "checksum mismatch: the file is damaged");
  }
  if (header.source != static_cast<std::uint32_t>(LutSource::kModel) &&
      header.source != static_cast<std::uint32_t>(LutSource::kRecorded)) {
    throw LutFileError(path, "unknown table source " + std::to_string(header.source));
  }
  const std::uint64_t table_end =
      header.section_table_offset + std::uint64_t{header.section_count} * sizeof(SectionEntry);
  if (header.section_table_offset % 8 != 0 || table_end > mapping.size() ||
      table_end < header.section_table_offset) {
    throw LutFileError(path, "section table outside the file");
  }
  // Every camera has sections of its own (its name at least), each a table entry: a count above
  // the entries is a damaged header, and would size what is allocated from it.
  if (header.camera_count >= kNoCamera || header.camera_count > header.section_count) {
    throw LutFileError(
        path, "the header says " + std::to_string(header.camera_count) +
                  " cameras, expected at most " +
                  std::to_string(std::min<std::uint32_t>(header.section_count, kNoCamera - 1U)) +
                  " (one per section of the file's " + std::to_string(header.section_count) + ")");
  }
  return header;
}

template <typename T>
std::span<const T> section_span(const std::filesystem::path& path, const Mapping& mapping,
                                const SectionEntry& entry) {
  if (entry.offset % alignof(T) != 0 || entry.bytes % sizeof(T) != 0 ||
      entry.offset > mapping.size() || entry.bytes > mapping.size() - entry.offset) {
    throw LutFileError(path, "section " + std::to_string(entry.kind) + " of camera " +
                                 std::to_string(entry.camera) + " does not fit the file");
  }
  return {reinterpret_cast<const T*>(mapping.data() + entry.offset), entry.bytes / sizeof(T)};
}

// The robot parts the file's LUT-2 sections are of: each a run of bodies after the one before.
std::vector<RobotPart> read_parts(const std::filesystem::path& path, const Mapping& mapping,
                                  std::span<const SectionEntry> entries) {
  std::vector<RobotPart> parts;
  for (const auto& entry : entries) {
    if (static_cast<SectionKind>(entry.kind) != SectionKind::kPartBodies) continue;
    const auto bodies = section_span<std::uint64_t>(path, mapping, entry);
    if (bodies.empty() || bodies.size() % 2 != 0 || bodies.size() / 2 > kMaxParts) {
      throw LutFileError(path, "robot part section of " + std::to_string(bodies.size()) +
                                   " numbers; expected 2 per part, 1.." +
                                   std::to_string(kMaxParts) + " parts");
    }
    for (std::size_t p = 0; p < bodies.size(); p += 2) {
      const std::uint64_t first = bodies[p];
      const std::uint64_t end = bodies[p + 1];
      const std::uint64_t expected_first = parts.empty() ? 0 : parts.back().end_body;
      if (first != expected_first || end <= first || end > kMaxJoints + 1) {
        throw LutFileError(path, "robot part " + std::to_string(p / 2) + " has bodies " +
                                     std::to_string(first) + ".." + std::to_string(end) +
                                     "; expected a run beginning at body " +
                                     std::to_string(expected_first));
      }
      parts.push_back(RobotPart{"part " + std::to_string(p / 2), first, end});
    }
  }
  if (parts.empty()) throw LutFileError(path, "no robot part section");
  for (const auto& entry : entries) {
    if (static_cast<SectionKind>(entry.kind) != SectionKind::kPartNames) continue;
    if (entry.part >= parts.size()) {
      throw LutFileError(path, "a name for robot part " + std::to_string(entry.part) + " of " +
                                   std::to_string(parts.size()));
    }
    const auto name = section_span<char>(path, mapping, entry);
    parts[entry.part].name.assign(name.begin(), name.end());
  }
  return parts;
}

}  // namespace

void write_lut_file(const std::filesystem::path& path, const LutSet& set) {
  FileImage image;
  if (set.cameras.size() >= kNoCamera) throw FileError(path, "too many cameras for a LUT file");
  if (set.parts.empty() || set.parts.size() > kMaxParts) {
    throw FileError(path, std::to_string(set.parts.size()) + " robot parts; a LUT file holds 1.." +
                              std::to_string(kMaxParts));
  }
  std::vector<std::uint64_t> bodies;
  for (const RobotPart& part : set.parts) {
    bodies.push_back(part.first_body);
    bodies.push_back(part.end_body);
  }
  image.add(SectionKind::kPartBodies, kNoCamera, std::span<const std::uint64_t>(bodies));
  for (std::size_t p = 0; p < set.parts.size(); ++p) {
    image.add(SectionKind::kPartNames, kNoCamera, set.parts[p].name.data(),
              set.parts[p].name.size(), static_cast<std::uint8_t>(p));
  }
  for (std::size_t c = 0; c < set.cameras.size(); ++c) {
    const auto camera = static_cast<std::uint16_t>(c);
    const CameraLuts& luts = set.cameras[c];
    if (luts.parts.size() != set.parts.size()) {
      throw FileError(path, "camera '" + luts.camera + "' has tables for " +
                                std::to_string(luts.parts.size()) + " robot parts, the set " +
                                std::to_string(set.parts.size()));
    }
    image.add(SectionKind::kCameraName, camera, luts.camera.data(), luts.camera.size());
    for (std::size_t p = 0; p < luts.parts.size(); ++p) {
      const PartLuts& tables = luts.parts[p];
      const auto part = static_cast<std::uint8_t>(p);
      std::uint64_t block_strips = 0;
      for (const auto& level : tables.pixel_blocks) block_strips += level.total_strips();
      const std::uint64_t stats[kCameraStatsWords] = {
          tables.covered_pairs, tables.pixel_to_cells.total_strips(), block_strips};
      image.add(SectionKind::kCameraStats, camera, stats, sizeof(stats), part);
      image.add(SectionKind::kPixelOffsets, camera, tables.pixel_to_cells.offsets(), part);
      image.add(SectionKind::kPixelStrips, camera, tables.pixel_to_cells.strip_bytes(), part);
      for (std::size_t l = 0; l < tables.pixel_blocks.size(); ++l) {
        const auto level = static_cast<std::uint8_t>(l + 1);
        image.add(SectionKind::kBlockOffsets, camera, tables.pixel_blocks[l].offsets(), part,
                  level);
        image.add(SectionKind::kBlockStrips, camera, tables.pixel_blocks[l].strip_bytes(), part,
                  level);
      }
      for (std::size_t n = 0; n < kNeighbourCount; ++n) {
        for (std::size_t l = 0; l < tables.differences[n].size(); ++l) {
          const auto level = static_cast<std::uint8_t>(l);
          image.add(kDifferenceOffsets[n], camera, tables.differences[n][l].offsets(), part, level);
          image.add(kDifferenceStrips[n], camera, tables.differences[n][l].strip_bytes(), part,
                    level);
        }
      }
    }
    if (luts.cell_to_pixels.cell_count() > 0) {
      image.add(SectionKind::kCellOffsets, camera, luts.cell_to_pixels.offsets());
      image.add(SectionKind::kCellRects, camera, luts.cell_to_pixels.rects());
    }
  }
  image.add(SectionKind::kStaticCells, kNoCamera,
            std::span<const std::uint64_t>(set.static_cells.words()));
  Header header{};
  std::memcpy(header.magic, kMagic, sizeof(kMagic));
  header.version = kLutFileVersion;
  header.header_bytes = sizeof(Header);
  header.fingerprint = set.fingerprint;
  header.grid_fingerprint = set.grid_fingerprint;
  header.source = static_cast<std::uint32_t>(set.source);
  header.columns = static_cast<std::uint32_t>(set.columns);
  header.rows = static_cast<std::uint32_t>(set.rows);
  header.camera_count = static_cast<std::uint32_t>(set.cameras.size());
  header.cell_count = set.static_cells.cell_count();
  write_file_atomically(path, image.finish(header));
}

LutFileSummary read_lut_file_summary(const std::filesystem::path& path) {
  const Mapping mapping(path);
  const Header header = checked_header(path, mapping);
  LutFileSummary summary;
  summary.version = header.version;
  summary.fingerprint = header.fingerprint;
  summary.grid_fingerprint = header.grid_fingerprint;
  summary.source = static_cast<LutSource>(header.source);
  summary.columns = static_cast<int>(header.columns);
  summary.rows = static_cast<int>(header.rows);
  summary.camera_count = header.camera_count;
  summary.cell_count = header.cell_count;
  summary.file_bytes = header.file_bytes;
  summary.cameras.resize(header.camera_count);
  const auto entries = section_span<SectionEntry>(
      path, mapping,
      SectionEntry{0, kNoCamera, 0, 0, header.section_table_offset,
                   std::uint64_t{header.section_count} * sizeof(SectionEntry)});
  summary.parts = read_parts(path, mapping, entries);
  for (const auto& entry : entries) {
    if (entry.camera == kNoCamera) continue;
    if (entry.camera >= summary.cameras.size()) {
      throw LutFileError(path, "a section names camera " + std::to_string(entry.camera));
    }
    LutFileSummary::Camera& camera = summary.cameras[entry.camera];
    switch (static_cast<SectionKind>(entry.kind)) {
      case SectionKind::kCameraName: {
        const auto name = section_span<char>(path, mapping, entry);
        camera.name.assign(name.begin(), name.end());
        break;
      }
      case SectionKind::kCameraStats: {
        const auto stats = section_span<std::uint64_t>(path, mapping, entry);
        if (stats.size() != kCameraStatsWords) {
          throw LutFileError(path, "camera statistics of the wrong size");
        }
        camera.covered_pairs += stats[0];
        camera.strips += stats[1];
        break;
      }
      case SectionKind::kPixelOffsets:
      case SectionKind::kPixelStrips:
      case SectionKind::kLeftDifferenceOffsets:
      case SectionKind::kLeftDifferenceStrips:
      case SectionKind::kUpperDifferenceOffsets:
      case SectionKind::kUpperDifferenceStrips:
        camera.pixel_table_bytes += entry.bytes;
        break;
      case SectionKind::kBlockOffsets:
      case SectionKind::kBlockStrips:
        camera.pixel_table_bytes += entry.bytes;
        camera.block_table_bytes += entry.bytes;
        camera.block_levels = std::max<int>(camera.block_levels, entry.level);
        break;
      case SectionKind::kCellOffsets:
      case SectionKind::kCellRects:
        camera.cell_table_bytes += entry.bytes;
        break;
      default:
        throw LutFileError(path, "unknown section kind " + std::to_string(entry.kind));
    }
  }
  return summary;
}

LutSet load_lut_file(const std::filesystem::path& path, const CspaceGrid& grid,
                     std::optional<std::uint64_t> expected_fingerprint) {
  auto mapping = std::make_shared<const Mapping>(path);
  const Header header = checked_header(path, *mapping);
  if (header.grid_fingerprint != grid.fingerprint() || header.cell_count != grid.cell_count()) {
    throw LutFileError(path, "built for another C-space grid (grid fingerprint " +
                                 std::to_string(header.grid_fingerprint) + ", this cell's is " +
                                 std::to_string(grid.fingerprint()) + "); build the tables again");
  }
  if (expected_fingerprint && header.fingerprint != *expected_fingerprint) {
    throw LutFileError(path, "built for another robot, camera set-up or settings (fingerprint " +
                                 std::to_string(header.fingerprint) + ", expected " +
                                 std::to_string(*expected_fingerprint) +
                                 "); build the tables again");
  }
  if (header.columns == 0 || header.rows == 0 || header.columns > 65535 || header.rows > 65535) {
    throw LutFileError(path, "feature grid " + std::to_string(header.columns) + " x " +
                                 std::to_string(header.rows) + " out of range");
  }
  const auto entries = section_span<SectionEntry>(
      path, *mapping,
      SectionEntry{0, kNoCamera, 0, 0, header.section_table_offset,
                   std::uint64_t{header.section_count} * sizeof(SectionEntry)});
  struct PartSections {
    const SectionEntry* pixel_offsets = nullptr;
    const SectionEntry* pixel_strips = nullptr;
    const SectionEntry* stats = nullptr;
    std::vector<const SectionEntry*> block_offsets;  // [level - 1]
    std::vector<const SectionEntry*> block_strips;
    std::vector<const SectionEntry*> difference_offsets[kNeighbourCount];  // [neighbour][level]
    std::vector<const SectionEntry*> difference_strips[kNeighbourCount];
  };
  struct CameraSections {
    const SectionEntry* name = nullptr;
    const SectionEntry* cell_offsets = nullptr;
    const SectionEntry* cell_rects = nullptr;
    std::vector<PartSections> parts;
  };
  LutSet set;
  set.parts = read_parts(path, *mapping, entries);
  std::vector<CameraSections> cameras(header.camera_count);
  for (auto& camera : cameras) camera.parts.resize(set.parts.size());
  const SectionEntry* static_cells = nullptr;
  for (const auto& entry : entries) {
    const auto kind = static_cast<SectionKind>(entry.kind);
    if (kind == SectionKind::kStaticCells) {
      static_cells = &entry;
      continue;
    }
    if (kind == SectionKind::kPartBodies || kind == SectionKind::kPartNames) continue;
    if (entry.camera >= cameras.size()) {
      throw LutFileError(path, "a section names camera " + std::to_string(entry.camera) + " of " +
                                   std::to_string(cameras.size()));
    }
    if (entry.part >= set.parts.size()) {
      throw LutFileError(path, "a section names robot part " + std::to_string(entry.part) + " of " +
                                   std::to_string(set.parts.size()));
    }
    CameraSections& camera = cameras[entry.camera];
    PartSections& sections = camera.parts[entry.part];
    switch (kind) {
      case SectionKind::kCameraName:
        camera.name = &entry;
        break;
      case SectionKind::kCellOffsets:
        camera.cell_offsets = &entry;
        break;
      case SectionKind::kCellRects:
        camera.cell_rects = &entry;
        break;
      case SectionKind::kPixelOffsets:
        sections.pixel_offsets = &entry;
        break;
      case SectionKind::kPixelStrips:
        sections.pixel_strips = &entry;
        break;
      case SectionKind::kCameraStats:
        sections.stats = &entry;
        break;
      case SectionKind::kBlockOffsets:
      case SectionKind::kBlockStrips: {
        if (entry.level < 1 || entry.level > 16) {
          throw LutFileError(path, "a block section of level " + std::to_string(entry.level));
        }
        auto& slots =
            kind == SectionKind::kBlockOffsets ? sections.block_offsets : sections.block_strips;
        if (slots.size() < entry.level) slots.resize(entry.level, nullptr);
        slots[entry.level - 1U] = &entry;
        break;
      }
      case SectionKind::kLeftDifferenceOffsets:
      case SectionKind::kLeftDifferenceStrips:
      case SectionKind::kUpperDifferenceOffsets:
      case SectionKind::kUpperDifferenceStrips: {
        if (entry.level > 16) {
          throw LutFileError(path, "a difference section of level " + std::to_string(entry.level));
        }
        const bool upper = kind == SectionKind::kUpperDifferenceOffsets ||
                           kind == SectionKind::kUpperDifferenceStrips;
        const std::size_t neighbour = upper ? kUpperNeighbour : kLeftNeighbour;
        auto& slots = kind == kDifferenceOffsets[neighbour] ? sections.difference_offsets[neighbour]
                                                            : sections.difference_strips[neighbour];
        if (slots.size() <= entry.level) slots.resize(entry.level + 1U, nullptr);
        slots[entry.level] = &entry;
        break;
      }
      default:
        throw LutFileError(path, "unknown section kind " + std::to_string(entry.kind));
    }
  }
  if (static_cells == nullptr) throw LutFileError(path, "no static-obstacle section");

  set.fingerprint = header.fingerprint;
  set.grid_fingerprint = header.grid_fingerprint;
  set.source = static_cast<LutSource>(header.source);
  set.columns = static_cast<int>(header.columns);
  set.rows = static_cast<int>(header.rows);
  const auto words = section_span<std::uint64_t>(path, *mapping, *static_cells);
  set.static_cells = CellSet(grid.cell_count());
  if (words.size() != set.static_cells.words().size()) {
    throw LutFileError(path, "static-obstacle section of the wrong size");
  }
  std::copy(words.begin(), words.end(), set.static_cells.words().begin());
  const auto table = [&](const SectionEntry& offsets, const SectionEntry& strips, int block) {
    return PixelToCellsTable(grid, (set.columns + block - 1) / block,
                             (set.rows + block - 1) / block,
                             section_span<std::uint64_t>(path, *mapping, offsets),
                             section_span<std::uint8_t>(path, *mapping, strips), mapping);
  };
  for (std::size_t c = 0; c < cameras.size(); ++c) {
    const CameraSections& sections = cameras[c];
    if (sections.name == nullptr)
      throw LutFileError(path, "camera " + std::to_string(c) + " lacks its name");
    if (set.source == LutSource::kRecorded &&
        (sections.cell_offsets == nullptr || sections.cell_rects == nullptr)) {
      throw LutFileError(path, "recorded set without LUT-1 for camera " + std::to_string(c));
    }
    const auto name = section_span<char>(path, *mapping, *sections.name);
    CameraLuts luts;
    luts.camera.assign(name.begin(), name.end());
    try {
      for (std::size_t p = 0; p < sections.parts.size(); ++p) {
        const PartSections& part = sections.parts[p];
        const std::string where =
            "camera '" + luts.camera + "', robot part '" + set.parts[p].name + "'";
        if (part.pixel_offsets == nullptr || part.pixel_strips == nullptr ||
            part.stats == nullptr) {
          throw LutFileError(path, where + " lacks its LUT-2 sections");
        }
        const auto stats = section_span<std::uint64_t>(path, *mapping, *part.stats);
        if (stats.size() != kCameraStatsWords) {
          throw LutFileError(path, where + ": statistics of the wrong size");
        }
        PartLuts tables;
        tables.covered_pairs = stats[0];
        if (part.block_offsets.size() != part.block_strips.size()) {
          throw LutFileError(path, where + ": block levels do not pair up");
        }
        tables.pixel_to_cells = table(*part.pixel_offsets, *part.pixel_strips, 1);
        for (std::size_t l = 0; l < part.block_offsets.size(); ++l) {
          if (part.block_offsets[l] == nullptr || part.block_strips[l] == nullptr) {
            throw LutFileError(path, where + " lacks block level " + std::to_string(l + 1));
          }
          tables.pixel_blocks.push_back(
              table(*part.block_offsets[l], *part.block_strips[l], 1 << (l + 1)));
        }
        for (std::size_t n = 0; n < kNeighbourCount; ++n) {
          const auto& offsets = part.difference_offsets[n];
          const auto& strips = part.difference_strips[n];
          if (offsets.size() != strips.size() || offsets.size() > part.block_offsets.size() + 1) {
            throw LutFileError(path, where + ": difference levels do not pair up");
          }
          for (std::size_t l = 0; l < offsets.size(); ++l) {
            if (offsets[l] == nullptr || strips[l] == nullptr) {
              throw LutFileError(path,
                                 where + " lacks the differences of level " + std::to_string(l));
            }
            tables.differences[n].push_back(table(*offsets[l], *strips[l], 1 << l));
          }
        }
        luts.parts.push_back(std::move(tables));
      }
      if (sections.cell_offsets != nullptr && sections.cell_rects != nullptr) {
        luts.cell_to_pixels = CellToPixelsTable(
            set.columns, set.rows,
            section_span<std::uint64_t>(path, *mapping, *sections.cell_offsets),
            section_span<FeatureRect>(path, *mapping, *sections.cell_rects), mapping);
      }
    } catch (const std::invalid_argument& error) {
      throw LutFileError(path, "camera '" + luts.camera + "': " + error.what());
    }
    set.cameras.push_back(std::move(luts));
  }
  return set;
}

}  // namespace safecell
