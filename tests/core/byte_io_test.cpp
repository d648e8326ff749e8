// SPDX-License-Identifier: Apache-2.0
#include "core/byte_io.h"

#include <gtest/gtest.h>

namespace strielad {
namespace {

TEST(ByteIoTest, FieldsRoundTripLittleEndian) {
  ByteWriter w;
  w.u8(7);
  w.u32(0x01020304u);
  w.u64(0x1122334455667788ull);
  w.f64(-1.5);
  const auto bytes = w.take();
  EXPECT_EQ(bytes[1], std::byte{0x04});  // least significant byte first
  ByteReader r(bytes, "test object");
  EXPECT_EQ(r.u8("a"), 7);
  EXPECT_EQ(r.u32("b"), 0x01020304u);
  EXPECT_EQ(r.u64("c"), 0x1122334455667788ull);
  EXPECT_EQ(r.f64("d"), -1.5);
  EXPECT_EQ(r.remaining(), 0u);
}

TEST(ByteIoTest, TruncatedReadNamesObjectFieldAndOffset) {
  const std::vector<std::byte> bytes(3);
  ByteReader r(bytes, "footer of x.bricks");
  try {
    r.u64("index_offset");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kTruncated);
    EXPECT_STREQ(e.what(),
                 "footer of x.bricks: field 'index_offset' at offset 0 needs 8 bytes, only 3 remain");
  }
}

}  // namespace
}  // namespace strielad
