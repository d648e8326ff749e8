// SPDX-License-Identifier: Apache-2.0
// verify_store checks a format-5 store's geometry like its data: the GEOMETRY file and
// every geometry brick (geometry.bricks, or section V of each step file), naming the file
// of each damaged byte or missing file.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/file_io.h"
#include "format/step_file_format.h"
#include "store/store.h"
#include "store/store_verifier.h"
#include "support/geometry_store.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using testing::GeometryField;
using testing::GeometryStoreSpec;

void flip_byte(const std::filesystem::path& file, std::uint64_t offset) {
  std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
  f.seekg(static_cast<std::streamoff>(offset));
  char c;
  f.get(c);
  f.seekp(static_cast<std::streamoff>(offset));
  f.put(static_cast<char>(c ^ 0x5a));
}

// Whether some problem contains every part.
bool has_problem(const VerifyReport& report, std::initializer_list<std::string_view> parts) {
  for (const auto& p : report.problems) {
    bool all = true;
    for (const auto part : parts) all = all && p.find(part) != std::string::npos;
    if (all) return true;
  }
  return false;
}

std::string problems_of(const VerifyReport& report) { return report.to_json().dump(1); }

// The first data brick of the field's index.
NodeId first_data_node(std::span<const format::IndexEntry> entries) {
  for (NodeId n = 0; n < entries.size(); ++n) {
    if (entries[n].kind == format::BrickKind::kData) return n;
  }
  ADD_FAILURE() << "no data brick";
  return 0;
}

TEST(GeometryStoreVerifyTest, IntactStoresVerifyWithEveryGeometryBrick) {
  for (const GeometryField field : {GeometryField::kInvariant, GeometryField::kVarying}) {
    const testing::TempDir dir;
    GeometryStoreSpec spec;
    spec.field = field;
    testing::write_geometry_store(dir / "store", spec);
    const auto report = verify_store(dir / "store");
    EXPECT_TRUE(report.ok()) << problems_of(report);
    const std::uint64_t nodes = Store::open(dir / "store")->octree().node_count();
    // The variable's bricks of every step, then the field's once or at every step.
    const std::uint64_t field_bricks =
        field == GeometryField::kInvariant ? nodes : spec.steps * nodes;
    EXPECT_EQ(report.bricks_checked, spec.steps * nodes + field_bricks);
  }
}

TEST(GeometryStoreVerifyTest, FlippedByteInGeometryFileIsNamed) {
  const testing::TempDir dir;
  testing::write_geometry_store(dir / "store");
  const auto path = dir / "store" / "GEOMETRY";
  flip_byte(path, std::filesystem::file_size(path) - 3);  // inside the last array
  const auto report = verify_store(dir / "store");
  EXPECT_TRUE(has_problem(report, {path.string()})) << problems_of(report);
}

TEST(GeometryStoreVerifyTest, FlippedByteInGeometryBricksIsNamedWithTheNode) {
  const testing::TempDir dir;
  testing::write_geometry_store(dir / "store");
  const NodeId victim = first_data_node(Store::open(dir / "store")->geometry_index(0));
  const auto e = Store::open(dir / "store")->geometry_index(0)[victim];
  const auto path = dir / "store" / "geometry.bricks";
  flip_byte(path, e.chunk_offset + e.chunk_size / 2);
  const auto report = verify_store(dir / "store");
  EXPECT_TRUE(has_problem(report, {path.string(), fmt::format("geometry field node {} ", victim),
                                   "chunk checksum mismatch"}))
      << problems_of(report);
  EXPECT_EQ(report.problems.size(), 1u) << problems_of(report);
}

TEST(GeometryStoreVerifyTest, FlippedByteInSectionVIsNamed) {
  const testing::TempDir dir;
  GeometryStoreSpec spec;
  spec.field = GeometryField::kVarying;
  testing::write_geometry_store(dir / "store", spec);
  const auto path = dir / "store" / format::step_file_name(1);
  // Section V (the field's index) of step 1, found through the footer and section table.
  const ReadOnlyFile file(path);
  std::vector<std::byte> footer_bytes(format::kStepFooterSize);
  file.read_at(file.size() - footer_bytes.size(), footer_bytes);
  const auto footer = format::decode_step_footer(footer_bytes, "test");
  std::vector<std::byte> table(footer.variable_count * format::kSectionEntrySize);
  file.read_at(footer.section_table_offset, table);
  const auto sections = format::decode_section_table(
      table, footer.variable_count, footer.node_count, footer.section_table_checksum,
      format::kStepHeaderSize, footer.section_table_offset, "test");
  ASSERT_EQ(sections.size(), 2u);
  flip_byte(path, sections[1].offset + sections[1].stored_size / 2);
  const auto report = verify_store(dir / "store");
  EXPECT_TRUE(has_problem(report, {path.string(), "geometry field"})) << problems_of(report);
  EXPECT_EQ(report.problems.size(), 1u) << problems_of(report);  // the variable still verifies
}

TEST(GeometryStoreVerifyTest, FlippedByteInAFieldChunkOfAStepFileIsNamed) {
  const testing::TempDir dir;
  GeometryStoreSpec spec;
  spec.field = GeometryField::kVarying;
  testing::write_geometry_store(dir / "store", spec);
  const auto entries = Store::open(dir / "store")->geometry_index(0);
  const NodeId victim = first_data_node(entries);
  const auto e = entries[victim];
  const auto path = dir / "store" / format::step_file_name(0);
  flip_byte(path, e.chunk_offset + e.chunk_size / 2);
  const auto report = verify_store(dir / "store");
  EXPECT_TRUE(has_problem(
      report, {path.string(), "step 0", fmt::format("geometry field node {} ", victim)}))
      << problems_of(report);
}

TEST(GeometryStoreVerifyTest, MissingGeometryBricksIsNamed) {
  const testing::TempDir dir;
  testing::write_geometry_store(dir / "store");
  const auto path = dir / "store" / "geometry.bricks";
  std::filesystem::remove(path);
  const auto report = verify_store(dir / "store");
  EXPECT_TRUE(has_problem(report, {path.string(), "missing"})) << problems_of(report);
}

TEST(GeometryStoreVerifyTest, MissingGeometryFileIsNamed) {
  const testing::TempDir dir;
  testing::write_geometry_store(dir / "store");
  const auto path = dir / "store" / "GEOMETRY";
  std::filesystem::remove(path);
  const auto report = verify_store(dir / "store");
  EXPECT_TRUE(has_problem(report, {path.string(), "missing"})) << problems_of(report);
}

}  // namespace
}  // namespace strielad
