// The result file: written under .tmp and renamed on finalize; series keep what was appended when
// a run stops early; every dataset carries its units.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>

#include "workbench/io/result_file.hpp"

namespace fs = std::filesystem;

namespace {
std::vector<double> readDataset(hid_t f, const char* path) {
  hid_t d = H5Dopen2(f, path, H5P_DEFAULT);
  hid_t s = H5Dget_space(d);
  hsize_t n = 0;
  H5Sget_simple_extent_dims(s, &n, nullptr);
  std::vector<double> v(n);
  if (n) H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  H5Sclose(s);
  H5Dclose(d);
  return v;
}
std::string readStringAttr(hid_t obj, const char* name) {
  hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
  hid_t t = H5Aget_type(a);
  std::string s(H5Tget_size(t), '\0');
  H5Aread(a, t, s.data());
  H5Tclose(t);
  H5Aclose(a);
  return s.substr(0, s.find('\0'));
}
}  // namespace

TEST(ResultFile, TmpThenRenameWithUnitsAndSeries) {
  fs::path dir = fs::temp_directory_path() / "rb_test_io";
  fs::create_directories(dir);
  std::string path = (dir / "r.h5").string();
  fs::remove(path);
  {
    rb::io::ResultFile f(path);
    EXPECT_TRUE(fs::exists(path + ".tmp"));
    EXPECT_FALSE(fs::exists(path));
    f.attr("/", "version", std::string("x"));
    f.attr("/stats", "rhs_evals", std::int64_t{42});
    f.dataset("/track/centreline/s", {0.0, 0.5, 1.0}, "m");
    auto& t = f.series("/time", "s");
    for (int i = 0; i < 3000; ++i) t.append(i * 1e-3);
    f.flush();
    t.append(99.0);
    f.finalize();
  }
  EXPECT_TRUE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path + ".tmp"));
  hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  auto s = readDataset(f, "/track/centreline/s");
  EXPECT_EQ(s, (std::vector<double>{0.0, 0.5, 1.0}));
  auto t = readDataset(f, "/time");
  ASSERT_EQ(t.size(), 3001u);
  EXPECT_DOUBLE_EQ(t[2999], 2.999);
  EXPECT_DOUBLE_EQ(t[3000], 99.0);
  hid_t d = H5Dopen2(f, "/time", H5P_DEFAULT);
  EXPECT_EQ(readStringAttr(d, "units"), "s");
  H5Dclose(d);
  hid_t root = H5Gopen2(f, "/", H5P_DEFAULT);
  EXPECT_EQ(readStringAttr(root, "version"), "x");
  H5Gclose(root);
  H5Fclose(f);
}

TEST(ResultFile, UncreatableFileIsAClearError) {
  try {
    rb::io::ResultFile f("/nonexistent_dir_rb/x.h5");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "HDF5: cannot create file '/nonexistent_dir_rb/x.h5.tmp'");
  }
}
