#pragma once
// SHA-256 (FIPS 180-4, same function as FIPS 180-2). Used for config hashes and
// the HDF5 content digests that the determinism tests compare.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace creaturelab::core {

// Incremental hasher: update() any number of times, then digest()/hexDigest().
// The first digest call finalises: later update() calls are ignored and later digest
// calls return the same value. Hash something else with a new Sha256.
class Sha256 {
public:
  Sha256();
  void update(const void* data, std::size_t size);
  void update(std::string_view bytes) { update(bytes.data(), bytes.size()); }
  std::array<std::uint8_t, 32> digest();  // finalises
  std::string hexDigest();                // finalises; 64 lowercase hex characters

private:
  void compressBlock(const std::uint8_t* block);

  std::array<std::uint32_t, 8> state_;
  std::array<std::uint8_t, 64> buffer_{};
  std::size_t buffered_ = 0;
  std::uint64_t total_bytes_ = 0;
  bool finished_ = false;
};

// One-shot: lowercase hex SHA-256 of the bytes.
std::string sha256Hex(std::string_view bytes);

}  // namespace creaturelab::core
