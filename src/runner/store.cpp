#include "runner/store.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>

#include "core/sha256.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5.hpp"
#include "io/xdmf.hpp"
#include "runner/value_json.hpp"

namespace creaturelab::runner {
namespace fs = std::filesystem;

namespace {

void writeProvenance(const io::Group& root, const Provenance& p) {
  for (const auto& [k, v] : p) io::setAttr(root, k, v);
}

void writeParameters(const io::Group& root, const kinds::Kind& kind, const kinds::Params& params) {
  for (const auto& spec : kind.params()) {
    io::setAttr(root, spec.name, params.at(spec.name));
    io::setAttr(root, spec.name + ".unit", spec.unit);
  }
}

// /fields/<name>: (frames, ny, nx), or (frames, nz, ny, nx) for a 3D grid, one frame per chunk, so a
// viewer reads a frame at a time; the grid's spacing and origin as attributes of /fields.
void writeFields(const io::Group& root, const kinds::FieldFrames& f) {
  if (f.frames() == 0 || f.fields.empty()) return;
  const io::Group group = root.requireGroup("fields");
  std::vector<hsize_t> dims = {hsize_t(f.frames()), hsize_t(f.ny), hsize_t(f.nx)};
  if (f.nz > 0) dims.insert(dims.begin() + 1, hsize_t(f.nz));
  std::vector<hsize_t> frame = dims;
  frame[0] = 1;
  const std::size_t values = std::size_t(f.frames()) * std::size_t(std::max(f.nz, 1)) * std::size_t(f.ny) * f.nx;
  for (const auto& [name, field] : f.fields) {
    if (field.data.size() != values)
      throw std::runtime_error("field '" + name + "' has " + std::to_string(field.data.size()) + " values, its grid " +
                               std::to_string(values));
    io::setAttr(io::writeArray(group, name, field.data.data(), dims, frame), "unit", field.unit);
  }
  io::setAttr(io::writeVector(group, "time_s", f.time_s), "unit", "s");
  io::setAttr(group, "dx_m", f.dx_m);
  io::setAttr(group, "dy_m", f.dy_m);
  io::setAttr(group, "origin_x_m", f.origin_x_m);
  io::setAttr(group, "origin_y_m", f.origin_y_m);
  if (f.nz == 0) return;
  io::setAttr(group, "dz_m", f.dz_m);
  io::setAttr(group, "origin_z_m", f.origin_z_m);
}

// Result::artifacts as <dir>/point_NNNNNN_<name>, each written to .tmp and renamed like the point file.
void writeArtifacts(const std::string& dir, int index, const kinds::Result& r) {
  const std::string stem = fs::path(pointFileName(index)).stem().string();
  for (const auto& [name, bytes] : r.artifacts) {
    if (name.empty() || name.find('/') != std::string::npos || name.find("..") != std::string::npos)
      throw std::runtime_error("artifact name '" + name + "' is not a plain file name");
    io::writeFileAtomically(dir + "/" + stem + "_" + name,
                            std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  }
}

void writeXdmfSidecar(const std::string& dir, int index, const kinds::FieldFrames& f) {
  if (f.frames() == 0 || f.fields.empty()) return;
  io::XdmfGrid g{pointFileName(index), f.time_s, f.nx, f.ny, f.nz, f.dx_m, f.dy_m, f.dz_m,
                 f.origin_x_m, f.origin_y_m, f.origin_z_m, {}};
  for (const auto& [name, field] : f.fields) g.fields.push_back(name);
  io::writeFileAtomically(dir + "/" + fs::path(pointFileName(index)).stem().string() + ".xdmf", io::xdmfText(g));
}

void writeResult(const io::Group& root, const kinds::Result& r, bool lagrangian) {
  const io::Group series = root.requireGroup("timeseries");
  for (const auto& [name, s] : r.timeseries) io::setAttr(io::writeVector(series, name, s.values), "unit", s.unit);
  const io::Group metrics = root.requireGroup("metrics");
  for (const auto& [name, m] : r.metrics) io::setAttr(io::writeScalar(metrics, name, m.value), "unit", m.unit);
  writeFields(root, r.fields);
  if (!r.topology.empty()) {
    const io::Group topology = root.requireGroup("topology");
    for (const auto& [name, values] : r.topology) io::writeVector(topology, name, values);
  }
  if (!lagrangian || r.lagrangian.empty()) return;
  const io::Group tracks = root.requireGroup("lagrangian");
  bool wrote_time = false;
  for (const auto& [name, t] : r.lagrangian) {
    if (t.frames() == 0) continue;
    const hsize_t nt = hsize_t(t.frames()), np = hsize_t(t.points), dim = hsize_t(t.dim);
    io::setAttr(io::writeArray(tracks, name, t.data.data(), {nt, np, dim}, std::vector<hsize_t>{1, np, dim}), "unit",
                t.unit);
    if (!wrote_time) io::setAttr(io::writeVector(tracks, "time_s", t.time_s), "unit", "s");
    wrote_time = true;
  }
}

// Index columns take the narrowest type that holds every value: int64, double, bool, else text.
struct Column {
  std::string type;  // "int64" | "double" | "bool" | "string"
};

Column columnType(const Table& table, const std::string& name) {
  bool all_int = true, all_num = true, all_bool = true;
  for (const auto& row : table.rows) {
    auto it = row.columns.find(name);
    if (it == row.columns.end()) continue;
    const auto& v = it->second;
    all_int &= std::holds_alternative<std::int64_t>(v);
    all_num &= std::holds_alternative<std::int64_t>(v) || std::holds_alternative<double>(v);
    all_bool &= std::holds_alternative<bool>(v);
  }
  return {all_bool ? "bool" : all_int ? "int64" : all_num ? "double" : "string"};
}

void writeColumn(const io::Group& sweep, const Table& table, const std::string& name, const std::string& type) {
  std::vector<double> d;
  std::vector<std::int64_t> i;
  std::vector<std::int8_t> b;
  std::vector<std::string> s;
  for (const auto& row : table.rows) {
    const kinds::Value v = row.columns.at(name);
    if (type == "int64") i.push_back(std::get<std::int64_t>(v));
    else if (type == "double") d.push_back(numericValue(v));
    else if (type == "bool") b.push_back(std::get<bool>(v) ? 1 : 0);
    else s.push_back(std::holds_alternative<std::string>(v) ? std::get<std::string>(v) : kinds::describeValue(v));
  }
  if (type == "int64") io::writeVector(sweep, name, i);
  else if (type == "double") io::writeVector(sweep, name, d);
  else if (type == "bool") io::writeVector(sweep, name, b);
  else io::writeVector(sweep, name, s);
}

// One /sweep column, read once, as parameter values.
std::vector<kinds::Value> readColumn(const io::Group& sweep, const std::string& name, const std::string& type) {
  std::vector<kinds::Value> out;
  if (type == "int64") {
    for (auto v : io::readVectorInt64(sweep, name)) out.emplace_back(v);
  } else if (type == "double") {
    for (auto v : io::readVectorDouble(sweep, name)) out.emplace_back(v);
  } else if (type == "bool") {
    for (auto v : io::readVectorInt8(sweep, name)) out.emplace_back(v != 0);
  } else {
    // A column mixing text and numbers (dt_s = ["auto", 0.01]) is stored as text; numbers come
    // back as numbers so selections such as where = { dt_s = 0.01 } still match.
    for (const auto& text : io::readVectorString(sweep, name)) {
      char* end = nullptr;
      const double x = std::strtod(text.c_str(), &end);
      if (!text.empty() && end && *end == '\0') out.emplace_back(x);
      else out.emplace_back(text);
    }
  }
  return out;
}

}  // namespace

// The contents of a point file and of the index, written while the file is open (File::close
// needs every group handle closed first, so these run in their own scope).
static void writePointContents(const io::Group& root, const Experiment& e, const kinds::Kind& kind, const Point& point,
                               const PointOutcome& outcome, Provenance provenance);
static void writeIndexContents(const io::Group& root, const Experiment& e, const kinds::Kind& kind, const Table& table,
                               const std::vector<CheckOutcome>& checks, Provenance provenance);

std::string pointFileName(int index) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "point_%06d.h5", index);
  return buf;
}

std::string pointConfigJson(const std::string& kind, const Point& point) {
  return nlohmann::json{{"kind", kind}, {"params", toJson(point.params)}}.dump();
}

std::string pointConfigSha(const std::string& kind, const Point& point) {
  return core::sha256Hex(pointConfigJson(kind, point));
}

void writePointFile(const std::string& dir, const Experiment& e, const kinds::Kind& kind, const Point& point,
                    const PointOutcome& outcome, Provenance provenance) {
  const std::string final_path = dir + "/" + pointFileName(point.index), tmp_path = final_path + ".tmp";
  writeArtifacts(dir, point.index, outcome.result);  // before the point file: a point file that exists is whole
  {
    io::File file = io::File::create(tmp_path);
    writePointContents(file.root(), e, kind, point, outcome, std::move(provenance));
    file.close();
  }
  fs::rename(tmp_path, final_path);  // a point file that exists is whole
  writeXdmfSidecar(dir, point.index, outcome.result.fields);
}

static void writePointContents(const io::Group& root, const Experiment& e, const kinds::Kind& kind, const Point& point,
                               const PointOutcome& outcome, Provenance provenance) {
  io::setAttr(root, "kind", e.kind);
  io::setAttr(root, "title", e.title);
  io::setAttr(root, "experiment", e.path);
  io::setAttr(root, "point_index", std::int64_t(point.index));
  io::setAttr(root, "label", point.label);
  io::setAttr(root, "status", outcome.ok ? "ok" : "failed");
  io::setAttr(root, "message", outcome.message);
  io::setAttr(root, "config_json", pointConfigJson(e.kind, point));
  io::setAttr(root, "config_sha256", pointConfigSha(e.kind, point));
  writeParameters(root, kind, point.params);
  provenance["started"] = outcome.started;
  provenance["finished"] = outcome.finished;
  writeProvenance(root, provenance);
  io::setAttr(root, "wall_time_s", outcome.wall_s);
  writeResult(root, outcome.result, e.output.lagrangian);
}

std::string readPointConfigSha(const std::string& path) {
  try {
    const io::File file = io::File::openReadOnly(path);
    return io::getAttrString(file.root(), "config_sha256");
  } catch (const io::Hdf5Error&) {
    return "";
  }
}

std::string pointFileDamage(const std::string& path, const std::string& kind, const Point& point,
                            const PointSeal* recorded) {
  std::string config;
  try {
    const io::File file = io::File::openReadOnly(path);
    config = io::getAttrString(file.root(), "config_sha256");
  } catch (const std::exception& e) {
    return e.what();
  }
  if (config != pointConfigSha(kind, point))
    throw ExperimentError(path + " was made by a different configuration; use --force or another --out");
  std::string content;
  try {
    content = io::contentDigest(path, provenanceAttributeNames());
  } catch (const std::exception& e) {
    return e.what();
  }
  if (recorded && recorded->config_sha256 == config && recorded->content_sha256 != content)
    return "its content differs from what index.h5 recorded (changed after the run)";
  return "";
}

Row readPointRow(const std::string& dir, const Point& point, const std::vector<std::string>& columns,
                 const kinds::Kind& kind) {
  Row row;
  row.index = point.index;
  row.label = point.label;
  for (const auto& c : columns) row.columns[c] = point.params.at(c);
  for (const auto& m : kind.metrics()) row.metrics[m.name] = std::nan("");
  const std::string path = dir + "/" + pointFileName(point.index);
  if (!fs::exists(path)) return row;
  try {
    const io::File file = io::File::openReadOnly(path);
    const io::Group root = file.root();
    row.config_sha256 = io::getAttrString(root, "config_sha256");
    if (row.config_sha256 != pointConfigSha(kind.name(), point))
      throw ExperimentError(path + " was made by a different configuration than this run (another run into the same "
                            "folder?): not listed; use --force or another --out");
    row.content_sha256 = io::contentDigest(path, provenanceAttributeNames());
    row.status = io::getAttrString(root, "status");
    row.message = io::getAttrString(root, "message");
    if (root.isGroup("metrics")) {
      const io::Group metrics = root.openGroup("metrics");
      for (auto& [name, value] : row.metrics)
        if (metrics.isDataset(name)) value = io::readScalarDouble(metrics, name);
    }
  } catch (const io::Hdf5Error& e) {
    throw ExperimentError(path + ": damaged point file (" + e.what() + "); run again with --resume to recompute it");
  }
  return row;
}

void writeIndex(const std::string& dir, const Experiment& e, const kinds::Kind& kind, const Table& table,
                const std::vector<CheckOutcome>& checks, Provenance provenance) {
  const std::string final_path = dir + "/index.h5", tmp_path = final_path + ".tmp";
  {
    io::File file = io::File::create(tmp_path);
    writeIndexContents(file.root(), e, kind, table, checks, std::move(provenance));
    file.close();
  }
  fs::rename(tmp_path, final_path);
}

static void writeIndexContents(const io::Group& root, const Experiment& e, const kinds::Kind& kind, const Table& table,
                               const std::vector<CheckOutcome>& checks, Provenance provenance) {
  io::setAttr(root, "kind", e.kind);
  io::setAttr(root, "title", e.title);
  io::setAttr(root, "experiment", e.path);
  io::setAttr(root, "experiment_toml", e.source_text);
  io::setAttr(root, "overrides_json", nlohmann::json(e.overrides).dump());
  io::setAttr(root, "config_json", e.resolved_json);
  io::setAttr(root, "config_sha256", core::sha256Hex(e.resolved_json));
  writeProvenance(root, provenance);

  const io::Group sweep = root.requireGroup("sweep");
  io::writeColumn(sweep, "point_index", table.rows, &Row::index);
  io::writeColumn(sweep, "label", table.rows, &Row::label);
  io::writeColumn(sweep, "status", table.rows, &Row::status);
  io::writeColumn(sweep, "message", table.rows, &Row::message);
  nlohmann::json types = nlohmann::json::object();
  for (const auto& c : table.columns) {
    const std::string type = columnType(table, c).type;
    writeColumn(sweep, table, c, type);
    types[c] = type;
    for (const auto& spec : kind.params())
      if (spec.name == c) io::setAttr(sweep.openDataset(c), "unit", spec.unit);
  }
  for (const auto& m : kind.metrics()) {
    const auto metric = [&](const Row& row) { return row.metrics.at(m.name); };
    io::setAttr(io::writeColumn(sweep, m.name, table.rows, metric), "unit", m.unit);
  }
  io::setAttr(sweep, "columns_json", nlohmann::json(table.columns).dump());
  io::setAttr(sweep, "column_types_json", types.dump());
  io::setAttr(sweep, "metrics_json", nlohmann::json(table.metrics).dump());

  const io::Group chk = root.requireGroup("checks");
  io::writeColumn(chk, "name", checks, &CheckOutcome::name);
  io::writeColumn(chk, "type", checks, &CheckOutcome::type);
  io::writeColumn(chk, "expected", checks, &CheckOutcome::expected);
  io::writeColumn(chk, "got", checks, &CheckOutcome::got);
  io::writeColumn(chk, "passed", checks, &CheckOutcome::passed);
  io::writeColumn(chk, "known_deviation", checks, &CheckOutcome::known_deviation);
  io::writeColumn(chk, "inconclusive", checks, &CheckOutcome::inconclusive);

  // The seal of each point file, checked by `check` and `compare` before they trust this index.
  std::vector<Row> present;
  for (const auto& row : table.rows)
    if (row.status != "missing") present.push_back(row);
  const io::Group integrity = root.requireGroup("integrity");
  io::writeColumn(integrity, "point_index", present, &Row::index);
  io::writeColumn(integrity, "config_sha256", present, &Row::config_sha256);
  io::writeColumn(integrity, "content_sha256", present, &Row::content_sha256);

  const io::Group links = root.requireGroup("points");
  for (const auto& row : table.rows)
    if (row.status != "missing")
      io::createExternalLink(links, fs::path(pointFileName(row.index)).stem().string(), pointFileName(row.index), "/");
}

namespace {

// index.h5 is read as untrusted input: HDF5 keeps attributes without a checksum, so the JSON they
// hold and the lengths of the /sweep columns are checked before a row is built.
struct IndexReader {
  std::string path;

  [[noreturn]] void bad(const std::string& what) const {
    throw std::runtime_error(path + ": damaged index (" + what + "); run the experiment again with --resume");
  }

  nlohmann::json json(const io::Group& group, const std::string& group_name, const std::string& attr) const {
    const std::string text = io::getAttrString(group, attr);
    try {
      return nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
      bad(group_name + " attribute " + attr + " is not JSON: " + e.what());
    }
  }

  std::vector<std::string> names(const io::Group& group, const std::string& group_name,
                                 const std::string& attr) const {
    const nlohmann::json j = json(group, group_name, attr);
    std::vector<std::string> out;
    if (!j.is_array()) bad(group_name + " attribute " + attr + " is not a list of names");
    for (const auto& item : j) {
      if (!item.is_string() || item.get<std::string>().empty()) bad(group_name + " attribute " + attr + " holds a non-name");
      out.push_back(item.get<std::string>());
    }
    return out;
  }

  template <class T>
  const T& sized(const T& values, std::size_t rows, const std::string& dataset) const {
    if (values.size() != rows)
      bad(dataset + " has " + std::to_string(values.size()) + " rows, /sweep/point_index " + std::to_string(rows));
    return values;
  }
};

}  // namespace

StoredRun readIndex(const std::string& dir) {
  const std::string path = dir + "/index.h5";
  if (fs::exists(dir) && !fs::is_directory(dir))
    throw std::runtime_error(dir + ": is a file; expected a run folder (the --out of `creaturelab run`)");
  if (!fs::exists(path))
    throw std::runtime_error(path + ": no index (not a run folder, or the run has not finished: use --resume)");
  const IndexReader in{path};
  const io::File file = io::File::openReadOnly(path);
  const io::Group root = file.root();
  StoredRun out;
  out.experiment_path = io::getAttrString(root, "experiment");
  out.experiment_text = io::getAttrString(root, "experiment_toml");
  out.overrides = in.names(root, "/", "overrides_json");
  const io::Group sweep = root.openGroup("sweep");
  out.table.columns = in.names(sweep, "/sweep", "columns_json");
  out.table.metrics = in.names(sweep, "/sweep", "metrics_json");
  const nlohmann::json types = in.json(sweep, "/sweep", "column_types_json");
  if (!types.is_object()) in.bad("/sweep attribute column_types_json is not an object");
  const auto index = io::readVectorInt64(sweep, "point_index");
  const std::size_t rows = index.size();
  const auto label = in.sized(io::readVectorString(sweep, "label"), rows, "/sweep/label");
  const auto status = in.sized(io::readVectorString(sweep, "status"), rows, "/sweep/status");
  const auto message = in.sized(io::readVectorString(sweep, "message"), rows, "/sweep/message");
  std::map<std::string, std::vector<double>> metric_values;
  for (const auto& m : out.table.metrics)
    metric_values[m] = in.sized(io::readVectorDouble(sweep, m), rows, "/sweep/" + m);
  std::map<std::string, std::vector<kinds::Value>> column_values;
  for (const auto& c : out.table.columns) {
    const auto type = types.find(c);
    static const std::vector<std::string> known{"int64", "double", "bool", "string"};
    if (type == types.end() || !type->is_string() ||
        std::find(known.begin(), known.end(), type->get<std::string>()) == known.end())
      in.bad("/sweep attribute column_types_json gives column " + c + " no known type");
    column_values[c] = in.sized(readColumn(sweep, c, type->get<std::string>()), rows, "/sweep/" + c);
  }
  for (size_t r = 0; r < rows; ++r) {
    if (index[r] < 0 || index[r] > std::numeric_limits<int>::max())
      in.bad("/sweep/point_index holds " + std::to_string(index[r]));
    Row row{int(index[r]), label[r], status[r], message[r], {}, {}, {}, {}};
    for (const auto& c : out.table.columns) row.columns[c] = column_values[c][r];
    for (const auto& m : out.table.metrics) row.metrics[m] = metric_values[m][r];
    out.table.rows.push_back(std::move(row));
  }
  if (root.isGroup("integrity")) {
    const io::Group integrity = root.openGroup("integrity");
    const auto ids = io::readVectorInt64(integrity, "point_index");
    const auto config = in.sized(io::readVectorString(integrity, "config_sha256"), ids.size(), "/integrity/config_sha256");
    const auto content =
        in.sized(io::readVectorString(integrity, "content_sha256"), ids.size(), "/integrity/content_sha256");
    for (size_t i = 0; i < ids.size(); ++i) {
      if (ids[i] < 0 || ids[i] > std::numeric_limits<int>::max())
        in.bad("/integrity/point_index holds " + std::to_string(ids[i]));
      out.seals[int(ids[i])] = {config[i], content[i]};
    }
  }
  return out;
}

}  // namespace creaturelab::runner
