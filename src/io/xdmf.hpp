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

}  // namespace creaturelab::io
