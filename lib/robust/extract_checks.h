// SPDX-License-Identifier: Apache-2.0
// The extraction and server stages of a robustness case. Extraction runs at level 0, at
// level 1 and at the root's level; the server stage asks an in-process strielad-serve
// (formats/protocol.md) for a cut and compares every answer with batch extraction.
#pragma once

#include <chrono>
#include <filesystem>
#include <string>

#include "robust/extreme_case.h"
#include "robust/stage_findings.h"
#include "scene/scene.h"
#include "store/store.h"

namespace strielad::robust {

// One sub-volume per limit of the case on "f" (ids 1, 2, ...), the case's longitude
// domain as sub-volume 100 (no limits), and "f" as the attribute of every mesh.
Scene case_scene(const ExtremeCase& c, const format::Manifest& manifest);

// Checks, per level, node and sub-volume:
// - the skip decision matches the node's exact range of the input (no valid sample:
//   skipped-no-data; range misses the limit: skipped-value-range; else extracted);
// - a mesh is closed and consistently oriented (every edge used as often in one
//   direction as in the other: two triangles, or four where the region touches itself
//   along an edge at samples exactly on a bound), without zero-area triangles, with unit
//   normals and finite positions inside the node's box;
// - attributes are finite, or NaN only in nodes with missing samples;
// - the enclosed volume lies between the volume of the cells whose eight corners are all
//   valid and inside the limit and that of the cells with at least one such corner (for
//   the domain sub-volume: equals the node box cut to the domain).
// A refusal (an extraction error other than kInternal) is reported as such.
StageFindings check_extraction(const ExtremeCase& c, const Store& store, int threads);

// Starts a server on `root` (the folder holding the store `dataset`), opens it, sets the
// case's scene and asks for every node (at most 64: the root, every coarse node and the
// first level-0 nodes). Every answer must arrive within `timeout`, equal batch extraction
// (outcome, reason, triangles, face kinds) and decode to finite positions within the
// node's box, unit normals and attributes that are finite or NaN.
StageFindings check_server(const ExtremeCase& c, const std::filesystem::path& root,
                           const std::string& dataset, int threads,
                           std::chrono::milliseconds timeout);

}  // namespace strielad::robust
