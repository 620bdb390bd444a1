#pragma once
// Scalar attributes on groups (the root included) and datasets.
// Stored types: f64 LE, i64 LE, h5py's boolean enum (int8 base, FALSE=0, TRUE=1: h5py
// reads numpy.bool_), variable-length UTF-8 string (h5py reads str). Setting an existing
// attribute replaces it.

#include "io/hdf5_object.hpp"

#include <concepts>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace creaturelab::io {

using AttrValue = std::variant<double, std::int64_t, bool, std::string>;

void setAttr(const Object& object, const std::string& name, double value);
void setAttr(const Object& object, const std::string& name, std::int64_t value);
void setAttr(const Object& object, const std::string& name, bool value);
void setAttr(const Object& object, const std::string& name, const std::string& value);
void setAttr(const Object& object, const std::string& name, std::string_view value);
// Without this overload a string literal would convert to bool.
void setAttr(const Object& object, const std::string& name, const char* value);
void setAttr(const Object& object, const std::string& name, const AttrValue& value);

// Other integers (int, unsigned, std::size_t, ...) are stored as int64; an unsigned value
// above INT64_MAX is an error.
template <std::integral T>
  requires(!std::same_as<T, bool> && !std::same_as<T, std::int64_t>)
void setAttr(const Object& object, const std::string& name, T value);

bool hasAttr(const Object& object, const std::string& name);
std::vector<std::string> attrNames(const Object& object);  // sorted by byte value

// Reads a scalar (or one-element) attribute of any of the four types. Other integer and
// float widths convert to int64 / double; fixed-length strings are accepted.
AttrValue getAttr(const Object& object, const std::string& name);
// Typed readers: an attribute of another type is an error that names it.
double getAttrDouble(const Object& object, const std::string& name);
std::int64_t getAttrInt64(const Object& object, const std::string& name);
bool getAttrBool(const Object& object, const std::string& name);
std::string getAttrString(const Object& object, const std::string& name);

namespace detail {
[[noreturn]] void failIntegerAttrOutOfRange(const Object& object, const std::string& name);
}  // namespace detail

template <std::integral T>
  requires(!std::same_as<T, bool> && !std::same_as<T, std::int64_t>)
void setAttr(const Object& object, const std::string& name, T value) {
  if constexpr (std::is_unsigned_v<T> && sizeof(T) >= sizeof(std::int64_t)) {
    if (value > static_cast<T>(std::numeric_limits<std::int64_t>::max())) {
      detail::failIntegerAttrOutOfRange(object, name);
    }
  }
  setAttr(object, name, static_cast<std::int64_t>(value));
}

}  // namespace creaturelab::io
