// SPDX-License-Identifier: Apache-2.0
#include "support/grib_fixture.h"

#include <eccodes.h>

#include <fstream>
#include <mutex>

#include "core/error.h"
#include "ingest/eccodes_call.h"

namespace strielad::testing {

void write_grib_file(const std::filesystem::path& path,
                     const std::vector<GribFixtureMessage>& messages) {
  std::lock_guard lock(ingest::eccodes_mutex());
  std::ofstream out(path, std::ios::binary);
  for (const auto& m : messages) {
    ingest::GribHandle h(
        codes_handle_new_from_samples(codes_context_get_default(), m.sample.c_str()));
    if (!h) throw make_error(ErrorCode::kNotFound, "no ecCodes sample '{}'", m.sample);
    for (const auto& [key, value] : m.keys) {
      const std::string what = "GRIB fixture " + m.sample + ": setting '" + key + "'";
      if (const auto* l = std::get_if<long>(&value)) {
        ingest::eccodes_check(codes_set_long(h.get(), key.c_str(), *l), what);
      } else if (const auto* d = std::get_if<double>(&value)) {
        ingest::eccodes_check(codes_set_double(h.get(), key.c_str(), *d), what);
      } else if (const auto* a = std::get_if<std::vector<double>>(&value)) {
        ingest::eccodes_check(codes_set_double_array(h.get(), key.c_str(), a->data(), a->size()),
                              what);
      } else {
        const auto& s = std::get<std::string>(value);
        std::size_t length = s.size();
        ingest::eccodes_check(codes_set_string(h.get(), key.c_str(), s.c_str(), &length), what);
      }
    }
    if (!m.values.empty()) {
      ingest::eccodes_check(
          codes_set_double_array(h.get(), "values", m.values.data(), m.values.size()),
          "GRIB fixture " + m.sample + ": setting the values");
    }
    const void* bytes = nullptr;
    std::size_t size = 0;
    ingest::eccodes_check(codes_get_message(h.get(), &bytes, &size), "GRIB fixture");
    out.write(static_cast<const char*>(bytes), static_cast<std::streamsize>(size));
  }
  if (!out) throw make_error(ErrorCode::kIo, "{}: cannot write the GRIB fixture", path.string());
}

}  // namespace strielad::testing
