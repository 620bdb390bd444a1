// SHA-256 against the FIPS 180-2 appendix B examples.
#include "core/sha256.hpp"

#include <gtest/gtest.h>

#include <string>

namespace cl = creaturelab::core;

TEST(Sha256, EmptyString) {
  EXPECT_EQ(cl::sha256Hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

TEST(Sha256, Fips180OneBlockAbc) {
  EXPECT_EQ(cl::sha256Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

TEST(Sha256, Fips180TwoBlock448Bit) {
  EXPECT_EQ(cl::sha256Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST(Sha256, Fips180OneMillionA) {
  EXPECT_EQ(cl::sha256Hex(std::string(1'000'000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, IncrementalEqualsOneShotForAnySplit) {
  const std::string message(1'000, 'q');
  const std::string expected = cl::sha256Hex(message);
  for (std::size_t split : {0u, 1u, 55u, 56u, 63u, 64u, 65u, 127u, 999u, 1000u}) {
    cl::Sha256 hasher;
    hasher.update(message.data(), split);
    hasher.update(message.data() + split, message.size() - split);
    EXPECT_EQ(hasher.hexDigest(), expected) << "split at " << split;
  }
}

TEST(Sha256, MillionAFedInOddChunks) {
  cl::Sha256 hasher;
  const std::string chunk(7, 'a');
  std::size_t fed = 0;
  for (; fed + chunk.size() <= 1'000'000; fed += chunk.size()) hasher.update(chunk);
  hasher.update(std::string(1'000'000 - fed, 'a'));
  EXPECT_EQ(hasher.hexDigest(), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}
