#pragma once
// One writer per run folder (DESIGN.md "Results"): a POSIX record lock (fcntl) on
// <dir>/.creaturelab.lock. The kernel releases it when the process ends, however it ends, so a
// crash never leaves a stale lock behind (the empty file stays; only the lock on it means anything).
// fcntl rather than flock: F_GETLK reports the holder's pid, which the refusal names.
//
// Modes: a whole run (or MPI rank 0 on behalf of its ranks, which write into the folder under
// rank 0's lock) takes byte 0 exclusively; `--points i/N` shares of one run are meant to run at
// once, so they share byte 0 (a whole run still excludes them), and the point files' configuration
// fingerprints keep shares of different configurations from mixing. Writing index.h5 takes byte 1
// exclusively and waits for it, so shares finishing together take turns.
#include <string>

namespace creaturelab::runner {

class FolderLock {
 public:
  enum class Mode { Exclusive, Shared };
  static constexpr const char* kFileName = ".creaturelab.lock";

  FolderLock() = default;
  // Creates the lock file if needed and locks it without waiting. Throws ExperimentError naming
  // the folder and the holder's pid when another process holds a conflicting lock.
  static FolderLock acquire(const std::string& dir, Mode mode);
  ~FolderLock();
  FolderLock(FolderLock&& other) noexcept : fd_(other.fd_), dir_(std::move(other.dir_)) { other.fd_ = -1; }
  FolderLock& operator=(FolderLock&& other) noexcept;
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

  bool held() const { return fd_ >= 0; }
  // Waits for the index byte (see above); released by unlockIndex() or when the lock goes.
  void lockIndex() const;
  void unlockIndex() const;

 private:
  int fd_ = -1;
  std::string dir_;
};

}  // namespace creaturelab::runner
