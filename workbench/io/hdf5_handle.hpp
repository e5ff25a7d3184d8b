#pragma once
// An HDF5 identifier owned by one scope (io/ only: the one folder that includes HDF5).
#include <hdf5.h>

namespace rb::io {

// Owns one HDF5 identifier and closes it with the matching H5*close on scope exit.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle(hid_t id, Closer close) : id_(id), close_(close) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t get() const { return id_; }
  bool ok() const { return id_ >= 0; }

 private:
  hid_t id_;
  Closer close_;
};

}  // namespace rb::io
