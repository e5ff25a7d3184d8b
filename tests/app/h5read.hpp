#pragma once
// Minimal HDF5 reading for tests (tests may include HDF5; the engine outside io/ may not).
#include <hdf5.h>

#include <string>
#include <vector>

namespace h5test {

inline bool exists(hid_t f, const std::string& path) {
  // Check each prefix so a missing group is not an error.
  std::size_t pos = 0;
  while ((pos = path.find('/', pos + 1)) != std::string::npos)
    if (H5Lexists(f, path.substr(0, pos).c_str(), H5P_DEFAULT) <= 0) return false;
  return H5Lexists(f, path.c_str(), H5P_DEFAULT) > 0;
}

inline std::vector<double> dataset(hid_t f, const std::string& path) {
  hid_t d = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
  if (d < 0) return {};
  hid_t s = H5Dget_space(d);
  hsize_t n = 0;
  H5Sget_simple_extent_dims(s, &n, nullptr);
  std::vector<double> v(n);
  if (n) H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  H5Sclose(s);
  H5Dclose(d);
  return v;
}

inline std::string stringAttr(hid_t f, const std::string& obj, const std::string& name) {
  hid_t o = H5Oopen(f, obj.c_str(), H5P_DEFAULT);
  hid_t a = H5Aopen(o, name.c_str(), H5P_DEFAULT);
  hid_t t = H5Aget_type(a);
  std::string s(H5Tget_size(t), '\0');
  H5Aread(a, t, s.data());
  H5Tclose(t);
  H5Aclose(a);
  H5Oclose(o);
  return s.substr(0, s.find('\0'));
}

template <typename T>
inline T numAttr(hid_t f, const std::string& obj, const std::string& name) {
  hid_t o = H5Oopen(f, obj.c_str(), H5P_DEFAULT);
  hid_t a = H5Aopen(o, name.c_str(), H5P_DEFAULT);
  T v{};
  H5Aread(a, sizeof(T) == 8 && T(0.5) != T(0) ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT64, &v);
  H5Aclose(a);
  H5Oclose(o);
  return v;
}

}  // namespace h5test
