// contentDigest: equal data hash equal, whenever and however it was written.
#include "scratch_dir_test.hpp"
#include "io/hdf5.hpp"

#include "core/text.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <thread>

namespace io = creaturelab::io;
namespace fs = std::filesystem;

namespace {

class Hdf5DigestTest : public creaturelab::testing::ScratchDirTest {
 protected:
  Hdf5DigestTest() : ScratchDirTest("creaturelab_io_digest") {}
};

const std::vector<std::string> kProvenance = {"started", "finished", "git_commit"};

struct PointOptions {
  double last_time = 1.0;
  std::string kind = "jellyfish";
  std::string label = "µg";
  bool chunked = false;
};

// A small result file shaped like DESIGN.md's point files.
void writePoint(const fs::path& path, const PointOptions& options = {}) {
  auto f = io::File::create(path);
  io::Group root = f.root();
  io::setAttr(root, "kind", options.kind);
  io::setAttr(root, "started", creaturelab::core::isoTimeUtcNow());
  io::setAttr(root, "contraction_hz", 0.7);
  io::setAttr(root, "contraction_hz.unit", "Hz");
  io::setAttr(root, "converged", true);
  io::Group series = root.requireGroup("timeseries");
  io::setAttr(io::writeVector(series, "time_s", std::vector<double>{0.0, 0.5, options.last_time}), "unit", "s");
  io::writeVector(series, "labels", std::vector<std::string>{"a", options.label});
  io::writeVector(series, "phase", std::vector<std::int64_t>{0, 1, 2});
  io::writeScalar(root.requireGroup("metrics"), "distance_m", 0.125);
  std::vector<double> frames(2 * 3 * 4);
  for (std::size_t i = 0; i < frames.size(); ++i) frames[i] = std::sin(static_cast<double>(i));
  std::optional<std::vector<hsize_t>> chunks;
  if (options.chunked) chunks = std::vector<hsize_t>{1, 3, 4};
  io::writeArray(root.requireGroup("fields"), "omega", frames.data(), {2, 3, 4}, chunks);
  io::setAttr(root, "finished", creaturelab::core::isoTimeUtcNow());
}

}  // namespace

TEST_F(Hdf5DigestTest, EqualForIdenticalWritesAtDifferentTimes) {
  writePoint(file("a.h5"));
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));  // "started"/"finished" differ
  writePoint(file("b.h5"));
  EXPECT_NE(io::getAttrString(io::File::openReadOnly(file("a.h5")).root(), "started"),
            io::getAttrString(io::File::openReadOnly(file("b.h5")).root(), "started"));
  const std::string digest = io::contentDigest(file("a.h5"), kProvenance);
  EXPECT_EQ(digest.size(), 64u);
  EXPECT_EQ(io::contentDigest(file("b.h5"), kProvenance), digest);
  // Not skipping the provenance attributes makes them count.
  EXPECT_NE(io::contentDigest(file("a.h5"), {}), io::contentDigest(file("b.h5"), {}));
}

TEST_F(Hdf5DigestTest, DiffersWhenOneValueChangesByOneUlp) {
  writePoint(file("a.h5"));
  writePoint(file("b.h5"), {.last_time = std::nextafter(1.0, 2.0)});
  EXPECT_NE(io::contentDigest(file("a.h5"), kProvenance), io::contentDigest(file("b.h5"), kProvenance));
}

TEST_F(Hdf5DigestTest, DiffersWhenAStringChanges) {
  writePoint(file("a.h5"));
  writePoint(file("b.h5"), {.label = "mg"});
  EXPECT_NE(io::contentDigest(file("a.h5"), kProvenance), io::contentDigest(file("b.h5"), kProvenance));
}

TEST_F(Hdf5DigestTest, DiffersWhenANonSkippedAttributeChanges) {
  writePoint(file("a.h5"));
  writePoint(file("b.h5"), {.kind = "web"});
  EXPECT_NE(io::contentDigest(file("a.h5"), kProvenance), io::contentDigest(file("b.h5"), kProvenance));
  // ...and is equal again when that attribute is skipped too.
  std::vector<std::string> skip = kProvenance;
  skip.push_back("kind");
  EXPECT_EQ(io::contentDigest(file("a.h5"), skip), io::contentDigest(file("b.h5"), skip));
}

TEST_F(Hdf5DigestTest, IndependentOfStorageLayout) {
  writePoint(file("contiguous.h5"));
  writePoint(file("chunked.h5"), {.chunked = true});
  EXPECT_EQ(io::contentDigest(file("contiguous.h5"), kProvenance), io::contentDigest(file("chunked.h5"), kProvenance));
}

TEST_F(Hdf5DigestTest, TypeNameAndShapeCount) {
  const auto digest_of = [&](const std::string& name, auto&& write) {
    {
      auto f = io::File::create(file(name));
      write(f.root());
    }
    return io::contentDigest(file(name), {});
  };
  const std::string doubles = digest_of("d.h5", [](const io::Group& g) {
    io::writeVector(g, "x", std::vector<double>{1, 2, 3, 4});
  });
  const std::string ints = digest_of("i.h5", [](const io::Group& g) {
    io::writeVector(g, "x", std::vector<std::int64_t>{1, 2, 3, 4});
  });
  const std::string renamed = digest_of("r.h5", [](const io::Group& g) {
    io::writeVector(g, "y", std::vector<double>{1, 2, 3, 4});
  });
  const std::string reshaped = digest_of("s.h5", [](const io::Group& g) {
    const double data[4] = {1, 2, 3, 4};
    io::writeArray(g, "x", data, {2, 2});
  });
  const std::string empty_group = digest_of("e.h5", [](const io::Group& g) {
    io::writeVector(g, "x", std::vector<double>{1, 2, 3, 4});
    g.createGroup("nothing");
  });
  EXPECT_NE(doubles, ints);
  EXPECT_NE(doubles, renamed);
  EXPECT_NE(doubles, reshaped);
  EXPECT_NE(doubles, empty_group);
}

TEST_F(Hdf5DigestTest, ExternalLinksCountByTargetNotContent) {
  writePoint(file("p0.h5"));
  const auto write_index = [&](const std::string& name, const std::string& target) {
    auto f = io::File::create(file(name));
    io::createExternalLink(f.root(), "p0", target, "/");
  };
  write_index("index_a.h5", "p0.h5");
  write_index("index_b.h5", "p0.h5");
  write_index("index_c.h5", "p1.h5");
  const std::string a = io::contentDigest(file("index_a.h5"), {});
  EXPECT_EQ(a, io::contentDigest(file("index_b.h5"), {}));
  EXPECT_NE(a, io::contentDigest(file("index_c.h5"), {}));
}

TEST_F(Hdf5DigestTest, LargeDatasetsAreHashedInBlocks) {
  // 3 frames of 1024 x 1024 doubles = 24 MiB: read as two blocks of the 16 MiB budget.
  const std::vector<hsize_t> dims = {3, 1024, 1024};
  std::vector<double> frames(3 * 1024 * 1024);
  for (std::size_t i = 0; i < frames.size(); ++i) frames[i] = static_cast<double>(i % 977) * 0.25;
  const auto write = [&](const std::string& name, std::optional<std::vector<hsize_t>> chunks) {
    auto f = io::File::create(file(name));
    io::writeArray(f.root(), "field", frames.data(), dims, chunks);
  };
  write("contiguous.h5", std::nullopt);
  write("chunked.h5", std::vector<hsize_t>{1, 1024, 1024});
  frames.back() += 1.0;  // a change in the last block
  write("changed.h5", std::nullopt);
  const std::string contiguous = io::contentDigest(file("contiguous.h5"), {});
  EXPECT_EQ(contiguous, io::contentDigest(file("chunked.h5"), {}));
  EXPECT_NE(contiguous, io::contentDigest(file("changed.h5"), {}));
}

TEST_F(Hdf5DigestTest, GoldenValueGuardsTheAlgorithm) {
  // Changing the digest algorithm invalidates every stored determinism hash: do it on
  // purpose (bump "content digest v1") and update this value.
  {
    auto f = io::File::create(file("golden.h5"));
    io::setAttr(f.root(), "kind", "web");
    io::setAttr(f.root(), "ok", true);
    io::setAttr(io::writeVector(f.root().requireGroup("timeseries"), "time_s", std::vector<double>{0.0, 0.5}),
                "unit", "s");
    io::writeVector(f.root(), "names", std::vector<std::string>{"µg", ""});
    io::writeVector(f.root(), "n", std::vector<std::int64_t>{-1, 7});
  }
  EXPECT_EQ(io::contentDigest(file("golden.h5"), {}), "522c0df58c19d8a052c8e31523fb0848cc840bd4637b64df6d46f03476cca1e0");
}

TEST_F(Hdf5DigestTest, MissingFileIsAnErrorNamingIt) {
  try {
    io::contentDigest(file("absent.h5"), {});
    FAIL() << "expected Hdf5Error";
  } catch (const io::Hdf5Error& error) {
    EXPECT_NE(std::string(error.what()).find("absent.h5"), std::string::npos) << error.what();
  }
}
