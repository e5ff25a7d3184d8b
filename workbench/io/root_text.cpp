#include "workbench/io/root_text.hpp"

#include <hdf5.h>

#include "workbench/core/files.hpp"
#include "workbench/io/result_reader.hpp"

namespace rb::io {

std::optional<std::string> readRootText(const std::string& path, const std::string& name) {
  // HDF5 would block opening a FIFO: only regular files are looked at.
  if (!isRegularFile(path)) return std::nullopt;
  // The reader of every result file (result_reader.hpp): one text, never more than it holds.
  const ResultReader r(path);
  if (!r.ok()) return std::nullopt;
  return r.text("/", name);
}

bool writeRootText(const std::string& path, const std::string& name, const std::string& value) {
  if (!isRegularFile(path)) return false;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (f < 0) return false;
  bool ok = true;
  if (H5Aexists(f, name.c_str()) > 0) ok = H5Adelete(f, name.c_str()) >= 0;
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.empty() ? 1 : value.size());
  H5Tset_strpad(type, H5T_STR_NULLPAD);
  H5Tset_cset(type, H5T_CSET_UTF8);
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t a = ok ? H5Acreate2(f, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT) : -1;
  ok = a >= 0 && H5Awrite(a, type, value.empty() ? "" : value.c_str()) >= 0;
  if (a >= 0) ok = H5Aclose(a) >= 0 && ok;
  H5Sclose(space);
  H5Tclose(type);
  ok = H5Fflush(f, H5F_SCOPE_LOCAL) >= 0 && ok;
  ok = H5Fclose(f) >= 0 && ok;
  return ok;
}

}  // namespace rb::io
