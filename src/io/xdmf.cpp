#include "io/xdmf.hpp"

#include "io/hdf5_detail.hpp"
#include "io/hdf5_error.hpp"

#include <cstdio>
#include <sstream>

namespace creaturelab::io {

namespace {

// XDMF 3 header and the temporal collection `name` opened; closeCollection() ends both.
void openCollection(std::ostringstream& s, const char* name) {
  s.precision(17);
  s << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
    << "  <Grid Name=\"" << name << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
}

void closeCollection(std::ostringstream& s) { s << "  </Grid>\n </Domain>\n</Xdmf>\n"; }

// A whole HDF5 dataset of doubles (Precision 8: XDMF's default Float is 4 bytes).
void floatItem(std::ostringstream& s, const std::string& dims, const std::string& where) {
  s << "     <DataItem Dimensions=\"" << dims << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << where
    << "</DataItem>\n";
}

}  // namespace

std::string xdmfText(const XdmfGrid& g) {
  std::ostringstream s;
  openCollection(s, "fields");
  // Cell counts, node counts (cells + 1), origin and spacing, slowest axis first: (z,) y, x.
  const bool volume = g.nz > 0;
  auto joined = [volume](auto z, auto y, auto x) {
    std::ostringstream out;
    out.precision(17);
    if (volume) out << z << " ";
    out << y << " " << x;
    return out.str();
  };
  const std::string cells = joined(g.nz, g.ny, g.nx), nodes = joined(g.nz + 1, g.ny + 1, g.nx + 1);
  const std::string rank = volume ? "3" : "2", zeros = volume ? " 0 0 0" : " 0 0", ones = volume ? " 1 1 1" : " 1 1";
  for (size_t k = 0; k < g.time_s.size(); ++k) {
    s << "   <Grid Name=\"frame " << k << "\" GridType=\"Uniform\">\n"
      << "    <Time Value=\"" << g.time_s[k] << "\" />\n"
      << "    <Topology TopologyType=\"" << rank << "DCoRectMesh\" Dimensions=\"" << nodes << "\" />\n"
      << "    <Geometry GeometryType=\"" << (volume ? "ORIGIN_DXDYDZ" : "ORIGIN_DXDY") << "\">\n"
      << "     <DataItem Dimensions=\"" << rank << "\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">"
      << joined(g.origin_z, g.origin_y, g.origin_x) << "</DataItem>\n"
      << "     <DataItem Dimensions=\"" << rank << "\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">"
      << joined(g.dz, g.dy, g.dx) << "</DataItem>\n"
      << "    </Geometry>\n";
    // Frame k of (frames, [nz,] ny, nx): start k 0 0 [0], stride 1 1 1 [1], count 1 [nz] ny nx, then
    // the dataset's shape.
    std::string slab = "|";  // appended piece by piece: gcc 12 misreads "|" + std::to_string(k) (-Wstringop-overflow)
    slab += std::to_string(k) + zeros + ":1" + ones + ":1 " + cells + ":" + std::to_string(g.time_s.size()) + " " + cells;
    for (const auto& f : g.fields) {
      s << "    <Attribute Name=\"" << f << "\" AttributeType=\"Scalar\" Center=\"Cell\">\n";
      floatItem(s, cells, g.h5_file + ":/fields/" + f + slab);
      s << "    </Attribute>\n";
    }
    s << "   </Grid>\n";
  }
  closeCollection(s);
  return s.str();
}

std::string frameViewName(const std::string& name, std::size_t k) {
  char frame[32];
  std::snprintf(frame, sizeof frame, "%06zu", k);
  return name + "_frames/" + frame;
}

std::string xdmfMeshText(const XdmfTriangleMesh& m) {
  std::ostringstream s;
  openCollection(s, "mesh");
  const std::string rows = std::to_string(m.vertices) + " 3", at = m.h5_file + ":" + m.group + "/";
  for (size_t k = 0; k < m.time_s.size(); ++k) {
    s << "   <Grid Name=\"frame " << k << "\" GridType=\"Uniform\">\n"
      << "    <Time Value=\"" << m.time_s[k] << "\" />\n"
      << "    <Topology TopologyType=\"Triangle\" NumberOfElements=\"" << m.triangles << "\">\n"
      << "     <DataItem Dimensions=\"" << m.triangles << " 3\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">"
      << at << "triangles</DataItem>\n    </Topology>\n"
      << "    <Geometry GeometryType=\"XYZ\">\n";
    floatItem(s, rows, at + frameViewName(m.positions, k));
    s << "    </Geometry>\n";
    std::vector<std::string> vectors = m.vectors;
    vectors.insert(vectors.begin(), m.positions);  // meshio keeps only the first frame's geometry
    for (const auto& v : vectors) {
      s << "    <Attribute Name=\"" << v << "\" AttributeType=\"Vector\" Center=\"Node\">\n";
      floatItem(s, rows, at + frameViewName(v, k));
      s << "    </Attribute>\n";
    }
    for (const auto& f : m.fixed_scalars)
      s << "    <Attribute Name=\"" << f << "\" AttributeType=\"Scalar\" Center=\"Node\">\n"
        << "     <DataItem Dimensions=\"" << m.vertices << "\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">" << at
        << f << "</DataItem>\n    </Attribute>\n";
    s << "   </Grid>\n";
  }
  closeCollection(s);
  return s.str();
}

void writeFrameViews(const Group& group, const std::string& name) {
  const auto lock = lockHdf5();
  const Dataset source = group.openDataset(name);
  const std::vector<hsize_t> shape = source.shape();
  if (shape.size() != 3) detail::failAt(group.id(), name, "make frame views of", "not a (frames, rows, columns) array");
  const Group views = group.createGroup(name + "_frames");
  const std::string source_path = source.path();
  const Handle type(detail::check(H5Dget_type(source.id()), group.id(), name, "read the type of"));
  const Handle source_space(detail::check(H5Dget_space(source.id()), group.id(), name, "read the shape of"));
  const Handle view_space = detail::dataspaceOf({shape[1], shape[2]});
  const Handle link_props = detail::linkCreateProps();
  for (hsize_t k = 0; k < shape[0]; ++k) {
    const std::string view = frameViewName(name, k);
    const hsize_t start[3] = {k, 0, 0}, count[3] = {1, shape[1], shape[2]};
    detail::check(H5Sselect_hyperslab(source_space.id(), H5S_SELECT_SET, start, nullptr, count, nullptr), group.id(),
                  view, "select the frame for");
    const Handle props = detail::datasetCreateProps();
    // "." = this file: the view moves with it.
    detail::check(H5Pset_virtual(props.id(), view_space.id(), ".", source_path.c_str(), source_space.id()),
                  group.id(), view, "map");
    const Handle created(detail::check(H5Dcreate2(views.id(), view.substr(view.rfind('/') + 1).c_str(), type.id(),
                                                  view_space.id(), link_props.id(), props.id(), H5P_DEFAULT),
                                       group.id(), view, "create the virtual dataset"));
  }
}

}  // namespace creaturelab::io
