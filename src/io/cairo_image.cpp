#include "io/cairo_image.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace creaturelab::io {

CairoImage::CairoImage(int width, int height, PixelFormat format) : width_(width), height_(height), format_(format) {
  if (width <= 0 || height <= 0)
    throw std::runtime_error("image of " + std::to_string(width) + " x " + std::to_string(height) +
                             " pixels: each side must be at least 1");
  surface_ = cairo_image_surface_create(format == PixelFormat::grey8 ? CAIRO_FORMAT_A8 : CAIRO_FORMAT_RGB24, width,
                                        height);
  cr_ = cairo_create(surface_);
  check("creating the image");
}

CairoImage CairoImage::fromCoverage(int width, int height, const std::vector<float>& coverage) {
  if (coverage.size() != std::size_t(width) * std::size_t(height))
    throw std::invalid_argument("fromCoverage: " + std::to_string(coverage.size()) + " values for a " +
                                std::to_string(width) + " x " + std::to_string(height) + " image");
  CairoImage img(width, height, PixelFormat::grey8);
  cairo_surface_flush(img.surface_);
  unsigned char* data = cairo_image_surface_get_data(img.surface_);
  const int stride = cairo_image_surface_get_stride(img.surface_);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      data[std::size_t(y) * std::size_t(stride) + std::size_t(x)] = static_cast<unsigned char>(
          std::lround(std::clamp(coverage[std::size_t(y) * std::size_t(width) + std::size_t(x)], 0.0f, 1.0f) * 255.0f));
  cairo_surface_mark_dirty(img.surface_);
  return img;
}

CairoImage::~CairoImage() {
  if (cr_) cairo_destroy(cr_);
  if (surface_) cairo_surface_destroy(surface_);
}

CairoImage::CairoImage(CairoImage&& o) noexcept
    : width_(o.width_), height_(o.height_), format_(o.format_), surface_(o.surface_), cr_(o.cr_) {
  o.surface_ = nullptr;
  o.cr_ = nullptr;
}

void CairoImage::check(const char* what) const {
  cairo_status_t s = cairo_surface_status(surface_);
  if (s == CAIRO_STATUS_SUCCESS) s = cairo_status(cr_);
  if (s != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string("cairo, ") + what + " (" + std::to_string(width_) + " x " +
                             std::to_string(height_) + " pixels): " + cairo_status_to_string(s));
}

std::vector<float> CairoImage::coverage() {
  if (format_ != PixelFormat::grey8) throw std::logic_error("coverage() of an rgb24 image");
  check("drawing");
  cairo_surface_flush(surface_);
  const unsigned char* data = cairo_image_surface_get_data(surface_);
  const int stride = cairo_image_surface_get_stride(surface_);
  std::vector<float> out(std::size_t(width_) * std::size_t(height_));
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x)
      out[std::size_t(y) * std::size_t(width_) + std::size_t(x)] =
          float(data[std::size_t(y) * std::size_t(stride) + std::size_t(x)]) / 255.0f;
  return out;
}

std::vector<std::uint8_t> CairoImage::rgb() {
  if (format_ != PixelFormat::rgb24) throw std::logic_error("rgb() of a grey8 image");
  check("drawing");
  cairo_surface_flush(surface_);
  const unsigned char* data = cairo_image_surface_get_data(surface_);
  const int stride = cairo_image_surface_get_stride(surface_);
  std::vector<std::uint8_t> out;
  out.reserve(std::size_t(width_) * std::size_t(height_) * 3);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      // CAIRO_FORMAT_RGB24: one native-endian 32-bit word per pixel, 0x00RRGGBB.
      std::uint32_t word;
      std::copy_n(data + std::size_t(y) * std::size_t(stride) + 4 * std::size_t(x), 4,
                  reinterpret_cast<unsigned char*>(&word));
      out.push_back(std::uint8_t(word >> 16));
      out.push_back(std::uint8_t(word >> 8));
      out.push_back(std::uint8_t(word));
    }
  return out;
}

std::vector<std::uint8_t> CairoImage::png() {
  check("drawing");
  cairo_surface_flush(surface_);
  std::vector<std::uint8_t> out;
  const cairo_status_t s = cairo_surface_write_to_png_stream(
      surface_,
      [](void* closure, const unsigned char* data, unsigned int length) {
        auto* bytes = static_cast<std::vector<std::uint8_t>*>(closure);
        bytes->insert(bytes->end(), data, data + length);
        return CAIRO_STATUS_SUCCESS;
      },
      &out);
  if (s != CAIRO_STATUS_SUCCESS) throw std::runtime_error(std::string("cairo, encoding PNG: ") + cairo_status_to_string(s));
  return out;
}

}  // namespace creaturelab::io
