// SPDX-License-Identifier: Apache-2.0
#include "bench/report_paths.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <system_error>

namespace strielad::bench {
namespace {

// Characters that end a path in running text (and may stand before one).
bool is_delimiter(char c) {
  switch (c) {
    case ' ': case '\t': case '\n': case '\r': case '"': case '\'': case '`': case ':':
    case ',': case ';': case '(': case ')': case '[': case ']': case '<': case '>':
    case '=': case '|':
      return true;
    default:
      return false;
  }
}

std::filesystem::path repository_above(std::filesystem::path dir) {
  std::error_code ec;
  for (; !dir.empty(); dir = dir.parent_path()) {
    if (std::filesystem::exists(dir / ".git", ec)) return dir;
    if (dir == dir.root_path()) break;
  }
  return {};
}

// `path` absolute and lexically normal, without a trailing '/'; empty for the root
// folder or an empty path (never rewritten).
std::string folder_text(const std::filesystem::path& path) {
  if (path.empty()) return {};
  std::error_code ec;
  auto abs = std::filesystem::absolute(path, ec);
  if (ec) return {};
  std::string s = abs.lexically_normal().string();
  while (s.size() > 1 && s.back() == '/') s.pop_back();
  return s == "/" ? std::string() : s;
}

bool inside(const std::string& path, const std::string& folder) {
  return !folder.empty() && path.compare(0, folder.size(), folder) == 0 &&
         (path.size() == folder.size() || path[folder.size()] == '/');
}

}  // namespace

std::filesystem::path find_repository_root() {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    if (auto root = repository_above(exe.parent_path()); !root.empty()) return root;
  }
  const auto cwd = std::filesystem::current_path(ec);
  return ec ? std::filesystem::path() : repository_above(cwd);
}

ReportPaths::ReportPaths(const std::filesystem::path& repository,
                         const std::vector<std::pair<std::string, std::filesystem::path>>& folders)
    : repository_(repository) {
  std::vector<Folder> known;  // the repository, $TMPDIR, $HOME
  if (const auto root = folder_text(repository); !root.empty()) known.push_back({root, ""});
  std::error_code ec;
  const auto tmp = folder_text(std::filesystem::temp_directory_path(ec));
  if (!ec && !tmp.empty()) known.push_back({tmp, "$TMPDIR"});
  if (const char* home = std::getenv("HOME"); home != nullptr && *home == '/') {
    if (const auto h = folder_text(home); !h.empty()) known.push_back({h, "$HOME"});
  }
  folders_ = known;
  for (const auto& [name, folder] : folders) {
    const std::string path = folder_text(folder);
    const bool named = std::any_of(folders_.begin(), folders_.end(), [&](const Folder& f) {
      return inside(path, f.path);
    });
    if (!path.empty() && !named) folders_.push_back({path, name});
  }
  std::stable_sort(folders_.begin(), folders_.end(), [](const Folder& a, const Folder& b) {
    return a.path.size() > b.path.size();
  });
}

ReportPaths ReportPaths::for_suite(const std::filesystem::path& work,
                                   const std::vector<std::string>& outputs) {
  std::vector<std::pair<std::string, std::filesystem::path>> folders;
  if (!work.empty()) folders.emplace_back("$WORK", work);
  for (const auto& output : outputs) {
    if (output.empty()) continue;
    folders.emplace_back("$OUT", std::filesystem::absolute(output).parent_path());
  }
  return ReportPaths(find_repository_root(), folders);
}

std::string ReportPaths::text(std::string_view text) const {
  std::string out;
  out.reserve(text.size());
  std::size_t i = 0;
  while (i < text.size()) {
    const bool starts_path = text[i] == '/' && (i == 0 || is_delimiter(text[i - 1]));
    const Folder* match = nullptr;
    if (starts_path) {
      for (const Folder& f : folders_) {
        const std::size_t end = i + f.path.size();
        if (text.compare(i, f.path.size(), f.path) == 0 &&
            (end == text.size() || text[end] == '/' || is_delimiter(text[end]))) {
          match = &f;
          break;
        }
      }
    }
    if (match == nullptr) {
      out += text[i++];
      continue;
    }
    i += match->path.size();
    if (!match->name.empty()) {
      out += match->name;
    } else if (i < text.size() && text[i] == '/') {
      ++i;  // relative to the repository: drop the root and its '/'
    } else {
      out += '.';
    }
  }
  return out;
}

void ReportPaths::rewrite(nlohmann::json& j) const {
  if (j.is_string()) {
    j = text(j.get_ref<const std::string&>());
  } else if (j.is_structured()) {
    for (auto& item : j) rewrite(item);
  }
}

void ReportPaths::rewrite(std::vector<Table>& tables) const {
  for (Table& t : tables) {
    t.title = text(t.title);
    for (auto& note : t.notes) note = text(note);
    for (auto& row : t.rows) {
      for (Cell& cell : row) {
        if (!cell.is_number()) cell.value = text(std::get<std::string>(cell.value));
      }
    }
  }
}

void ReportPaths::rewrite_file(const std::filesystem::path& file) const {
  std::ifstream in(file, std::ios::binary);
  if (!in) return;
  std::ostringstream content;
  content << in.rdbuf();
  in.close();
  const std::string before = content.str();
  const std::string after = text(before);
  if (after != before) write_text_file(file, after);
}

std::filesystem::path ReportPaths::resolve(const std::string& written) const {
  for (const Folder& f : folders_) {
    if (f.name.empty() || written.compare(0, f.name.size(), f.name) != 0) continue;
    const std::string rest = written.substr(f.name.size());
    if (rest.empty()) return f.path;
    if (rest.front() == '/') return f.path + rest;
  }
  if (!written.empty() && written.front() != '/' && !repository_.empty()) {
    return (repository_ / written).lexically_normal();
  }
  return written;
}

}  // namespace strielad::bench
