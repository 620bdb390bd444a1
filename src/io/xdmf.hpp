#pragma once
// XDMF 3 sidecar text that ParaView's Xdmf3 readers (Xdmf3ReaderS/T, what ParaView opens a .xdmf
// with) and meshio's xdmf.TimeSeriesReader read; the HDF5 data stay where the run wrote them.
#include "io/hdf5_object.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace creaturelab::io {

// Cell-centred fields stored as /fields/<name> with shape (frames, ny, nx), or (frames, nz, ny, nx)
// when nz > 0: a temporal collection of 2D or 3D co-rectilinear grids (2DCoRectMesh, 3DCoRectMesh:
// node counts, origin and spacing listed slowest axis first), each field a cell attribute. Each
// frame selects its slab with XDMF 3's "file:/path|start:stride:count:dataspace" form (ParaView's
// Xdmf3 readers; its legacy XDMF 2 reader cannot, and meshio reads no co-rectilinear grid at all).
struct XdmfGrid {
  std::string h5_file;  // as referenced from the .xdmf (a bare name when side by side)
  std::vector<double> time_s;
  int nx = 0, ny = 0, nz = 0;  // cells; nz = 0: a 2D grid
  double dx = 0, dy = 0, dz = 0, origin_x = 0, origin_y = 0, origin_z = 0;
  std::vector<std::string> fields;  // dataset names under /fields
};

std::string xdmfText(const XdmfGrid& grid);

// A triangle mesh whose vertices move from frame to frame (a rendered jellyfish, src/render/):
// <group>/triangles (triangles, 3) int64 indices, fixed; <group>/<positions> (frames, vertices, 3)
// doubles; per-frame vector attributes (frames, vertices, 3) and fixed per-vertex scalars (vertices).
// Each frame names whole datasets only, the per-frame views of writeFrameViews(), so every reader
// opens it: ParaView (Xdmf3 and legacy XDMF readers) and meshio's TimeSeriesReader, which takes
// the mesh from the first frame and gets each frame's positions as the point data "<positions>".
struct XdmfTriangleMesh {
  std::string h5_file;  // as referenced from the .xdmf
  std::string group;    // e.g. "/render"
  std::vector<double> time_s;
  long vertices = 0, triangles = 0;
  std::string positions = "positions_m";
  std::vector<std::string> vectors;        // per frame, per vertex, e.g. "normals"
  std::vector<std::string> fixed_scalars;  // per vertex, int64 or double, e.g. "part"
};

std::string xdmfMeshText(const XdmfTriangleMesh& mesh);

// The name of frame `k`'s view of dataset `name`: "<name>_frames/NNNNNN" (relative to its group).
std::string frameViewName(const std::string& name, std::size_t k);

// For a (frames, rows, columns) dataset `name` in `group`, writes frameViewName(name, k) for every
// frame k: an HDF5 virtual dataset (rows, columns) mapping that frame of `name` in the same file,
// no data copied. XDMF readers without slab selection (meshio) read these.
void writeFrameViews(const Group& group, const std::string& name);

}  // namespace creaturelab::io
