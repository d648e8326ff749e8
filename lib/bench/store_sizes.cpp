// SPDX-License-Identifier: Apache-2.0
#include "bench/store_sizes.h"

#include "core/file_io.h"
#include "format/step_file_format.h"
#include "store/store.h"

namespace strielad::bench {

double StoreSizes::stored_overhead() const {
  std::uint64_t fine = 0, coarse = 0;
  for (const auto& v : variables) {
    fine += v.level0_chunk_bytes;
    coarse += v.coarse_chunk_bytes;
  }
  return fine ? static_cast<double>(coarse) / static_cast<double>(fine) : 0.0;
}

const VariableStoreSize* StoreSizes::find(const std::string& name) const {
  for (const auto& v : variables) {
    if (v.name == name) return &v;
  }
  return nullptr;
}

StoreSizes measure_store_sizes(const std::filesystem::path& dir) {
  const auto store = Store::open(dir);
  const OctreeLayout& layout = store->octree();
  StoreSizes sizes;
  sizes.node_count = layout.node_count();
  sizes.levels = layout.level_count();
  sizes.brick = layout.brick();
  sizes.overhead_fraction = layout.overhead_fraction();
  const auto path = store->step_path(0);
  sizes.step_file_bytes = std::filesystem::file_size(path);

  // The section table gives each variable's stored index size.
  const ReadOnlyFile file(path);
  std::vector<std::byte> footer_bytes(format::kStepFooterSize);
  file.read_at(file.size() - footer_bytes.size(), footer_bytes);
  const format::StepFooter footer = format::decode_step_footer(footer_bytes, path.string());
  std::vector<std::byte> table(std::size_t{footer.variable_count} * format::kSectionEntrySize);
  file.read_at(footer.section_table_offset, table);
  const auto sections = format::decode_section_table(
      table, footer.variable_count, footer.node_count, footer.section_table_checksum,
      format::kStepHeaderSize, footer.section_table_offset, path.string());
  const double fixed = static_cast<double>(format::kStepHeaderSize + format::kStepFooterSize +
                                           table.size()) /
                       static_cast<double>(store->variable_count());

  const NodeId level0_end = static_cast<NodeId>(layout.level(0).node_count());
  for (std::uint32_t v = 0; v < store->variable_count(); ++v) {
    const auto& meta = store->manifest().variables[v];
    VariableStoreSize s;
    s.name = meta.name;
    s.raw_bytes = store->manifest().dims().count() * dtype_size(meta.dtype);
    s.index_bytes = sections[v].stored_size;
    s.fixed_share_bytes = fixed;
    const auto entries = store->index(0, v);
    for (NodeId n = 0; n < entries.size(); ++n) {
      const auto& e = entries[n];
      s.chunk_bytes += e.chunk_size;
      (n < level0_end ? s.level0_chunk_bytes : s.coarse_chunk_bytes) += e.chunk_size;
      switch (e.kind) {
        case format::BrickKind::kEmpty: ++s.empty; break;
        case format::BrickKind::kConstant: ++s.constant; break;
        case format::BrickKind::kData: ++s.data; break;
      }
    }
    sizes.variables.push_back(std::move(s));
  }
  return sizes;
}

}  // namespace strielad::bench
