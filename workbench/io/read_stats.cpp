#include "workbench/io/read_stats.hpp"

#include <hdf5.h>

#include <algorithm>
#include <vector>

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

// A 1-D dataset of /stats (g) read as `type` into n elements of `size` bytes; false when it is
// missing or of another shape.
bool read1d(hid_t g, const char* name, hid_t type, std::size_t n, void* out) {
  if (H5Lexists(g, name, H5P_DEFAULT) <= 0) return false;
  const hid_t d = H5Dopen2(g, name, H5P_DEFAULT);
  if (d < 0) return false;
  const hid_t space = H5Dget_space(d);
  const bool ok = H5Sget_simple_extent_ndims(space) == 1 &&
                  static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)) == n &&
                  H5Dread(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out) >= 0;
  H5Sclose(space);
  H5Dclose(d);
  return ok;
}

// stage_names (fixed-length strings) and stage_share into rec.number["stage_share_<name>"].
void readStageShares(hid_t g, StatsRecord& rec) {
  if (H5Lexists(g, "stage_names", H5P_DEFAULT) <= 0) return;
  const hid_t d = H5Dopen2(g, "stage_names", H5P_DEFAULT);
  if (d < 0) return;
  const hid_t t = H5Dget_type(d);
  const hid_t space = H5Dget_space(d);
  const auto n =
      static_cast<std::size_t>(std::max<hssize_t>(0, H5Sget_simple_extent_npoints(space)));
  const std::size_t width = H5Tget_size(t);
  std::string raw(n * width, '\0');
  const bool names_ok = H5Tget_class(t) == H5T_STRING && !H5Tis_variable_str(t) && n > 0 &&
                        H5Dread(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, raw.data()) >= 0;
  H5Sclose(space);
  H5Tclose(t);
  H5Dclose(d);
  std::vector<double> share(n);
  if (!names_ok || !read1d(g, "stage_share", H5T_NATIVE_DOUBLE, n, share.data())) return;
  for (std::size_t i = 0; i < n; ++i) {
    const std::string name = raw.substr(i * width, width);
    rec.number["stage_share_" + name.substr(0, name.find('\0'))] = share[i];
  }
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
    readStageShares(g, rec);
    H5Gclose(g);
    out = rec;
  }
  H5Fclose(f);
  return out;
}

}  // namespace rb::io
