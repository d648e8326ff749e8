// SPDX-License-Identifier: Apache-2.0
// Error text sent to clients names datasets, never the server's files: the library's
// errors start with the path of the file at fault (/srv/stores/run1/MANIFEST: ...), which
// would tell every client where the server keeps its data. The server's own log keeps
// the full message.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace strielad::serve {

// `message` with each mention of the directory `store_dir` (a whole path: followed by
// the end, '/' or punctuation, not by more of a name) replaced by `dataset`, the name the
// client opened it by: "/srv/stores/run1/steps/step-000003.bricks: ..." becomes
// "run1/steps/step-000003.bricks: ...".
std::string name_dataset_not_path(std::string_view message, const std::filesystem::path& store_dir,
                                  std::string_view dataset);

// `message` with each remaining path under `root` made relative to it, and `root`
// itself called "the server's root": the last guard before text leaves the server.
std::string hide_root(std::string_view message, const std::filesystem::path& root);

}  // namespace strielad::serve
