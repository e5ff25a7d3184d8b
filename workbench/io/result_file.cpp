#include "workbench/io/result_file.hpp"

#include "workbench/io/hdf5_handle.hpp"
#include "workbench/io/hdf5_init.hpp"
#include "workbench/io/result_reader.hpp"

#include <fcntl.h>
#include <hdf5.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace rb::io {
namespace {

constexpr hsize_t kChunk = kSeriesChunk;
// Compact storage: deflate level (4: most of level 9's gain on float series at a fraction of its
// time) and the rank of the chunk index B-tree nodes (HDF5's default 32 sizes every node for 64
// chunks; a study case's series have a few).
constexpr unsigned kCompactDeflate = 4;
constexpr unsigned kCompactIstoreK = 2;

// The name of this machine: temporaries carry it, so only the machine that made one judges
// whether its process is gone (a study folder may be shared by the nodes of a cluster).
std::string hostName() {
  char buf[256] = {};
  if (::gethostname(buf, sizeof buf - 1) != 0 || buf[0] == '\0') return "host";
  std::string h(buf);
  for (char& c : h)
    if (c == '.' || c == '/') c = '_';
  return h;
}

// Removes the temporaries of `path` ("<path>.tmp.<host>.<pid>.<n>") whose process on this
// machine no longer exists: a process killed while writing (SIGKILL cannot be caught) leaves its
// temporary behind. A temporary of another machine is left to that machine. The scan reads at
// most kMaxScanned entries of the folder, so a huge folder costs a bounded time.
void removeStaleTemporaries(const std::string& path, const std::string& host) {
  namespace fs = std::filesystem;
  constexpr int kMaxScanned = 100000;
  std::error_code ec;
  const fs::path p(path);
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  const std::string prefix = p.filename().string() + ".tmp." + host + ".";
  int scanned = 0;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end && scanned < kMaxScanned;
       it.increment(ec), ++scanned) {
    const std::string name = it->path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const std::string rest = name.substr(prefix.size());  // "<pid>.<n>"
    const std::size_t dot = rest.find('.');
    if (dot == 0 || dot == std::string::npos) continue;
    char* stop = nullptr;
    const long pid = std::strtol(rest.c_str(), &stop, 10);
    if (stop != rest.c_str() + dot || pid <= 0 || pid == ::getpid()) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // alive (or unknown)
    std::error_code rm;
    if (it->is_regular_file(rm)) fs::remove(it->path(), rm);
  }
}

// A unique temporary name beside `path`, created exclusively so that no other run (or a second
// run of the same scenario) can write to it. The HDF5 file is then created over the empty file.
std::string claimTemporary(const std::string& path) {
  static const std::string host = hostName();
  removeStaleTemporaries(path, host);
  const std::string base = path + ".tmp." + host + "." + std::to_string(::getpid()) + ".";
  for (int n = 0; n < 1000; ++n) {
    std::string name = base + std::to_string(n);
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd >= 0) {
      ::close(fd);
      return name;
    }
    if (errno != EEXIST)
      throw WriteError("cannot create the result file '" + name + "': " + std::strerror(errno));
  }
  throw WriteError("cannot create a temporary result file beside '" + path + "'");
}

}  // namespace

void initHdf5() {
  static const bool done = [] {
    H5dont_atexit();
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)done;
}

void ResultFile::fail(const std::string& what, const std::string& name) {
  discard();
  throw WriteError("cannot write the result '" + path_ + "' (" + what + " '" + name +
                   "'; disk full or not writable?); nothing was written under that name");
}

ResultFile::ResultFile(std::string path, Storage storage)
    : path_(std::move(path)), storage_(storage) {
  initHdf5();
  tmp_ = claimTemporary(path_);
  // Dense attribute storage (file format 1.8 or later) lifts the 64 KiB limit of an attribute in
  // an object header, so a large scenario text fits in its provenance attribute.
  Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  Handle fcpl(H5Pcreate(H5P_FILE_CREATE), H5Pclose);
  if (!fapl.ok() || !fcpl.ok() ||
      H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V18, H5F_LIBVER_LATEST) < 0 ||
      H5Pset_fclose_degree(fapl.get(), H5F_CLOSE_STRONG) < 0 ||
      H5Pset_attr_phase_change(fcpl.get(), 0, 0) < 0 ||
      (storage_ == Storage::Compact && H5Pset_istore_k(fcpl.get(), kCompactIstoreK) < 0)) {
    std::remove(tmp_.c_str());
    throw WriteError("HDF5: cannot set up the result file '" + tmp_ + "'");
  }
  file_ = H5Fcreate(tmp_.c_str(), H5F_ACC_TRUNC, fcpl.get(), fapl.get());
  if (file_ < 0) {
    std::remove(tmp_.c_str());
    throw WriteError("HDF5: cannot create the result file '" + tmp_ + "'");
  }
}

ResultFile::ResultFile(std::string path, UpdateExisting) : path_(std::move(path)) {
  initHdf5();
  tmp_ = claimTemporary(path_);
  std::error_code ec;
  std::filesystem::copy_file(path_, tmp_, std::filesystem::copy_options::overwrite_existing, ec);
  Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (ec || !fapl.ok() || H5Pset_fclose_degree(fapl.get(), H5F_CLOSE_STRONG) < 0) {
    std::remove(tmp_.c_str());
    throw WriteError("cannot copy the result '" + path_ + "' to update it" +
                     (ec ? ": " + ec.message() : std::string()));
  }
  file_ = H5Fopen(tmp_.c_str(), H5F_ACC_RDWR, fapl.get());
  if (file_ < 0) {
    std::remove(tmp_.c_str());
    throw WriteError("HDF5: cannot open the copy of '" + path_ + "' for writing");
  }
  // The copy opened for writing opens any file an external link names for writing too: an
  // update (remove, create) through such a link would change that other file. Checked on the
  // copy itself, whatever a reader saw of `path` before.
  try {
    detail::requireSelfContained(file_, path_);
  } catch (...) {
    discard();
    throw;
  }
}

void ResultFile::remove(const std::string& path) {
  if (file_ < 0) fail("file already closed", path);
  const hid_t f = static_cast<hid_t>(file_);
  if (H5Lexists(f, path.c_str(), H5P_DEFAULT) <= 0) return;
  // A group under the removed path must be looked up (or created) anew.
  closeGroups();
  if (H5Ldelete(f, path.c_str(), H5P_DEFAULT) < 0) fail("cannot remove", path);
}

ResultFile::~ResultFile() {
  if (!finalized_) discard();
}

void ResultFile::closeGroups() noexcept {
  for (const auto& [path, g] : groups_) H5Gclose(static_cast<hid_t>(g));
  groups_.clear();
}

void ResultFile::closeAll() noexcept {
  for (auto& s : series_) H5Dclose(static_cast<hid_t>(s->dataset_));
  series_.clear();
  closeGroups();
  if (file_ >= 0) H5Fclose(static_cast<hid_t>(file_));
  file_ = -1;
}

void ResultFile::discard() noexcept {
  if (finalized_) return;
  closeAll();
  if (!tmp_.empty()) std::remove(tmp_.c_str());
}

std::int64_t ResultFile::group(const std::string& path) {
  if (file_ < 0) fail("file already closed", path);
  const std::string key = path.empty() ? "/" : path;
  if (const auto it = groups_.find(key); it != groups_.end()) return it->second;
  hid_t g = -1;
  if (key == "/") {
    g = H5Gopen2(static_cast<hid_t>(file_), "/", H5P_DEFAULT);
    if (g < 0) fail("cannot open group", path);
  } else {
    // The parent first (created when missing), then the group in it: each level is looked up
    // once, and each new group gets dense attribute storage.
    std::string leaf;
    const hid_t parent = static_cast<hid_t>(parentGroup(key, leaf));
    if (H5Lexists(parent, leaf.c_str(), H5P_DEFAULT) > 0) {
      g = H5Gopen2(parent, leaf.c_str(), H5P_DEFAULT);
      if (g < 0) fail("cannot open group", path);
    } else {
      Handle gcpl(H5Pcreate(H5P_GROUP_CREATE), H5Pclose);
      if (!gcpl.ok() || H5Pset_attr_phase_change(gcpl.get(), 0, 0) < 0)
        fail("cannot create group", path);
      g = H5Gcreate2(parent, leaf.c_str(), H5P_DEFAULT, gcpl.get(), H5P_DEFAULT);
      if (g < 0) fail("cannot create group", path);
    }
  }
  groups_.emplace(key, g);
  return g;
}

std::int64_t ResultFile::parentGroup(const std::string& path, std::string& leaf) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) {
    leaf = path;
    return group("/");
  }
  leaf = path.substr(slash + 1);
  return group(slash == 0 ? std::string("/") : path.substr(0, slash));
}

void ResultFile::attr(const std::string& grp, const std::string& name, const std::string& value) {
  const hid_t g = static_cast<hid_t>(group(grp));
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  if (!type.ok() || !space.ok() || H5Tset_size(type.get(), value.empty() ? 1 : value.size()) < 0 ||
      H5Tset_strpad(type.get(), H5T_STR_NULLPAD) < 0 || H5Tset_cset(type.get(), H5T_CSET_UTF8) < 0)
    fail("cannot write attribute", name);
  if (H5Aexists(g, name.c_str()) > 0 && H5Adelete(g, name.c_str()) < 0)
    fail("cannot replace attribute", name);
  Handle a(H5Acreate2(g, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
           H5Aclose);
  const char* data = value.empty() ? "" : value.c_str();
  if (!a.ok() || H5Awrite(a.get(), type.get(), data) < 0) fail("cannot write attribute", name);
}

namespace {
template <typename T>
bool writeScalarAttr(hid_t obj, const std::string& name, hid_t type, T value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  if (!space.ok()) return false;
  if (H5Aexists(obj, name.c_str()) > 0 && H5Adelete(obj, name.c_str()) < 0) return false;
  Handle a(H5Acreate2(obj, name.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  return a.ok() && H5Awrite(a.get(), type, &value) >= 0;
}

bool writeUnits(hid_t obj, const std::string& units) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  if (!type.ok() || !space.ok() || H5Tset_size(type.get(), units.empty() ? 1 : units.size()) < 0 ||
      H5Tset_strpad(type.get(), H5T_STR_NULLPAD) < 0 || H5Tset_cset(type.get(), H5T_CSET_UTF8) < 0)
    return false;
  Handle a(H5Acreate2(obj, "units", type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  return a.ok() && H5Awrite(a.get(), type.get(), units.empty() ? "" : units.c_str()) >= 0;
}
}  // namespace

void ResultFile::attr(const std::string& grp, const std::string& name, double value) {
  if (!writeScalarAttr(static_cast<hid_t>(group(grp)), name, H5T_NATIVE_DOUBLE, value))
    fail("cannot write attribute", name);
}

void ResultFile::attr(const std::string& grp, const std::string& name, std::int64_t value) {
  if (!writeScalarAttr(static_cast<hid_t>(group(grp)), name, H5T_NATIVE_INT64, value))
    fail("cannot write attribute", name);
}

void ResultFile::dataset(const std::string& path, const std::vector<double>& data,
                         const std::string& units) {
  dataset2d(path, data.size(), 0, data, units);
}

void ResultFile::dataset2d(const std::string& path, std::size_t rows, std::size_t cols,
                           const std::vector<double>& data, const std::string& units) {
  // cols == 0: a 1-D dataset of `rows` values.
  const int rank = cols == 0 ? 1 : 2;
  if (data.size() != rows * (cols == 0 ? 1 : cols))
    throw std::logic_error("result file: data of the wrong size for '" + path + "'");
  std::string leaf;
  const hid_t parent = static_cast<hid_t>(parentGroup(path, leaf));
  hsize_t dims[2] = {rows, cols};
  Handle space(H5Screate_simple(rank, dims, nullptr), H5Sclose);
  if (!space.ok()) fail("cannot create dataset", path);
  Handle d(H5Dcreate2(parent, leaf.c_str(), H5T_NATIVE_DOUBLE, space.get(), H5P_DEFAULT,
                      H5P_DEFAULT, H5P_DEFAULT),
           H5Dclose);
  if (!d.ok()) fail("cannot create dataset", path);
  if (!data.empty() &&
      H5Dwrite(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0)
    fail("cannot write dataset", path);
  if (!writeUnits(d.get(), units)) fail("cannot write units of", path);
}

void ResultFile::stringDataset(const std::string& path, const std::vector<std::string>& values) {
  std::string leaf;
  const hid_t parent = static_cast<hid_t>(parentGroup(path, leaf));
  std::size_t width = 1;
  for (const auto& v : values) width = std::max(width, v.size());
  std::string packed(width * values.size(), '\0');
  for (std::size_t i = 0; i < values.size(); ++i)
    packed.replace(i * width, values[i].size(), values[i]);
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  const hsize_t n = values.size();
  Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  if (!type.ok() || !space.ok() || H5Tset_size(type.get(), width) < 0 ||
      H5Tset_strpad(type.get(), H5T_STR_NULLPAD) < 0 || H5Tset_cset(type.get(), H5T_CSET_UTF8) < 0)
    fail("cannot create dataset", path);
  Handle d(H5Dcreate2(parent, leaf.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT,
                      H5P_DEFAULT),
           H5Dclose);
  if (!d.ok()) fail("cannot create dataset", path);
  if (!values.empty() &&
      H5Dwrite(d.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, packed.data()) < 0)
    fail("cannot write dataset", path);
}

Series& ResultFile::series(const std::string& path, const std::string& units) {
  std::string leaf;
  const hid_t parent = static_cast<hid_t>(parentGroup(path, leaf));
  hsize_t zero = 0, unlimited = H5S_UNLIMITED, chunk = kChunk;
  Handle space(H5Screate_simple(1, &zero, &unlimited), H5Sclose);
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  if (!space.ok() || !dcpl.ok() || H5Pset_chunk(dcpl.get(), 1, &chunk) < 0)
    fail("cannot create dataset", path);
  if (storage_ == Storage::Compact && H5Zfilter_avail(H5Z_FILTER_DEFLATE) > 0 &&
      (H5Pset_shuffle(dcpl.get()) < 0 || H5Pset_deflate(dcpl.get(), kCompactDeflate) < 0))
    fail("cannot set the compression of dataset", path);
  const hid_t d = H5Dcreate2(parent, leaf.c_str(), H5T_NATIVE_DOUBLE, space.get(), H5P_DEFAULT,
                             dcpl.get(), H5P_DEFAULT);
  if (d < 0) fail("cannot create dataset", path);
  series_.push_back(std::unique_ptr<Series>(new Series(d)));
  if (!writeUnits(d, units)) fail("cannot write units of", path);
  return *series_.back();
}

void ResultFile::flushSeries(Series& s) {
  if (s.buffer_.empty()) return;
  hsize_t newSize = s.written_ + s.buffer_.size();
  const hid_t d = static_cast<hid_t>(s.dataset_);
  if (H5Dset_extent(d, &newSize) < 0) fail("cannot extend dataset", "series");
  Handle fspace(H5Dget_space(d), H5Sclose);
  hsize_t start = s.written_, count = s.buffer_.size();
  Handle mspace(H5Screate_simple(1, &count, nullptr), H5Sclose);
  if (!fspace.ok() || !mspace.ok() ||
      H5Sselect_hyperslab(fspace.get(), H5S_SELECT_SET, &start, nullptr, &count, nullptr) < 0 ||
      H5Dwrite(d, H5T_NATIVE_DOUBLE, mspace.get(), fspace.get(), H5P_DEFAULT, s.buffer_.data()) < 0)
    fail("cannot append to dataset", "series");
  s.written_ = newSize;
  s.buffer_.clear();
}

void ResultFile::flush() {
  if (finalized_) return;
  if (file_ < 0) fail("file already closed", tmp_);
  for (auto& s : series_) flushSeries(*s);
  if (H5Fflush(static_cast<hid_t>(file_), H5F_SCOPE_GLOBAL) < 0) fail("cannot flush", tmp_);
}

void ResultFile::finalize() {
  if (finalized_) return;
  if (file_ < 0) fail("file already closed", tmp_);
  // The buffered series data only: closing the file below flushes everything (and fails when
  // that fails), so a flush of the file's metadata here would write it twice.
  for (auto& s : series_) flushSeries(*s);
  for (auto& s : series_) {
    if (H5Dclose(static_cast<hid_t>(s->dataset_)) < 0) {
      s->dataset_ = -1;
      fail("cannot close dataset", "series");
    }
  }
  series_.clear();
  closeGroups();
  const herr_t rc = H5Fclose(static_cast<hid_t>(file_));
  file_ = -1;
  if (rc < 0) fail("cannot close", tmp_);
  // The data must be on disk before the rename makes it the result (a crash in between must not
  // leave a renamed, incomplete file).
  const int fd = ::open(tmp_.c_str(), O_RDONLY | O_CLOEXEC);
  const bool synced = fd >= 0 && ::fsync(fd) == 0;
  if (fd >= 0) ::close(fd);
  if (!synced) fail("cannot sync", tmp_);
  if (std::rename(tmp_.c_str(), path_.c_str()) != 0) fail("cannot rename to", path_);
  finalized_ = true;
}

}  // namespace rb::io
