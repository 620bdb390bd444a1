#include "runner/folder_lock.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "runner/experiment.hpp"

namespace creaturelab::runner {
namespace {

struct flock range(short type, off_t start) {
  struct flock l {};
  l.l_type = type;
  l.l_whence = SEEK_SET;
  l.l_start = start;
  l.l_len = 1;
  return l;
}

}  // namespace

FolderLock FolderLock::acquire(const std::string& dir, Mode mode) {
  const std::string path = dir + "/" + kFileName;
  FolderLock lock;
  lock.dir_ = dir;
  lock.fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);  // never through a link
  if (lock.fd_ < 0) throw ExperimentError(path + ": cannot open the run folder's lock: " + std::strerror(errno));
  const short type = mode == Mode::Exclusive ? F_WRLCK : F_RDLCK;
  for (int attempt = 0; attempt < 3; ++attempt) {
    struct flock want = range(type, 0);
    if (::fcntl(lock.fd_, F_SETLK, &want) == 0) return lock;
    if (errno != EACCES && errno != EAGAIN)
      throw ExperimentError(path + ": cannot lock the run folder: " + std::strerror(errno));
    struct flock holder = range(type, 0);
    if (::fcntl(lock.fd_, F_GETLK, &holder) == 0 && holder.l_type != F_UNLCK)
      throw ExperimentError("output folder " + dir + " is being written by another creaturelab process (pid " +
                            std::to_string(holder.l_pid) + "); wait for it to end or use another --out");
    // The holder let go between the two calls: try again.
  }
  throw ExperimentError("output folder " + dir + " is being written by another creaturelab process");
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);  // closing releases every lock this process holds on the file
}

FolderLock& FolderLock::operator=(FolderLock&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = other.fd_;
    dir_ = std::move(other.dir_);
    other.fd_ = -1;
  }
  return *this;
}

void FolderLock::lockIndex() const {
  if (fd_ < 0) return;
  struct flock want = range(F_WRLCK, 1);
  while (::fcntl(fd_, F_SETLKW, &want) != 0)
    if (errno != EINTR)
      throw ExperimentError(dir_ + "/" + kFileName + ": cannot lock the index: " + std::strerror(errno));
}

void FolderLock::unlockIndex() const {
  if (fd_ < 0) return;
  struct flock none = range(F_UNLCK, 1);
  ::fcntl(fd_, F_SETLK, &none);
}

}  // namespace creaturelab::runner
