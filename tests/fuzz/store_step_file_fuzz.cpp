// SPDX-License-Identifier: Apache-2.0
// Fuzzes the store's read path (store/store.h) on a whole step file: the input is step 0
// of the checked-in golden store (tests/data/golden-store-v1), whose manifest is marked
// incomplete so that a step of any size is read. Opening the step (header, footer,
// section table), every variable's index section and every brick must reject with
// strielad::Error, never crash. Seeds: the golden store's two step files. Damaged bytes
// mostly meet the section and chunk checksums first; the step-file decoders are fuzzed
// behind them in step_file_decoders_fuzz.cpp.
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "core/error.h"
#include "format/manifest.h"
#include "fuzz/fuzz_files.h"
#include "fuzz/fuzz_target.h"
#include "store/store.h"

using namespace strielad;

namespace {

const std::filesystem::path kGolden =
    std::filesystem::path(STRIELAD_SOURCE_DIR) / "tests/data/golden-store-v1";

std::vector<std::uint8_t> file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.empty()) throw std::runtime_error("cannot read " + path.string());
  return bytes;
}

// A store directory with the golden manifest, incomplete; returns its path.
std::filesystem::path store_dir() {
  static const std::filesystem::path dir = [] {
    const auto manifest_bytes = file_bytes(kGolden / "MANIFEST");
    format::Manifest m = format::decode_manifest(
        std::span(reinterpret_cast<const std::byte*>(manifest_bytes.data()), manifest_bytes.size()),
        "golden MANIFEST");
    m.complete = false;
    m.steps.clear();
    m.summary = nlohmann::json::object();
    const auto store = fuzz::process_dir() / "store";
    std::filesystem::create_directories(store / "steps");
    const auto encoded = format::encode_manifest(m);
    std::ofstream(store / "MANIFEST", std::ios::binary)
        .write(reinterpret_cast<const char*>(encoded.data()), static_cast<std::streamsize>(encoded.size()));
    return store;
  }();
  return dir;
}

}  // namespace

std::vector<std::vector<std::uint8_t>> strielad_fuzz_seeds() {
  return {file_bytes(kGolden / "steps/step-000000.bricks"),
          file_bytes(kGolden / "steps/step-000001.bricks")};
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto dir = store_dir();
  {
    std::ofstream out(dir / format::step_file_name(0), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  StoreOpenOptions options;
  options.allow_incomplete = true;
  const auto store = Store::open(dir, options);
  for (std::uint32_t v = 0; v < store->variable_count(); ++v) {
    try {
      const auto index = store->index(0, v);
      for (NodeId node = 0; node < index.size(); ++node) {
        try {
          store->read_brick(0, v, node);
        } catch (const Error&) {
        }
      }
    } catch (const Error&) {
    }
  }
  return 0;
}
