#include "io/hdf5_object.hpp"

#include "io/hdf5_detail.hpp"
#include "io/hdf5_error.hpp"

#include <algorithm>

namespace creaturelab::io {
namespace {

// "a/b/c" -> {"a", "b", "c"}; empty parts ("a//b", trailing "/") are dropped.
std::vector<std::string> splitPath(const std::string& path) {
  std::vector<std::string> parts;
  std::string part;
  for (char c : path) {
    if (c == '/') {
      if (!part.empty()) parts.push_back(std::move(part));
      part.clear();
    } else {
      part.push_back(c);
    }
  }
  if (!part.empty()) parts.push_back(std::move(part));
  return parts;
}

// Prefixes of `path` that name each successive part: "/a/b" -> {"/a", "/a/b"}.
std::vector<std::string> pathPrefixes(const std::string& path) {
  std::vector<std::string> prefixes;
  std::string prefix = (!path.empty() && path.front() == '/') ? "/" : "";
  for (const std::string& part : splitPath(path)) {
    if (!prefix.empty() && prefix.back() != '/') prefix += '/';
    prefix += part;
    prefixes.push_back(prefix);
  }
  return prefixes;
}

bool linkExists(hid_t loc, const std::string& path) {
  const htri_t exists = H5Lexists(loc, path.c_str(), H5P_DEFAULT);
  if (exists < 0) H5Eclear2(H5E_DEFAULT);
  return exists > 0;
}

// The kind of object `path` resolves to, or H5I_BADID when it does not resolve.
// Assumes every part but the last is known to exist as a group.
H5I_type_t resolvedType(hid_t loc, const std::string& path) {
  const htri_t resolves = H5Oexists_by_name(loc, path.c_str(), H5P_DEFAULT);
  if (resolves <= 0) {
    H5Eclear2(H5E_DEFAULT);
    return H5I_BADID;
  }
  Handle object(H5Oopen(loc, path.c_str(), H5P_DEFAULT));
  if (!object) {
    H5Eclear2(H5E_DEFAULT);
    return H5I_BADID;
  }
  return H5Iget_type(object.id());
}

// Type of the object at `path` after checking, part by part, that the path exists.
H5I_type_t typeAtPath(hid_t loc, const std::string& path) {
  const std::vector<std::string> prefixes = pathPrefixes(path);
  if (prefixes.empty()) return H5I_BADID;
  H5I_type_t type = H5I_BADID;
  for (const std::string& prefix : prefixes) {
    if (type != H5I_BADID && type != H5I_GROUP) return H5I_BADID;
    if (!linkExists(loc, prefix)) return H5I_BADID;
    type = resolvedType(loc, prefix);
  }
  return type;
}

herr_t collectLinkName(hid_t /*group*/, const char* name, const H5L_info_t* /*info*/, void* out) {
  static_cast<std::vector<std::string>*>(out)->emplace_back(name);
  return 0;
}

}  // namespace

std::string Object::path() const {
  auto lock = lockHdf5();
  return detail::objectPathOf(id());
}

std::string Object::fileName() const {
  auto lock = lockHdf5();
  return detail::fileNameOf(id());
}

std::vector<hsize_t> Dataset::shape() const {
  auto lock = lockHdf5();
  Handle space(detail::check(H5Dget_space(id()), id(), "", "read the shape of dataset"));
  return detail::extentOf(space.id());
}

Group Group::createGroup(const std::string& name) const {
  auto lock = lockHdf5();
  Handle link_props = detail::linkCreateProps();
  Handle group_props = detail::groupCreateProps();
  return Group(Handle(detail::check(H5Gcreate2(id(), name.c_str(), link_props.id(), group_props.id(), H5P_DEFAULT),
                                    id(), name, "create group")));
}

Group Group::openGroup(const std::string& path) const {
  auto lock = lockHdf5();
  return Group(Handle(detail::check(H5Gopen2(id(), path.c_str(), H5P_DEFAULT), id(), path, "open group")));
}

Group Group::requireGroup(const std::string& path) const {
  auto lock = lockHdf5();
  const std::vector<std::string> prefixes = pathPrefixes(path);
  if (prefixes.empty()) detail::failAt(id(), path, "create group", "the path is empty");
  for (const std::string& prefix : prefixes) {
    if (!linkExists(id(), prefix)) {
      createGroup(prefix);
    } else if (resolvedType(id(), prefix) != H5I_GROUP) {
      detail::failAt(id(), path, "create group", "\"" + prefix + "\" exists and is not a group");
    }
  }
  return openGroup(prefixes.back());
}

Dataset Group::openDataset(const std::string& path) const {
  auto lock = lockHdf5();
  return Dataset(Handle(detail::check(H5Dopen2(id(), path.c_str(), H5P_DEFAULT), id(), path, "open dataset")));
}

bool Group::has(const std::string& path) const {
  auto lock = lockHdf5();
  const std::vector<std::string> prefixes = pathPrefixes(path);
  if (prefixes.empty()) return false;
  for (std::size_t i = 0; i < prefixes.size(); ++i) {
    if (!linkExists(id(), prefixes[i])) return false;
    if (i + 1 < prefixes.size() && resolvedType(id(), prefixes[i]) != H5I_GROUP) return false;
  }
  return true;
}

bool Group::isGroup(const std::string& path) const {
  auto lock = lockHdf5();
  return typeAtPath(id(), path) == H5I_GROUP;
}

bool Group::isDataset(const std::string& path) const {
  auto lock = lockHdf5();
  return typeAtPath(id(), path) == H5I_DATASET;
}

std::vector<std::string> Group::childNames() const {
  auto lock = lockHdf5();
  std::vector<std::string> names;
  detail::check(H5Literate(id(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collectLinkName, &names), id(), "",
                "list the members of group");
  std::sort(names.begin(), names.end());
  return names;
}

void createExternalLink(const Group& group, const std::string& link_name, const std::string& target_file,
                        const std::string& target_path) {
  auto lock = lockHdf5();
  Handle link_props = detail::linkCreateProps();
  detail::check(H5Lcreate_external(target_file.c_str(), target_path.c_str(), group.id(), link_name.c_str(),
                                   link_props.id(), H5P_DEFAULT),
                group.id(), link_name, "create external link to \"" + target_file + ":" + target_path + "\" at");
}

}  // namespace creaturelab::io
