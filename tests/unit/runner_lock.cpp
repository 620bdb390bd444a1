// One writer per run folder: the fcntl lock refuses a second process and names the
// holder's pid; shares (--points) coexist with each other but not with a whole run; the lock goes
// with the process. The second process is a fork: fcntl locks never conflict within one process.
#include "scratch_dir_test.hpp"
#include "runner/folder_lock.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>

#include "runner/experiment.hpp"

namespace {

using creaturelab::runner::ExperimentError;
using creaturelab::runner::FolderLock;
using Mode = FolderLock::Mode;

class RunnerLock : public creaturelab::testing::ScratchDirTest {
 protected:
  RunnerLock() : ScratchDirTest("creaturelab_runner_lock") {}
};

// In a child process: 0 if the lock was taken, 1 if refused naming `holder`'s pid, 2 otherwise.
int tryInChild(const std::string& dir, Mode mode, pid_t holder) {
  const pid_t child = fork();
  if (child == 0) {
    int code = 2;
    try {
      FolderLock::acquire(dir, mode);
      code = 0;
    } catch (const ExperimentError& e) {
      code = std::string(e.what()).find("(pid " + std::to_string(holder) + ")") != std::string::npos ? 1 : 2;
    }
    _exit(code);
  }
  int status = 0;
  waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 3;
}

TEST_F(RunnerLock, ASecondWriterIsRefusedWithTheHoldersPid) {
  const FolderLock lock = FolderLock::acquire(dir_.string(), Mode::Exclusive);
  EXPECT_EQ(tryInChild(dir_.string(), Mode::Exclusive, getpid()), 1);
  EXPECT_EQ(tryInChild(dir_.string(), Mode::Shared, getpid()), 1);
}

TEST_F(RunnerLock, SharesCoexistButExcludeAWholeRun) {
  const FolderLock lock = FolderLock::acquire(dir_.string(), Mode::Shared);
  EXPECT_EQ(tryInChild(dir_.string(), Mode::Shared, getpid()), 0);
  EXPECT_EQ(tryInChild(dir_.string(), Mode::Exclusive, getpid()), 1);
}

TEST_F(RunnerLock, TheLockGoesWithItsHolder) {
  { const FolderLock lock = FolderLock::acquire(dir_.string(), Mode::Exclusive); }
  EXPECT_EQ(tryInChild(dir_.string(), Mode::Exclusive, getpid()), 0);
  // A holder that dies without cleaning up (here: _exit) leaves no lock behind.
  const pid_t child = fork();
  if (child == 0) {
    static FolderLock held = FolderLock::acquire(dir_.string(), Mode::Exclusive);  // never released by hand
    _exit(held.held() ? 0 : 1);
  }
  waitpid(child, nullptr, 0);
  EXPECT_NO_THROW(FolderLock::acquire(dir_.string(), Mode::Exclusive));
}

}  // namespace
