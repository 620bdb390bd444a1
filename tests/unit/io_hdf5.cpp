// HDF5 wrapper: files, groups, datasets, columns of records, links, errors.
#include "scratch_dir_test.hpp"
#include "io/hdf5.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <thread>

namespace io = creaturelab::io;
namespace fs = std::filesystem;

namespace {

// A fresh directory per test (ctest runs tests as parallel processes).
class Hdf5Test : public creaturelab::testing::ScratchDirTest {
 protected:
  Hdf5Test() : ScratchDirTest("creaturelab_io") {}
};

std::string readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_F(Hdf5Test, DoubleVectorRoundTripIsBitwise) {
  const std::vector<double> values = {0.0, -0.0, 1.0 / 3.0, -1e300, 5e-324,
                                      std::numeric_limits<double>::infinity(), std::nan("")};
  {
    auto f = io::File::create(file("d.h5"));
    io::writeVector(f.root(), "values", values);
  }
  auto f = io::File::openReadOnly(file("d.h5"));
  const std::vector<double> back = io::readVectorDouble(f.root(), "values");
  ASSERT_EQ(back.size(), values.size());
  EXPECT_EQ(std::memcmp(back.data(), values.data(), values.size() * sizeof(double)), 0);
}

TEST_F(Hdf5Test, IntegerVectorsRoundTrip) {
  const std::vector<std::int64_t> wide = {std::numeric_limits<std::int64_t>::min(), -1, 0, 1,
                                          std::numeric_limits<std::int64_t>::max()};
  const std::vector<std::int8_t> narrow = {-128, -1, 0, 1, 127};
  {
    auto f = io::File::create(file("i.h5"));
    io::writeVector(f.root(), "wide", wide);
    io::writeVector(f.root(), "narrow", narrow);
  }
  auto f = io::File::openReadOnly(file("i.h5"));
  EXPECT_EQ(io::readVectorInt64(f.root(), "wide"), wide);
  EXPECT_EQ(io::readVectorInt8(f.root(), "narrow"), narrow);
  // Numeric conversion on read, as HDF5 does it.
  EXPECT_EQ(io::readVectorDouble(f.root(), "narrow"), (std::vector<double>{-128, -1, 0, 1, 127}));
}

TEST_F(Hdf5Test, EmptyVectorsRoundTrip) {
  {
    auto f = io::File::create(file("e.h5"));
    io::writeVector(f.root(), "d", std::vector<double>{});
    io::writeVector(f.root(), "s", std::vector<std::string>{});
  }
  auto f = io::File::openReadOnly(file("e.h5"));
  EXPECT_TRUE(io::readVectorDouble(f.root(), "d").empty());
  EXPECT_TRUE(io::readVectorString(f.root(), "s").empty());
  EXPECT_EQ(io::datasetShape(f.root(), "d"), (std::vector<hsize_t>{0}));
}

TEST_F(Hdf5Test, Utf8StringsRoundTripAsWritten) {
  const std::vector<std::string> names = {"distance_m", "µg", "", "Rudolf & Mould — Fig. 5", "日本語"};
  {
    auto f = io::File::create(file("s.h5"));
    io::writeVector(f.root(), "names", names);
  }
  auto f = io::File::openReadOnly(file("s.h5"));
  EXPECT_EQ(io::readVectorString(f.root(), "names"), names);
}

TEST_F(Hdf5Test, StringWithNulIsRejected) {
  auto f = io::File::create(file("nul.h5"));
  EXPECT_THROW(io::writeVector(f.root(), "bad", std::vector<std::string>{std::string("a\0b", 3)}), io::Hdf5Error);
}

TEST_F(Hdf5Test, ScalarRoundTrip) {
  {
    auto f = io::File::create(file("scalar.h5"));
    io::writeScalar(f.root().requireGroup("metrics"), "distance_m", 0.125);
  }
  auto f = io::File::openReadOnly(file("scalar.h5"));
  EXPECT_EQ(io::readScalarDouble(f.root(), "metrics/distance_m"), 0.125);
  EXPECT_TRUE(io::datasetShape(f.root(), "metrics/distance_m").empty());
  EXPECT_TRUE(f.root().openDataset("/metrics/distance_m").shape().empty());
}

TEST_F(Hdf5Test, ChunkedThreeDimensionalArray) {
  const std::vector<hsize_t> dims = {4, 3, 5};  // (nt, ny, nx)
  std::vector<double> frames(4 * 3 * 5);
  for (std::size_t i = 0; i < frames.size(); ++i) frames[i] = 0.5 * static_cast<double>(i);
  {
    auto f = io::File::create(file("field.h5"));
    io::writeArray(f.root().requireGroup("fields"), "vorticity", frames.data(), dims,
                   std::vector<hsize_t>{1, 3, 5});
  }
  auto f = io::File::openReadOnly(file("field.h5"));
  EXPECT_EQ(io::datasetShape(f.root(), "fields/vorticity"), dims);
  EXPECT_EQ(io::readArrayDouble(f.root(), "fields/vorticity"), frames);

  // One frame per chunk, as asked.
  io::Dataset dataset = f.root().openDataset("fields/vorticity");
  auto lock = io::lockHdf5();
  io::Handle props(H5Dget_create_plist(dataset.id()));
  ASSERT_EQ(H5Pget_layout(props.id()), H5D_CHUNKED);
  hsize_t chunk[3] = {};
  ASSERT_EQ(H5Pget_chunk(props.id(), 3, chunk), 3);
  EXPECT_EQ(chunk[0], 1u);
  EXPECT_EQ(chunk[1], 3u);
  EXPECT_EQ(chunk[2], 5u);
}

TEST_F(Hdf5Test, GroupsNestSortAndAnswerQueries) {
  auto f = io::File::create(file("g.h5"));
  io::Group root = f.root();
  io::Group deep = root.requireGroup("a/b/c");
  EXPECT_EQ(deep.path(), "/a/b/c");
  root.requireGroup("a/b");  // existing parts are opened, not recreated
  io::writeVector(root.requireGroup("timeseries"), "time_s", std::vector<double>{0, 1});
  io::writeVector(root.openGroup("timeseries"), "b_speed", std::vector<double>{0, 1});
  root.createGroup("Zeta");

  EXPECT_EQ(root.childNames(), (std::vector<std::string>{"Zeta", "a", "timeseries"}));
  EXPECT_EQ(root.openGroup("timeseries").childNames(), (std::vector<std::string>{"b_speed", "time_s"}));
  EXPECT_TRUE(root.has("a/b/c"));
  EXPECT_TRUE(root.has("/timeseries/time_s"));
  EXPECT_FALSE(root.has("a/x/c"));
  EXPECT_FALSE(root.has("timeseries/time_s/deeper"));
  EXPECT_TRUE(root.isGroup("a/b"));
  EXPECT_FALSE(root.isDataset("a/b"));
  EXPECT_TRUE(root.isDataset("timeseries/time_s"));
  EXPECT_FALSE(root.isDataset("missing"));
  EXPECT_THROW(root.createGroup("Zeta"), io::Hdf5Error);
  EXPECT_THROW(root.requireGroup("timeseries/time_s/x"), io::Hdf5Error);
}

TEST_F(Hdf5Test, ExternalLinkResolvesNextToTheLinkingFile) {
  {
    auto point = io::File::create(file("point_0003.h5"));
    io::writeScalar(point.root().requireGroup("metrics"), "distance_m", 2.5);
    io::setAttr(point.root(), "point_index", std::int64_t{3});
  }
  {
    auto index = io::File::create(file("index.h5"));
    // Bare file name: looked up in the directory of index.h5, whatever the working directory.
    io::createExternalLink(index.root().requireGroup("points"), "0003", "point_0003.h5", "/");
  }
  ASSERT_NE(fs::current_path(), dir_);
  auto index = io::File::openReadOnly(file("index.h5"));
  io::Group root = index.root();
  EXPECT_TRUE(root.has("points/0003"));
  EXPECT_TRUE(root.isGroup("points/0003"));
  EXPECT_EQ(io::readScalarDouble(root, "points/0003/metrics/distance_m"), 2.5);
  io::Group point = root.openGroup("points/0003");
  EXPECT_EQ(io::getAttrInt64(point, "point_index"), 3);
}

TEST_F(Hdf5Test, DanglingExternalLinkExistsButDoesNotResolve) {
  {
    auto index = io::File::create(file("index.h5"));
    io::createExternalLink(index.root(), "gone", "missing.h5", "/");
  }
  auto index = io::File::openReadOnly(file("index.h5"));
  EXPECT_TRUE(index.root().has("gone"));
  EXPECT_FALSE(index.root().isGroup("gone"));
  EXPECT_THROW(index.root().openGroup("gone"), io::Hdf5Error);
}

TEST_F(Hdf5Test, ErrorsNameTheFileAndObject) {
  const fs::path missing = file("no_such_file.h5");
  try {
    io::File::openReadOnly(missing);
    FAIL() << "expected Hdf5Error";
  } catch (const io::Hdf5Error& error) {
    EXPECT_NE(std::string(error.what()).find(missing.string()), std::string::npos) << error.what();
  }

  {
    auto f = io::File::create(file("err.h5"));
    io::writeVector(f.root().requireGroup("metrics"), "speed", std::vector<double>{1.0});
  }
  auto f = io::File::openReadOnly(file("err.h5"));
  const auto expect_names = [&](const std::function<void()>& action, const std::string& object) {
    try {
      action();
      ADD_FAILURE() << "expected Hdf5Error for " << object;
    } catch (const io::Hdf5Error& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find(file("err.h5").string()), std::string::npos) << message;
      EXPECT_NE(message.find(object), std::string::npos) << message;
    }
  };
  expect_names([&] { io::readVectorDouble(f.root(), "metrics/missing"); }, "/metrics/missing");
  expect_names([&] { io::readVectorDouble(f.root().openGroup("metrics"), "missing"); }, "/metrics/missing");
  expect_names([&] { io::readVectorString(f.root(), "metrics/speed"); }, "/metrics/speed");
  expect_names([&] { io::readScalarDouble(f.root(), "metrics"); }, "/metrics");
  expect_names([&] { io::writeVector(f.root(), "new", std::vector<double>{1.0}); }, "/new");  // read-only file
  expect_names([&] { io::getAttr(f.root(), "nope"); }, "\"nope\"");
}

TEST_F(Hdf5Test, WritingAnExistingNameAndBadChunksFail) {
  auto f = io::File::create(file("dup.h5"));
  io::writeVector(f.root(), "x", std::vector<double>{1.0});
  EXPECT_THROW(io::writeVector(f.root(), "x", std::vector<double>{2.0}), io::Hdf5Error);
  const double data[6] = {};
  EXPECT_THROW(io::writeArray(f.root(), "a", data, {2, 3}, std::vector<hsize_t>{1}), io::Hdf5Error);
  EXPECT_THROW(io::writeArray(f.root(), "b", data, {2, 3}, std::vector<hsize_t>{0, 3}), io::Hdf5Error);
}

TEST_F(Hdf5Test, CloseRefusesWhileHandlesAreOpen) {
  auto f = io::File::create(file("close.h5"));
  {
    io::Group group = f.root().requireGroup("g");
    EXPECT_THROW(f.close(), io::Hdf5Error);
  }
  EXPECT_NO_THROW(f.close());
  EXPECT_FALSE(f.isOpen());
  // Now closed for real: the file can be renamed and reopened.
  fs::rename(file("close.h5"), file("renamed.h5"));
  auto reopened = io::File::openReadOnly(file("renamed.h5"));
  EXPECT_TRUE(reopened.root().isGroup("g"));
}

TEST_F(Hdf5Test, IdenticalContentGivesIdenticalBytes) {
  const auto write = [&](const fs::path& path) {
    auto f = io::File::create(path);
    {
      io::Group series = f.root().requireGroup("timeseries");
      io::setAttr(io::writeVector(series, "time_s", std::vector<double>{0.0, 0.5, 1.0}), "unit", "s");
    }
    io::setAttr(f.root(), "kind", "web");
    f.close();  // all handles are gone, so the file closes now
  };
  write(file("first.h5"));
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));  // object times have 1 s resolution
  write(file("second.h5"));
  EXPECT_EQ(readBytes(file("first.h5")), readBytes(file("second.h5")));
}

TEST_F(Hdf5Test, ColumnsOfRecordsAreStoredAsTheVectorsOfTheirFields) {
  struct Record {
    std::string name;
    int count;
    bool ok;
    double value;
  };
  const std::vector<Record> records = {{"a", 1, true, 0.5}, {"b", -2, false, -1e300}};
  {
    auto f = io::File::create(file("columns.h5"));
    io::writeColumn(f.root(), "name", records, &Record::name);
    io::writeColumn(f.root(), "count", records, &Record::count);
    io::writeColumn(f.root(), "ok", records, &Record::ok);
    io::writeColumn(f.root(), "twice", records, [](const Record& r) { return 2 * r.value; });
  }
  {
    auto f = io::File::create(file("vectors.h5"));
    io::writeVector(f.root(), "name", std::vector<std::string>{"a", "b"});
    io::writeVector(f.root(), "count", std::vector<std::int64_t>{1, -2});
    io::writeVector(f.root(), "ok", std::vector<std::int8_t>{1, 0});
    io::writeVector(f.root(), "twice", std::vector<double>{1.0, -2e300});
  }
  EXPECT_EQ(readBytes(file("columns.h5")), readBytes(file("vectors.h5")));
}

TEST_F(Hdf5Test, ThreadsMayWriteDifferentFilesConcurrently) {
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([this, t] {
      auto f = io::File::create(file("t" + std::to_string(t) + ".h5"));
      for (int i = 0; i < 50; ++i) {
        io::Group g = f.root().requireGroup(std::to_string(i));
        io::writeVector(g, "v", std::vector<double>(100, i));
        io::setAttr(g, "i", i);
      }
    });
  }
  for (auto& thread : threads) thread.join();
  const std::string first = io::contentDigest(file("t0.h5"), {});
  for (int t = 1; t < 4; ++t) EXPECT_EQ(io::contentDigest(file(std::string("t") + std::to_string(t) + ".h5"), {}), first);
}

TEST(Hdf5Handle, IsMoveOnlyAndClosesOnce) {
  static_assert(!std::is_copy_constructible_v<io::Handle>);
  static_assert(std::is_nothrow_move_constructible_v<io::Handle>);
  hid_t raw = H5I_INVALID_HID;
  {
    auto lock = io::lockHdf5();
    raw = H5Screate(H5S_SCALAR);
  }
  io::Handle first(raw);
  io::Handle second(std::move(first));
  EXPECT_FALSE(first.valid());  // NOLINT(bugprone-use-after-move): moved-from state is specified
  EXPECT_EQ(second.id(), raw);
  EXPECT_GT(H5Iis_valid(raw), 0);
  second.reset();
  EXPECT_FALSE(second.valid());
  EXPECT_LE(H5Iis_valid(raw), 0);
}

TEST_F(Hdf5Test, SlabsAndIntegerArrays) {
  // A (frames, rows, 3) array written a frame at a time, and an integer table (a mesh's triangles).
  const std::vector<std::int64_t> table = {0, 1, 2, 2, 1, 3};
  {
    auto f = io::File::create(file("s.h5"));
    const io::Dataset d = io::createArray(f.root(), "frames", {3, 2, 3}, std::vector<hsize_t>{1, 2, 3});
    for (int k = 0; k < 3; ++k) {
      const std::vector<double> frame = {k + 0.0, k + 0.1, k + 0.2, k + 0.3, k + 0.4, k + 0.5};
      io::writeSlab(d, hsize_t(k), 1, frame.data());
    }
    const std::vector<double> beyond(6, 0.0);
    EXPECT_THROW(io::writeSlab(d, 3, 1, beyond.data()), io::Hdf5Error);  // the fourth frame of three
    io::writeArray(f.root(), "table", table.data(), {2, 3});
  }
  auto f = io::File::openReadOnly(file("s.h5"));
  EXPECT_EQ(io::datasetShape(f.root(), "frames"), (std::vector<hsize_t>{3, 2, 3}));
  const auto all = io::readArrayDouble(f.root(), "frames");
  EXPECT_EQ(all[0], 0.0);
  EXPECT_EQ(all[6 + 4], 1.4);
  EXPECT_EQ(all[12 + 5], 2.5);
  EXPECT_EQ(io::datasetShape(f.root(), "table"), (std::vector<hsize_t>{2, 3}));
}
