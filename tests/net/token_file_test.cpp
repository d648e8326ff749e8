// SPDX-License-Identifier: Apache-2.0
// The shared secret's file: refused, naming the file and its mode, when group or others
// have any permission on it (as ssh refuses an unprotected key; it used to be a warning
// and the server started with a secret anyone could read); read when only its owner may.
#include "net/token_file.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <fstream>

#include "support/expect_error.h"
#include "support/temp_dir.h"

namespace strielad::net {
namespace {

using testing::expect_error;
using testing::TempDir;

std::string write_token(const TempDir& dir, const std::string& text, mode_t mode) {
  const std::string path = (dir / "token").string();
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
  EXPECT_EQ(::chmod(path.c_str(), mode), 0);
  return path;
}

TEST(TokenFileTest, ReadableByOthersIsRefusedNamingFileAndMode) {
  TempDir dir;
  for (const auto& [mode, text] : {std::pair{0644, "0644"}, std::pair{0640, "0640"},
                                   std::pair{0604, "0604"}, std::pair{0620, "0620"},
                                   std::pair{0601, "0601"}, std::pair{0660, "0660"}}) {
    const std::string path = write_token(dir, "s3cret\n", static_cast<mode_t>(mode));
    expect_error([&] { read_token_file(path); }, ErrorCode::kInvalidInput,
                 {path, std::string("mode ") + text, "chmod 600"});
  }
}

TEST(TokenFileTest, OwnerOnlyFileIsRead) {
  TempDir dir;
  EXPECT_EQ(read_token_file(write_token(dir, "s3cret\r\n", 0600)), "s3cret");
  EXPECT_EQ(read_token_file(write_token(dir, "s3cret", 0400)), "s3cret");
}

TEST(TokenFileTest, MissingEmptyAndOverlongFilesAreRefused) {
  TempDir dir;
  expect_error([&] { read_token_file((dir / "none").string()); }, ErrorCode::kNotFound,
               {"none", "cannot read the token file"});
  expect_error([&] { read_token_file(write_token(dir, "\n", 0600)); }, ErrorCode::kInvalidInput,
               {"the token file is empty"});
  expect_error([&] { read_token_file(write_token(dir, std::string(4097, 'x'), 0600)); },
               ErrorCode::kInvalidInput, {"token longer than 4096 bytes"});
  expect_error([&] { read_token_file(write_token(dir, std::string(100000, 'x'), 0600)); },
               ErrorCode::kInvalidInput, {"token longer than 4096 bytes"});
  EXPECT_EQ(read_token_file(write_token(dir, std::string(4096, 'x') + "\n", 0600)).size(), 4096u);
}

}  // namespace
}  // namespace strielad::net
