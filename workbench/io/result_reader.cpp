#include "workbench/io/result_reader.hpp"

#include <fcntl.h>
#include <hdf5.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "workbench/core/files.hpp"
#include "workbench/io/hdf5_handle.hpp"
#include "workbench/io/hdf5_init.hpp"

namespace rb::io {
namespace {

// Deflate's largest compression ratio (zlib's technical notes: 1032:1): a filtered dataset
// cannot expand to more than this times the bytes it occupies in the file.
constexpr double kMaxInflate = 1032.0;
// Longest external link value whose target is quoted in a refusal.
constexpr std::size_t kMaxQuotedLink = 1024;

std::string bytesText(double b) {
  const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (b >= 1000.0 && u < 6) {
    b /= 1000.0;
    ++u;
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, u == 0 ? "%.0f %s" : "%.3g %s", b, units[u]);
  return buf;
}

// "" when `points` elements of `type` fit in `limit` bytes, else why not (what `where` declares).
std::string oversized(const std::string& where, hssize_t points, hid_t type, double limit,
                      std::uint64_t fileBytes) {
  const std::size_t size = H5Tget_size(type);
  const double declared = static_cast<double>(std::max<hssize_t>(points, 0)) *
                          static_cast<double>(std::max<std::size_t>(size, 1));
  if (points >= 0 && size > 0 && declared <= limit) return "";
  return where + " declares " + std::to_string(points) + " values of " + std::to_string(size) +
         " bytes (" + bytesText(declared) + ") in a file of " +
         bytesText(static_cast<double>(fileBytes)) + ": more than the file can hold";
}

// "" when the dataset `d` holds no more data than the file can: its declared bytes at most the
// file's (with filters: deflate's largest ratio times the bytes its chunks occupy, plus the
// file's).
std::string datasetOversized(hid_t d, hid_t space, hid_t type, const std::string& where,
                             std::uint64_t fileBytes) {
  double limit = static_cast<double>(fileBytes);
  Handle dcpl(H5Dget_create_plist(d), H5Pclose);
  if (dcpl.ok() && H5Pget_nfilters(dcpl.get()) > 0)
    limit += kMaxInflate * static_cast<double>(H5Dget_storage_size(d));
  return oversized(where, H5Sget_simple_extent_npoints(space), type, limit, fileBytes);
}

// An attribute has no filters: all of its bytes are in the file.
std::string attributeOversized(hid_t space, hid_t type, const std::string& where,
                               std::uint64_t fileBytes) {
  return oversized(where, H5Sget_simple_extent_npoints(space), type, static_cast<double>(fileBytes),
                   fileBytes);
}

// The index of the first non-finite value, nullopt when every one is finite.
std::optional<std::size_t> firstNonFinite(const std::vector<double>& v) {
  const auto it = std::find_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); });
  if (it == v.end()) return std::nullopt;
  return static_cast<std::size_t>(it - v.begin());
}

std::string valueText(double x) {
  return std::isnan(x) ? "NaN" : (x > 0 ? "+inf" : "-inf");
}

herr_t collectName(hid_t, const char* name, const H5L_info_t*, void* data) {
  static_cast<std::vector<std::string>*>(data)->emplace_back(name);
  return 0;
}

herr_t collectAttrName(hid_t, const char* name, const H5A_info_t*, void* data) {
  static_cast<std::vector<std::string>*>(data)->emplace_back(name);
  return 0;
}

// The first link that leaves the file, in words ("" while none is found).
herr_t findLeavingLink(hid_t root, const char* name, const H5L_info_t* info, void* data) {
  if (info->type == H5L_TYPE_HARD || info->type == H5L_TYPE_SOFT) return 0;
  auto* found = static_cast<std::string*>(data);
  const std::string path = "/" + std::string(name);
  if (info->type != H5L_TYPE_EXTERNAL) {
    *found = path + " is a user-defined link (type " + std::to_string(info->type) + ")";
    return 1;
  }
  *found = path + " is an external link";
  if (info->u.val_size > 0 && info->u.val_size <= kMaxQuotedLink) {
    std::string buf(info->u.val_size, '\0');
    const char* file = nullptr;
    const char* object = nullptr;
    if (H5Lget_val(root, name, buf.data(), buf.size(), H5P_DEFAULT) >= 0 &&
        H5Lunpack_elink_val(buf.data(), buf.size(), nullptr, &file, &object) >= 0 && file && object)
      *found += " to '" + std::string(file) + ":" + object + "'";
  }
  return 1;
}

// nonFinite(): the non-finite datasets and attributes found so far, and the first declared size
// beyond the file's bytes (the visit stops there; the caller throws: no exception may cross the
// HDF5 library's frames).
struct NonFiniteVisit {
  std::vector<std::string>* out;
  std::size_t limit;
  std::uint64_t fileBytes;
  std::string object;  // the object whose attributes are iterated
  std::string oversized;
};

// Whether every element read by `read` into n doubles is finite (an unreadable one is not this
// check's finding).
bool allFinite(hssize_t n, const std::function<herr_t(void*)>& read) {
  if (n <= 0) return true;
  std::vector<double> v(static_cast<std::size_t>(n));
  if (read(v.data()) < 0) return true;
  return !firstNonFinite(v);
}

herr_t checkAttr(hid_t o, const char* name, const H5A_info_t*, void* data) {
  auto* v = static_cast<NonFiniteVisit*>(data);
  const Handle a(H5Aopen(o, name, H5P_DEFAULT), H5Aclose);
  if (!a.ok()) return 0;
  const Handle t(H5Aget_type(a.get()), H5Tclose);
  const Handle sp(H5Aget_space(a.get()), H5Sclose);
  if (!t.ok() || !sp.ok() || H5Tget_class(t.get()) != H5T_FLOAT) return 0;
  const std::string where = (v->object == "/" ? std::string() : v->object) + "@" + name;
  v->oversized = attributeOversized(sp.get(), t.get(), where, v->fileBytes);
  if (!v->oversized.empty()) return 1;
  if (!allFinite(H5Sget_simple_extent_npoints(sp.get()),
                 [&](void* buf) { return H5Aread(a.get(), H5T_NATIVE_DOUBLE, buf); }))
    v->out->push_back(where);
  return v->out->size() >= v->limit ? 1 : 0;
}

herr_t checkObject(hid_t root, const char* name, const H5O_info_t* info, void* data) {
  auto* v = static_cast<NonFiniteVisit*>(data);
  v->object = std::string(name) == "." ? "/" : "/" + std::string(name);
  const Handle o(H5Oopen(root, name, H5P_DEFAULT), H5Oclose);
  if (!o.ok()) return 0;
  hsize_t idx = 0;
  H5Aiterate2(o.get(), H5_INDEX_NAME, H5_ITER_INC, &idx, checkAttr, v);
  if (!v->oversized.empty()) return 1;
  if (info->type != H5O_TYPE_DATASET || v->out->size() >= v->limit) return 0;
  const Handle t(H5Dget_type(o.get()), H5Tclose);
  const Handle sp(H5Dget_space(o.get()), H5Sclose);
  if (!t.ok() || !sp.ok() || H5Tget_class(t.get()) != H5T_FLOAT) return 0;
  v->oversized = datasetOversized(o.get(), sp.get(), t.get(), v->object, v->fileBytes);
  if (!v->oversized.empty()) return 1;
  if (!allFinite(H5Sget_simple_extent_npoints(sp.get()), [&](void* buf) {
        return H5Dread(o.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf);
      }))
    v->out->push_back(v->object);
  return v->out->size() >= v->limit ? 1 : 0;
}

}  // namespace

namespace detail {

void requireSelfContained(std::int64_t file, const std::string& name) {
  std::string found;
  H5Lvisit(static_cast<hid_t>(file), H5_INDEX_NAME, H5_ITER_INC, findLeavingLink, &found);
  if (!found.empty())
    throw BadResult(name + ": " + found +
                    "; a result file is read only from itself (links to other files are "
                    "refused, nothing is read or written through them)");
}

}  // namespace detail

ResultReader::ResultReader(const std::string& path) : path_(path) {
  initHdf5();
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return;  // absent: the caller says what is missing
  if (!S_ISREG(st.st_mode))
    throw BadResult(path + ": is " + fileKindName(st.st_mode) + ", not a result file");
  // O_NONBLOCK: should the path become a FIFO after the stat, the open does not block, and the
  // fstat refuses it. HDF5 then opens this very file by its descriptor's name, not what the path
  // may name by then.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return;  // unreadable (permissions): not a file that can be read
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    throw BadResult(path + ": is " + fileKindName(st.st_mode) + ", not a result file");
  }
  bytes_ = static_cast<std::uint64_t>(st.st_size);
  const std::string byFd = "/proc/self/fd/" + std::to_string(fd);
  file_ = H5Fopen(isRegularFile(byFd) ? byFd.c_str() : path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ::close(fd);
  if (file_ < 0) return;
  try {
    detail::requireSelfContained(file_, path_);
  } catch (...) {
    H5Fclose(static_cast<hid_t>(file_));
    file_ = -1;
    throw;
  }
}

ResultReader::~ResultReader() {
  if (file_ >= 0) H5Fclose(static_cast<hid_t>(file_));
}

bool ResultReader::has(const std::string& path) const {
  if (file_ < 0 || path.empty() || path[0] != '/') return false;
  if (path == "/") return true;
  // Each prefix in turn: H5Lexists fails on a missing intermediate group.
  std::size_t pos = 0;
  while ((pos = path.find('/', pos + 1)) != std::string::npos)
    if (H5Lexists(static_cast<hid_t>(file_), path.substr(0, pos).c_str(), H5P_DEFAULT) <= 0)
      return false;
  return H5Lexists(static_cast<hid_t>(file_), path.c_str(), H5P_DEFAULT) > 0;
}

std::optional<std::vector<double>> ResultReader::dataset(const std::string& path) const {
  if (!has(path)) return std::nullopt;
  const Handle d(H5Dopen2(static_cast<hid_t>(file_), path.c_str(), H5P_DEFAULT), H5Dclose);
  if (!d.ok()) return std::nullopt;
  const Handle s(H5Dget_space(d.get()), H5Sclose);
  const Handle t(H5Dget_type(d.get()), H5Tclose);
  if (!s.ok() || !t.ok() || H5Sget_simple_extent_ndims(s.get()) != 1) return std::nullopt;
  if (const auto why = datasetOversized(d.get(), s.get(), t.get(), path, bytes_); !why.empty())
    throw BadResult(path_ + ": " + why);
  hsize_t n = 0;
  if (H5Sget_simple_extent_dims(s.get(), &n, nullptr) != 1) return std::nullopt;
  std::vector<double> v(n);
  if (n > 0 && H5Dread(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0)
    return std::nullopt;
  return v;
}

std::optional<std::string> ResultReader::nonFiniteSample(const std::string& path,
                                                         const std::vector<double>& values) const {
  const auto k = firstNonFinite(values);
  if (!k) return std::nullopt;
  return path_ + ": " + path + " holds " + valueText(values[*k]) + " at sample " +
         std::to_string(*k) + " of " + std::to_string(values.size()) +
         "; a signal used in a computation must be finite";
}

std::optional<std::vector<double>> ResultReader::samples(const std::string& path) const {
  auto v = dataset(path);
  if (v)
    if (auto why = nonFiniteSample(path, *v)) throw BadResult(*why);
  return v;
}

std::optional<std::vector<std::string>> ResultReader::strings(const std::string& path) const {
  if (!has(path)) return std::nullopt;
  const Handle d(H5Dopen2(static_cast<hid_t>(file_), path.c_str(), H5P_DEFAULT), H5Dclose);
  if (!d.ok()) return std::nullopt;
  const Handle t(H5Dget_type(d.get()), H5Tclose);
  const Handle s(H5Dget_space(d.get()), H5Sclose);
  hsize_t n = 0;
  if (!t.ok() || !s.ok() || H5Tget_class(t.get()) != H5T_STRING || H5Tis_variable_str(t.get()) ||
      H5Sget_simple_extent_ndims(s.get()) != 1 ||
      H5Sget_simple_extent_dims(s.get(), &n, nullptr) != 1)
    return std::nullopt;
  if (const auto why = datasetOversized(d.get(), s.get(), t.get(), path, bytes_); !why.empty())
    throw BadResult(path_ + ": " + why);
  const std::size_t width = H5Tget_size(t.get());
  std::string packed(width * n, '\0');
  if (n > 0 && H5Dread(d.get(), t.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, packed.data()) < 0)
    return std::nullopt;
  std::vector<std::string> v;
  for (std::size_t i = 0; i < n; ++i) {
    std::string x = packed.substr(i * width, width);
    v.push_back(x.substr(0, x.find('\0')));
  }
  return v;
}

std::optional<double> ResultReader::number(const std::string& object,
                                           const std::string& name) const {
  if (!has(object)) return std::nullopt;
  const Handle o(H5Oopen(static_cast<hid_t>(file_), object.c_str(), H5P_DEFAULT), H5Oclose);
  if (!o.ok() || H5Aexists(o.get(), name.c_str()) <= 0) return std::nullopt;
  const Handle a(H5Aopen(o.get(), name.c_str(), H5P_DEFAULT), H5Aclose);
  const Handle t(a.ok() ? H5Aget_type(a.get()) : -1, H5Tclose);
  const Handle s(a.ok() ? H5Aget_space(a.get()) : -1, H5Sclose);
  const H5T_class_t c = t.ok() ? H5Tget_class(t.get()) : H5T_NO_CLASS;
  // One value only: H5Aread writes every element of the attribute into the buffer.
  double v = 0.0;
  if ((c != H5T_FLOAT && c != H5T_INTEGER) || !s.ok() ||
      H5Sget_simple_extent_npoints(s.get()) != 1 || H5Aread(a.get(), H5T_NATIVE_DOUBLE, &v) < 0)
    return std::nullopt;
  return v;
}

std::optional<double> ResultReader::finiteNumber(const std::string& object,
                                                 const std::string& name) const {
  const auto v = number(object, name);
  if (v && !std::isfinite(*v))
    throw BadResult(path_ + ": " + (object == "/" ? std::string() : object) + "@" + name + " is " +
                    valueText(*v) + "; a parameter used in a computation must be finite");
  return v;
}

std::optional<std::string> ResultReader::text(const std::string& object,
                                              const std::string& name) const {
  if (!has(object)) return std::nullopt;
  const Handle o(H5Oopen(static_cast<hid_t>(file_), object.c_str(), H5P_DEFAULT), H5Oclose);
  if (!o.ok() || H5Aexists(o.get(), name.c_str()) <= 0) return std::nullopt;
  const Handle a(H5Aopen(o.get(), name.c_str(), H5P_DEFAULT), H5Aclose);
  const Handle t(a.ok() ? H5Aget_type(a.get()) : -1, H5Tclose);
  const Handle s(a.ok() ? H5Aget_space(a.get()) : -1, H5Sclose);
  // One string only: H5Aread writes every element of the attribute into the buffer.
  if (!t.ok() || !s.ok() || H5Tget_class(t.get()) != H5T_STRING ||
      H5Sget_simple_extent_npoints(s.get()) != 1)
    return std::nullopt;
  if (!H5Tis_variable_str(t.get())) {
    const std::string where = (object == "/" ? std::string() : object) + "@" + name;
    if (const auto why = attributeOversized(s.get(), t.get(), where, bytes_); !why.empty())
      throw BadResult(path_ + ": " + why);
    std::string v(H5Tget_size(t.get()), '\0');
    if (H5Aread(a.get(), t.get(), v.data()) < 0) return std::nullopt;
    return v.substr(0, v.find('\0'));
  }
  // Variable length (h5py writes a Python str so): one string, freed by the library.
  char* p = nullptr;
  if (H5Aread(a.get(), t.get(), static_cast<void*>(&p)) < 0 || p == nullptr) return std::nullopt;
  std::string v(p);
  H5free_memory(p);
  return v;
}

std::vector<std::string> ResultReader::attributes(const std::string& object) const {
  std::vector<std::string> out;
  if (!has(object)) return out;
  const Handle o(H5Oopen(static_cast<hid_t>(file_), object.c_str(), H5P_DEFAULT), H5Oclose);
  if (!o.ok()) return out;
  hsize_t idx = 0;
  H5Aiterate2(o.get(), H5_INDEX_NAME, H5_ITER_INC, &idx, collectAttrName, &out);
  return out;
}

std::vector<std::string> ResultReader::members(const std::string& group) const {
  std::vector<std::string> out;
  if (!has(group)) return out;
  const Handle g(H5Gopen2(static_cast<hid_t>(file_), group.c_str(), H5P_DEFAULT), H5Gclose);
  if (!g.ok()) return out;
  hsize_t idx = 0;
  H5Literate(g.get(), H5_INDEX_NAME, H5_ITER_INC, &idx, collectName, &out);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::string> ResultReader::vehicleGroups() const {
  if (!has("/vehicles")) return {""};
  std::vector<std::string> out;
  const std::string names = text("/vehicles", "names").value_or("");
  for (std::size_t at = 0; at < names.size();) {
    const std::size_t end = std::min(names.find('\n', at), names.size());
    if (end > at) out.push_back("/vehicles/" + names.substr(at, end - at));
    at = end + 1;
  }
  if (out.empty())
    for (const auto& n : members("/vehicles")) out.push_back("/vehicles/" + n);
  return out;
}

std::vector<std::string> ResultReader::nonFinite(std::size_t limit) const {
  std::vector<std::string> out;
  if (file_ < 0 || limit == 0) return out;
  NonFiniteVisit v{&out, limit, bytes_, "/", ""};
  H5Ovisit2(static_cast<hid_t>(file_), H5_INDEX_NAME, H5_ITER_INC, checkObject, &v, H5O_INFO_BASIC);
  if (!v.oversized.empty()) throw BadResult(path_ + ": " + v.oversized);
  return out;
}

}  // namespace rb::io
