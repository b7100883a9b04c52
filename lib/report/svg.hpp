// Small helpers for SVG written by hand: compact numbers, ids unique
// within one HTML page (inline SVGs share the page's ids), the font and a
// text's rough width. Text goes in through io::xml_escape.
#pragma once

#include <string>
#include <string_view>

namespace frostwall::report::svg {

// A coordinate with two decimals at most, trailing zeros dropped.
std::string num(double v);

// "prefix-N", N counting up over the process (thread-safe).
std::string unique_id(std::string_view prefix);

// The font stack of every figure (a journal-figure sans serif).
inline constexpr const char* font_family = "DejaVu Sans, Helvetica, Arial, sans-serif";

// Rough width of a text in pixels at a font size: labels are placed
// before a browser measures them, so layout keeps a margin.
double text_width(std::string_view text, double font_size);

}  // namespace frostwall::report::svg
