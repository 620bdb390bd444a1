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

namespace {

// One frame's rows of a (frames, vertices, 3) dataset.
void frameSlab(std::ostringstream& s, const XdmfTriangleMesh& m, size_t k, const std::string& name) {
  s << "     <DataItem ItemType=\"HyperSlab\" Dimensions=\"" << m.vertices << " 3\" Type=\"HyperSlab\">\n"
    << "      <DataItem Dimensions=\"3 3\" Format=\"XML\">" << k << " 0 0  1 1 1  1 " << m.vertices << " 3</DataItem>\n"
    << "      <DataItem Dimensions=\"" << m.time_s.size() << " " << m.vertices << " 3\" NumberType=\"Float\" "
    << "Precision=\"8\" Format=\"HDF\">" << m.h5_file << ":" << m.group << "/" << name << "</DataItem>\n"
    << "     </DataItem>\n";
}

}  // namespace

std::string xdmfMeshText(const XdmfTriangleMesh& m) {
  std::ostringstream s;
  s.precision(17);
  s << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"2.0\">\n <Domain>\n"
    << "  <Grid Name=\"mesh\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (size_t k = 0; k < m.time_s.size(); ++k) {
    s << "   <Grid Name=\"frame " << k << "\" GridType=\"Uniform\">\n"
      << "    <Time Value=\"" << m.time_s[k] << "\" />\n"
      << "    <Topology TopologyType=\"Triangle\" NumberOfElements=\"" << m.triangles << "\">\n"
      << "     <DataItem Dimensions=\"" << m.triangles << " 3\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">"
      << m.h5_file << ":" << m.group << "/triangles</DataItem>\n    </Topology>\n"
      << "    <Geometry GeometryType=\"XYZ\">\n";
    frameSlab(s, m, k, m.positions);
    s << "    </Geometry>\n";
    for (const auto& v : m.vectors) {
      s << "    <Attribute Name=\"" << v << "\" AttributeType=\"Vector\" Center=\"Node\">\n";
      frameSlab(s, m, k, v);
      s << "    </Attribute>\n";
    }
    for (const auto& f : m.fixed_scalars)
      s << "    <Attribute Name=\"" << f << "\" AttributeType=\"Scalar\" Center=\"Node\">\n"
        << "     <DataItem Dimensions=\"" << m.vertices << "\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">"
        << m.h5_file << ":" << m.group << "/" << f << "</DataItem>\n    </Attribute>\n";
    s << "   </Grid>\n";
  }
  s << "  </Grid>\n </Domain>\n</Xdmf>\n";
  return s.str();
}

}  // namespace creaturelab::io
