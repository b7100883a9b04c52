// An RGBA raster encoded as PNG in memory (VTK's PNG writer; no window,
// no GPU), for the report's inline data URIs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace frostwall::report {

struct RgbaImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;  // rows top to bottom, 4 bytes a pixel
  RgbaImage(int w, int h) : width(w), height(h), pixels(std::size_t(w) * std::size_t(h) * 4, 0) {}
  std::uint8_t* at(int x, int y) { return pixels.data() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4; }
};

// The PNG file's bytes.
std::string encode_png(const RgbaImage& image);

// "data:image/png;base64,..."
std::string png_data_uri(const RgbaImage& image);

}  // namespace frostwall::report
