#include "io/file_seal.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <string_view>
#include <vector>

#include "core/sha256.hpp"
#include "io/hdf5_error.hpp"

namespace creaturelab::io {
namespace {

constexpr std::string_view kPrefix = "creaturelab seal sha256 ";
constexpr std::string_view kHdf5Signature = "\x89HDF\r\n\x1a\n";
constexpr std::size_t kLineBytes = kPrefix.size() + 64 + 1;

// Closes a POSIX descriptor on every path out.
struct Descriptor {
  int fd = -1;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

[[noreturn]] void failFile(const std::filesystem::path& path, const std::string& what) {
  throw Hdf5Error("file \"" + path.string() + "\": " + what + ": " + std::strerror(errno));
}

// Reads up to `size` bytes at `offset`; returns the count read (short only at the end of the file).
std::size_t readAt(int fd, char* buffer, std::size_t size, off_t offset) {
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::pread(fd, buffer + done, size - done, offset + off_t(done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    done += std::size_t(n);
  }
  return done;
}

// SHA-256 (hex) of every byte from kSealBlockBytes to the end; "" when the file cannot be read.
std::string hashAfterBlock(int fd) {
  core::Sha256 sha;
  std::vector<char> buffer(std::size_t{1} << 20);
  off_t offset = off_t(kSealBlockBytes);
  for (;;) {
    const ssize_t n = ::pread(fd, buffer.data(), buffer.size(), offset);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return "";
    if (n == 0) break;
    sha.update(buffer.data(), std::size_t(n));
    offset += n;
  }
  return sha.hexDigest();
}

}  // namespace

void sealFile(const std::filesystem::path& path) {
  Descriptor file{::open(path.c_str(), O_RDWR | O_NOFOLLOW | O_CLOEXEC)};
  if (file.fd < 0) failFile(path, "cannot open to seal");
  const std::string digest = hashAfterBlock(file.fd);
  if (digest.empty()) failFile(path, "cannot read to seal");
  std::array<char, kSealBlockBytes> block{};
  const std::string line = std::string(kPrefix) + digest + "\n";
  std::copy(line.begin(), line.end(), block.begin());
  if (::pwrite(file.fd, block.data(), block.size(), 0) != ssize_t(block.size())) failFile(path, "cannot write its seal");
  if (::fsync(file.fd) != 0) failFile(path, "cannot sync");
}

SealCheck checkSeal(const std::filesystem::path& path) {
  // Non-blocking: a FIFO planted under a file's name would otherwise block here (and in libhdf5).
  Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) return {};
  struct stat st {};
  if (::fstat(file.fd, &st) != 0 || S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode) || S_ISCHR(st.st_mode))
    return {SealState::broken, "not a regular file"};
  std::array<char, kSealBlockBytes + 8> head{};
  const std::size_t got = readAt(file.fd, head.data(), head.size(), 0);
  const std::string_view bytes(head.data(), got);
  if (bytes.substr(0, kHdf5Signature.size()) == kHdf5Signature) return {};
  const bool has_block = got > kSealBlockBytes && bytes.substr(kSealBlockBytes) == kHdf5Signature;
  const bool has_prefix = bytes.substr(0, kPrefix.size()) == kPrefix;
  if (!has_block && !has_prefix) return {};  // not an HDF5 file this program wrote: libhdf5 says what it is
  if (got < kSealBlockBytes) return {SealState::broken, "shorter than its seal block (truncated)"};
  const std::string_view line = bytes.substr(0, kLineBytes);
  const bool zeros = std::all_of(head.begin() + kLineBytes, head.begin() + kSealBlockBytes, [](char c) { return c == 0; });
  if (!has_prefix || line.back() != '\n' || !zeros)
    return {SealState::broken, "its seal (the first 512 bytes) is damaged"};
  const std::string digest = hashAfterBlock(file.fd);
  if (digest.empty()) return {SealState::broken, "cannot be read whole"};
  if (line.substr(kPrefix.size(), 64) != digest)
    return {SealState::broken, "its bytes differ from its seal (damaged, truncated or changed after it was written)"};
  return {SealState::intact, ""};
}

void requireIntactSeal(const std::filesystem::path& path) {
  const SealCheck seal = checkSeal(path);
  if (seal.state == SealState::broken) throw Hdf5Error("file \"" + path.string() + "\": " + seal.problem);
}

}  // namespace creaturelab::io
