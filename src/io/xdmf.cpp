#include "io/xdmf.hpp"

#include <sstream>

namespace creaturelab::io {

std::string xdmfText(const XdmfGrid& g) {
  std::ostringstream s;
  s.precision(17);
  // Node counts are cells + 1; XDMF lists dimensions slowest first (y, x).
  s << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"2.0\">\n <Domain>\n"
    << "  <Grid Name=\"fields\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (size_t k = 0; k < g.time_s.size(); ++k) {
    s << "   <Grid Name=\"frame " << k << "\" GridType=\"Uniform\">\n"
      << "    <Time Value=\"" << g.time_s[k] << "\" />\n"
      << "    <Topology TopologyType=\"2DCoRectMesh\" Dimensions=\"" << g.ny + 1 << " " << g.nx + 1 << "\" />\n"
      << "    <Geometry GeometryType=\"ORIGIN_DXDY\">\n"
      << "     <DataItem Dimensions=\"2\" Format=\"XML\">" << g.origin_y << " " << g.origin_x << "</DataItem>\n"
      << "     <DataItem Dimensions=\"2\" Format=\"XML\">" << g.dy << " " << g.dx << "</DataItem>\n"
      << "    </Geometry>\n";
    for (const auto& f : g.fields) {
      s << "    <Attribute Name=\"" << f << "\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
        << "     <DataItem ItemType=\"HyperSlab\" Dimensions=\"" << g.ny << " " << g.nx << "\" Type=\"HyperSlab\">\n"
        << "      <DataItem Dimensions=\"3 3\" Format=\"XML\">" << k << " 0 0  1 1 1  1 " << g.ny << " " << g.nx
        << "</DataItem>\n"
        << "      <DataItem Dimensions=\"" << g.time_s.size() << " " << g.ny << " " << g.nx
        << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << g.h5_file << ":/fields/" << f
        << "</DataItem>\n     </DataItem>\n    </Attribute>\n";
    }
    s << "   </Grid>\n";
  }
  s << "  </Grid>\n </Domain>\n</Xdmf>\n";
  return s.str();
}

}  // namespace creaturelab::io
