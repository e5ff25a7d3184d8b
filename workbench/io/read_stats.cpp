#include "workbench/io/read_stats.hpp"

#include <hdf5.h>

#include "workbench/io/hdf5_init.hpp"

namespace rb::io {
namespace {

struct Visit {
  StatsRecord* rec;
};

herr_t readAttr(hid_t loc, const char* name, const H5A_info_t*, void* data) {
  auto* rec = static_cast<Visit*>(data)->rec;
  hid_t a = H5Aopen(loc, name, H5P_DEFAULT);
  if (a < 0) return 0;
  hid_t t = H5Aget_type(a);
  H5T_class_t cls = H5Tget_class(t);
  if (cls == H5T_STRING) {
    std::string s(H5Tget_size(t), '\0');
    if (!H5Tis_variable_str(t) && H5Aread(a, t, s.data()) >= 0)
      rec->text[name] = s.substr(0, s.find('\0'));
  } else if (cls == H5T_INTEGER || cls == H5T_FLOAT) {
    double v = 0;
    if (H5Aread(a, H5T_NATIVE_DOUBLE, &v) >= 0) rec->number[name] = v;
  }
  H5Tclose(t);
  H5Aclose(a);
  return 0;
}

}  // namespace

std::optional<StatsRecord> readStats(const std::string& path) {
  initHdf5();
  hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return std::nullopt;
  std::optional<StatsRecord> out;
  if (H5Lexists(f, "/stats", H5P_DEFAULT) > 0) {
    hid_t g = H5Gopen2(f, "/stats", H5P_DEFAULT);
    StatsRecord rec;
    Visit v{&rec};
    hsize_t idx = 0;
    H5Aiterate2(g, H5_INDEX_NAME, H5_ITER_NATIVE, &idx, readAttr, &v);
    H5Gclose(g);
    out = rec;
  }
  H5Fclose(f);
  return out;
}

}  // namespace rb::io
