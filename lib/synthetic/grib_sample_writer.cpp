// SPDX-License-Identifier: Apache-2.0
#include "synthetic/grib_sample_writer.h"

#include <eccodes.h>

#include <cmath>
#include <mutex>
#include <string>

#include "core/error.h"
#include "core/file_io.h"
#include "ingest/eccodes_call.h"
#include "synthetic/sample_writer.h"

namespace strielad::synthetic {
namespace {

// The reference time of kSampleTimeUnits.
constexpr long kReferenceDate = 20130426;
constexpr long kReferenceTime = 1200;
// Stands for a bitmap point while values are set; no sample value comes near it.
constexpr double kGribMissing = 1.0e30;
// Millimetres: heights up to 4294 km fit GRIB 2's 32-bit scaled value.
constexpr long kHeightScaleFactor = 3;

void check_axis(const std::vector<double>& axis, const char* name) {
  const std::size_t n = axis.size();
  if (n < 2) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "GRIB sample: the {} axis has {} point(s); regular_ll needs at least 2",
                     name, n);
  }
  const double step = (axis[n - 1] - axis[0]) / static_cast<double>(n - 1);
  for (std::size_t i = 0; i < n; ++i) {
    const double even = axis[0] + step * static_cast<double>(i);
    if (std::abs(axis[i] - even) > 1e-9) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "GRIB sample: the {} axis is not regular: point {} is {:.12g}, {:.12g} "
                       "from the even spacing of {:.12g} degrees",
                       name, i, axis[i], axis[i] - even, step);
    }
  }
  for (const double end : {axis.front(), axis.back()}) {
    if (std::abs(end * 1e6 - std::round(end * 1e6)) > 1e-6) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "GRIB sample: the {} axis ends at {:.12g} degrees, not a whole number of "
                       "micro-degrees (GRIB 2's unit)",
                       name, end);
    }
  }
}

void set_long(const ingest::GribHandle& h, const char* key, long value) {
  ingest::eccodes_check(codes_set_long(h.get(), key, value),
                        std::string("GRIB sample: setting ") + key);
}

void set_double(const ingest::GribHandle& h, const char* key, double value) {
  ingest::eccodes_check(codes_set_double(h.get(), key, value),
                        std::string("GRIB sample: setting ") + key);
}

void set_string(const ingest::GribHandle& h, const char* key, const char* value) {
  std::size_t length = std::char_traits<char>::length(value);
  ingest::eccodes_check(codes_set_string(h.get(), key, value, &length),
                        std::string("GRIB sample: setting ") + key);
}

// The grid, reference time and packing every message shares. Caller holds the mutex.
ingest::GribHandle grid_template(const SampleGrid& grid, int bits) {
  ingest::GribHandle h(
      codes_handle_new_from_samples(codes_context_get_default(), "regular_ll_sfc_grib2"));
  if (!h) throw make_error(ErrorCode::kNotFound, "GRIB sample: no ecCodes sample regular_ll_sfc_grib2");
  set_long(h, "Ni", static_cast<long>(grid.dims.x));
  set_long(h, "Nj", static_cast<long>(grid.dims.y));
  set_long(h, "iScansNegatively", 0);
  set_long(h, "jScansPositively", 1);
  set_double(h, "latitudeOfFirstGridPointInDegrees", grid.lat.front());
  set_double(h, "longitudeOfFirstGridPointInDegrees", grid.lon.front());
  set_double(h, "latitudeOfLastGridPointInDegrees", grid.lat.back());
  set_double(h, "longitudeOfLastGridPointInDegrees", grid.lon.back());
  set_double(h, "iDirectionIncrementInDegrees", grid.lon[1] - grid.lon[0]);
  set_double(h, "jDirectionIncrementInDegrees", grid.lat[1] - grid.lat[0]);
  set_long(h, "dataDate", kReferenceDate);
  set_long(h, "dataTime", kReferenceTime);
  set_long(h, "significanceOfReferenceTime", 1);  // start of forecast
  set_long(h, "productDefinitionTemplateNumber", 0);
  set_long(h, "typeOfSecondFixedSurface", 255);
  if (bits == 0) {
    set_string(h, "packingType", "grid_ieee");
    set_long(h, "precision", 1);  // float32
  } else {
    set_string(h, "packingType", "grid_simple");
    set_long(h, "bitsPerValue", bits);
  }
  return h;
}

// GRIB 2 code table 4.4 unit and count of a step in whole minutes.
std::pair<long, long> forecast_time(double seconds) {
  const auto s = static_cast<long>(std::llround(seconds));
  if (s % 3600 == 0) return {1, s / 3600};  // hours
  return {0, s / 60};                       // minutes
}

}  // namespace

GribLevelKind parse_grib_level_kind(std::string_view text) {
  if (text == "height") return GribLevelKind::kHeightAboveSea;
  if (text == "model") return GribLevelKind::kModelLevel;
  throw make_error(ErrorCode::kInvalidArgument,
                   "GRIB levels '{}': expected height (heightAboveSea) or model (hybrid)", text);
}

GribParameter grib_parameter(SampleVariable variable) noexcept {
  switch (variable) {
    case SampleVariable::kClw: return {0, 1, 83, "clwc"};
    case SampleVariable::kCli: return {0, 1, 84, "ciwc"};
    case SampleVariable::kQr: return {0, 1, 85, "crwc"};
    case SampleVariable::kTa: return {0, 0, 0, "t"};
    case SampleVariable::kPres: return {0, 3, 0, "pres"};
    case SampleVariable::kUa: return {0, 2, 2, "u"};
    case SampleVariable::kVa: return {0, 2, 3, "v"};
    case SampleVariable::kWa: return {0, 2, 9, "wz"};
  }
  return {};
}

void check_grib_regular_grid(const SampleGrid& grid) {
  check_axis(grid.lon, "longitude");
  check_axis(grid.lat, "latitude");
}

GribSampleFileWriter::GribSampleFileWriter(std::filesystem::path path, const SampleGrid& grid,
                                           GribSampleLayout layout)
    : path_(std::move(path)), grid_(grid), layout_(std::move(layout)) {
  check_grib_regular_grid(grid);
  if (layout_.bits < 0 || layout_.bits > 32) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "GRIB sample: {} bits per value; expected 1..32, or 0 for IEEE float32",
                     layout_.bits);
  }
  for (const double t : layout_.times) {
    if (t < 0 || std::abs(t / 60 - std::round(t / 60)) > 1e-9) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "GRIB sample: step at {} s is not a whole, non-negative number of minutes "
                       "(GRIB validity times are in minutes); use --step-seconds in minutes",
                       t);
    }
  }
  temp_path_ = temporary_sibling(path_);
  out_.open(temp_path_, std::ios::binary | std::ios::trunc);
  if (!out_) throw make_error(ErrorCode::kIo, "{}: cannot create", temp_path_.string());
  values_.resize(grid.level_size());
}

GribSampleFileWriter::~GribSampleFileWriter() {
  if (committed_) return;
  out_.close();
  std::error_code ec;
  std::filesystem::remove(temp_path_, ec);
}

void GribSampleFileWriter::write_level(std::size_t variable_index, std::size_t t, std::size_t k,
                                       std::span<const float> level) {
  if (level.size() != values_.size() || variable_index >= layout_.variables.size() ||
      t >= layout_.times.size() || k >= grid_.dims.z) {
    throw make_error(ErrorCode::kInternal, "{}: level {} of variable {} at step {} out of range",
                     path_.string(), k, variable_index, t);
  }
  bool any_missing = false;
  for (std::size_t i = 0; i < level.size(); ++i) {
    const float v = level[i];
    const bool missing = std::isnan(v) || v == kSampleFillValue;
    any_missing = any_missing || missing;
    values_[i] = missing ? kGribMissing : static_cast<double>(v);
  }
  const GribParameter p = grib_parameter(layout_.variables[variable_index]);
  const auto [unit, count] = forecast_time(layout_.times[t]);
  std::lock_guard lock(ingest::eccodes_mutex());
  const ingest::GribHandle h = grid_template(grid_, layout_.bits);
  set_long(h, "discipline", p.discipline);
  set_long(h, "parameterCategory", p.category);
  set_long(h, "parameterNumber", p.number);
  if (layout_.levels == GribLevelKind::kHeightAboveSea) {
    set_long(h, "typeOfFirstFixedSurface", 102);
    set_long(h, "scaleFactorOfFirstFixedSurface", kHeightScaleFactor);
    set_long(h, "scaledValueOfFirstFixedSurface",
             std::lround(grid_.height[k] * std::pow(10.0, kHeightScaleFactor)));
  } else {
    set_long(h, "typeOfFirstFixedSurface", 105);
    set_long(h, "scaleFactorOfFirstFixedSurface", 0);
    set_long(h, "scaledValueOfFirstFixedSurface", static_cast<long>(k + 1));
  }
  set_long(h, "indicatorOfUnitOfTimeRange", unit);
  set_long(h, "forecastTime", count);
  if (any_missing) {
    set_double(h, "missingValue", kGribMissing);
    set_long(h, "bitmapPresent", 1);
  }
  ingest::eccodes_check(codes_set_double_array(h.get(), "values", values_.data(), values_.size()),
                        "GRIB sample: setting the values");
  const void* bytes = nullptr;
  std::size_t size = 0;
  ingest::eccodes_check(codes_get_message(h.get(), &bytes, &size), "GRIB sample: encoding");
  out_.write(static_cast<const char*>(bytes), static_cast<std::streamsize>(size));
  if (!out_) throw make_error(ErrorCode::kIo, "{}: cannot write", temp_path_.string());
}

std::uint64_t GribSampleFileWriter::commit() {
  out_.close();
  if (!out_) throw make_error(ErrorCode::kIo, "{}: cannot close", temp_path_.string());
  const std::uint64_t size = publish_sample_file(temp_path_, path_);
  committed_ = true;
  return size;
}

}  // namespace strielad::synthetic
