// SPDX-License-Identifier: Apache-2.0
#include "support/wind_store.h"

#include "convert/converter.h"
#include "synthetic/sample_dataset.h"

namespace strielad::testing {

std::filesystem::path write_wind_store(const std::filesystem::path& dir, Dims3 dims,
                                       std::size_t steps, unsigned brick) {
  synthetic::SampleSpec spec;
  spec.dims = dims;
  spec.steps = steps;
  spec.variables = {"clw", "ua", "va", "wa"};
  const auto written = synthetic::write_sample_dataset(spec, dir / "nc");
  build::ConvertOptions options;
  for (const auto& f : written.files) options.inputs.push_back(f.path);
  options.store = dir / "wind";
  options.brick = brick;
  options.threads = 2;
  build::convert(options);
  return options.store;
}

}  // namespace strielad::testing
