#include "workbench/io/result_reader.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "workbench/io/hdf5_init.hpp"

namespace rb::io {
namespace {

herr_t collectName(hid_t, const char* name, const H5L_info_t*, void* data) {
  static_cast<std::vector<std::string>*>(data)->emplace_back(name);
  return 0;
}

// Reads every element of an attribute or dataset as double; false when it cannot be read.
bool allFinite(hid_t space, const std::function<herr_t(void*)>& read) {
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  if (n <= 0) return true;
  std::vector<double> v(static_cast<std::size_t>(n));
  if (read(v.data()) < 0) return true;  // unreadable: not this check's finding
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

struct NonFiniteVisit {
  std::vector<std::string>* out;
  std::size_t limit;
  std::string object;  // the object whose attributes are iterated
};

herr_t checkAttr(hid_t o, const char* name, const H5A_info_t*, void* data) {
  auto* v = static_cast<NonFiniteVisit*>(data);
  const hid_t a = H5Aopen(o, name, H5P_DEFAULT);
  if (a < 0) return 0;
  const hid_t t = H5Aget_type(a);
  const hid_t sp = H5Aget_space(a);
  if (t >= 0 && sp >= 0 && H5Tget_class(t) == H5T_FLOAT &&
      !allFinite(sp, [&](void* buf) { return H5Aread(a, H5T_NATIVE_DOUBLE, buf); }))
    v->out->push_back((v->object == "/" ? std::string() : v->object) + "@" + name);
  if (sp >= 0) H5Sclose(sp);
  if (t >= 0) H5Tclose(t);
  H5Aclose(a);
  return v->out->size() >= v->limit ? 1 : 0;
}

herr_t checkObject(hid_t root, const char* name, const H5O_info_t* info, void* data) {
  auto* v = static_cast<NonFiniteVisit*>(data);
  v->object = std::string(name) == "." ? "/" : "/" + std::string(name);
  const hid_t o = H5Oopen(root, name, H5P_DEFAULT);
  if (o < 0) return 0;
  hsize_t idx = 0;
  H5Aiterate2(o, H5_INDEX_NAME, H5_ITER_INC, &idx, checkAttr, v);
  if (info->type == H5O_TYPE_DATASET && v->out->size() < v->limit) {
    const hid_t t = H5Dget_type(o);
    const hid_t sp = H5Dget_space(o);
    if (t >= 0 && sp >= 0 && H5Tget_class(t) == H5T_FLOAT && !allFinite(sp, [&](void* buf) {
          return H5Dread(o, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf);
        }))
      v->out->push_back(v->object);
    if (sp >= 0) H5Sclose(sp);
    if (t >= 0) H5Tclose(t);
  }
  H5Oclose(o);
  return v->out->size() >= v->limit ? 1 : 0;
}

}  // namespace

ResultReader::ResultReader(const std::string& path) {
  initHdf5();
  file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
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
  const hid_t d = H5Dopen2(static_cast<hid_t>(file_), path.c_str(), H5P_DEFAULT);
  if (d < 0) return std::nullopt;
  std::optional<std::vector<double>> out;
  const hid_t s = H5Dget_space(d);
  hsize_t n = 0;
  if (s >= 0 && H5Sget_simple_extent_ndims(s) == 1 &&
      H5Sget_simple_extent_dims(s, &n, nullptr) == 1) {
    std::vector<double> v(n);
    if (n == 0 || H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) >= 0)
      out = std::move(v);
  }
  if (s >= 0) H5Sclose(s);
  H5Dclose(d);
  return out;
}

std::optional<std::vector<std::string>> ResultReader::strings(const std::string& path) const {
  if (!has(path)) return std::nullopt;
  const hid_t d = H5Dopen2(static_cast<hid_t>(file_), path.c_str(), H5P_DEFAULT);
  if (d < 0) return std::nullopt;
  std::optional<std::vector<std::string>> out;
  const hid_t t = H5Dget_type(d);
  const hid_t s = H5Dget_space(d);
  hsize_t n = 0;
  if (t >= 0 && s >= 0 && H5Tget_class(t) == H5T_STRING && !H5Tis_variable_str(t) &&
      H5Sget_simple_extent_ndims(s) == 1 && H5Sget_simple_extent_dims(s, &n, nullptr) == 1) {
    const std::size_t width = H5Tget_size(t);
    std::string packed(width * n, '\0');
    if (n == 0 || H5Dread(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, packed.data()) >= 0) {
      std::vector<std::string> v;
      for (std::size_t i = 0; i < n; ++i) {
        std::string x = packed.substr(i * width, width);
        v.push_back(x.substr(0, x.find('\0')));
      }
      out = std::move(v);
    }
  }
  if (s >= 0) H5Sclose(s);
  if (t >= 0) H5Tclose(t);
  H5Dclose(d);
  return out;
}

std::optional<double> ResultReader::number(const std::string& object,
                                           const std::string& name) const {
  if (!has(object)) return std::nullopt;
  const hid_t o = H5Oopen(static_cast<hid_t>(file_), object.c_str(), H5P_DEFAULT);
  if (o < 0) return std::nullopt;
  std::optional<double> out;
  if (H5Aexists(o, name.c_str()) > 0) {
    const hid_t a = H5Aopen(o, name.c_str(), H5P_DEFAULT);
    const hid_t t = a >= 0 ? H5Aget_type(a) : -1;
    const H5T_class_t c = t >= 0 ? H5Tget_class(t) : H5T_NO_CLASS;
    double v = 0.0;
    if ((c == H5T_FLOAT || c == H5T_INTEGER) && H5Aread(a, H5T_NATIVE_DOUBLE, &v) >= 0) out = v;
    if (t >= 0) H5Tclose(t);
    if (a >= 0) H5Aclose(a);
  }
  H5Oclose(o);
  return out;
}

std::optional<std::string> ResultReader::text(const std::string& object,
                                              const std::string& name) const {
  if (!has(object)) return std::nullopt;
  const hid_t o = H5Oopen(static_cast<hid_t>(file_), object.c_str(), H5P_DEFAULT);
  if (o < 0) return std::nullopt;
  std::optional<std::string> out;
  if (H5Aexists(o, name.c_str()) > 0) {
    const hid_t a = H5Aopen(o, name.c_str(), H5P_DEFAULT);
    const hid_t t = a >= 0 ? H5Aget_type(a) : -1;
    if (t >= 0 && H5Tget_class(t) == H5T_STRING && !H5Tis_variable_str(t)) {
      std::string s(H5Tget_size(t), '\0');
      if (H5Aread(a, t, s.data()) >= 0) out = s.substr(0, s.find('\0'));
    } else if (t >= 0 && H5Tget_class(t) == H5T_STRING) {
      // Variable length (h5py writes a Python str so): one string, freed by the library.
      char* p = nullptr;
      if (H5Aread(a, t, static_cast<void*>(&p)) >= 0 && p != nullptr) {
        out = std::string(p);
        H5free_memory(p);
      }
    }
    if (t >= 0) H5Tclose(t);
    if (a >= 0) H5Aclose(a);
  }
  H5Oclose(o);
  return out;
}

std::vector<std::string> ResultReader::members(const std::string& group) const {
  std::vector<std::string> out;
  if (!has(group)) return out;
  const hid_t g = H5Gopen2(static_cast<hid_t>(file_), group.c_str(), H5P_DEFAULT);
  if (g < 0) return out;
  hsize_t idx = 0;
  H5Literate(g, H5_INDEX_NAME, H5_ITER_INC, &idx, collectName, &out);
  H5Gclose(g);
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
  NonFiniteVisit v{&out, limit, "/"};
  H5Ovisit2(static_cast<hid_t>(file_), H5_INDEX_NAME, H5_ITER_INC, checkObject, &v, H5O_INFO_BASIC);
  return out;
}

}  // namespace rb::io
