// Small per-case output: `workbench run --track-store DIR` writes the track once per distinct
// track into DIR/<track hash>.h5 and references it from /track; `--compact` leaves out the
// per-patch datasets and compresses the series. The stored track and every signal a compact run
// keeps must be the bytes a plain run writes.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <algorithm>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "../app/h5read.hpp"
#include "../app/scenario_run.hpp"
#include "workbench/app/run.hpp"
#include "workbench/io/track_store.hpp"

namespace fs = std::filesystem;

namespace {

const char* kScenario = "scenarios/studies/case3_base.lua";

// A fresh folder under the temporary folder.
fs::path freshDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / "rb_study_output" / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

rb::app::RunOptions caseRun(const fs::path& out, std::vector<std::string> overrides = {}) {
  overrides.insert(overrides.begin(), "run.duration=0.2");
  return h5test::quietRun(kScenario, out.string(), overrides);
}

// Every dataset below `root` of an open file, by its path.
std::set<std::string> datasetsBelow(hid_t f, const std::string& root) {
  std::set<std::string> out;
  if (!h5test::exists(f, root)) return out;
  hid_t g = H5Oopen(f, root.c_str(), H5P_DEFAULT);
  struct Ctx {
    std::string root;
    std::set<std::string>* out;
  } ctx{root, &out};
  H5Ovisit(
      g, H5_INDEX_NAME, H5_ITER_NATIVE,
      [](hid_t, const char* name, const H5O_info_t* info, void* data) -> herr_t {
        auto* c = static_cast<Ctx*>(data);
        if (info->type == H5O_TYPE_DATASET && std::strcmp(name, ".") != 0)
          c->out->insert(c->root + "/" + name);
        return 0;
      },
      &ctx);
  H5Oclose(g);
  return out;
}

// The raw bytes of a 1-D float64 dataset are those of the other file's dataset.
bool sameBytes(hid_t a, hid_t b, const std::string& path) {
  const auto x = h5test::dataset(a, path);
  const auto y = h5test::dataset(b, path);
  return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(double)) == 0;
}

// Dataset `path` of `part` is a contiguous run of the same dataset of `whole`, starting at
// `offset`, and shorter than it.
bool sliceOf(hid_t part, hid_t whole, const std::string& path, std::size_t offset) {
  const auto x = h5test::dataset(part, path);
  const auto y = h5test::dataset(whole, path);
  return !x.empty() && offset + x.size() < y.size() &&
         std::memcmp(x.data(), y.data() + offset, x.size() * sizeof(double)) == 0;
}

// The number of filters of a dataset's storage.
int filters(hid_t f, const std::string& path) {
  hid_t d = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
  hid_t p = H5Dget_create_plist(d);
  const int n = H5Pget_nfilters(p);
  H5Pclose(p);
  H5Dclose(d);
  return n;
}

std::vector<fs::path> storeFiles(const fs::path& dir) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path());
  return out;
}

std::string attrText(const fs::path& file, const std::string& obj, const std::string& name) {
  hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return "<no file>";
  std::string v = H5Aexists_by_name(f, obj.c_str(), name.c_str(), H5P_DEFAULT) > 0
                      ? h5test::stringAttr(f, obj, name)
                      : "<no attribute>";
  H5Fclose(f);
  return v;
}

}  // namespace

TEST(TrackStore, RunsWithTheSameTrackShareOneStoreFile) {
  const fs::path d = freshDir("same");
  auto a = caseRun(d / "a.h5");
  a.track_store = (d / "tracks").string();
  auto b = caseRun(d / "b.h5", {"solver.step=5e-4"});  // another case on the same track
  b.track_store = a.track_store;
  ASSERT_EQ(rb::app::runScenario(a), 0);
  ASSERT_EQ(rb::app::runScenario(b), 0);
  const auto files = storeFiles(d / "tracks");
  ASSERT_EQ(files.size(), 1u);
  const std::string hash = files[0].stem().string();
  EXPECT_EQ(hash.size(), 32u);
  for (const char* r : {"a.h5", "b.h5"}) {
    EXPECT_EQ(attrText(d / r, "/track", "track_hash"), hash) << r;
    EXPECT_EQ(attrText(d / r, "/track", "stored_in"), "tracks/" + hash + ".h5") << r;
  }
  EXPECT_EQ(attrText(files[0], "/track", "track_hash"), hash);
}

TEST(TrackStore, DifferentTracksGetDifferentStoreFiles) {
  const fs::path d = freshDir("different");
  auto a = caseRun(d / "a.h5");
  a.track_store = (d / "tracks").string();
  auto b = caseRun(d / "b.h5", {"track.irregularities.seed=7"});
  b.track_store = a.track_store;
  ASSERT_EQ(rb::app::runScenario(a), 0);
  ASSERT_EQ(rb::app::runScenario(b), 0);
  ASSERT_EQ(storeFiles(d / "tracks").size(), 2u);
  EXPECT_NE(attrText(d / "a.h5", "/track", "track_hash"),
            attrText(d / "b.h5", "/track", "track_hash"));
}

// The store holds the whole track; a plain run's file the stretch its vehicle covers (the same
// samples).
TEST(TrackStore, StoredTrackIsThePlainRunsTrackAndTheResultKeepsOnlyAttributes) {
  const fs::path d = freshDir("equal");
  ASSERT_EQ(rb::app::runScenario(caseRun(d / "plain.h5")), 0);
  auto s = caseRun(d / "stored.h5");
  s.track_store = (d / "tracks").string();
  ASSERT_EQ(rb::app::runScenario(s), 0);
  const auto files = storeFiles(d / "tracks");
  ASSERT_EQ(files.size(), 1u);
  hid_t plain = H5Fopen((d / "plain.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  hid_t store = H5Fopen(files[0].c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  hid_t stored = H5Fopen((d / "stored.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(plain, 0);
  ASSERT_GE(store, 0);
  ASSERT_GE(stored, 0);
  const auto names = datasetsBelow(plain, "/track");
  EXPECT_EQ(names.size(), 30u);  // centreline 9, segments 6, irregularities 10, target PSD 5
  EXPECT_EQ(datasetsBelow(store, "/track"), names);
  // Where the plain run's stretch starts in the whole track's samples.
  const auto offsetIn = [&](const std::string& s_path) {
    const auto part = h5test::dataset(plain, s_path);
    const auto whole = h5test::dataset(store, s_path);
    return part.empty() ? whole.size()
                        : static_cast<std::size_t>(
                              std::find(whole.begin(), whole.end(), part.front()) - whole.begin());
  };
  const std::size_t k0 = offsetIn("/track/centreline/s");
  const std::size_t i0 = offsetIn("/track/irregularities/s");
  for (const auto& n : names) {
    if (n.rfind("/track/centreline/", 0) == 0)
      EXPECT_TRUE(sliceOf(plain, store, n, k0)) << n;
    else if (n.rfind("/track/irregularities/", 0) == 0 && n.find("target_psd") == std::string::npos)
      EXPECT_TRUE(sliceOf(plain, store, n, i0)) << n;
    else
      EXPECT_TRUE(sameBytes(plain, store, n)) << n;
    EXPECT_EQ(h5test::stringAttr(plain, n, "units"), h5test::stringAttr(store, n, "units")) << n;
  }
  // 0.2 s at 20 m/s from s = 0: the wagon's 4 m of track and a sample beyond either end.
  const auto irr_s = h5test::dataset(plain, "/track/irregularities/s");
  ASSERT_GE(irr_s.size(), 2u);
  EXPECT_LT(irr_s.back() - irr_s.front(), 20.0);
  EXPECT_EQ(h5test::numAttr<std::int64_t>(plain, "/track/irregularities", "seed"),
            h5test::numAttr<std::int64_t>(store, "/track/irregularities", "seed"));
  EXPECT_TRUE(datasetsBelow(stored, "/track").empty());
  for (const char* a : {"length", "step", "gauge", "build_time_s"})
    EXPECT_GT(H5Aexists_by_name(stored, "/track", a, H5P_DEFAULT), 0) << a;
  EXPECT_EQ(h5test::numAttr<double>(plain, "/track", "length"),
            h5test::numAttr<double>(stored, "/track", "length"));
  H5Fclose(plain);
  H5Fclose(store);
  H5Fclose(stored);
}

TEST(TrackStore, PlainRunWritesNoReference) {
  const fs::path d = freshDir("plain");
  ASSERT_EQ(rb::app::runScenario(caseRun(d / "plain.h5")), 0);
  EXPECT_EQ(attrText(d / "plain.h5", "/track", "stored_in"), "<no attribute>");
  EXPECT_EQ(attrText(d / "plain.h5", "/", "compact"), "<no attribute>");
}

TEST(TrackStore, CorruptOrForeignStoreFileIsReplaced) {
  const fs::path d = freshDir("corrupt");
  auto a = caseRun(d / "a.h5");
  a.track_store = (d / "tracks").string();
  ASSERT_EQ(rb::app::runScenario(a), 0);
  const fs::path file = storeFiles(d / "tracks").at(0);
  const std::string hash = file.stem().string();
  ASSERT_TRUE(rb::io::isStoredTrack(file.string(), hash));
  EXPECT_FALSE(rb::io::isStoredTrack(file.string(), std::string(32, '0')));
  const auto size = fs::file_size(file);
  fs::resize_file(file, size / 2);  // a truncated file
  EXPECT_FALSE(rb::io::isStoredTrack(file.string(), hash));
  ASSERT_EQ(rb::app::runScenario(a), 0);
  EXPECT_TRUE(rb::io::isStoredTrack(file.string(), hash));
  EXPECT_EQ(fs::file_size(file), size);
  std::ofstream(file, std::ios::trunc) << "not HDF5";
  ASSERT_EQ(rb::app::runScenario(a), 0);
  EXPECT_TRUE(rb::io::isStoredTrack(file.string(), hash));
  EXPECT_EQ(storeFiles(d / "tracks").size(), 1u);  // no temporary left behind
}

TEST(Compact, SignalsAreThePlainRunsBitForBitAndWhatIsLeftOutIsStated) {
  const fs::path d = freshDir("compact");
  ASSERT_EQ(rb::app::runScenario(caseRun(d / "plain.h5")), 0);
  auto c = caseRun(d / "compact.h5");
  c.compact = true;
  c.track_store = (d / "tracks").string();
  ASSERT_EQ(rb::app::runScenario(c), 0);
  hid_t plain = H5Fopen((d / "plain.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  hid_t compact = H5Fopen((d / "compact.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(plain, 0);
  ASSERT_GE(compact, 0);
  EXPECT_TRUE(h5test::exists(plain, "/contact/ws1/left/patch0/normal_force"));
  EXPECT_FALSE(h5test::exists(compact, "/contact/ws1/left/patch0"));
  std::size_t compared = 0;
  for (const char* g : {"/time", "/vehicle", "/bodies", "/contact", "/elements"}) {
    std::set<std::string> names = datasetsBelow(plain, g);
    if (h5test::exists(plain, g) && names.empty()) names.insert(g);  // a dataset itself
    std::set<std::string> kept;
    for (const auto& n : names)
      if (n.find("/patch") == std::string::npos) kept.insert(n);
    std::set<std::string> in_compact = datasetsBelow(compact, g);
    if (h5test::exists(compact, g) && in_compact.empty()) in_compact.insert(g);
    EXPECT_EQ(in_compact, kept) << g;
    for (const auto& n : kept) {
      EXPECT_TRUE(sameBytes(plain, compact, n)) << n;
      ++compared;
    }
  }
  EXPECT_GT(compared, 150u);  // /time, speed, 7 bodies x 6, 8 wheels x 19
  EXPECT_NE(h5test::stringAttr(compact, "/", "compact").find("patch0"), std::string::npos);
  EXPECT_EQ(filters(compact, "/bodies/ws1/y"), 2);  // shuffle + deflate
  EXPECT_EQ(filters(plain, "/bodies/ws1/y"), 0);
  H5Fclose(plain);
  H5Fclose(compact);
}

TEST(TrackStore, HashSeesEveryBitNameAndOrder) {
  using C = rb::io::TrackContent;
  C c;
  c.items.emplace_back(C::Attr{"/track", "length", 500.0});
  c.items.emplace_back(C::Dataset{"/track/centreline/s", "m", {0.0, 0.5, 1.0}, "arc length", ""});
  c.items.emplace_back(C::Dataset{"/track/centreline/x", "m", {0.0, 0.5, 1.0}, "x", ""});
  const std::string h = rb::io::trackHash(c);
  EXPECT_EQ(h.size(), 32u);
  EXPECT_EQ(rb::io::trackHash(c), h);
  C bit = c;
  std::get<C::Dataset>(bit.items[2]).data[1] = std::nextafter(0.5, 1.0);  // one ulp
  EXPECT_NE(rb::io::trackHash(bit), h);
  C order = c;
  std::swap(order.items[1], order.items[2]);
  EXPECT_NE(rb::io::trackHash(order), h);
  C units = c;
  std::get<C::Dataset>(units.items[1]).units = "km";
  EXPECT_NE(rb::io::trackHash(units), h);
  C kind = c;  // the same number as an integer attribute
  std::get<C::Attr>(kind.items[0]).value = std::int64_t{500};
  EXPECT_NE(rb::io::trackHash(kind), h);
}
