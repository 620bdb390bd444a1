// io/xdmf.hpp: XDMF 3 text (fields by slab, the triangle mesh by per-frame views) and the per-frame
// views themselves (HDF5 virtual datasets that read back as the frames). Real readers open the
// files in tests/cli/xdmf_readers.sh.
#include "io/xdmf.hpp"

#include "io/hdf5.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace io = creaturelab::io;
namespace fs = std::filesystem;

TEST(Xdmf, FieldsSelectEachFrameBySlab) {
  const io::XdmfGrid g{"p.h5", {0.0, 0.5, 1.0, 1.5}, 3, 2, 0, 0.1, 0.2, 0.0, 0.0, 0.0, 0.0, {"u"}};
  const std::string x = io::xdmfText(g);
  EXPECT_NE(x.find("<Xdmf Version=\"3.0\">"), std::string::npos);
  EXPECT_NE(x.find("Dimensions=\"2 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">p.h5:/fields/u|1 0 0:1 1 1:1 "
                   "2 3:4 2 3</DataItem>"),
            std::string::npos);
  EXPECT_NE(x.find("Precision=\"8\" Format=\"XML\">0.20000000000000001 0.10000000000000001</DataItem>"),
            std::string::npos);
  EXPECT_EQ(x.find("HyperSlab"), std::string::npos);  // ParaView's Xdmf3 readers skip that form
}

// nz > 0: a 3D co-rectilinear grid, node counts, origin and spacing in z, y, x order, each frame a
// (1, nz, ny, nx) slab of the (frames, nz, ny, nx) dataset as a cell attribute.
TEST(Xdmf, VolumeFieldsAre3dCoRectMeshesWithCellAttributes) {
  const io::XdmfGrid g{"p.h5", {0.0, 0.5}, 3, 2, 4, 0.1, 0.2, 0.25, 1.0, 2.0, -0.5, {"q", "u"}};
  const std::string x = io::xdmfText(g);
  EXPECT_NE(x.find("<Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"5 3 4\" />"), std::string::npos);
  EXPECT_NE(x.find("<Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n     <DataItem Dimensions=\"3\" NumberType=\"Float\" "
                   "Precision=\"8\" Format=\"XML\">-0.5 2 1</DataItem>\n     <DataItem Dimensions=\"3\" "
                   "NumberType=\"Float\" Precision=\"8\" Format=\"XML\">0.25 0.20000000000000001 "
                   "0.10000000000000001</DataItem>"),
            std::string::npos);
  EXPECT_NE(x.find("<Attribute Name=\"u\" AttributeType=\"Scalar\" Center=\"Cell\">\n     <DataItem Dimensions=\"4 "
                   "2 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">p.h5:/fields/u|1 0 0 0:1 1 1 1:1 4 2 3:2 "
                   "4 2 3</DataItem>"),
            std::string::npos);
  EXPECT_EQ(x.find("2DCoRectMesh"), std::string::npos);
}

TEST(Xdmf, MeshNamesWholeDatasetsOnly) {
  const io::XdmfTriangleMesh m{"r.h5", "/render", {0.0, 0.1}, 5, 4, "positions_m", {"normals"}, {"part"}};
  const std::string x = io::xdmfMeshText(m);
  EXPECT_NE(x.find("<Geometry GeometryType=\"XYZ\">\n     <DataItem Dimensions=\"5 3\" NumberType=\"Float\" "
                   "Precision=\"8\" Format=\"HDF\">r.h5:/render/positions_m_frames/000001</DataItem>"),
            std::string::npos);
  EXPECT_NE(x.find("<Attribute Name=\"positions_m\""), std::string::npos);  // meshio's moving positions
  EXPECT_NE(x.find("r.h5:/render/normals_frames/000001"), std::string::npos);
  EXPECT_EQ(x.find('|'), std::string::npos);
  EXPECT_EQ(x.find("HyperSlab"), std::string::npos);
}

TEST(Xdmf, FrameViewsReadBackAsTheFrames) {
  const fs::path path = fs::path(testing::TempDir()) / "io_xdmf_views.h5";
  std::vector<double> frames(3 * 4 * 3);
  for (std::size_t i = 0; i < frames.size(); ++i) frames[i] = 0.5 * double(i);
  {
    io::File file = io::File::create(path);
    {
      const io::Group g = file.root().requireGroup("render");
      io::writeArray(g, "positions_m", frames.data(), {3, 4, 3}, std::vector<hsize_t>{1, 4, 3});
      io::writeArray(g, "flat", frames.data(), {12, 3});
      io::writeFrameViews(g, "positions_m");
      EXPECT_THROW(io::writeFrameViews(g, "flat"), io::Hdf5Error);
    }
    file.close();  // sealed: the views live in a sealed file like render.h5
  }
  io::File file = io::File::openReadOnly(path);
  const io::Group g = file.root().openGroup("render");
  EXPECT_EQ(g.openGroup("positions_m_frames").childNames(), (std::vector<std::string>{"000000", "000001", "000002"}));
  for (std::size_t k = 0; k < 3; ++k) {
    const std::string view = io::frameViewName("positions_m", k);
    EXPECT_EQ(io::datasetShape(g, view), (std::vector<hsize_t>{4, 3}));
    EXPECT_EQ(io::readArrayDouble(g, view), std::vector<double>(frames.begin() + 12 * k, frames.begin() + 12 * (k + 1)))
        << view;
  }
  fs::remove(path);
}
