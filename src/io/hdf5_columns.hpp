#pragma once
// Records (a vector of structs) stored column by column: one 1-D dataset per field, the layout
// h5py and pandas read as a table.
//
//   io::writeColumn(group, "cost", evaluations, &Evaluation::cost);
//   io::writeColumn(group, name, rows, [&](const Row& r) { return r.metrics.at(name); });
//
// The stored type follows the field's: bool as int8 0/1, other integers as int64, floating
// point as double, text as string (the types writeVector stores).

#include "io/hdf5_dataset.hpp"

#include <concepts>
#include <cstdint>
#include <functional>
#include <ranges>
#include <string>
#include <type_traits>
#include <vector>

namespace creaturelab::io {

// The element type writeVector stores a field of type T as.
template <class T>
using ColumnType =
    std::conditional_t<std::same_as<T, bool>, std::int8_t,
                       std::conditional_t<std::integral<T>, std::int64_t,
                                          std::conditional_t<std::floating_point<T>, double, std::string>>>;

// Writes `field` (a member pointer or a callable on one record) of every record, in order.
template <std::ranges::input_range Records, class Field>
Dataset writeColumn(const Group& group, const std::string& name, const Records& records, Field&& field) {
  using Value = std::remove_cvref_t<std::invoke_result_t<Field&, std::ranges::range_reference_t<const Records>>>;
  std::vector<ColumnType<Value>> column;
  for (const auto& record : records) column.push_back(ColumnType<Value>(std::invoke(field, record)));
  return writeVector(group, name, column);
}

}  // namespace creaturelab::io
