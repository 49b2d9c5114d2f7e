#include "safecell/lut_files/lut_file.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "model_fixture.hpp"
#include "safecell/base/crc32.hpp"
#include "safecell/errors/input_error.hpp"
#include "safecell/lut_build/cell_table_builder.hpp"
#include "safecell/lut_build/model_luts.hpp"
#include "safecell/lut_files/lut_cache.hpp"
#include "safecell/silhouettes/model_silhouettes.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;

class LutFile : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    cell_ = new CellModel(test::coarse_default_cell());
    grid_ = new CspaceGrid(make_grid(cell_->config));
    set_ = new LutSet(build_model_luts(*cell_, *grid_));
  }
  static void TearDownTestSuite() {
    delete set_;
    delete grid_;
    delete cell_;
  }
  void SetUp() override {
    folder_ =
        fs::temp_directory_path() /
        ("safecell_lut_file_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  static std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  static void write(const fs::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  }
  // The problem text of the refusal, or "" when the file loads.
  static std::string refusal(const fs::path& path, std::optional<std::uint64_t> fingerprint) {
    try {
      (void)load_lut_file(path, *grid_, fingerprint);
    } catch (const LutFileError& error) {
      return error.what();
    }
    return "";
  }

  static CellModel* cell_;
  static CspaceGrid* grid_;
  static LutSet* set_;
  fs::path folder_;
};

CellModel* LutFile::cell_ = nullptr;
CspaceGrid* LutFile::grid_ = nullptr;
LutSet* LutFile::set_ = nullptr;

void expect_same(const LutSet& a, const LutSet& b) {
  EXPECT_EQ(a.fingerprint, b.fingerprint);
  EXPECT_EQ(a.grid_fingerprint, b.grid_fingerprint);
  EXPECT_EQ(a.source, b.source);
  EXPECT_EQ(a.columns, b.columns);
  EXPECT_EQ(a.rows, b.rows);
  EXPECT_EQ(a.static_cells, b.static_cells);
  ASSERT_EQ(a.parts.size(), b.parts.size());
  for (std::size_t p = 0; p < a.parts.size(); ++p) {
    EXPECT_EQ(a.parts[p].name, b.parts[p].name);
    EXPECT_EQ(a.parts[p].first_body, b.parts[p].first_body);
    EXPECT_EQ(a.parts[p].end_body, b.parts[p].end_body);
  }
  ASSERT_EQ(a.cameras.size(), b.cameras.size());
  for (std::size_t c = 0; c < a.cameras.size(); ++c) {
    const CameraLuts& x = a.cameras[c];
    const CameraLuts& y = b.cameras[c];
    EXPECT_EQ(x.camera, y.camera);
    ASSERT_EQ(x.parts.size(), y.parts.size());
    for (std::size_t p = 0; p < x.parts.size(); ++p) {
      const PartLuts& u = x.parts[p];
      const PartLuts& v = y.parts[p];
      EXPECT_EQ(u.covered_pairs, v.covered_pairs);
      EXPECT_TRUE(std::ranges::equal(u.pixel_to_cells.offsets(), v.pixel_to_cells.offsets()));
      EXPECT_TRUE(
          std::ranges::equal(u.pixel_to_cells.strip_bytes(), v.pixel_to_cells.strip_bytes()));
      ASSERT_EQ(u.pixel_blocks.size(), v.pixel_blocks.size());
      for (std::size_t l = 0; l < u.pixel_blocks.size(); ++l) {
        EXPECT_TRUE(std::ranges::equal(u.pixel_blocks[l].offsets(), v.pixel_blocks[l].offsets()));
        EXPECT_TRUE(
            std::ranges::equal(u.pixel_blocks[l].strip_bytes(), v.pixel_blocks[l].strip_bytes()));
      }
      for (std::size_t n = 0; n < kNeighbourCount; ++n) {
        ASSERT_EQ(u.differences[n].size(), v.differences[n].size()) << "neighbour " << n;
        for (std::size_t l = 0; l < u.differences[n].size(); ++l) {
          EXPECT_TRUE(
              std::ranges::equal(u.differences[n][l].offsets(), v.differences[n][l].offsets()));
          EXPECT_TRUE(std::ranges::equal(u.differences[n][l].strip_bytes(),
                                         v.differences[n][l].strip_bytes()));
        }
      }
    }
    EXPECT_TRUE(std::ranges::equal(x.cell_to_pixels.offsets(), y.cell_to_pixels.offsets()));
    EXPECT_TRUE(std::ranges::equal(x.cell_to_pixels.rects(), y.cell_to_pixels.rects()));
  }
}

TEST_F(LutFile, ModelSetRoundTrips) {
  const fs::path path = folder_ / "luts.sclut";
  write_lut_file(path, *set_);
  const LutSet loaded = load_lut_file(path, *grid_, set_->fingerprint);
  expect_same(*set_, loaded);
  const LutFileSummary summary = read_lut_file_summary(path);
  EXPECT_EQ(summary.camera_count, 4U);
  EXPECT_EQ(summary.cell_count, grid_->cell_count());
  EXPECT_EQ(summary.file_bytes, fs::file_size(path));
  ASSERT_EQ(summary.cameras.size(), 4U);
  EXPECT_EQ(summary.cameras[2].name, "cam2");
  std::uint64_t strips = 0;
  for (const PartLuts& part : set_->cameras[2].parts) strips += part.pixel_to_cells.total_strips();
  EXPECT_EQ(summary.cameras[2].strips, strips);
  EXPECT_EQ(summary.cameras[2].covered_pairs, set_->cameras[2].covered_pairs());
  ASSERT_EQ(summary.parts.size(), set_->parts.size());
  EXPECT_EQ(summary.parts.back().name, set_->parts.back().name);
  EXPECT_EQ(summary.parts.back().end_body, cell_->robot->dof() + 1);
  EXPECT_GT(summary.cameras[2].covered_pairs, 0U);
  EXPECT_EQ(summary.cameras[2].cell_table_bytes, 0U);
  EXPECT_EQ(summary.cameras[2].block_levels, 3);
  EXPECT_EQ(summary.cameras[2].pixel_table_bytes, set_->cameras[2].pixel_table_bytes());
}

TEST_F(LutFile, RecordedSetKeepsItsCellTables) {
  LutSet recorded = *set_;
  recorded.source = LutSource::kRecorded;
  CellTableBuild build;
  build.cell_count = grid_->cell_count();
  build.table_count = recorded.cameras.size();
  build.columns = recorded.columns;
  build.rows = recorded.rows;
  const ModelSilhouettes silhouettes(*cell_, *grid_, ModelLutOptions{});
  auto tables =
      build_cell_to_pixels_tables(build, [&](CellIndex cell, std::vector<FeatureMask>& masks) {
        silhouettes.add_silhouettes(cell, masks);
      });
  for (std::size_t c = 0; c < tables.size(); ++c) recorded.cameras[c].cell_to_pixels = tables[c];
  const fs::path path = folder_ / "recorded.sclut";
  write_lut_file(path, recorded);
  expect_same(recorded, load_lut_file(path, *grid_, std::nullopt));
}

TEST_F(LutFile, DamagedAndForeignFilesAreRefused) {
  const fs::path path = folder_ / "luts.sclut";
  write_lut_file(path, *set_);
  const std::string good = read(path);

  EXPECT_NE(refusal(path, set_->fingerprint + 1).find("another robot"), std::string::npos);

  CellConfig finer_config = default_cell();
  finer_config.m_max_m = 0.35;
  finer_config.joints.at(3).discretised = false;
  const CspaceGrid other_grid = make_grid(load_cell_model(finer_config).config);
  try {
    (void)load_lut_file(path, other_grid, std::nullopt);
    ADD_FAILURE() << "a file of another grid was loaded";
  } catch (const LutFileError& error) {
    EXPECT_NE(std::string(error.what()).find("another C-space grid"), std::string::npos);
  }

  std::string flipped = good;
  flipped[flipped.size() / 2] = static_cast<char>(flipped[flipped.size() / 2] ^ 0x10);
  write(path, flipped);
  EXPECT_NE(refusal(path, std::nullopt).find("checksum"), std::string::npos);

  write(path, good.substr(0, good.size() - 100));
  EXPECT_NE(refusal(path, std::nullopt).find("truncated"), std::string::npos);

  std::string other_version = good;
  other_version[8] = 9;  // the version field follows the 8 magic bytes
  write(path, other_version);
  EXPECT_NE(refusal(path, std::nullopt).find("format version 9"), std::string::npos);

  std::string not_ours = good;
  not_ours[0] = 'X';
  write(path, not_ours);
  EXPECT_NE(refusal(path, std::nullopt).find("magic"), std::string::npos);

  write(path, "short");
  EXPECT_NE(refusal(path, std::nullopt).find("too short"), std::string::npos);

  EXPECT_NE(refusal(folder_ / "missing.sclut", std::nullopt).find("cannot open"),
            std::string::npos);

  write(path, good);
  EXPECT_EQ(refusal(path, set_->fingerprint), "");
}

// A header whose counts are absurd but whose checksum holds (written so on purpose, or by a bug) is
// refused before anything is sized from it: `luts info` once ended in std::bad_alloc (exit 70).
TEST_F(LutFile, AHeaderCountingMoreCamerasThanSectionsIsRefusedBeforeAllocating) {
  const fs::path path = folder_ / "luts.sclut";
  write_lut_file(path, *set_);
  const std::string good = read(path);
  constexpr std::size_t kCameraCountOffset = 44;  // after magic, version, sizes, fingerprints,
  constexpr std::size_t kChecksumOffset = 72;     // source, columns and rows
  const auto with_cameras = [&](std::uint32_t count) {
    std::string bytes = good;
    std::memcpy(bytes.data() + kCameraCountOffset, &count, sizeof(count));
    std::memset(bytes.data() + kChecksumOffset, 0, 4);
    Crc32 crc;
    crc.update(bytes.data(), bytes.size());
    const std::uint32_t checksum = crc.value();
    std::memcpy(bytes.data() + kChecksumOffset, &checksum, sizeof(checksum));
    return bytes;
  };
  write(path, with_cameras(4));  // control: the true count with a recomputed checksum loads
  EXPECT_EQ(refusal(path, set_->fingerprint), "");
  EXPECT_EQ(read_lut_file_summary(path).camera_count, 4U);
  write(path, with_cameras(0xFFFFFFFFU));
  EXPECT_NE(refusal(path, std::nullopt).find("the header says 4294967295 cameras"),
            std::string::npos)
      << refusal(path, std::nullopt);
  try {
    (void)read_lut_file_summary(path);
    ADD_FAILURE() << "the summary of a file of 2^32 - 1 cameras was read";
  } catch (const LutFileError& error) {
    EXPECT_NE(std::string(error.what()).find("4294967295 cameras"), std::string::npos);
  }
}

// Cameras that see none of the robot's reach make tables with no pair in them: such a cell protects
// nobody, and the cache refuses it with every camera's pairs (it built them and exited 0).
TEST_F(LutFile, ACellWhoseCamerasSeeNoneOfTheRobotIsRefused) {
  CellModel blind = *cell_;
  for (PinholeCamera& camera : blind.cameras) {
    const Eigen::Vector3d at = camera.position_m();
    const Eigen::Vector3d outward(at.x() * 3.0, at.y() * 3.0, at.z());  // level, away from it
    camera = PinholeCamera::look_at(camera.name(), at, outward, Eigen::Vector3d::UnitZ(), 0.8,
                                    camera.intrinsics().width_px, camera.intrinsics().height_px);
  }
  try {
    (void)model_luts_cached(blind, *grid_, ModelLutOptions{}, folder_);
    ADD_FAILURE() << "the tables of a cell no camera of which sees the robot were taken";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("only 0 of 4 cameras see any of the robot's reach"),
              std::string::npos)
        << error.what();
  }
  // Control: the cell as it is passes (its cameras see the robot).
  EXPECT_NO_THROW((void)model_luts_cached(*cell_, *grid_, ModelLutOptions{}, folder_));
}

// A grid whose table build needs more memory than the machine has is refused before it starts.
TEST_F(LutFile, ABuildBeyondTheMachinesMemoryIsRefusedBeforeItStarts) {
  CellConfig fine = test::coarse_default_config();
  fine.m_max_m = 0.01;  // some 548 M cells: about 250 GB while built
  const CellModel cell = load_cell_model(fine);
  const CspaceGrid grid = make_grid(cell.config);
  const double machine_bytes =
      static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGESIZE));
  if (machine_bytes > 450.0 * grid.cell_count()) GTEST_SKIP() << "this machine could build them";
  try {
    (void)model_luts_cached(cell, grid, ModelLutOptions{}, folder_);
    ADD_FAILURE() << "a build of " << grid.cell_count() << " cells was started";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("GB while they are built"), std::string::npos)
        << error.what();
  }
}

// A build is announced with its estimate before it starts, drawn from the build's own work; a
// load from the cache is not. (The estimate's seconds are a measurement on this machine: compared
// with the build's in the commit that made it, not here.)
TEST_F(LutFile, ABuildIsAnnouncedWithItsEstimateALoadIsNot) {
  std::vector<LutBuildEstimate> announced;
  bool built_before_announced = false;
  const auto announce = [&](const LutBuildEstimate& estimate) {
    built_before_announced = fs::exists(
        lut_cache_file(folder_, model_lut_fingerprint(*cell_, *grid_, ModelLutOptions{})));
    announced.push_back(estimate);
  };
  const CachedLuts built =
      model_luts_cached(*cell_, *grid_, ModelLutOptions{}, folder_, {}, announce);
  ASSERT_TRUE(built.built);
  ASSERT_EQ(announced.size(), 1U);
  EXPECT_FALSE(built_before_announced);
  const LutBuildEstimate& estimate = announced.front();
  EXPECT_EQ(estimate.cells, grid_->cell_count());
  EXPECT_DOUBLE_EQ(estimate.peak_bytes, lut_build_peak_bytes(*grid_));
  // The cells the build draws: per part, those of its last body's joints.
  const ModelSilhouettes silhouettes(*cell_, *grid_, ModelLutOptions{});
  std::uint64_t drawn = 0;
  for (const RobotPart& part : silhouettes.parts()) {
    drawn += silhouettes.envelope().prefix_count(part.end_body - 1);
  }
  EXPECT_EQ(estimate.drawn_cells, drawn);
  EXPECT_GT(estimate.sampled_cells, 0U);
  EXPECT_LE(estimate.sampled_cells, drawn);
  EXPECT_GT(estimate.seconds, 0.0);
  EXPECT_GE(estimate.threads, 1U);
  EXPECT_EQ(built.estimate.drawn_cells, estimate.drawn_cells);

  const CachedLuts loaded =
      model_luts_cached(*cell_, *grid_, ModelLutOptions{}, folder_, {}, announce);
  EXPECT_FALSE(loaded.built);
  EXPECT_EQ(announced.size(), 1U) << "a load from the cache was announced as a build";
}

TEST_F(LutFile, CacheBuildsOnceThenLoadsAndReplacesADamagedFile) {
  const CachedLuts first = model_luts_cached(*cell_, *grid_, ModelLutOptions{}, folder_);
  EXPECT_TRUE(first.built);
  EXPECT_TRUE(fs::exists(first.file));
  const CachedLuts second = model_luts_cached(*cell_, *grid_, ModelLutOptions{}, folder_);
  EXPECT_FALSE(second.built);
  EXPECT_EQ(second.file, first.file);
  expect_same(first.set, second.set);

  std::string damaged = read(first.file);
  damaged[damaged.size() - 10] = static_cast<char>(damaged[damaged.size() - 10] ^ 1);
  write(first.file, damaged);
  const CachedLuts third = model_luts_cached(*cell_, *grid_, ModelLutOptions{}, folder_);
  EXPECT_TRUE(third.built);
  EXPECT_NE(third.note.find("checksum"), std::string::npos) << third.note;
  expect_same(first.set, third.set);

  ModelLutOptions padded;
  padded.padding_m = 0.05;
  EXPECT_NE(model_luts_cached(*cell_, *grid_, padded, folder_).file, first.file);
}

}  // namespace
}  // namespace safecell
