// SPDX-License-Identifier: Apache-2.0
// The hardware-limit contenders of the conversion benchmark: reading input files start to
// end, and reading them while writing a copy (then fsync), with one fixed buffer size.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>

namespace strielad::bench {

inline constexpr std::size_t kCopyBufferBytes = std::size_t{4} << 20;  // 4 MiB

struct CopyResult {
  std::uint64_t bytes = 0;
  double seconds = 0;
};

// Reads every file to the end with read(2) into one buffer. Throws kIo.
CopyResult read_files(std::span<const std::filesystem::path> files,
                      std::size_t buffer_bytes = kCopyBufferBytes);

// Reads every file to the end with O_DIRECT (DirectReadFile, reads of `piece_bytes`;
// by default the converter's, ingest::SlabReader::kDirectPieceBytes): the disk's own
// speed, without the page cache. nullopt when a file's file system refuses O_DIRECT.
// Throws kIo.
std::optional<CopyResult> read_files_direct(std::span<const std::filesystem::path> files,
                                            std::size_t piece_bytes);

// Copies each file into `out_dir` (same file name) with read(2)/write(2), fsyncs every
// copy before the clock stops. Throws kIo.
CopyResult copy_files(std::span<const std::filesystem::path> files,
                      const std::filesystem::path& out_dir,
                      std::size_t buffer_bytes = kCopyBufferBytes);

// Opens `path` and fsyncs it (makes a competitor's output durable, as the converter's is).
void fsync_file(const std::filesystem::path& path);

}  // namespace strielad::bench
