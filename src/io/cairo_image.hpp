#pragma once
// Raster images drawn with cairo (libcairo2-dev): a thin RAII face over one image surface and its
// drawing context, the pixels read back as floats, PNG bytes from cairo's own encoder. In memory
// only: no file is read or written here (the runner writes the bytes it is given).
//
// Two pixel formats: grey8 (cairo's A8: one coverage byte per pixel, what the Charlotte's-web
// measurement rasters are) and rgb24 (opaque colour, the renders).
#include <cairo.h>

#include <cstdint>
#include <vector>

namespace creaturelab::io {

enum class PixelFormat { grey8, rgb24 };

class CairoImage {
 public:
  // A width x height image, every pixel 0 (grey8: empty; rgb24: black). Throws std::runtime_error
  // naming the size when cairo cannot make it (0 or too large a side, out of memory).
  CairoImage(int width, int height, PixelFormat format);
  // A grey8 image holding `coverage` (row-major, width x height values in [0, 1], clamped).
  static CairoImage fromCoverage(int width, int height, const std::vector<float>& coverage);
  ~CairoImage();
  CairoImage(CairoImage&& other) noexcept;
  CairoImage& operator=(CairoImage&&) = delete;
  CairoImage(const CairoImage&) = delete;
  CairoImage& operator=(const CairoImage&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  PixelFormat format() const { return format_; }
  cairo_t* cr() { return cr_; }                    // draw with the cairo API
  cairo_surface_t* surface() { return surface_; }  // e.g. as a source or mask for another image

  // grey8: each pixel's coverage in [0, 1] (byte / 255), row-major, row 0 at the top.
  // Flushes pending drawing first. Throws std::logic_error on an rgb24 image.
  std::vector<float> coverage();
  // rgb24: 3 bytes per pixel (r, g, b), row-major. Throws std::logic_error on a grey8 image.
  std::vector<std::uint8_t> rgb();
  // The image as a PNG file's bytes (cairo's encoder; grey8 as 8-bit alpha-only, rgb24 as RGB).
  // Throws std::runtime_error with cairo's message if encoding fails.
  std::vector<std::uint8_t> png();

 private:
  void check(const char* what) const;  // throws if the surface or context is in an error state

  int width_, height_;
  PixelFormat format_;
  cairo_surface_t* surface_ = nullptr;
  cairo_t* cr_ = nullptr;
};

}  // namespace creaturelab::io
