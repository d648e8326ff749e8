// SPDX-License-Identifier: Apache-2.0
#include "serve/client_error_text.h"

namespace strielad::serve {
namespace {

// Whether `c` ends a path mention: the end of the text, a separator or the punctuation
// messages put after paths. Anything else continues the name (/srv/run1 is not /srv/run10).
bool ends_mention(std::string_view text, std::size_t at) {
  if (at >= text.size()) return true;
  switch (text[at]) {
    case '/': case ':': case ' ': case '\'': case '"': case ')': case ',': case ';': case '\n':
      return true;
    default:
      return false;
  }
}

// Replaces every whole mention of `path` in `text` with `replacement`; with `eat_slash`
// also the separator after it (a path under it becomes relative).
std::string replace_path(std::string_view text, std::string path, std::string_view replacement,
                         bool eat_slash) {
  while (path.size() > 1 && path.back() == '/') path.pop_back();
  if (path.empty() || path == "/") return std::string(text);
  std::string out;
  std::size_t from = 0;
  for (std::size_t at = text.find(path); at != std::string_view::npos; at = text.find(path, at)) {
    const std::size_t end = at + path.size();
    if (!ends_mention(text, end)) {
      at = end;
      continue;
    }
    out.append(text, from, at - from);
    if (eat_slash && end < text.size() && text[end] == '/') {
      from = end + 1;
    } else {
      out.append(replacement);
      from = end;
    }
    at = from;
  }
  out.append(text, from);
  return out;
}

}  // namespace

std::string name_dataset_not_path(std::string_view message, const std::filesystem::path& store_dir,
                                  std::string_view dataset) {
  return replace_path(message, store_dir.string(), dataset, false);
}

std::string hide_root(std::string_view message, const std::filesystem::path& root) {
  return replace_path(message, root.string(), "the server's root", true);
}

}  // namespace strielad::serve
