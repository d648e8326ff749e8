// SPDX-License-Identifier: Apache-2.0
// GEOMETRY and geometry.bricks are written once (convert/geometry_writer.h): a re-run
// finds the same bytes and leaves them, a different file is refused by name, and no
// temporary file is left behind.
#include <gtest/gtest.h>

#include "convert/geometry_writer.h"
#include "core/file_io.h"
#include "format/step_file_format.h"
#include "store/store.h"
#include "support/expect_error.h"
#include "support/geometry_store.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using testing::expect_error;

std::size_t files_in(const std::filesystem::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

// A constant brick per node: the smallest valid geometry field.
std::vector<build::EncodedBrick> constant_bricks(std::size_t nodes, double value) {
  std::vector<build::EncodedBrick> bricks(nodes);
  for (auto& b : bricks) {
    b.entry.kind = format::BrickKind::kConstant;
    b.entry.constant = value;
    b.entry.min = b.entry.max = value;
    b.entry.valid_count = 1;
  }
  return bricks;
}

TEST(GeometryWriterTest, GeometryFileIsWrittenOnceAndAReRunFindsTheSameBytes) {
  const testing::TempDir dir;
  const testing::GeometryStoreSpec spec;
  const format::GeometryFile file{0x1234, testing::geometry_store_coordinates(spec)};
  EXPECT_TRUE(build::write_geometry_file(dir.path(), file));
  const auto bytes = read_file_bytes(dir / "GEOMETRY");
  EXPECT_EQ(format::decode_geometry_file(bytes, "GEOMETRY").coordinates, file.coordinates);
  EXPECT_FALSE(build::write_geometry_file(dir.path(), file));
  EXPECT_EQ(read_file_bytes(dir / "GEOMETRY"), bytes);
  format::GeometryFile other = file;
  other.store_id = 0x5678;
  expect_error([&] { build::write_geometry_file(dir.path(), other); }, ErrorCode::kCorrupt,
               {(dir / "GEOMETRY").string(), "differs"});
  EXPECT_EQ(files_in(dir.path()), 1u);
}

TEST(GeometryWriterTest, GeometryBricksIsAStepFileOfOneSectionWrittenOnce) {
  const testing::TempDir dir;
  EXPECT_TRUE(build::write_geometry_bricks(dir.path(), 0xabc, constant_bricks(9, 250.0)));
  const auto path = dir / "geometry.bricks";
  const auto bytes = read_file_bytes(path);
  const auto header = format::decode_step_header(std::span(bytes).first(format::kStepHeaderSize),
                                                 "geometry.bricks");
  EXPECT_EQ(header, (format::StepHeader{0xabc, format::kGeometryStep, 1, 9}));
  const auto footer = format::decode_step_footer(
      std::span(bytes).last(format::kStepFooterSize), "geometry.bricks");
  EXPECT_EQ(footer.step, format::kGeometryStep);
  EXPECT_EQ(footer.variable_count, 1u);

  EXPECT_FALSE(build::write_geometry_bricks(dir.path(), 0xabc, constant_bricks(9, 250.0)));
  EXPECT_EQ(read_file_bytes(path), bytes);
  expect_error([&] { build::write_geometry_bricks(dir.path(), 0xabc, constant_bricks(9, 251.0)); },
               ErrorCode::kCorrupt, {path.string(), "differs"});
  EXPECT_EQ(read_file_bytes(path), bytes);
  EXPECT_EQ(files_in(dir.path()), 1u);  // no temporary left
}

}  // namespace
}  // namespace strielad
