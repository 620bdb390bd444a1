#include "io/hdf5_dataset.hpp"

#include "io/hdf5_detail.hpp"
#include "io/hdf5_error.hpp"

#include <cstring>

namespace creaturelab::io {
namespace {

Dataset createDataset(const Group& group, const std::string& name, hid_t file_type,
                      const std::vector<hsize_t>& dims, const std::optional<std::vector<hsize_t>>& chunk_dims) {
  Handle space = detail::dataspaceOf(dims);
  Handle create_props = detail::datasetCreateProps();
  if (chunk_dims) {
    if (chunk_dims->size() != dims.size() || dims.empty()) {
      detail::failAt(group.id(), name, "create dataset",
                     "chunk rank " + std::to_string(chunk_dims->size()) + " differs from data rank " +
                         std::to_string(dims.size()));
    }
    detail::check(H5Pset_chunk(create_props.id(), static_cast<int>(dims.size()), chunk_dims->data()), group.id(),
                  name, "set the chunk shape of dataset");
  }
  Handle link_props = detail::linkCreateProps();
  return Dataset(Handle(detail::check(
      H5Dcreate2(group.id(), name.c_str(), file_type, space.id(), link_props.id(), create_props.id(), H5P_DEFAULT),
      group.id(), name, "create dataset")));
}

template <class T>
Dataset writeNumeric(const Group& group, const std::string& name, const T* data, const std::vector<hsize_t>& dims,
                     const std::optional<std::vector<hsize_t>>& chunk_dims, hid_t file_type, hid_t memory_type) {
  auto lock = lockHdf5();
  Dataset dataset = createDataset(group, name, file_type, dims, chunk_dims);
  if (detail::elementCount(dims) > 0) {
    detail::check(H5Dwrite(dataset.id(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), group.id(), name,
                  "write dataset");
  }
  return dataset;
}

struct OpenedDataset {
  Dataset dataset;
  std::vector<hsize_t> dims;
};

// Opens `name`; `required_rank` < 0 accepts any rank.
OpenedDataset openForReading(const Group& group, const std::string& name, int required_rank) {
  Dataset dataset(
      Handle(detail::check(H5Dopen2(group.id(), name.c_str(), H5P_DEFAULT), group.id(), name, "open dataset")));
  Handle space(detail::check(H5Dget_space(dataset.id()), group.id(), name, "get the shape of dataset"));
  std::vector<hsize_t> dims = detail::extentOf(space.id());
  if (required_rank >= 0 && dims.size() != static_cast<std::size_t>(required_rank)) {
    detail::failAt(group.id(), name, "read dataset",
                   "it has rank " + std::to_string(dims.size()) + ", expected rank " + std::to_string(required_rank));
  }
  return {std::move(dataset), std::move(dims)};
}

template <class T>
std::vector<T> readNumeric(const Group& group, const std::string& name, int required_rank, hid_t memory_type) {
  auto lock = lockHdf5();
  OpenedDataset opened = openForReading(group, name, required_rank);
  std::vector<T> values(detail::elementCount(opened.dims));
  if (!values.empty()) {
    detail::check(H5Dread(opened.dataset.id(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
                  group.id(), name, "read dataset");
  }
  return values;
}

}  // namespace

Dataset writeVector(const Group& group, const std::string& name, const std::vector<double>& values) {
  return writeNumeric(group, name, values.data(), {values.size()}, std::nullopt, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE);
}

Dataset writeVector(const Group& group, const std::string& name, const std::vector<std::int64_t>& values) {
  return writeNumeric(group, name, values.data(), {values.size()}, std::nullopt, H5T_STD_I64LE, H5T_NATIVE_INT64);
}

Dataset writeVector(const Group& group, const std::string& name, const std::vector<std::int8_t>& values) {
  return writeNumeric(group, name, values.data(), {values.size()}, std::nullopt, H5T_STD_I8LE, H5T_NATIVE_INT8);
}

Dataset writeVector(const Group& group, const std::string& name, const std::vector<std::string>& values) {
  auto lock = lockHdf5();
  std::vector<const char*> pointers;
  pointers.reserve(values.size());
  for (const std::string& value : values) {
    if (value.find('\0') != std::string::npos) {
      detail::failAt(group.id(), name, "write dataset", "a string contains a NUL byte");
    }
    pointers.push_back(value.c_str());
  }
  Handle type = detail::utf8StringType();
  Dataset dataset = createDataset(group, name, type.id(), {values.size()}, std::nullopt);
  if (!values.empty()) {
    detail::check(H5Dwrite(dataset.id(), type.id(), H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()), group.id(),
                  name, "write dataset");
  }
  return dataset;
}

Dataset writeScalar(const Group& group, const std::string& name, double value) {
  return writeNumeric(group, name, &value, {}, std::nullopt, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE);
}

Dataset writeArray(const Group& group, const std::string& name, const double* data, std::vector<hsize_t> dims,
                   std::optional<std::vector<hsize_t>> chunk_dims) {
  return writeNumeric(group, name, data, dims, chunk_dims, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE);
}

Dataset writeArray(const Group& group, const std::string& name, const std::int64_t* data, std::vector<hsize_t> dims,
                   std::optional<std::vector<hsize_t>> chunk_dims) {
  return writeNumeric(group, name, data, dims, chunk_dims, H5T_STD_I64LE, H5T_NATIVE_INT64);
}

Dataset createArray(const Group& group, const std::string& name, std::vector<hsize_t> dims,
                    std::optional<std::vector<hsize_t>> chunk_dims) {
  auto lock = lockHdf5();
  return createDataset(group, name, H5T_IEEE_F64LE, dims, chunk_dims);
}

void writeSlab(const Dataset& dataset, hsize_t first, hsize_t count, const double* data) {
  auto lock = lockHdf5();
  Handle file_space(detail::check(H5Dget_space(dataset.id()), dataset.id(), "", "get the shape of dataset"));
  std::vector<hsize_t> dims = detail::extentOf(file_space.id());
  if (dims.empty() || first + count > dims[0]) {
    detail::failAt(dataset.id(), "", "write rows of dataset",
                   "rows " + std::to_string(first) + ".." + std::to_string(first + count) + " are outside its " +
                       std::to_string(dims.empty() ? 0 : dims[0]) + " rows");
  }
  std::vector<hsize_t> start(dims.size(), 0), extent = dims;
  start[0] = first;
  extent[0] = count;
  detail::check(H5Sselect_hyperslab(file_space.id(), H5S_SELECT_SET, start.data(), nullptr, extent.data(), nullptr),
                dataset.id(), "", "select rows of dataset");
  Handle memory_space = detail::dataspaceOf(extent);
  if (count == 0) return;
  detail::check(H5Dwrite(dataset.id(), H5T_NATIVE_DOUBLE, memory_space.id(), file_space.id(), H5P_DEFAULT, data),
                dataset.id(), "", "write rows of dataset");
}

std::vector<double> readVectorDouble(const Group& group, const std::string& name) {
  return readNumeric<double>(group, name, 1, H5T_NATIVE_DOUBLE);
}

std::vector<std::int64_t> readVectorInt64(const Group& group, const std::string& name) {
  return readNumeric<std::int64_t>(group, name, 1, H5T_NATIVE_INT64);
}

std::vector<std::int8_t> readVectorInt8(const Group& group, const std::string& name) {
  return readNumeric<std::int8_t>(group, name, 1, H5T_NATIVE_INT8);
}

std::vector<double> readArrayDouble(const Group& group, const std::string& name) {
  return readNumeric<double>(group, name, -1, H5T_NATIVE_DOUBLE);
}

double readScalarDouble(const Group& group, const std::string& name) {
  auto lock = lockHdf5();
  const std::vector<double> values = readNumeric<double>(group, name, -1, H5T_NATIVE_DOUBLE);
  if (values.size() != 1) {
    detail::failAt(group.id(), name, "read dataset",
                   "it has " + std::to_string(values.size()) + " elements, expected a scalar");
  }
  return values.front();
}

std::vector<std::string> readVectorString(const Group& group, const std::string& name) {
  auto lock = lockHdf5();
  OpenedDataset opened = openForReading(group, name, 1);
  Handle file_type(detail::check(H5Dget_type(opened.dataset.id()), group.id(), name, "get the type of dataset"));
  if (H5Tget_class(file_type.id()) != H5T_STRING) {
    detail::failAt(group.id(), name, "read dataset", "it does not hold strings");
  }
  Handle space(H5Dget_space(opened.dataset.id()));
  return detail::readStrings(file_type.id(), space.id(), [&](hid_t memory_type, void* buffer) {
    detail::check(H5Dread(opened.dataset.id(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer), group.id(),
                  name, "read dataset");
  });
}

std::vector<hsize_t> datasetShape(const Group& group, const std::string& name) {
  auto lock = lockHdf5();
  return openForReading(group, name, -1).dims;
}

}  // namespace creaturelab::io
