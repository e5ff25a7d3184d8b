// The result file: written under a temporary of its own and renamed on finalize only; a file not
// finalized never touches the final name; series keep what was appended when a run stops early;
// every dataset carries its units.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <fstream>
#include <iterator>

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
    EXPECT_TRUE(fs::exists(f.tmpPath()));
    EXPECT_EQ(f.tmpPath().rfind(path + ".tmp.", 0), 0u) << f.tmpPath();
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
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find("r.h5.tmp"), std::string::npos) << e.path();
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
  } catch (const rb::io::WriteError& e) {
    EXPECT_NE(
        std::string(e.what()).find("cannot create the result file '/nonexistent_dir_rb/x.h5.tmp."),
        std::string::npos)
        << e.what();
  }
}

namespace {
std::string bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}
}  // namespace

// A file that is not finalized (an exception, a run that did not start) is deleted and leaves an
// earlier result as it was.
TEST(ResultFile, NotFinalizedNeverReplacesTheResult) {
  fs::path dir = fs::temp_directory_path() / "rb_test_io_keep";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string path = (dir / "r.h5").string();
  {
    rb::io::ResultFile f(path);
    f.attr("/", "version", std::string("good"));
    f.finalize();
  }
  const std::string good = bytes(path);
  std::string tmp;
  {
    rb::io::ResultFile f(path);
    tmp = f.tmpPath();
    f.attr("/", "version", std::string("half written"));
    f.series("/time", "s").append(1.0);
  }
  EXPECT_EQ(bytes(path), good);
  EXPECT_FALSE(fs::exists(tmp));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

// Two writers of one result never share a temporary: each file is complete, the last finalized
// one is the result.
TEST(ResultFile, ConcurrentWritersHaveTheirOwnTemporaries) {
  fs::path dir = fs::temp_directory_path() / "rb_test_io_two";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string path = (dir / "r.h5").string();
  rb::io::ResultFile a(path);
  rb::io::ResultFile b(path);
  EXPECT_NE(a.tmpPath(), b.tmpPath());
  auto& ta = a.series("/time", "s");
  auto& tb = b.series("/time", "s");
  for (int i = 0; i < 5000; ++i) {
    ta.append(i);
    tb.append(-i);
  }
  b.finalize();
  a.finalize();
  hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const auto t = readDataset(f, "/time");
  H5Fclose(f);
  ASSERT_EQ(t.size(), 5000u);
  EXPECT_EQ(t[4999], 4999.0);  // a's data, whole
}

// Attributes beyond the 64 KiB of an object header (a large scenario text) are stored densely.
TEST(ResultFile, LargeStringAttribute) {
  fs::path dir = fs::temp_directory_path() / "rb_test_io_large";
  fs::create_directories(dir);
  const std::string path = (dir / "r.h5").string();
  const std::string text(200000, 'x');
  {
    rb::io::ResultFile f(path);
    f.attr("/", "scenario_text", text);
    f.attr("/stats", "message", text);
    f.finalize();
  }
  hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  hid_t root = H5Gopen2(f, "/", H5P_DEFAULT);
  EXPECT_EQ(readStringAttr(root, "scenario_text"), text);
  H5Gclose(root);
  H5Fclose(f);
}
