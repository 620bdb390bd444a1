#pragma once
// SHA-256 (FIPS 180-4) for config hashes and the HDF5 content digests that the determinism tests
// compare. A thin face over OpenSSL's EVP digest API (libssl-dev), a maintained, validated
// implementation; nothing of the hash itself is written here.

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

struct evp_md_ctx_st;  // OpenSSL's EVP_MD_CTX, kept out of this header

namespace creaturelab::core {

// Incremental hasher: update() any number of times, then digest()/hexDigest().
// The first digest call finalises: later update() calls are ignored and later digest
// calls return the same value. Hash something else with a new Sha256. Move-only.
class Sha256 {
public:
  Sha256();  // throws std::runtime_error if OpenSSL cannot set up SHA-256
  void update(const void* data, std::size_t size);
  void update(std::string_view bytes) { update(bytes.data(), bytes.size()); }
  std::array<std::uint8_t, 32> digest();  // finalises
  std::string hexDigest();                // finalises; 64 lowercase hex characters

private:
  struct FreeCtx {
    void operator()(evp_md_ctx_st* ctx) const;
  };
  std::unique_ptr<evp_md_ctx_st, FreeCtx> ctx_;
  std::array<std::uint8_t, 32> digest_{};
  bool finished_ = false;
};

// One-shot: lowercase hex SHA-256 of the bytes.
std::string sha256Hex(std::string_view bytes);

}  // namespace creaturelab::core
