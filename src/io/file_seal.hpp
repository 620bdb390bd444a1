#pragma once
// The seal of a file this program writes: libhdf5 trusts what it reads (a corrupt global heap can
// make it crash), so every HDF5 file is created with a 512-byte user block that, once the file is
// closed, holds one line "creaturelab seal sha256 <hex>\n" (the SHA-256 of every byte after the
// block) and zeros. Readers check the seal before libhdf5 opens the file. A file whose superblock
// sits at byte 0 has no user block (an older run, another program's file) and is not checked.
#include <cstddef>
#include <filesystem>
#include <string>

namespace creaturelab::io {

inline constexpr std::size_t kSealBlockBytes = 512;  // the user block, HDF5's smallest

// Writes the seal of a closed file that was created with a kSealBlockBytes user block, and fsyncs
// the file. Does not follow a symbolic link. Throws Hdf5Error naming the file.
void sealFile(const std::filesystem::path& path);

enum class SealState {
  none,    // no user block: a file this program did not seal
  intact,  // the seal matches every byte after the block
  broken,  // a user block whose seal is damaged or does not match the bytes (problem says which)
};

struct SealCheck {
  SealState state = SealState::none;
  std::string problem;  // for broken: what is wrong, in words
};

// Reads the whole file (a missing or unreadable file is SealState::none: opening it reports that;
// a FIFO, socket or character device is broken: libhdf5 would block on it).
SealCheck checkSeal(const std::filesystem::path& path);

// Throws Hdf5Error "file "<path>": <problem>" when the seal is broken.
void requireIntactSeal(const std::filesystem::path& path);

}  // namespace creaturelab::io
