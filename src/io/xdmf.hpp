#pragma once
// XDMF 2 sidecar text for cell-centred fields stored in an HDF5 file as /fields/<name> with shape
// (frames, ny, nx): a temporal collection of 2D co-rectilinear grids that ParaView opens.
#include <string>
#include <vector>

namespace creaturelab::io {

struct XdmfGrid {
  std::string h5_file;  // as referenced from the .xdmf (a bare name when side by side)
  std::vector<double> time_s;
  int nx = 0, ny = 0;
  double dx = 0, dy = 0, origin_x = 0, origin_y = 0;
  std::vector<std::string> fields;  // dataset names under /fields
};

std::string xdmfText(const XdmfGrid& grid);

// A triangle mesh whose vertices move from frame to frame (a rendered jellyfish, src/render/):
// <group>/triangles (triangles, 3) int64 indices, fixed; <group>/<positions> (frames, vertices, 3)
// doubles; per-frame vector attributes (frames, vertices, 3) and fixed per-vertex scalars (vertices).
// A temporal collection of unstructured triangle grids that ParaView opens.
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

}  // namespace creaturelab::io
