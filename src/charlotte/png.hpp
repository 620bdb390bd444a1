#pragma once
// A minimal PNG encoder for the renders (8-bit RGB, no interlace, filter 0 on every row), after the
// PNG specification (ISO/IEC 15948, W3C PNG 2nd ed.): signature, IHDR, IDAT (zlib stream), IEND,
// each chunk with its CRC-32. With zlib present the image data is deflated; without it the zlib
// stream is written as stored (uncompressed) deflate blocks, which every PNG reader accepts.
// No I/O: returns the file's bytes.
#include <cstdint>
#include <vector>

#include "charlotte/raster.hpp"

namespace creaturelab::charlotte {

std::vector<std::uint8_t> encodePng(const RgbImage& image);

// CRC-32 (ISO 3309, polynomial 0xEDB88320 reflected), as PNG chunks use it. Exposed for tests.
std::uint32_t crc32(const std::uint8_t* data, std::size_t size, std::uint32_t crc = 0);

}  // namespace creaturelab::charlotte
