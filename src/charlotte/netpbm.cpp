#include "charlotte/netpbm.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

namespace creaturelab::charlotte {
namespace {

bool isSpace(std::uint8_t c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

class Reader {
 public:
  Reader(std::span<const std::uint8_t> bytes, const std::string& name) : b_(bytes), name_(name) {}

  [[noreturn]] void fail(const std::string& what) const { throw std::invalid_argument(name_ + ": " + what); }

  // Skips whitespace and '#' comments (to the end of the line), as the Netpbm header allows.
  void skipSpaceAndComments() {
    while (pos_ < b_.size()) {
      if (isSpace(b_[pos_])) ++pos_;
      else if (b_[pos_] == '#') {
        while (pos_ < b_.size() && b_[pos_] != '\n' && b_[pos_] != '\r') ++pos_;
      } else return;
    }
  }

  // A decimal header field (width, height, maxval), at most 9 digits so it cannot overflow.
  long headerNumber(const char* field) {
    skipSpaceAndComments();
    if (pos_ >= b_.size()) fail(std::string("the header ends before the ") + field);
    long v = 0;
    int digits = 0;
    while (pos_ < b_.size() && b_[pos_] >= '0' && b_[pos_] <= '9') {
      if (++digits > 9) fail(std::string("the ") + field + " has more than 9 digits");
      v = v * 10 + (b_[pos_++] - '0');
    }
    if (digits == 0) fail(std::string("the ") + field + " is not a number (found '" + char(b_[pos_]) + "')");
    return v;
  }

  // Binary formats: exactly one whitespace byte separates the header from the pixels.
  void oneSpace(const char* after) {
    if (pos_ >= b_.size() || !isSpace(b_[pos_]))
      fail(std::string("expected one whitespace byte after the ") + after + ", before the pixel data");
    ++pos_;
  }

  // Text formats: the next value; for P1 a single digit (P1 allows digits without separators).
  long textValue(bool single_digit, long x, long y) {
    skipSpaceAndComments();
    if (pos_ >= b_.size())
      fail("the pixel data ends at row " + std::to_string(y + 1) + ", column " + std::to_string(x + 1) +
           " (truncated file?)");
    if (b_[pos_] < '0' || b_[pos_] > '9')
      fail("pixel at row " + std::to_string(y + 1) + ", column " + std::to_string(x + 1) + " is not a number (found '" +
           char(b_[pos_]) + "')");
    if (single_digit) return b_[pos_++] - '0';
    long v = 0;
    int digits = 0;
    while (pos_ < b_.size() && b_[pos_] >= '0' && b_[pos_] <= '9') {
      if (++digits > 6) fail("pixel at row " + std::to_string(y + 1) + ", column " + std::to_string(x + 1) + " is too large");
      v = v * 10 + (b_[pos_++] - '0');
    }
    return v;
  }

  std::span<const std::uint8_t> take(std::size_t n) {
    if (b_.size() - pos_ < n)
      fail("truncated: the pixel data needs " + std::to_string(n) + " bytes, the file has " +
           std::to_string(b_.size() - pos_));
    auto s = b_.subspan(pos_, n);
    pos_ += n;
    return s;
  }

  std::size_t pos() const { return pos_; }
  std::size_t size() const { return b_.size(); }
  std::uint8_t peek(std::size_t i) const { return b_[i]; }

 private:
  std::span<const std::uint8_t> b_;
  const std::string& name_;
  std::size_t pos_ = 0;
};

}  // namespace

Raster parseNetpbm(std::span<const std::uint8_t> bytes, const std::string& name) {
  Reader in(bytes, name);
  if (bytes.empty()) in.fail("the file is empty; expected a PBM or PGM image (P1, P2, P4 or P5)");
  if (bytes.size() < 2 || bytes[0] != 'P' || !(bytes[1] == '1' || bytes[1] == '2' || bytes[1] == '4' || bytes[1] == '5')) {
    std::string start;
    for (std::size_t i = 0; i < std::min<std::size_t>(2, bytes.size()); ++i)
      start += (bytes[i] >= 0x20 && bytes[i] < 0x7f) ? char(bytes[i]) : '?';
    in.fail("not a PBM or PGM image: it starts with \"" + start +
            "\", expected P1, P2 (text) or P4, P5 (binary); convert other formats first, e.g. with ImageMagick: "
            "convert in.png out.pgm");
  }
  const char kind = char(bytes[1]);
  Reader& r = in;
  (void)r.take(2);  // the magic number
  const long width = r.headerNumber("width"), height = r.headerNumber("height");
  if (width == 0 || height == 0)
    r.fail("the image is " + std::to_string(width) + " x " + std::to_string(height) + " pixels; it needs at least one pixel");
  if (width > kMaxImageSidePx || height > kMaxImageSidePx || width * height > kMaxImagePixels)
    r.fail("the image is " + std::to_string(width) + " x " + std::to_string(height) + " pixels, too large: at most " +
           std::to_string(kMaxImageSidePx) + " pixels a side and " + std::to_string(kMaxImagePixels) +
           " pixels in all (the canvas is 600 x 600); scale it down first");
  const bool bitmap = kind == '1' || kind == '4';
  long maxval = 1;
  if (!bitmap) {
    maxval = r.headerNumber("maxval");
    if (maxval < 1 || maxval > 65535) r.fail("maxval " + std::to_string(maxval) + " is outside 1..65535");
  }
  Raster out(static_cast<int>(width), static_cast<int>(height));
  auto set = [&](long x, long y, long v) {
    if (v > maxval)
      r.fail("pixel at row " + std::to_string(y + 1) + ", column " + std::to_string(x + 1) + " is " + std::to_string(v) +
             ", above maxval " + std::to_string(maxval));
    // PBM: 1 = black = ink. PGM: 0 = black, maxval = white; ink = 1 - grey / maxval.
    out.at(int(x), int(y)) = bitmap ? float(v) : float(1.0 - double(v) / double(maxval));
  };
  if (kind == '1' || kind == '2') {
    for (long y = 0; y < height; ++y)
      for (long x = 0; x < width; ++x) set(x, y, r.textValue(kind == '1', x, y));
  } else if (kind == '4') {
    r.oneSpace("height");
    const std::size_t row_bytes = std::size_t((width + 7) / 8);
    const auto data = r.take(row_bytes * std::size_t(height));
    for (long y = 0; y < height; ++y)
      for (long x = 0; x < width; ++x) set(x, y, (data[std::size_t(y) * row_bytes + std::size_t(x / 8)] >> (7 - x % 8)) & 1);
  } else {  // P5
    r.oneSpace("maxval");
    const std::size_t bytes_per = maxval < 256 ? 1 : 2;
    const auto data = r.take(bytes_per * std::size_t(width) * std::size_t(height));
    for (long y = 0; y < height; ++y)
      for (long x = 0; x < width; ++x) {
        const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * bytes_per;
        set(x, y, bytes_per == 1 ? long(data[i]) : long(data[i]) << 8 | long(data[i + 1]));  // 16 bits: big-endian
      }
  }
  return out;
}

Raster readNetpbmFile(const std::string& path) {
  if (path.empty()) throw std::invalid_argument("no image file given: set image_file to a PBM or PGM file");
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw std::invalid_argument(path + ": cannot be read (not a regular file)");
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::invalid_argument(path + ": cannot be read (" + std::strerror(errno) + ")");
  // Refuse to read a file far larger than the largest acceptable image (16-bit PGM plus header).
  f.seekg(0, std::ios::end);
  const std::streamoff size = f.tellg();
  if (size < 0) throw std::invalid_argument(path + ": cannot be read (not a regular file?)");
  if (size > 2 * kMaxImagePixels + 4096)
    throw std::invalid_argument(path + ": the file is " + std::to_string(size) +
                                " bytes, larger than any accepted image (at most " + std::to_string(kMaxImageSidePx) +
                                " pixels a side, " + std::to_string(kMaxImagePixels) + " pixels in all)");
  f.seekg(0);
  std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
  if (f.bad()) throw std::invalid_argument(path + ": cannot be read (I/O error)");
  return parseNetpbm(bytes, path);
}

}  // namespace creaturelab::charlotte
