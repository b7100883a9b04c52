#include "report/svg.hpp"

#include <atomic>
#include <fmt/core.h>

namespace frostwall::report::svg {

std::string num(double v) {
  std::string s = fmt::format("{:.2f}", v);
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

std::string unique_id(std::string_view prefix) {
  static std::atomic<unsigned long> counter{0};
  return fmt::format("{}-{}", prefix, ++counter);
}

double text_width(std::string_view text, double font_size) {
  // UTF-8 continuation bytes do not start a glyph.
  std::size_t glyphs = 0;
  for (unsigned char c : text) glyphs += (c & 0xC0) != 0x80;
  return 0.58 * font_size * static_cast<double>(glyphs);
}

}  // namespace frostwall::report::svg
