// SPDX-License-Identifier: Apache-2.0
#include "convert/step_writer.h"

#include "core/checksum.h"
#include "core/error.h"

namespace strielad::build {

StepWriter::StepWriter(const std::filesystem::path& path, const format::StepHeader& header)
    : header_(header),
      file_(path),
      entries_(header.variable_count, std::vector<format::IndexEntry>(header.node_count)),
      written_(header.variable_count, std::vector<bool>(header.node_count, false)) {
  file_.append(format::encode_step_header(header));
}

void StepWriter::add_brick(std::uint32_t variable, NodeId node, EncodedBrick brick) {
  if (variable >= header_.variable_count || node >= header_.node_count || written_[variable][node]) {
    throw make_error(ErrorCode::kInternal, "step writer: bad or repeated brick (variable {}, node {})",
                     variable, node);
  }
  written_[variable][node] = true;
  if (brick.entry.kind == format::BrickKind::kData) {
    brick.entry.chunk_offset = file_.size();
    file_.append(brick.chunk);
    chunk_bytes_ += brick.chunk.size();
  }
  entries_[variable][node] = brick.entry;
}

void StepWriter::commit() {
  for (std::uint32_t v = 0; v < header_.variable_count; ++v) {
    for (NodeId n = 0; n < header_.node_count; ++n) {
      if (!written_[v][n]) {
        throw make_error(ErrorCode::kInternal, "step writer: variable {} node {} never written", v, n);
      }
    }
  }
  std::vector<format::SectionEntry> sections;
  for (std::uint32_t v = 0; v < header_.variable_count; ++v) {
    const auto stored = format::encode_index_section(entries_[v], format::SectionCodec::kZstd);
    format::SectionEntry s;
    s.variable = v;
    s.codec = format::SectionCodec::kZstd;
    s.offset = file_.size();
    s.stored_size = stored.size();
    s.raw_size = std::uint64_t{header_.node_count} * format::kIndexEntrySize;
    s.checksum = checksum64(stored);
    file_.append(stored);
    sections.push_back(s);
  }
  format::StepFooter footer;
  footer.section_table_offset = file_.size();
  const auto table = format::encode_section_table(sections);
  file_.append(table);
  footer.variable_count = header_.variable_count;
  footer.node_count = header_.node_count;
  footer.store_id = header_.store_id;
  footer.step = header_.step;
  footer.section_table_checksum = checksum64(table);
  footer.chunk_bytes = chunk_bytes_;
  file_.append(format::encode_step_footer(footer));
  file_.commit();
}

}  // namespace strielad::build
