// The seal of every HDF5 file this program writes (io/file_seal.hpp), and writes that never go
// through a planted link (File::create, writeFileAtomically).
#include "scratch_dir_test.hpp"
#include "io/atomic_file.hpp"
#include "io/file_seal.hpp"
#include "io/hdf5.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace io = creaturelab::io;
namespace fs = std::filesystem;

namespace {

class FileSealTest : public creaturelab::testing::ScratchDirTest {
 protected:
  FileSealTest() : ScratchDirTest("creaturelab_io_seal") {}

  fs::path written(const std::string& name) const {
    const fs::path path = file(name);
    io::File f = io::File::create(path);
    io::setAttr(io::writeVector(f.root(), "x", std::vector<double>{1, 2, 3}), "unit", "m");
    io::setAttr(f.root(), "kind", "strand");
    f.close();
    return path;
  }
};

std::string bytesOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void overwrite(const fs::path& path, std::size_t at, char value) {
  std::fstream f(path, std::ios::binary | std::ios::in | std::ios::out);
  f.seekp(std::streamoff(at));
  f.put(value);
}

TEST_F(FileSealTest, AClosedFileIsSealedAndOpens) {
  const fs::path path = written("a.h5");
  EXPECT_EQ(bytesOf(path).rfind("creaturelab seal sha256 ", 0), 0u);
  EXPECT_EQ(io::checkSeal(path).state, io::SealState::intact);
  const io::File f = io::File::openReadOnly(path);
  EXPECT_EQ(io::getAttrString(f.root(), "kind"), "strand");
}

TEST_F(FileSealTest, OneChangedByteAfterTheBlockBreaksItAndNothingOpens) {
  const fs::path path = written("a.h5");
  const std::string bytes = bytesOf(path);
  overwrite(path, bytes.size() - 3, char(bytes[bytes.size() - 3] ^ 1));
  const io::SealCheck seal = io::checkSeal(path);
  EXPECT_EQ(seal.state, io::SealState::broken);
  EXPECT_NE(seal.problem.find("differ from its seal"), std::string::npos) << seal.problem;
  try {
    (void)io::File::openReadOnly(path);
    FAIL() << "a broken seal opened";
  } catch (const io::Hdf5Error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  EXPECT_THROW(io::contentDigest(path, {}), io::Hdf5Error);
}

TEST_F(FileSealTest, ADamagedSealLineOrPaddingIsBroken) {
  const fs::path line = written("line.h5"), padding = written("padding.h5");
  overwrite(line, 30, 'x');
  overwrite(padding, 300, 'x');
  EXPECT_EQ(io::checkSeal(line).state, io::SealState::broken);
  EXPECT_EQ(io::checkSeal(padding).state, io::SealState::broken);
}

TEST_F(FileSealTest, AFileCutShortIsBroken) {
  const fs::path path = written("a.h5");
  fs::resize_file(path, fs::file_size(path) - 100);
  EXPECT_EQ(io::checkSeal(path).state, io::SealState::broken);
  fs::resize_file(path, 200);
  EXPECT_EQ(io::checkSeal(path).state, io::SealState::broken);
}

TEST_F(FileSealTest, AFileWithoutAUserBlockIsNotChecked) {
  const fs::path path = file("plain.h5");
  {
    auto lock = io::lockHdf5();
    const hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(id, 0);
    H5Fclose(id);
  }
  EXPECT_EQ(io::checkSeal(path).state, io::SealState::none);
  EXPECT_NO_THROW((void)io::File::openReadOnly(path));
}

TEST_F(FileSealTest, AFifoIsRefusedWithoutBlocking) {
  const fs::path path = file("fifo.h5");
  ASSERT_EQ(::mkfifo(path.c_str(), 0644), 0);
  EXPECT_EQ(io::checkSeal(path).state, io::SealState::broken);
  EXPECT_THROW((void)io::File::openReadOnly(path), io::Hdf5Error);
}

TEST_F(FileSealTest, ReadWriteKeepsTheSeal) {
  const fs::path path = written("a.h5");
  {
    io::File f = io::File::openReadWrite(path);
    io::setAttr(f.root(), "kind", "web");
    f.close();
  }
  EXPECT_EQ(io::checkSeal(path).state, io::SealState::intact);
}

TEST_F(FileSealTest, CreateReplacesAPlantedLinkAndLeavesItsTarget) {
  std::ofstream(file("target.txt")) << "keep";
  fs::create_symlink(file("target.txt"), file("a.h5.tmp"));
  written("a.h5.tmp");
  EXPECT_FALSE(fs::is_symlink(file("a.h5.tmp")));
  EXPECT_EQ(bytesOf(file("target.txt")), "keep");
}

TEST_F(FileSealTest, WriteFileAtomicallyNeverWritesThroughLinks) {
  std::ofstream(file("target.txt")) << "keep";
  std::ofstream(file("tmp_target.txt")) << "keep";
  fs::create_symlink(file("target.txt"), file("out.txt"));
  fs::create_symlink(file("tmp_target.txt"), file("out.txt.tmp"));
  io::writeFileAtomically(file("out.txt"), "new");
  EXPECT_FALSE(fs::is_symlink(file("out.txt")));
  EXPECT_EQ(bytesOf(file("out.txt")), "new");
  EXPECT_FALSE(fs::exists(fs::symlink_status(file("out.txt.tmp"))));
  EXPECT_EQ(bytesOf(file("target.txt")), "keep");
  EXPECT_EQ(bytesOf(file("tmp_target.txt")), "keep");
}

TEST_F(FileSealTest, WriteFileAtomicallyFailsNamingThePathAndKeepsTheOld) {
  std::ofstream(file("old.txt")) << "old";
  try {
    io::writeFileAtomically(file("missing_folder") / "x.txt", "new");
    FAIL() << "wrote into a missing folder";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("x.txt"), std::string::npos) << e.what();
  }
  EXPECT_EQ(bytesOf(file("old.txt")), "old");
}

}  // namespace
