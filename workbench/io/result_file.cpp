#include "workbench/io/result_file.hpp"

#include <hdf5.h>

#include <cstdio>
#include <stdexcept>

namespace rb::io {
namespace {

constexpr hsize_t kChunk = 1024;

[[noreturn]] void fail(const std::string& what, const std::string& path) {
  throw std::runtime_error("HDF5: " + what + " '" + path + "'");
}

hid_t linkCreateProps() {
  hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  return lcpl;
}

void writeStringAttr(hid_t obj, const std::string& name, const std::string& value) {
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.empty() ? 1 : value.size());
  H5Tset_strpad(type, H5T_STR_NULLPAD);
  H5Tset_cset(type, H5T_CSET_UTF8);
  hid_t space = H5Screate(H5S_SCALAR);
  if (H5Aexists(obj, name.c_str()) > 0) H5Adelete(obj, name.c_str());
  hid_t a = H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  const char* data = value.empty() ? "" : value.c_str();
  if (a < 0 || H5Awrite(a, type, data) < 0) {
    H5Sclose(space);
    H5Tclose(type);
    fail("cannot write attribute", name);
  }
  H5Aclose(a);
  H5Sclose(space);
  H5Tclose(type);
}

template <typename T>
void writeScalarAttr(hid_t obj, const std::string& name, hid_t type, T value) {
  hid_t space = H5Screate(H5S_SCALAR);
  if (H5Aexists(obj, name.c_str()) > 0) H5Adelete(obj, name.c_str());
  hid_t a = H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  if (a < 0 || H5Awrite(a, type, &value) < 0) {
    H5Sclose(space);
    fail("cannot write attribute", name);
  }
  H5Aclose(a);
  H5Sclose(space);
}

}  // namespace

ResultFile::ResultFile(std::string path) : path_(std::move(path)) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors are reported by us, not printed by HDF5
  file_ = H5Fcreate(tmpPath().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0) fail("cannot create file", tmpPath());
}

ResultFile::~ResultFile() {
  try {
    finalize();
  } catch (...) {
    // Destructors must not throw; the .tmp file stays for inspection.
  }
}

std::int64_t ResultFile::group(const std::string& path) {
  if (path.empty() || path == "/") return H5Gopen2(file_, "/", H5P_DEFAULT);
  if (H5Lexists(file_, path.c_str(), H5P_DEFAULT) > 0)
    return H5Gopen2(file_, path.c_str(), H5P_DEFAULT);
  hid_t lcpl = linkCreateProps();
  hid_t g = H5Gcreate2(file_, path.c_str(), lcpl, H5P_DEFAULT, H5P_DEFAULT);
  H5Pclose(lcpl);
  if (g < 0) fail("cannot create group", path);
  return g;
}

void ResultFile::attr(const std::string& grp, const std::string& name, const std::string& value) {
  hid_t g = group(grp);
  writeStringAttr(g, name, value);
  H5Gclose(g);
}

void ResultFile::attr(const std::string& grp, const std::string& name, double value) {
  hid_t g = group(grp);
  writeScalarAttr(g, name, H5T_NATIVE_DOUBLE, value);
  H5Gclose(g);
}

void ResultFile::attr(const std::string& grp, const std::string& name, std::int64_t value) {
  hid_t g = group(grp);
  writeScalarAttr(g, name, H5T_NATIVE_INT64, value);
  H5Gclose(g);
}

void ResultFile::dataset(const std::string& path, const std::vector<double>& data,
                         const std::string& units) {
  hsize_t n = data.size();
  hid_t space = H5Screate_simple(1, &n, nullptr);
  hid_t lcpl = linkCreateProps();
  hid_t d =
      H5Dcreate2(file_, path.c_str(), H5T_NATIVE_DOUBLE, space, lcpl, H5P_DEFAULT, H5P_DEFAULT);
  H5Pclose(lcpl);
  H5Sclose(space);
  if (d < 0) fail("cannot create dataset", path);
  if (n > 0 && H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0) {
    H5Dclose(d);
    fail("cannot write dataset", path);
  }
  writeStringAttr(d, "units", units);
  H5Dclose(d);
}

void ResultFile::dataset2d(const std::string& path, std::size_t rows, std::size_t cols,
                           const std::vector<double>& data, const std::string& units) {
  if (data.size() != rows * cols) fail("2-D data of the wrong size for", path);
  hsize_t dims[2] = {rows, cols};
  hid_t space = H5Screate_simple(2, dims, nullptr);
  hid_t lcpl = linkCreateProps();
  hid_t d =
      H5Dcreate2(file_, path.c_str(), H5T_NATIVE_DOUBLE, space, lcpl, H5P_DEFAULT, H5P_DEFAULT);
  H5Pclose(lcpl);
  H5Sclose(space);
  if (d < 0) fail("cannot create dataset", path);
  if (!data.empty() &&
      H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0) {
    H5Dclose(d);
    fail("cannot write dataset", path);
  }
  writeStringAttr(d, "units", units);
  H5Dclose(d);
}

Series& ResultFile::series(const std::string& path, const std::string& units) {
  hsize_t zero = 0, unlimited = H5S_UNLIMITED, chunk = kChunk;
  hid_t space = H5Screate_simple(1, &zero, &unlimited);
  hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(dcpl, 1, &chunk);
  hid_t lcpl = linkCreateProps();
  hid_t d = H5Dcreate2(file_, path.c_str(), H5T_NATIVE_DOUBLE, space, lcpl, dcpl, H5P_DEFAULT);
  H5Pclose(lcpl);
  H5Pclose(dcpl);
  H5Sclose(space);
  if (d < 0) fail("cannot create dataset", path);
  writeStringAttr(d, "units", units);
  series_.push_back(std::unique_ptr<Series>(new Series(this, d)));
  return *series_.back();
}

void ResultFile::flushSeries(Series& s) {
  if (s.buffer_.empty()) return;
  hsize_t newSize = s.written_ + s.buffer_.size();
  hid_t d = static_cast<hid_t>(s.dataset_);
  if (H5Dset_extent(d, &newSize) < 0) fail("cannot extend dataset", "series");
  hid_t fspace = H5Dget_space(d);
  hsize_t start = s.written_, count = s.buffer_.size();
  H5Sselect_hyperslab(fspace, H5S_SELECT_SET, &start, nullptr, &count, nullptr);
  hid_t mspace = H5Screate_simple(1, &count, nullptr);
  herr_t rc = H5Dwrite(d, H5T_NATIVE_DOUBLE, mspace, fspace, H5P_DEFAULT, s.buffer_.data());
  H5Sclose(mspace);
  H5Sclose(fspace);
  if (rc < 0) fail("cannot append to dataset", "series");
  s.written_ = newSize;
  s.buffer_.clear();
}

void ResultFile::flush() {
  if (finalized_) return;
  for (auto& s : series_) flushSeries(*s);
  H5Fflush(file_, H5F_SCOPE_GLOBAL);
}

void ResultFile::finalize() {
  if (finalized_) return;
  flush();
  for (auto& s : series_) H5Dclose(static_cast<hid_t>(s->dataset_));
  series_.clear();
  H5Fclose(file_);
  finalized_ = true;
  if (std::rename(tmpPath().c_str(), path_.c_str()) != 0) fail("cannot rename to", path_);
}

}  // namespace rb::io
