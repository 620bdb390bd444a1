#include "io/hdf5_detail.hpp"

#include <cstdint>

namespace creaturelab::io::detail {

namespace {
herr_t keepInnermost(unsigned /*n*/, const H5E_error2_t* error, void* out) {
  if (error != nullptr && error->desc != nullptr && error->desc[0] != '\0') {
    *static_cast<std::string*>(out) = error->desc;
  }
  return 0;
}
}  // namespace

std::string takeHdf5Message() {
  std::string message;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, keepInnermost, &message);
  H5Eclear2(H5E_DEFAULT);
  return message;
}

std::string fileNameOf(hid_t id) {
  const ssize_t length = H5Fget_name(id, nullptr, 0);
  if (length <= 0) {
    H5Eclear2(H5E_DEFAULT);
    return {};
  }
  std::string name(static_cast<std::size_t>(length) + 1, '\0');
  H5Fget_name(id, name.data(), name.size());
  name.resize(static_cast<std::size_t>(length));
  return name;
}

std::string objectPathOf(hid_t id) {
  const ssize_t length = H5Iget_name(id, nullptr, 0);
  if (length <= 0) {
    H5Eclear2(H5E_DEFAULT);
    return {};
  }
  std::string path(static_cast<std::size_t>(length) + 1, '\0');
  H5Iget_name(id, path.data(), path.size());
  path.resize(static_cast<std::size_t>(length));
  return path;
}

std::string childPath(hid_t parent, std::string_view name) {
  if (!name.empty() && name.front() == '/') return std::string(name);
  std::string path = objectPathOf(parent);
  if (path.empty() || path.back() != '/') path += '/';
  path += name;
  return path;
}

namespace {
[[noreturn]] void throwError(std::string_view what, std::string_view object, std::string_view file,
                             const std::string& cause) {
  std::string message = "HDF5: cannot ";
  message += what;
  if (!object.empty()) {
    message += " \"";
    message += object;
    message += "\" in";
  }
  message += " file \"";
  message += file;
  message += "\"";
  if (!cause.empty()) message += ": " + cause;
  throw Hdf5Error(message);
}
}  // namespace

void fail(std::string_view what, std::string_view object, std::string_view file) {
  throwError(what, object, file, takeHdf5Message());
}

void failAt(hid_t parent, std::string_view name, std::string_view what, std::string_view reason) {
  // Take HDF5's message first: the name look-ups below clear the stack when they fail.
  const std::string hdf5_message = takeHdf5Message();
  const std::string cause = reason.empty() ? hdf5_message : std::string(reason);
  const std::string object = name.empty() ? objectPathOf(parent) : childPath(parent, name);
  throwError(what, object, fileNameOf(parent), cause);
}

Handle groupCreateProps() {
  Handle props(H5Pcreate(H5P_GROUP_CREATE));
  H5Pset_obj_track_times(props.id(), false);
  return props;
}

Handle datasetCreateProps() {
  Handle props(H5Pcreate(H5P_DATASET_CREATE));
  H5Pset_obj_track_times(props.id(), false);
  return props;
}

Handle linkCreateProps() {
  Handle props(H5Pcreate(H5P_LINK_CREATE));
  H5Pset_char_encoding(props.id(), H5T_CSET_UTF8);
  return props;
}

Handle attributeCreateProps() {
  Handle props(H5Pcreate(H5P_ATTRIBUTE_CREATE));
  H5Pset_char_encoding(props.id(), H5T_CSET_UTF8);
  return props;
}

Handle utf8StringType() {
  Handle type(H5Tcopy(H5T_C_S1));
  H5Tset_size(type.id(), H5T_VARIABLE);
  H5Tset_cset(type.id(), H5T_CSET_UTF8);
  return type;
}

Handle boolEnumType() {
  Handle type(H5Tenum_create(H5T_NATIVE_INT8));
  const std::int8_t false_value = 0;
  const std::int8_t true_value = 1;
  H5Tenum_insert(type.id(), "FALSE", &false_value);
  H5Tenum_insert(type.id(), "TRUE", &true_value);
  return type;
}

bool isBoolEnum(hid_t type) {
  if (H5Tget_class(type) != H5T_ENUM || H5Tget_size(type) != 1 || H5Tget_nmembers(type) != 2) return false;
  for (unsigned i = 0; i < 2; ++i) {
    char* name = H5Tget_member_name(type, i);
    if (name == nullptr) return false;
    std::int8_t value = -1;
    H5Tget_member_value(type, i, &value);
    const std::string_view view(name);
    const bool ok = (view == "FALSE" && value == 0) || (view == "TRUE" && value == 1);
    H5free_memory(name);
    if (!ok) return false;
  }
  return true;
}

Handle dataspaceOf(const std::vector<hsize_t>& dims) {
  if (dims.empty()) return Handle(H5Screate(H5S_SCALAR));
  return Handle(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr));
}

std::vector<hsize_t> extentOf(hid_t dataspace) {
  const int rank = H5Sget_simple_extent_ndims(dataspace);
  std::vector<hsize_t> dims(rank > 0 ? static_cast<std::size_t>(rank) : 0);
  if (rank > 0) H5Sget_simple_extent_dims(dataspace, dims.data(), nullptr);
  return dims;
}

hsize_t elementCount(const std::vector<hsize_t>& dims) {
  hsize_t count = 1;
  for (hsize_t d : dims) count *= d;
  return count;
}

std::vector<std::string> readStrings(hid_t file_type, hid_t space, const std::function<void(hid_t, void*)>& read) {
  const std::size_t count = elementCount(extentOf(space));
  std::vector<std::string> values(count);
  if (count == 0) return values;
  if (H5Tis_variable_str(file_type) > 0) {
    Handle memory_type = utf8StringType();
    H5Tset_cset(memory_type.id(), H5Tget_cset(file_type));
    std::vector<char*> pointers(count, nullptr);
    read(memory_type.id(), pointers.data());
    for (std::size_t i = 0; i < count; ++i) {
      if (pointers[i] != nullptr) values[i] = pointers[i];
    }
    H5Dvlen_reclaim(memory_type.id(), space, H5P_DEFAULT, pointers.data());
    return values;
  }
  // Fixed length: NUL-terminated or NUL-padded strings stop at the first NUL,
  // space-padded ones lose their trailing spaces.
  const std::size_t size = H5Tget_size(file_type);
  std::vector<char> buffer(count * size);
  read(file_type, buffer.data());
  const bool space_padded = H5Tget_strpad(file_type) == H5T_STR_SPACEPAD;
  for (std::size_t i = 0; i < count; ++i) {
    std::string value(buffer.data() + i * size, size);
    if (space_padded) {
      value.erase(value.find_last_not_of(' ') + 1);
    } else if (const auto nul = value.find('\0'); nul != std::string::npos) {
      value.resize(nul);
    }
    values[i] = std::move(value);
  }
  return values;
}

}  // namespace creaturelab::io::detail
