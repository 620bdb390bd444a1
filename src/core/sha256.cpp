#include "core/sha256.hpp"

#include <openssl/evp.h>

#include <stdexcept>

namespace creaturelab::core {

void Sha256::FreeCtx::operator()(evp_md_ctx_st* ctx) const { EVP_MD_CTX_free(ctx); }

Sha256::Sha256() : ctx_(EVP_MD_CTX_new()) {
  if (!ctx_ || EVP_DigestInit_ex(ctx_.get(), EVP_sha256(), nullptr) != 1)
    throw std::runtime_error("SHA-256: OpenSSL could not set up the digest (EVP_DigestInit_ex failed)");
}

void Sha256::update(const void* data, std::size_t size) {
  if (finished_ || size == 0) return;
  if (EVP_DigestUpdate(ctx_.get(), data, size) != 1) throw std::runtime_error("SHA-256: EVP_DigestUpdate failed");
}

std::array<std::uint8_t, 32> Sha256::digest() {
  if (!finished_) {
    unsigned int length = 0;
    if (EVP_DigestFinal_ex(ctx_.get(), digest_.data(), &length) != 1 || length != digest_.size())
      throw std::runtime_error("SHA-256: EVP_DigestFinal_ex failed");
    finished_ = true;
  }
  return digest_;
}

std::string Sha256::hexDigest() {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(64);
  for (std::uint8_t b : digest()) {
    out.push_back(kHex[b >> 4]);
    out.push_back(kHex[b & 15]);
  }
  return out;
}

std::string sha256Hex(std::string_view bytes) {
  Sha256 h;
  h.update(bytes);
  return h.hexDigest();
}

}  // namespace creaturelab::core
