// SPDX-License-Identifier: Apache-2.0
// How reports name the files of the machine that ran them. A report (JSON, CSV, Markdown,
// a suite's captured output) carries no absolute path of that machine: a path inside the
// repository is written relative to its root, one inside the temporary or the home folder
// as $TMPDIR/... or $HOME/..., and one inside another named folder as that folder's
// placeholder ($WORK/store, $OUT/io.json). A command quoted in a report thus runs again
// from the repository's root, the same in every report of one run, once the placeholders
// are set.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bench/table_writer.h"

namespace strielad::bench {

// The root of the repository this program was built in: the nearest folder holding .git
// above the executable, else above the current folder; empty when there is none.
std::filesystem::path find_repository_root();

class ReportPaths {
 public:
  // `repository`: empty for none. The system's temporary folder ($TMPDIR) and the home
  // folder ($HOME) are always known. `folders`: placeholder ("$WORK") and folder, used only
  // for a folder outside the repository, $TMPDIR and $HOME.
  ReportPaths(const std::filesystem::path& repository,
              const std::vector<std::pair<std::string, std::filesystem::path>>& folders);

  // The paths of one program's reports: its scratch folder as $WORK (none when empty), and
  // the folder of each of its output files as $OUT, where not already known.
  static ReportPaths for_suite(const std::filesystem::path& work,
                               const std::vector<std::string>& outputs);

  // `text` with every absolute path that begins with a known folder rewritten.
  std::string text(std::string_view text) const;
  // Every string of `j`, keys excepted, as text() writes it.
  void rewrite(nlohmann::json& j) const;
  // Every cell, title and note of the tables, as text() writes them.
  void rewrite(std::vector<Table>& tables) const;
  // The file's text rewritten in place; a file that cannot be read is left as it is.
  void rewrite_file(const std::filesystem::path& file) const;

  // The path for a file that text() wrote as `written`: a placeholder becomes its folder,
  // a relative path is taken from the repository's root; anything else is unchanged.
  std::filesystem::path resolve(const std::string& written) const;

 private:
  struct Folder {
    std::string path;  // absolute, without a trailing '/'
    std::string name;  // placeholder; empty for the repository (written relative to it)
  };
  std::filesystem::path repository_;
  std::vector<Folder> folders_;  // longest path first
};

}  // namespace strielad::bench
