#pragma once
// An RGBA float image: the in-memory form of every EXR/PNG confvis reads or writes, and of each
// cube-map face. Linear values, no colour space attached.
#include <cassert>
#include <cstddef>
#include <vector>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct ImageRGBA {
  int width = 0, height = 0;
  std::vector<float> pixels;  // RGBA interleaved, row-major, row 0 at the top

  ImageRGBA() = default;
  // A width x height image filled with `value` in all four channels.
  ImageRGBA(int w, int h, float value = 0.0f)
      : width(w), height(h), pixels(static_cast<std::size_t>(w) * h * 4, value) {
    assert(w >= 0 && h >= 0);
  }

  bool empty() const { return width <= 0 || height <= 0; }
  std::size_t pixelCount() const { return static_cast<std::size_t>(width) * height; }

  // The 4 channels of pixel (x, y); x to the right, y downwards.
  float* at(int x, int y) {
    assert(x >= 0 && x < width && y >= 0 && y < height);
    return pixels.data() + (static_cast<std::size_t>(y) * width + x) * 4;
  }
  const float* at(int x, int y) const {
    assert(x >= 0 && x < width && y >= 0 && y < height);
    return pixels.data() + (static_cast<std::size_t>(y) * width + x) * 4;
  }

  // False if any channel of any pixel is NaN or infinite; writers refuse such images.
  bool allFinite() const;
};

}  // namespace confvis
