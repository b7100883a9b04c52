// Checks of generated HTML for the report and study tests: tags balanced
// (void elements allowed, inline SVG included), nothing left of the
// template, nothing that would reach the network.
#pragma once

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

namespace frostwall::test {

// Empty when every element is closed in order; else a description of the
// first problem. Comments, <!DOCTYPE> and the text of <style> are skipped;
// "<x/>" closes itself; HTML void elements need no end tag.
inline std::string html_balance_problem(const std::string& html) {
  static const std::vector<std::string> void_elements{"area",  "base", "br",   "col",    "embed", "hr", "img",
                                                      "input", "link", "meta", "source", "track", "wbr"};
  std::vector<std::string> open;
  std::size_t pos = 0;
  while ((pos = html.find('<', pos)) != std::string::npos) {
    if (html.compare(pos, 4, "<!--") == 0) {
      pos = html.find("-->", pos);
      if (pos == std::string::npos) return "unterminated comment";
      continue;
    }
    if (html.compare(pos, 2, "<!") == 0) {
      pos = html.find('>', pos);
      continue;
    }
    const std::size_t end = html.find('>', pos);
    if (end == std::string::npos) return "unterminated tag at " + std::to_string(pos);
    std::string tag = html.substr(pos + 1, end - pos - 1);
    const bool closing = !tag.empty() && tag[0] == '/';
    const bool self_closing = !tag.empty() && tag.back() == '/';
    std::string name;
    for (std::size_t k = closing ? 1 : 0;
         k < tag.size() && (std::isalnum(static_cast<unsigned char>(tag[k])) || tag[k] == '-'); ++k)
      name += static_cast<char>(std::tolower(static_cast<unsigned char>(tag[k])));
    if (name.empty()) return "not a tag at " + std::to_string(pos) + ": <" + tag.substr(0, 20);
    pos = end + 1;
    if (closing) {
      if (open.empty() || open.back() != name)
        return "</" + name + "> closes <" + (open.empty() ? std::string("nothing") : open.back()) + "> at " +
               std::to_string(pos);
      open.pop_back();
      continue;
    }
    if (self_closing || std::find(void_elements.begin(), void_elements.end(), name) != void_elements.end()) continue;
    if (name == "style" || name == "title" || name == "script") {  // raw text up to the end tag
      const std::size_t close = html.find("</" + name, pos);
      if (close == std::string::npos) return "<" + name + "> never closed";
      pos = close;
    }
    open.push_back(name);
  }
  if (!open.empty()) return "<" + open.back() + "> never closed";
  return "";
}

// Everything that would make a page load something from elsewhere.
inline std::vector<std::string> external_references(const std::string& html) {
  std::vector<std::string> found;
  for (const char* needle : {"http:", "https:", "src=\"//", "href=\"//", "url(//", "@import", "<script", "<link"}) {
    std::string lower = html;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
    if (lower.find(needle) != std::string::npos) found.push_back(needle);
  }
  return found;
}

inline std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t pos = 0; (pos = text.find(what, pos)) != std::string::npos; pos += what.size()) ++n;
  return n;
}

}  // namespace frostwall::test
