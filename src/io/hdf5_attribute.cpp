#include "io/hdf5_attribute.hpp"

#include "io/hdf5_detail.hpp"
#include "io/hdf5_error.hpp"

#include <algorithm>

namespace creaturelab::io {
namespace {

std::string onAttr(std::string_view verb, const std::string& name) {
  return std::string(verb) + " attribute \"" + name + "\" on";
}

void writeAttr(const Object& object, const std::string& name, hid_t file_type, hid_t memory_type,
               const void* data) {
  auto lock = lockHdf5();
  const htri_t exists =
      detail::check(H5Aexists(object.id(), name.c_str()), object.id(), "", onAttr("look up", name));
  if (exists > 0) detail::check(H5Adelete(object.id(), name.c_str()), object.id(), "", onAttr("replace", name));
  Handle space(H5Screate(H5S_SCALAR));
  Handle props = detail::attributeCreateProps();
  Handle attribute(detail::check(H5Acreate2(object.id(), name.c_str(), file_type, space.id(), props.id(), H5P_DEFAULT),
                                 object.id(), "", onAttr("create", name)));
  detail::check(H5Awrite(attribute.id(), memory_type, data), object.id(), "", onAttr("write", name));
}

const char* typeName(const AttrValue& value) {
  constexpr const char* kNames[] = {"double", "int64", "bool", "string"};
  return kNames[value.index()];
}

template <class T>
T getTyped(const Object& object, const std::string& name, const char* expected) {
  AttrValue value = getAttr(object, name);
  if (auto* typed = std::get_if<T>(&value)) return std::move(*typed);
  auto lock = lockHdf5();
  detail::failAt(object.id(), "", onAttr("read", name),
                 std::string("it holds a ") + typeName(value) + ", expected a " + expected);
}

herr_t collectAttrName(hid_t /*object*/, const char* name, const H5A_info_t* /*info*/, void* out) {
  static_cast<std::vector<std::string>*>(out)->emplace_back(name);
  return 0;
}

}  // namespace

void setAttr(const Object& object, const std::string& name, double value) {
  writeAttr(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

void setAttr(const Object& object, const std::string& name, std::int64_t value) {
  writeAttr(object, name, H5T_STD_I64LE, H5T_NATIVE_INT64, &value);
}

void setAttr(const Object& object, const std::string& name, bool value) {
  auto lock = lockHdf5();
  Handle type = detail::boolEnumType();
  const std::int8_t stored = value ? 1 : 0;
  writeAttr(object, name, type.id(), type.id(), &stored);
}

void setAttr(const Object& object, const std::string& name, const std::string& value) {
  auto lock = lockHdf5();
  if (value.find('\0') != std::string::npos) {
    detail::failAt(object.id(), "", onAttr("write", name), "the string contains a NUL byte");
  }
  Handle type = detail::utf8StringType();
  const char* pointer = value.c_str();
  writeAttr(object, name, type.id(), type.id(), &pointer);
}

void setAttr(const Object& object, const std::string& name, std::string_view value) {
  setAttr(object, name, std::string(value));
}

void setAttr(const Object& object, const std::string& name, const char* value) {
  setAttr(object, name, std::string(value));
}

void setAttr(const Object& object, const std::string& name, const AttrValue& value) {
  std::visit([&](const auto& v) { setAttr(object, name, v); }, value);
}

bool hasAttr(const Object& object, const std::string& name) {
  auto lock = lockHdf5();
  return detail::check(H5Aexists(object.id(), name.c_str()), object.id(), "", onAttr("look up", name)) > 0;
}

std::vector<std::string> attrNames(const Object& object) {
  auto lock = lockHdf5();
  std::vector<std::string> names;
  detail::check(H5Aiterate2(object.id(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collectAttrName, &names), object.id(),
                "", "list the attributes of");
  std::sort(names.begin(), names.end());
  return names;
}

AttrValue getAttr(const Object& object, const std::string& name) {
  auto lock = lockHdf5();
  const std::string what = onAttr("read", name);
  Handle attribute(detail::check(H5Aopen(object.id(), name.c_str(), H5P_DEFAULT), object.id(), "", what));
  Handle type(detail::check(H5Aget_type(attribute.id()), object.id(), "", what));
  Handle space(detail::check(H5Aget_space(attribute.id()), object.id(), "", what));
  const hsize_t count = detail::elementCount(detail::extentOf(space.id()));
  if (count != 1) {
    detail::failAt(object.id(), "", what, "it has " + std::to_string(count) + " elements, expected 1");
  }
  switch (H5Tget_class(type.id())) {
    case H5T_FLOAT: {
      double value = 0.0;
      detail::check(H5Aread(attribute.id(), H5T_NATIVE_DOUBLE, &value), object.id(), "", what);
      return value;
    }
    case H5T_INTEGER: {
      std::int64_t value = 0;
      detail::check(H5Aread(attribute.id(), H5T_NATIVE_INT64, &value), object.id(), "", what);
      return value;
    }
    case H5T_ENUM: {
      if (!detail::isBoolEnum(type.id())) {
        detail::failAt(object.id(), "", what, "it is an enum other than h5py's boolean (FALSE=0, TRUE=1)");
      }
      std::int8_t value = 0;
      detail::check(H5Aread(attribute.id(), type.id(), &value), object.id(), "", what);
      return value != 0;
    }
    case H5T_STRING: {
      std::vector<std::string> values = detail::readStrings(type.id(), space.id(), [&](hid_t memory_type, void* buffer) {
        detail::check(H5Aread(attribute.id(), memory_type, buffer), object.id(), "", what);
      });
      return std::move(values.front());
    }
    default:
      detail::failAt(object.id(), "", what, "its type is not float, integer, boolean or string");
  }
}

double getAttrDouble(const Object& object, const std::string& name) {
  return getTyped<double>(object, name, "double");
}

std::int64_t getAttrInt64(const Object& object, const std::string& name) {
  return getTyped<std::int64_t>(object, name, "int64");
}

bool getAttrBool(const Object& object, const std::string& name) { return getTyped<bool>(object, name, "bool"); }

std::string getAttrString(const Object& object, const std::string& name) {
  return getTyped<std::string>(object, name, "string");
}

namespace detail {
void failIntegerAttrOutOfRange(const Object& object, const std::string& name) {
  auto lock = lockHdf5();
  failAt(object.id(), "", onAttr("write", name), "the unsigned value exceeds the int64 range");
}
}  // namespace detail

}  // namespace creaturelab::io
