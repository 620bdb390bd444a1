#include "fit/profile_io.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <vector>

#include "io/hdf5.hpp"

namespace creaturelab::fit {
namespace {

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    const auto comma = line.find(',', start);
    out.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

bool parseNumber(const std::string& text, double& out) {
  if (text.empty()) return false;
  char* end = nullptr;
  out = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size();
}

}  // namespace

Profile readProfileCsv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw FitError(path + ": cannot open the data file");
  Profile p;
  p.source = path;
  std::string line;
  std::vector<std::string> header;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const auto fields = splitFields(t);
    const std::string where = path + ":" + std::to_string(line_no) + ": ";
    if (header.empty()) {
      double ignored = 0;
      if (parseNumber(fields[0], ignored))
        throw FitError(where + "expected a header row first (e.g. time_s,value), got numbers");
      if (fields.size() != 2 && fields.size() != 3)
        throw FitError(where + "the header has " + std::to_string(fields.size()) +
                       " columns; expected time_s,value or time_s,value,weight");
      header = fields;
      continue;
    }
    if (fields.size() != header.size())
      throw FitError(where + std::to_string(fields.size()) + " columns, but the header has " +
                     std::to_string(header.size()));
    double x[3] = {0, 0, 1};
    for (std::size_t c = 0; c < fields.size(); ++c) {
      if (!parseNumber(fields[c], x[c]))
        throw FitError(where + header[c] + " '" + fields[c] + "' is not a number");
      if (!std::isfinite(x[c]))
        throw FitError(where + header[c] + " is " + fields[c] + ": remove the row (NaN and infinite samples are not fitted)");
    }
    p.time_s.push_back(x[0]);
    p.value.push_back(x[1]);
    if (header.size() == 3) p.weight.push_back(x[2]);
  }
  if (header.empty()) throw FitError(path + ": empty file (expected a header row and samples)");
  if (p.time_s.empty()) throw FitError(path + ": no samples after the header");
  return p;
}

Hdf5Profile readProfileHdf5(const std::string& path, const Hdf5ProfileSource& source) {
  namespace fs = std::filesystem;
  Hdf5Profile out;
  out.file = path;
  if (fs::is_directory(path)) {
    char name[64];
    std::snprintf(name, sizeof name, "point_%06d.h5", source.point);
    out.file = (fs::path(path) / name).string();
  }
  if (!fs::exists(out.file)) throw FitError(out.file + ": no such HDF5 file");
  try {
    const io::File file = io::File::openReadOnly(out.file);
    const io::Group root = file.root();
    for (const std::string* name : {&source.time_dataset, &source.value_dataset, &source.weight_dataset})
      if (!name->empty() && !root.isDataset(*name))
        throw FitError(out.file + ": no dataset '" + *name + "' (choose one with --dataset / --time-dataset)");
    Profile& p = out.profile;
    p.source = out.file + ":/" + source.value_dataset;
    p.time_s = io::readVectorDouble(root, source.time_dataset);
    p.value = io::readVectorDouble(root, source.value_dataset);
    if (!source.weight_dataset.empty()) p.weight = io::readVectorDouble(root, source.weight_dataset);
    if (io::hasAttr(root, "contraction_hz")) {
      const io::AttrValue hz = io::getAttr(root, "contraction_hz");
      if (const double* d = std::get_if<double>(&hz)) out.contraction_hz = *d;
    }
  } catch (const io::Hdf5Error& e) {
    throw FitError(std::string(e.what()));
  }
  return out;
}

}  // namespace creaturelab::fit
