#pragma once
// Handles to HDF5 groups and datasets, and the links between them.

#include "io/hdf5_handle.hpp"

#include <hdf5.h>

#include <string>
#include <vector>

namespace creaturelab::io {

// Anything that can carry attributes: a group (the root included) or a dataset.
class Object {
public:
  hid_t id() const noexcept { return handle_.id(); }
  bool valid() const noexcept { return handle_.valid(); }
  std::string path() const;      // e.g. "/metrics/speed"
  std::string fileName() const;  // the file this handle was opened through

protected:
  Object() = default;
  explicit Object(Handle handle) : handle_(std::move(handle)) {}

private:
  Handle handle_;
};

class Dataset : public Object {
public:
  Dataset() = default;
  explicit Dataset(Handle handle) : Object(std::move(handle)) {}
  std::vector<hsize_t> shape() const;  // empty for a scalar
};

// Names below are link names relative to this group; "a/b" paths are accepted where
// noted. childNames() and attribute names come back sorted by byte value.
class Group : public Object {
public:
  Group() = default;
  explicit Group(Handle handle) : Object(std::move(handle)) {}

  Group createGroup(const std::string& name) const;   // error if it exists
  Group openGroup(const std::string& path) const;     // follows soft and external links
  Group requireGroup(const std::string& path) const;  // opens or creates each part of "a/b/c"
  Dataset openDataset(const std::string& path) const;

  bool has(const std::string& path) const;  // a link of that name exists ("a/b" allowed)
  bool isGroup(const std::string& path) const;    // false if missing or a dangling link
  bool isDataset(const std::string& path) const;  // false if missing or a dangling link
  std::vector<std::string> childNames() const;
};

// Creates `link_name` in `group` pointing at `target_path` inside `target_file`. A relative
// `target_file` is looked up (among other places) next to the file holding the link, so
// use the bare file name for files in the same run folder: the folder can then be moved.
void createExternalLink(const Group& group, const std::string& link_name, const std::string& target_file,
                        const std::string& target_path);

}  // namespace creaturelab::io
