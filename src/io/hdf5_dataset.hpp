#pragma once
// Writing and reading whole datasets. Stored types: IEEE f64 little-endian, i64 / i8
// little-endian, variable-length UTF-8 strings (h5py: Dataset.asstr() gives str).
// Writers fail if the name exists. Readers convert numeric types as HDF5 does (an int64
// dataset can be read with readVectorDouble), and accept both variable- and fixed-length
// strings.

#include "io/hdf5_object.hpp"

#include <hdf5.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace creaturelab::io {

Dataset writeVector(const Group& group, const std::string& name, const std::vector<double>& values);
Dataset writeVector(const Group& group, const std::string& name, const std::vector<std::int64_t>& values);
Dataset writeVector(const Group& group, const std::string& name, const std::vector<std::int8_t>& values);
// Strings must not contain NUL bytes (HDF5 would cut them there); that is an error.
Dataset writeVector(const Group& group, const std::string& name, const std::vector<std::string>& values);

Dataset writeScalar(const Group& group, const std::string& name, double value);

// Row-major N-D array of prod(dims) doubles. With chunk_dims (same rank as dims, each
// >= 1) the dataset is chunked, e.g. {1, ny, nx} for one frame per chunk.
Dataset writeArray(const Group& group, const std::string& name, const double* data, std::vector<hsize_t> dims,
                   std::optional<std::vector<hsize_t>> chunk_dims = std::nullopt);

// The same for integers (e.g. a mesh's (triangles, 3) vertex indices).
Dataset writeArray(const Group& group, const std::string& name, const std::int64_t* data, std::vector<hsize_t> dims,
                   std::optional<std::vector<hsize_t>> chunk_dims = std::nullopt);

// A dataset of doubles written later in slabs along its first dimension (frames written as they
// are made): createArray makes it (contents 0 until written), writeSlab writes `count` rows from
// row `first`, each row the product of the other dimensions.
Dataset createArray(const Group& group, const std::string& name, std::vector<hsize_t> dims,
                    std::optional<std::vector<hsize_t>> chunk_dims = std::nullopt);
void writeSlab(const Dataset& dataset, hsize_t first, hsize_t count, const double* data);

// 1-D readers (a rank other than 1 is an error).
std::vector<double> readVectorDouble(const Group& group, const std::string& name);
std::vector<std::int64_t> readVectorInt64(const Group& group, const std::string& name);
std::vector<std::int8_t> readVectorInt8(const Group& group, const std::string& name);
std::vector<std::string> readVectorString(const Group& group, const std::string& name);

// A scalar dataset, or one of exactly one element.
double readScalarDouble(const Group& group, const std::string& name);

// Any rank, flattened row-major; pair with datasetShape().
std::vector<double> readArrayDouble(const Group& group, const std::string& name);

std::vector<hsize_t> datasetShape(const Group& group, const std::string& name);  // {} for a scalar

}  // namespace creaturelab::io
