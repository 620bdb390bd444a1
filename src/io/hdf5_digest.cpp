#include "io/hdf5_digest.hpp"

#include "core/sha256.hpp"
#include "io/file_seal.hpp"
#include "io/hdf5_detail.hpp"
#include "io/hdf5_error.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cstring>
#include <set>

namespace creaturelab::io {
namespace {

constexpr std::size_t kBlockBytes = std::size_t{16} << 20;  // read big datasets 16 MiB at a time
constexpr int kMaxDepth = 256;                               // guards against hard-link cycles

// A readable, canonical description of an HDF5 datatype.
std::string typeSignature(hid_t type) {
  const std::size_t size = H5Tget_size(type);
  const auto order = [&] { return H5Tget_order(type) == H5T_ORDER_BE ? "be" : "le"; };
  switch (H5Tget_class(type)) {
    case H5T_INTEGER:
      return "int" + std::to_string(size) + (H5Tget_sign(type) == H5T_SGN_NONE ? "u" : "s") + order();
    case H5T_FLOAT:
      return "float" + std::to_string(size) + order();
    case H5T_STRING: {
      const std::string cset = H5Tget_cset(type) == H5T_CSET_UTF8 ? "utf8" : "ascii";
      if (H5Tis_variable_str(type) > 0) return "string(variable," + cset + ")";
      return "string(" + std::to_string(size) + "," + cset + ",pad" + std::to_string(H5Tget_strpad(type)) + ")";
    }
    case H5T_ENUM: {
      Handle base(H5Tget_super(type));
      std::string signature = "enum(" + typeSignature(base.id());
      for (int i = 0; i < H5Tget_nmembers(type); ++i) {
        char* name = H5Tget_member_name(type, static_cast<unsigned>(i));
        signature += std::string(";") + (name != nullptr ? name : "");
        H5free_memory(name);
      }
      return signature + ")";
    }
    case H5T_COMPOUND: {
      std::string signature = "compound" + std::to_string(size) + "(";
      for (int i = 0; i < H5Tget_nmembers(type); ++i) {
        const auto index = static_cast<unsigned>(i);
        char* name = H5Tget_member_name(type, index);
        Handle member(H5Tget_member_type(type, index));
        signature += std::string(name != nullptr ? name : "") + "@" + std::to_string(H5Tget_member_offset(type, index)) +
                     ":" + typeSignature(member.id()) + ";";
        H5free_memory(name);
      }
      return signature + ")";
    }
    case H5T_ARRAY: {
      Handle base(H5Tget_super(type));
      std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(0, H5Tget_array_ndims(type))));
      H5Tget_array_dims2(type, dims.data());
      std::string signature = "array[";
      for (hsize_t d : dims) signature += std::to_string(d) + ",";
      return signature + "](" + typeSignature(base.id()) + ")";
    }
    case H5T_VLEN: {
      Handle base(H5Tget_super(type));
      return "vlen(" + typeSignature(base.id()) + ")";
    }
    default:
      return "class" + std::to_string(static_cast<int>(H5Tget_class(type))) + "size" + std::to_string(size);
  }
}

// True when values of `type` hold pointers in memory (variable-length strings/sequences).
bool containsVariable(hid_t type) {
  switch (H5Tget_class(type)) {
    case H5T_STRING: return H5Tis_variable_str(type) > 0;
    case H5T_VLEN: return true;
    case H5T_COMPOUND:
      for (int i = 0; i < H5Tget_nmembers(type); ++i) {
        Handle member(H5Tget_member_type(type, static_cast<unsigned>(i)));
        if (containsVariable(member.id())) return true;
      }
      return false;
    case H5T_ARRAY: {
      Handle base(H5Tget_super(type));
      return containsVariable(base.id());
    }
    default: return false;
  }
}

class Digest {
public:
  explicit Digest(const std::vector<std::string>& skip) : skip_(skip.begin(), skip.end()) {
    field("creaturelab content digest v1");
  }

  std::string hex() { return sha_.hexDigest(); }

  void group(hid_t id, const std::string& path, int depth) {
    if (depth > kMaxDepth) detail::failAt(id, "", "digest group", "groups nest too deeply (hard-link cycle?)");
    field("group");
    field(path);
    attributes(id, path);
    for (const std::string& name : sortedLinkNames(id)) link(id, name, childPathOf(path, name), depth);
  }

private:
  static std::string childPathOf(const std::string& parent, const std::string& name) {
    return parent == "/" ? "/" + name : parent + "/" + name;
  }

  static herr_t collectLink(hid_t, const char* name, const H5L_info_t*, void* out) {
    static_cast<std::vector<std::string>*>(out)->emplace_back(name);
    return 0;
  }

  static std::vector<std::string> sortedLinkNames(hid_t group) {
    std::vector<std::string> names;
    detail::check(H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, nullptr, collectLink, &names), group, "",
                  "list the members of group");
    std::sort(names.begin(), names.end());
    return names;
  }

  static herr_t collectAttr(hid_t, const char* name, const H5A_info_t*, void* out) {
    static_cast<std::vector<std::string>*>(out)->emplace_back(name);
    return 0;
  }

  void link(hid_t parent, const std::string& name, const std::string& path, int depth) {
    H5L_info_t info;
    detail::check(H5Lget_info(parent, name.c_str(), &info, H5P_DEFAULT), parent, name, "digest link");
    if (info.type == H5L_TYPE_HARD) {
      Handle object(detail::check(H5Oopen(parent, name.c_str(), H5P_DEFAULT), parent, name, "digest object"));
      switch (H5Iget_type(object.id())) {
        case H5I_GROUP: group(object.id(), path, depth + 1); return;
        case H5I_DATASET: dataset(object.id(), path); return;
        case H5I_DATATYPE:
          field("datatype");
          field(path);
          field(typeSignature(object.id()));
          attributes(object.id(), path);
          return;
        default: detail::failAt(parent, name, "digest object", "it is not a group, dataset or datatype");
      }
    }
    std::vector<char> value(info.u.val_size);
    detail::check(H5Lget_val(parent, name.c_str(), value.data(), value.size(), H5P_DEFAULT), parent, name,
                  "digest link");
    if (info.type == H5L_TYPE_SOFT) {
      field("soft link");
      field(path);
      field(std::string_view(value.data(), strnlen(value.data(), value.size())));
    } else if (info.type == H5L_TYPE_EXTERNAL) {
      unsigned flags = 0;
      const char* file = nullptr;
      const char* object = nullptr;
      detail::check(H5Lunpack_elink_val(value.data(), value.size(), &flags, &file, &object), parent, name,
                    "digest external link");
      field("external link");
      field(path);
      field(file);
      field(object);
    } else {
      field("user link");
      field(path);
      update(value.data(), value.size());
    }
  }

  void attributes(hid_t object, const std::string& path) {
    std::vector<std::string> names;
    detail::check(H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_INC, nullptr, collectAttr, &names), object, "",
                  "list the attributes of");
    std::sort(names.begin(), names.end());
    for (const std::string& name : names) {
      if (skip_.count(name) != 0) continue;
      const std::string what = "digest attribute \"" + name + "\" of";
      Handle attribute(detail::check(H5Aopen(object, name.c_str(), H5P_DEFAULT), object, "", what));
      Handle type(detail::check(H5Aget_type(attribute.id()), object, "", what));
      Handle space(detail::check(H5Aget_space(attribute.id()), object, "", what));
      field("attribute");
      field(path);
      field(name);
      header(type.id(), space.id());
      wholeValues(type.id(), space.id(), [&](hid_t memory_type, void* buffer) {
        detail::check(H5Aread(attribute.id(), memory_type, buffer), object, "", what);
      });
    }
  }

  void dataset(hid_t id, const std::string& path) {
    Handle type(detail::check(H5Dget_type(id), id, "", "digest dataset"));
    Handle space(detail::check(H5Dget_space(id), id, "", "digest dataset"));
    field("dataset");
    field(path);
    header(type.id(), space.id());
    attributes(id, path);
    const std::vector<hsize_t> dims = detail::extentOf(space.id());
    if (detail::elementCount(dims) == 0) return;
    const auto read_all = [&](hid_t memory_type, void* buffer) {
      detail::check(H5Dread(id, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer), id, "", "digest dataset");
    };
    if (dims.empty() || containsVariable(type.id())) {
      wholeValues(type.id(), space.id(), read_all);
    } else {
      storedBytesInBlocks(id, type.id(), dims);
    }
  }

  // Type signature and shape: the framing that makes the raw bytes unambiguous.
  void header(hid_t type, hid_t space) {
    field(typeSignature(type));
    const std::vector<hsize_t> dims = detail::extentOf(space);
    number(dims.size());
    for (hsize_t d : dims) number(d);
  }

  // Reads a fixed-size dataset as stored (memory type = file type: no conversion),
  // `rows` of the first dimension at a time so big fields need not fit in memory twice.
  void storedBytesInBlocks(hid_t id, hid_t type, const std::vector<hsize_t>& dims) {
    const std::size_t row_bytes = H5Tget_size(type) * detail::elementCount({dims.begin() + 1, dims.end()});
    if (row_bytes == 0) return;
    const hsize_t rows_per_block = std::max<hsize_t>(1, kBlockBytes / row_bytes);
    Handle file_space(H5Dget_space(id));
    std::vector<char> buffer;
    for (hsize_t first = 0; first < dims[0]; first += rows_per_block) {
      std::vector<hsize_t> start(dims.size(), 0);
      std::vector<hsize_t> count = dims;
      start[0] = first;
      count[0] = std::min(rows_per_block, dims[0] - first);
      detail::check(H5Sselect_hyperslab(file_space.id(), H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr),
                    id, "", "digest dataset");
      Handle memory_space = detail::dataspaceOf(count);
      buffer.resize(count[0] * row_bytes);
      detail::check(H5Dread(id, type, memory_space.id(), file_space.id(), H5P_DEFAULT, buffer.data()), id, "",
                    "digest dataset");
      update(buffer.data(), buffer.size());
    }
  }

  // Reads all values at once. Fixed-size types: the stored bytes. Types with variable
  // parts: read in the native layout and hashed member by member (pointers followed).
  void wholeValues(hid_t type, hid_t space, const std::function<void(hid_t, void*)>& read) {
    const std::size_t count = detail::elementCount(detail::extentOf(space));
    if (count == 0) return;
    if (!containsVariable(type)) {
      std::vector<char> buffer(count * H5Tget_size(type));
      read(type, buffer.data());
      update(buffer.data(), buffer.size());
      return;
    }
    Handle memory_type(H5Tget_native_type(type, H5T_DIR_ASCEND));
    const std::size_t size = H5Tget_size(memory_type.id());
    std::vector<char> buffer(count * size);
    read(memory_type.id(), buffer.data());
    for (std::size_t i = 0; i < count; ++i) element(memory_type.id(), buffer.data() + i * size);
    H5Dvlen_reclaim(memory_type.id(), space, H5P_DEFAULT, buffer.data());
  }

  void element(hid_t type, const char* data) {
    switch (H5Tget_class(type)) {
      case H5T_STRING:
        if (H5Tis_variable_str(type) > 0) {
          const char* text = nullptr;
          std::memcpy(&text, data, sizeof text);
          field(text != nullptr ? std::string_view(text) : std::string_view("\0(null)", 7));
          return;
        }
        break;
      case H5T_COMPOUND:
        for (int i = 0; i < H5Tget_nmembers(type); ++i) {
          const auto index = static_cast<unsigned>(i);
          Handle member(H5Tget_member_type(type, index));
          element(member.id(), data + H5Tget_member_offset(type, index));
        }
        return;
      case H5T_ARRAY: {
        Handle base(H5Tget_super(type));
        const std::size_t base_size = H5Tget_size(base.id());
        const std::size_t count = base_size == 0 ? 0 : H5Tget_size(type) / base_size;
        for (std::size_t k = 0; k < count; ++k) element(base.id(), data + k * base_size);
        return;
      }
      case H5T_VLEN: {
        hvl_t sequence{};
        std::memcpy(&sequence, data, sizeof sequence);
        Handle base(H5Tget_super(type));
        const std::size_t base_size = H5Tget_size(base.id());
        number(sequence.len);
        for (std::size_t k = 0; k < sequence.len; ++k) {
          element(base.id(), static_cast<const char*>(sequence.p) + k * base_size);
        }
        return;
      }
      default: break;
    }
    update(data, H5Tget_size(type));
  }

  void update(const void* data, std::size_t size) { sha_.update(data, size); }

  void number(std::uint64_t value) {
    unsigned char bytes[8];
    for (int i = 0; i < 8; ++i) bytes[i] = static_cast<unsigned char>(value >> (8 * i));
    update(bytes, sizeof bytes);
  }

  // Length-prefixed, so consecutive fields cannot run into each other.
  void field(std::string_view text) {
    number(text.size());
    update(text.data(), text.size());
  }

  std::set<std::string> skip_;
  core::Sha256 sha_;
};

}  // namespace

std::string contentDigest(const std::filesystem::path& path, const std::vector<std::string>& attr_names_to_skip) {
  requireIntactSeal(path);  // before libhdf5 reads a byte of it
  auto lock = lockHdf5();
  const hid_t file_id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file_id < 0) detail::fail("open (read-only) for a digest", "", path.string());
  Handle file(file_id);
  Handle root(H5Gopen2(file.id(), "/", H5P_DEFAULT));
  if (!root) detail::fail("open root group for a digest", "/", path.string());
  Digest digest(attr_names_to_skip);
  digest.group(root.id(), "/", 0);
  return digest.hex();
}

}  // namespace creaturelab::io
