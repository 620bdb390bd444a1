#include "charlotte/png.hpp"

#include <array>
#include <stdexcept>
#include <string>

#ifdef CREATURELAB_HAVE_ZLIB
#include <zlib.h>
#endif

namespace creaturelab::charlotte {
namespace {

std::array<std::uint32_t, 256> crcTable() {
  std::array<std::uint32_t, 256> t{};
  for (std::uint32_t n = 0; n < 256; ++n) {
    std::uint32_t c = n;
    for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    t[n] = c;
  }
  return t;
}

void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out.push_back(std::uint8_t(v >> s));
}

void chunk(std::vector<std::uint8_t>& out, const char type[4], const std::vector<std::uint8_t>& data) {
  put32(out, std::uint32_t(data.size()));
  const std::size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data.begin(), data.end());
  put32(out, crc32(out.data() + start, out.size() - start));
}

// The zlib stream (RFC 1950) of the filtered scanlines.
std::vector<std::uint8_t> zlibStream(const std::vector<std::uint8_t>& raw) {
#ifdef CREATURELAB_HAVE_ZLIB
  uLongf size = compressBound(uLong(raw.size()));
  std::vector<std::uint8_t> out(size);
  if (compress2(out.data(), &size, raw.data(), uLong(raw.size()), 6) != Z_OK)
    throw std::runtime_error("encodePng: zlib compress2 failed");
  out.resize(size);
  return out;
#else
  // Stored deflate blocks (RFC 1951 §3.2.4), at most 65535 bytes each, then the Adler-32 (RFC 1950).
  std::vector<std::uint8_t> out = {0x78, 0x01};
  std::size_t pos = 0;
  do {
    const std::size_t n = std::min<std::size_t>(65535, raw.size() - pos);
    out.push_back(pos + n == raw.size() ? 1 : 0);
    out.push_back(std::uint8_t(n));
    out.push_back(std::uint8_t(n >> 8));
    out.push_back(std::uint8_t(~n));
    out.push_back(std::uint8_t(~n >> 8));
    out.insert(out.end(), raw.begin() + long(pos), raw.begin() + long(pos + n));
    pos += n;
  } while (pos < raw.size());
  std::uint32_t a = 1, b = 0;
  for (std::uint8_t c : raw) {
    a = (a + c) % 65521;
    b = (b + a) % 65521;
  }
  put32(out, (b << 16) | a);
  return out;
#endif
}

}  // namespace

std::uint32_t crc32(const std::uint8_t* data, std::size_t size, std::uint32_t crc) {
  static const auto table = crcTable();
  crc = ~crc;
  for (std::size_t i = 0; i < size; ++i) crc = table[(crc ^ data[i]) & 0xff] ^ (crc >> 8);
  return ~crc;
}

std::vector<std::uint8_t> encodePng(const RgbImage& image) {
  if (image.width <= 0 || image.height <= 0 || image.rgb.size() != std::size_t(image.width) * image.height * 3)
    throw std::invalid_argument("encodePng: the image is empty or its pixel buffer has the wrong size");
  std::vector<std::uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<std::uint8_t> ihdr;
  put32(ihdr, std::uint32_t(image.width));
  put32(ihdr, std::uint32_t(image.height));
  ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});  // 8 bits, truecolour, deflate, adaptive filters, no interlace
  chunk(out, "IHDR", ihdr);
  std::vector<std::uint8_t> raw;
  const std::size_t row = std::size_t(image.width) * 3;
  raw.reserve((row + 1) * std::size_t(image.height));
  for (int y = 0; y < image.height; ++y) {
    raw.push_back(0);  // filter type 0 (none)
    raw.insert(raw.end(), image.rgb.begin() + long(row * std::size_t(y)), image.rgb.begin() + long(row * std::size_t(y + 1)));
  }
  chunk(out, "IDAT", zlibStream(raw));
  chunk(out, "IEND", {});
  return out;
}

}  // namespace creaturelab::charlotte
