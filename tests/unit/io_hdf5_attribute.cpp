// HDF5 wrapper: typed scalar attributes on the root, groups and datasets.
#include "scratch_dir_test.hpp"
#include "io/hdf5.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <limits>

namespace io = creaturelab::io;
namespace fs = std::filesystem;

namespace {

class Hdf5AttributeTest : public creaturelab::testing::ScratchDirTest {
 protected:
  Hdf5AttributeTest() : ScratchDirTest("creaturelab_io_attr") {}
};

}  // namespace

TEST_F(Hdf5AttributeTest, EveryTypeRoundTripsOnRootGroupAndDataset) {
  {
    auto f = io::File::create(file("a.h5"));
    io::Group root = f.root();
    io::setAttr(root, "title", "Distance vs contraction frequency — µg");
    io::setAttr(root, "point_index", std::int64_t{-12});
    io::setAttr(root, "contraction_hz", 0.7);
    io::setAttr(root, "passed", true);
    io::setAttr(root, "failed", false);
    io::Group metrics = root.requireGroup("metrics");
    io::setAttr(metrics, "count", 3);  // int -> int64
    io::setAttr(metrics, "empty", std::string());
    io::Dataset speed = io::writeScalar(metrics, "speed_m_per_s", 0.02);
    io::setAttr(speed, "unit", std::string_view("m/s"));
    io::setAttr(speed, "variant", io::AttrValue{2.5});
  }
  auto f = io::File::openReadOnly(file("a.h5"));
  io::Group root = f.root();
  EXPECT_EQ(io::getAttrString(root, "title"), "Distance vs contraction frequency — µg");
  EXPECT_EQ(io::getAttrInt64(root, "point_index"), -12);
  EXPECT_EQ(io::getAttrDouble(root, "contraction_hz"), 0.7);
  EXPECT_TRUE(io::getAttrBool(root, "passed"));
  EXPECT_FALSE(io::getAttrBool(root, "failed"));
  EXPECT_EQ(io::getAttr(root, "passed"), io::AttrValue{true});
  EXPECT_EQ(io::getAttr(root, "point_index"), io::AttrValue{std::int64_t{-12}});
  EXPECT_EQ(io::getAttr(root, "title").index(), 3u);

  io::Group metrics = root.openGroup("metrics");
  EXPECT_EQ(io::getAttrInt64(metrics, "count"), 3);
  EXPECT_EQ(io::getAttrString(metrics, "empty"), "");
  io::Dataset speed = metrics.openDataset("speed_m_per_s");
  EXPECT_EQ(io::getAttrString(speed, "unit"), "m/s");
  EXPECT_EQ(io::getAttrDouble(speed, "variant"), 2.5);
}

TEST_F(Hdf5AttributeTest, NamesAreSortedAndSettingReplaces) {
  auto f = io::File::create(file("n.h5"));
  io::Group root = f.root();
  io::setAttr(root, "b", 1.0);
  io::setAttr(root, "a.unit", "m");
  io::setAttr(root, "a", 2.0);
  io::setAttr(root, "B", 3.0);
  EXPECT_EQ(io::attrNames(root), (std::vector<std::string>{"B", "a", "a.unit", "b"}));
  EXPECT_TRUE(io::hasAttr(root, "a.unit"));
  EXPECT_FALSE(io::hasAttr(root, "c"));

  io::setAttr(root, "b", "now a string");  // replaced, type may change
  EXPECT_EQ(io::getAttrString(root, "b"), "now a string");
  EXPECT_EQ(io::attrNames(root).size(), 4u);
}

TEST_F(Hdf5AttributeTest, IntegerOverloadsAndRange) {
  auto f = io::File::create(file("i.h5"));
  io::Group root = f.root();
  io::setAttr(root, "u32", std::uint32_t{4000000000u});
  io::setAttr(root, "size", std::size_t{42});
  io::setAttr(root, "min", std::numeric_limits<std::int64_t>::min());
  EXPECT_EQ(io::getAttrInt64(root, "u32"), 4000000000);
  EXPECT_EQ(io::getAttrInt64(root, "size"), 42);
  EXPECT_EQ(io::getAttrInt64(root, "min"), std::numeric_limits<std::int64_t>::min());
  EXPECT_THROW(io::setAttr(root, "huge", std::numeric_limits<std::uint64_t>::max()), io::Hdf5Error);
}

TEST_F(Hdf5AttributeTest, WrongTypeOrMissingNamesTheAttributeObjectAndFile) {
  auto f = io::File::create(file("w.h5"));
  io::Group group = f.root().requireGroup("metrics");
  io::setAttr(group, "unit", "m");
  try {
    io::getAttrDouble(group, "unit");
    FAIL() << "expected Hdf5Error";
  } catch (const io::Hdf5Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("\"unit\""), std::string::npos) << message;
    EXPECT_NE(message.find("/metrics"), std::string::npos) << message;
    EXPECT_NE(message.find(file("w.h5").string()), std::string::npos) << message;
    EXPECT_NE(message.find("string"), std::string::npos) << message;
  }
  EXPECT_THROW(io::getAttr(group, "missing"), io::Hdf5Error);
  EXPECT_THROW(io::setAttr(group, "nul", std::string("a\0b", 3)), io::Hdf5Error);
}
