// SPDX-License-Identifier: Apache-2.0
// strielad-convert --lossy: which variables are coded by zfp within which bound
// (formats/store.md, "zfp chunks (version 6)"). Parsing, checking against the inputs, and
// resolving a relative bound against the variable's range over the whole conversion.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "format/codec_spec.h"
#include "ingest/input_catalog.h"

namespace strielad::build {

struct LossyRequest {
  std::string variable;
  format::LossyMode mode = format::LossyMode::kAbsolute;
  double value = 0;  // the tolerance (abs) or the fraction of the variable's range (rel)
  friend bool operator==(const LossyRequest&, const LossyRequest&) = default;
};

// "ta=abs:0.05,clw=rel:1e-3" -> requests. Throws kInvalidArgument naming --lossy and the
// item for a missing '=' or ':', an unknown mode, or a tolerance that is not a positive
// finite number (negative, zero, NaN, infinite, or not a number at all).
std::vector<LossyRequest> parse_lossy(std::string_view text);

// The manifest's lossy spec of each request, in request order: an abs tolerance as is, a
// rel one times (max - min) of the variable's valid samples over every time step of the
// catalog (one extra read of the variable, whatever steps this run converts, so that
// every run of a store resolves the same plan). Throws kInvalidArgument naming --lossy for
// a variable the catalog does not hold or one named twice, and for a rel bound that
// resolves to no positive finite tolerance (a variable without valid samples, or constant).

std::vector<format::LossySpec> resolve_lossy(const ingest::InputCatalog& catalog,
                                             const ingest::ScanOptions& scan,
                                             const std::vector<LossyRequest>& requests);

}  // namespace strielad::build
