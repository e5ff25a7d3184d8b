// Binary table files and the on-disk table cache (table_io.hpp).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <sys/stat.h>

#include "contact_tables.hpp"
#include "railbench/version.hpp"
#include "workbench/contact/table_io.hpp"

namespace {

using namespace rb::contact;
namespace fs = std::filesystem;

// A fresh directory under the system temporary directory, removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    std::random_device rd;
    path_ = fs::temp_directory_path() /
            ("railbench_table_io_" + hashHex((std::uint64_t{rd()} << 32) ^ rd()));
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

bool sameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

void expectSameStats(const TableBuildStats& a, const TableBuildStats& b) {
  EXPECT_TRUE(sameBits(a.build_seconds, b.build_seconds));
  EXPECT_EQ(a.bytes, b.bytes);
  EXPECT_EQ(a.nodes, b.nodes);
  EXPECT_EQ(a.newton_iterations, b.newton_iterations);
  EXPECT_EQ(a.restarts, b.restarts);
  EXPECT_EQ(a.failures, b.failures);
  EXPECT_EQ(a.warnings, b.warnings);
  EXPECT_EQ(a.notes, b.notes);
}

// Every evaluation of the two LUTs on a dense point set (inside, on nodes and outside the grid),
// counted as bit mismatches.
std::size_t lutMismatches(const LutTable& a, const LutTable& b) {
  std::size_t bad = 0, points = 0;
  const GridSpec& gy = a.yGrid();
  const GridSpec& gg = a.gaugeGrid();
  LutSample sa, sb;
  const int ny = 257, ng = 23;
  for (int iy = 0; iy < ny; ++iy) {
    const double y = gy.min - 2 * gy.step + (gy.max - gy.min + 4 * gy.step) * iy / (ny - 1);
    for (int ig = 0; ig < ng; ++ig) {
      const double xi = gg.min - 0.3e-3 + (gg.max - gg.min + 0.6e-3) * ig / (ng - 1);
      ++points;
      a.eval(y, xi, sa);
      b.eval(y, xi, sb);
      if (sa.inside != sb.inside) ++bad;
      for (std::size_t c = 0; c < kLutChannels; ++c) {
        bad += !sameBits(sa.value[c], sb.value[c]) + !sameBits(sa.d_dy[c], sb.d_dy[c]) +
               !sameBits(sa.d_dxi[c], sb.d_dxi[c]);
        const LutValue va = a.evalChannel(c, y, xi), vb = b.evalChannel(c, y, xi);
        bad += !sameBits(va.v, vb.v) + !sameBits(va.dy, vb.dy) + !sameBits(va.dxi, vb.dxi) +
               !sameBits(va.dyy, vb.dyy) + !sameBits(va.dyxi, vb.dyxi) +
               !sameBits(va.dxixi, vb.dxixi) + (va.inside != vb.inside);
      }
      LutValue za, pa, zb, pb;
      a.evalZPhi(y, xi, za, pa);
      b.evalZPhi(y, xi, zb, pb);
      for (auto [u, v] : {std::pair{za, zb}, std::pair{pa, pb}}) {
        bad += !sameBits(u.v, v.v) + !sameBits(u.dy, v.dy) + !sameBits(u.dxi, v.dxi) +
               !sameBits(u.dyy, v.dyy) + !sameBits(u.dyxi, v.dyxi) + !sameBits(u.dxixi, v.dxixi);
      }
    }
  }
  // Stored nodes and flags.
  for (std::size_t ig = 0; ig < a.ng(); ++ig) {
    for (std::size_t iy = 0; iy < a.ny(); ++iy) {
      bad += a.flags(iy, ig) != b.flags(iy, ig);
      for (std::size_t c = 0; c < kLutChannels; ++c) {
        bad += !sameBits(a.node(c, iy, ig), b.node(c, iy, ig));
      }
    }
  }
  std::printf("    LUT: %zu points x %zu channels compared\n", points, kLutChannels);
  return bad;
}

// Every evaluation of the two KEC tables: knots, midpoints, random points, outside the grid, both
// sides; f with its spline derivatives (the spline is rebuilt on load) and the online solver.
std::size_t kecMismatches(const KecTable& a, const KecTable& b) {
  std::size_t bad = 0;
  const GridSpec& g = a.grid();
  std::vector<double> s;
  for (std::size_t i = 0; i < g.count(); ++i) {
    s.push_back(g.at(i));
    s.push_back(g.at(i) + 0.5 * g.step);
    s.push_back(g.at(i) + 0.123 * g.step);
  }
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(g.min - 5 * g.step, g.max + 5 * g.step);
  for (int i = 0; i < 2000; ++i) s.push_back(u(rng));
  KecPoint pa, pb;
  for (Side side : {Side::Left, Side::Right}) {
    for (double x : s) {
      a.eval(side, x, pa);
      b.eval(side, x, pb);
      bad += (pa.inside != pb.inside) + !sameBits(pa.d2f, pb.d2f);
      for (std::size_t q = 0; q < kKecQuantities; ++q) {
        bad += !sameBits(pa.value[q], pb.value[q]) + !sameBits(pa.d_ds[q], pb.d_ds[q]);
      }
      double da = 0, db = 0, dda = 0, ddb = 0;
      bad += !sameBits(a.f(side, x, &da, &dda), b.f(side, x, &db, &ddb));
      bad += !sameBits(da, db) + !sameBits(dda, ddb);
      bad += a.inTransition(side, x) != b.inTransition(side, x);
    }
    for (std::size_t i = 0; i < g.count(); ++i) {
      for (std::size_t q = 0; q < kKecQuantities; ++q) {
        bad += !sameBits(a.node(side, static_cast<KecQuantity>(q), i),
                         b.node(side, static_cast<KecQuantity>(q), i));
      }
    }
  }
  // The online solver followed over y.
  KecSolution sa = solveKec(a, KecInput{}), sb = solveKec(b, KecInput{});
  for (int i = 1; i <= 200; ++i) {
    const KecInput in{1e-5 * i, 1e-6 * (i % 7), -1e-6 * (i % 5), 2e-7 * (i % 3), 0.0};
    sa = solveKec(a, in, &sa);
    sb = solveKec(b, in, &sb);
    bad += (sa.status != sb.status) + (sa.iterations != sb.iterations) + !sameBits(sa.z, sb.z) +
           !sameBits(sa.phi, sb.phi) + !sameBits(sa.s_lk, sb.s_lk) + !sameBits(sa.s_rk, sb.s_rk) +
           !sameBits(sa.d2f_lk, sb.d2f_lk) + !sameBits(sa.residual, sb.residual);
  }
  std::printf("    KEC: %zu points x 2 sides compared, 200 solves\n", s.size());
  return bad;
}

void expectSameLutMeta(const LutTable& a, const LutTable& b) {
  EXPECT_EQ(a.configHash(), b.configHash());
  EXPECT_EQ(a.ny(), b.ny());
  EXPECT_EQ(a.ng(), b.ng());
  EXPECT_TRUE(sameBits(a.yGrid().step, b.yGrid().step));
  EXPECT_TRUE(sameBits(a.gaugeGrid().min, b.gaugeGrid().min));
  EXPECT_EQ(a.hasFlange(Side::Left), b.hasFlange(Side::Left));
  EXPECT_EQ(a.hasFlange(Side::Right), b.hasFlange(Side::Right));
  ASSERT_EQ(a.jumps().size(), b.jumps().size());
  for (std::size_t i = 0; i < a.jumps().size(); ++i) {
    const LutJump &x = a.jumps()[i], &y = b.jumps()[i];
    EXPECT_EQ(x.side, y.side);
    EXPECT_TRUE(sameBits(x.xi_g, y.xi_g) && sameBits(x.y_before, y.y_before) &&
                sameBits(x.y_after, y.y_after) && sameBits(x.s_w_before, y.s_w_before) &&
                sameBits(x.s_w_after, y.s_w_after));
  }
  ASSERT_EQ(a.twoPointContacts().size(), b.twoPointContacts().size());
  for (std::size_t i = 0; i < a.twoPointContacts().size(); ++i) {
    const TwoPointContact &x = a.twoPointContacts()[i], &y = b.twoPointContacts()[i];
    EXPECT_EQ(x.side, y.side);
    EXPECT_EQ(x.tread_edge, y.tread_edge);
    EXPECT_TRUE(sameBits(x.xi_g, y.xi_g) && sameBits(x.y, y.y) && sameBits(x.z, y.z) &&
                sameBits(x.phi, y.phi) && sameBits(x.s_w_tread, y.s_w_tread) &&
                sameBits(x.s_r_tread, y.s_r_tread) && sameBits(x.gamma_tread, y.gamma_tread) &&
                sameBits(x.s_w_flange, y.s_w_flange) && sameBits(x.s_r_flange, y.s_r_flange) &&
                sameBits(x.gamma_flange, y.gamma_flange));
  }
  expectSameStats(a.stats(), b.stats());
}

void expectSameKecMeta(const KecTable& a, const KecTable& b) {
  EXPECT_EQ(a.configHash(), b.configHash());
  EXPECT_EQ(a.grid().count(), b.grid().count());
  EXPECT_TRUE(sameBits(a.r0(), b.r0()));
  EXPECT_TRUE(sameBits(a.railLr(), b.railLr()));
  for (Side side : {Side::Left, Side::Right}) {
    EXPECT_TRUE(sameBits(a.validMin(side), b.validMin(side)));
    EXPECT_TRUE(sameBits(a.validMax(side), b.validMax(side)));
    ASSERT_EQ(a.transitions(side).size(), b.transitions(side).size());
    for (std::size_t i = 0; i < a.transitions(side).size(); ++i) {
      const KecTransition &x = a.transitions(side)[i], &y = b.transitions(side)[i];
      EXPECT_EQ(x.own, y.own);
      EXPECT_EQ(x.flange, y.flange);
      EXPECT_TRUE(sameBits(x.s_jump, y.s_jump) && sameBits(x.lo, y.lo) && sameBits(x.hi, y.hi) &&
                  sameBits(x.s_w_field, y.s_w_field) && sameBits(x.s_w_flange, y.s_w_flange) &&
                  sameBits(x.y, y.y));
    }
  }
  expectSameStats(a.stats(), b.stats());
}

TEST(TableIo, LutRoundTripIsBitIdentical) {
  TempDir dir;
  for (auto [t, cfg] : {std::pair{&rbtest::coneLut(), rbtest::coneConfig()},
                        std::pair{&rbtest::s1002Lut(), rbtest::s1002On60E1()}}) {
    const std::string path = dir.file("t.lut");
    saveTable(*t, cfg, path);
    EXPECT_FALSE(fs::exists(path + ".tmp"));
    std::printf("    LUT file %.2f MB\n", static_cast<double>(fs::file_size(path)) / 1e6);
    const auto t0 = std::chrono::steady_clock::now();
    std::optional<LutTable> back = loadLut(path, cfg);
    const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("    LUT load %.1f ms (built in %.1f ms)\n", dt * 1e3,
                t->stats().build_seconds * 1e3);
    ASSERT_TRUE(back.has_value());
    expectSameLutMeta(*t, *back);
    EXPECT_EQ(lutMismatches(*t, *back), 0u);
  }
  // The S1002 table really exercises jumps, two-point contacts and notes.
  EXPECT_FALSE(rbtest::s1002Lut().jumps().empty());
  EXPECT_FALSE(rbtest::s1002Lut().twoPointContacts().empty());
}

TEST(TableIo, KecRoundTripIsBitIdenticalWithTheSplineRebuilt) {
  TempDir dir;
  for (auto [t, cfg] : {std::pair{&rbtest::coneKec(), rbtest::coneConfig()},
                        std::pair{&rbtest::s1002Kec(), rbtest::s1002On60E1()}}) {
    const std::string path = dir.file("t.kec");
    saveTable(*t, cfg, path);
    std::optional<KecTable> back = loadKec(path, cfg);
    ASSERT_TRUE(back.has_value());
    expectSameKecMeta(*t, *back);
    EXPECT_EQ(kecMismatches(*t, *back), 0u);
  }
  EXPECT_FALSE(rbtest::s1002Kec().transitions(Side::Left).empty());
  EXPECT_FALSE(rbtest::s1002Kec().stats().notes.empty());
}

TEST(TableIo, BadFilesGiveNullopt) {
  TempDir dir;
  const LutTable& lut = rbtest::coneLut();
  const KecTable& kec = rbtest::coneKec();
  const ContactGeometryConfig cfg = rbtest::coneConfig();
  ContactGeometryConfig other = cfg;
  other.beta = 1.0 / 20.0;
  const std::string lp = dir.file("a.lut"), kp = dir.file("a.kec"), bad = dir.file("bad");
  saveTable(lut, cfg, lp);
  saveTable(kec, cfg, kp);
  const std::string lbytes = readBytes(lp), kbytes = readBytes(kp);
  ASSERT_TRUE(loadLut(lp, cfg));
  ASSERT_TRUE(loadKec(kp, cfg));

  // Missing, empty, garbage.
  EXPECT_FALSE(loadLut(dir.file("missing.lut"), cfg));
  EXPECT_FALSE(loadLut(dir.path().string(), cfg));  // a directory
  writeBytes(bad, "");
  EXPECT_FALSE(loadLut(bad, cfg));
  writeBytes(bad, std::string(1000, 'x'));
  EXPECT_FALSE(loadKec(bad, cfg));
  // Other inputs, wrong magic (a LUT read as a KEC and vice versa, an edited magic).
  EXPECT_FALSE(loadLut(lp, other));
  EXPECT_FALSE(loadKec(kp, other));
  EXPECT_FALSE(loadKec(lp, cfg));
  EXPECT_FALSE(loadLut(kp, cfg));
  std::string b = lbytes;
  b[10] = 'X';  // "railbench-Xut"
  writeBytes(bad, b);
  EXPECT_FALSE(loadLut(bad, cfg));
  // Byte-order marker (16..23), format version (24..31), algorithm version (32..39).
  for (std::size_t at : {16u, 24u, 32u}) {
    b = lbytes;
    b[at] = static_cast<char>(b[at] + 1);
    writeBytes(bad, b);
    EXPECT_FALSE(loadLut(bad, cfg)) << "byte " << at;
  }
  // Truncated anywhere (including right after the header and one byte short), extended.
  for (const std::string* bytes : {&lbytes, &kbytes}) {
    const std::size_t n = bytes->size();
    for (std::size_t len : {std::size_t{0}, std::size_t{15}, std::size_t{48}, std::size_t{56},
                            n / 3, n / 2, n - 9, n - 8, n - 1}) {
      writeBytes(bad, bytes->substr(0, len));
      EXPECT_FALSE(loadLut(bad, cfg)) << len;
      EXPECT_FALSE(loadKec(bad, cfg)) << len;
    }
    writeBytes(bad, *bytes + "x");
    EXPECT_FALSE(loadLut(bad, cfg));
    EXPECT_FALSE(loadKec(bad, cfg));
  }
  // A single flipped bit anywhere (header, sizes, data, strings, checksum).
  std::mt19937_64 rng(3);
  int tried = 0;
  for (const std::string* bytes : {&lbytes, &kbytes}) {
    std::vector<std::size_t> where = {
        0, 40, 48, 56, 64, bytes->size() / 2, bytes->size() - 100, bytes->size() - 1};
    for (int i = 0; i < 40; ++i) where.push_back(rng() % bytes->size());
    for (std::size_t at : where) {
      b = *bytes;
      b[at] = static_cast<char>(b[at] ^ (1 << (rng() % 8)));
      writeBytes(bad, b);
      EXPECT_FALSE(loadLut(bad, cfg)) << "byte " << at;
      EXPECT_FALSE(loadKec(bad, cfg)) << "byte " << at;
      ++tried;
    }
  }
  std::printf("    %d single-bit corruptions rejected\n", tried);
  // The good files are untouched.
  EXPECT_TRUE(loadLut(lp, cfg));
  EXPECT_TRUE(loadKec(kp, cfg));
}

TEST(TableIo, SaveErrorsThrowNamingThePath) {
  TempDir dir;
  const std::string path = dir.file("no/such/dir/t.lut");
  try {
    saveTable(rbtest::coneLut(), rbtest::coneConfig(), path);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  // Target is a directory: the rename fails, the temporary file is removed.
  const std::string target = dir.file("d.kec");
  fs::create_directories(fs::path(target) / "x");
  EXPECT_THROW(saveTable(rbtest::coneKec(), rbtest::coneConfig(), target), std::runtime_error);
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir.path())) files += e.is_regular_file();
  EXPECT_EQ(files, 0u);
}

TEST(TableIo, DiskCacheBuildsOnceThenLoads) {
  TempDir dir;
  const ContactGeometryConfig cfg = rbtest::s1002On60E1();
  const std::string sub = dir.file("cache/tables");  // created by the cache
  using clock = std::chrono::steady_clock;
  auto ms = [](clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(clock::now() - t0).count();
  };
  std::shared_ptr<const LutTable> lut1, lut2;
  std::shared_ptr<const KecTable> kec1, kec2;
  {
    DiskTableCache cache(sub);
    EXPECT_TRUE(fs::is_directory(sub));
    bool built = false;
    auto t0 = clock::now();
    lut1 = cache.lut(cfg, &built);
    const double tb = ms(t0);
    EXPECT_TRUE(built);
    t0 = clock::now();
    kec1 = cache.kec(cfg, &built);
    const double tkb = ms(t0);
    EXPECT_TRUE(built);
    EXPECT_EQ(fs::path(cache.lutPath(cfg)).parent_path(), fs::path(sub));
    EXPECT_EQ(fs::path(cache.lutPath(cfg)).extension(), ".lut");
    EXPECT_TRUE(fs::exists(cache.lutPath(cfg)));
    EXPECT_TRUE(fs::exists(cache.kecPath(cfg)));
    // A second cache object on the same directory stands for the next process of a sweep.
    DiskTableCache again(sub);
    t0 = clock::now();
    lut2 = again.lut(cfg, &built);
    const double tl = ms(t0);
    EXPECT_FALSE(built);
    t0 = clock::now();
    kec2 = again.kec(cfg, &built);
    const double tkl = ms(t0);
    EXPECT_FALSE(built);
    std::printf(
        "    S1002 LUT: build+save %.1f ms, load %.1f ms; KEC: build+save %.1f ms, load "
        "%.1f ms\n",
        tb, tl, tkb, tkl);
  }
  expectSameLutMeta(*lut1, *lut2);
  EXPECT_EQ(lutMismatches(*lut1, *lut2), 0u);
  expectSameKecMeta(*kec1, *kec2);
  EXPECT_EQ(kecMismatches(*kec1, *kec2), 0u);
  // No temporary files left behind.
  std::size_t entries = 0;
  for (const auto& e : fs::directory_iterator(sub)) {
    ++entries;
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
  }
  EXPECT_EQ(entries, 2u);
}

TEST(TableIo, DiskCacheKeysOnTheConfigAndRepairsBadFiles) {
  TempDir dir;
  DiskTableCache cache(dir.path().string());
  ContactGeometryConfig a = rbtest::coneConfig();
  ContactGeometryConfig b = a;
  b.beta = 1.0 / 20.0;
  EXPECT_NE(cache.lutPath(a), cache.lutPath(b));
  EXPECT_NE(cache.kecPath(a), cache.kecPath(b));
  bool built = false;
  auto la = cache.lut(a, &built);
  EXPECT_TRUE(built);
  auto lb = cache.lut(b, &built);
  EXPECT_TRUE(built);  // another file, not the beta = 1/40 one
  EXPECT_NE(la->configHash(), lb->configHash());
  EXPECT_TRUE(fs::exists(cache.lutPath(a)) && fs::exists(cache.lutPath(b)));
  cache.lut(b, &built);
  EXPECT_FALSE(built);
  // A damaged cache file is rebuilt and replaced.
  std::string bytes = readBytes(cache.lutPath(a));
  writeBytes(cache.lutPath(a), bytes.substr(0, bytes.size() / 2));
  auto la2 = cache.lut(a, &built);
  EXPECT_TRUE(built);
  EXPECT_TRUE(loadLut(cache.lutPath(a), a));
  cache.lut(a, &built);
  EXPECT_FALSE(built);
  EXPECT_EQ(lutMismatches(*la, *la2), 0u);
}

TEST(TableIo, RacingWritersLeaveOneValidFile) {
  // Threads stand in for processes: each builds the table (cache miss) and renames its own
  // temporary file over the same target.
  TempDir dir;
  const ContactGeometryConfig cfg = rbtest::coneConfig();
  std::vector<std::shared_ptr<const KecTable>> got(4);
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < got.size(); ++i) {
    threads.emplace_back([&, i] { got[i] = DiskTableCache(dir.path().string()).kec(cfg); });
  }
  for (std::thread& t : threads) t.join();
  DiskTableCache cache(dir.path().string());
  bool built = true;
  auto loaded = cache.kec(cfg, &built);
  EXPECT_FALSE(built);
  for (const auto& t : got) {
    ASSERT_TRUE(t);
    EXPECT_EQ(kecMismatches(*t, *loaded), 0u);
  }
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path())) ++entries;
  EXPECT_EQ(entries, 1u);
}

// The checksum a forger recomputes after editing a file (FNV-1a 64 over 8-byte words, then the
// tail bytes, of everything before the checksum), as table_io.cpp writes it.
std::string withChecksum(std::string bytes) {
  bytes.resize(bytes.size() - 8);
  std::uint64_t h = 14695981039346656037ULL;
  std::size_t i = 0;
  for (; i + 8 <= bytes.size(); i += 8) {
    std::uint64_t w;
    std::memcpy(&w, bytes.data() + i, 8);
    h = (h ^ w) * 1099511628211ULL;
  }
  for (; i < bytes.size(); ++i) h = (h ^ static_cast<unsigned char>(bytes[i])) * 1099511628211ULL;
  bytes.append(reinterpret_cast<const char*>(&h), 8);
  return bytes;
}

TEST(TableIo, KeyHoldsEveryInputAndTheVersions) {
  const ContactGeometryConfig a = rbtest::coneConfig();
  const std::string key = tableInputKey(a, TableKind::Kec);
  EXPECT_NE(key.find("algorithm=" + std::to_string(kTableAlgorithmVersion) + "\n"),
            std::string::npos);
  EXPECT_NE(key.find(std::string("workbench=") + rb::kVersion + "\n"), std::string::npos);
  EXPECT_EQ(key, tableInputKey(rbtest::coneConfig(), TableKind::Kec));
  EXPECT_NE(key, tableInputKey(a, TableKind::Lut));
  ContactGeometryConfig b = a;
  b.newton_max_iter += 1;
  EXPECT_NE(key, tableInputKey(b, TableKind::Kec));
  b = a;
  b.kec_dbar *= 1.0 + 1e-15;
  EXPECT_NE(key, tableInputKey(b, TableKind::Kec));
  b = a;
  b.right_wheel = b.left_wheel;  // same samples, not mirrored
  EXPECT_NE(key, tableInputKey(b, TableKind::Kec));
}

// A valid file of one table placed under another table's name, with its header rewritten and
// its checksum recomputed, must not load for that other table; nor may a file claiming another
// table-algorithm version or workbench version. The cache then rebuilds the right table.
TEST(TableIo, ForgedFileForAnotherTableIsRebuilt) {
  TempDir dir;
  DiskTableCache cache(dir.path().string());
  const ContactGeometryConfig a = rbtest::coneConfig();
  ContactGeometryConfig b = a;
  b.beta = 1.0 / 20.0;
  bool built = false;
  const auto ka = cache.kec(a, &built);
  const auto kb = cache.kec(b, &built);
  const std::string fileA = readBytes(cache.kecPath(a));
  const std::string fileB = readBytes(cache.kecPath(b));

  // A's file under B's name, every header word B's, checksum recomputed: the stored key still
  // describes A.
  std::string forged = fileA;
  std::memcpy(forged.data() + 16, fileB.data() + 16, 32);  // byte order, versions, key size
  writeBytes(cache.kecPath(b), withChecksum(forged));
  EXPECT_FALSE(loadKec(cache.kecPath(b), b));
  writeBytes(cache.kecPath(b), fileA);  // plainly copied
  EXPECT_FALSE(loadKec(cache.kecPath(b), b));
  const auto again = cache.kec(b, &built);
  EXPECT_TRUE(built);
  EXPECT_EQ(kecMismatches(*kb, *again), 0u);
  EXPECT_NE(kecMismatches(*ka, *again), 0u);
  EXPECT_TRUE(loadKec(cache.kecPath(b), b));

  // Another table-algorithm version (bytes 32..39), checksum recomputed.
  forged = fileA;
  forged[32] = static_cast<char>(forged[32] + 1);
  writeBytes(cache.kecPath(a), withChecksum(forged));
  EXPECT_FALSE(loadKec(cache.kecPath(a), a));
  // Another workbench version inside the key, checksum recomputed.
  forged = fileA;
  const std::size_t at = forged.find(std::string("workbench=") + rb::kVersion);
  ASSERT_NE(at, std::string::npos);
  forged[at + 10] = forged[at + 10] == '9' ? '8' : '9';
  writeBytes(cache.kecPath(a), withChecksum(forged));
  EXPECT_FALSE(loadKec(cache.kecPath(a), a));
  // Unchanged bytes with a recomputed checksum still load (the forging helper is right).
  writeBytes(cache.kecPath(a), withChecksum(fileA));
  EXPECT_TRUE(loadKec(cache.kecPath(a), a));
}

// A FIFO where a cache file should be is a miss (the table is built and the FIFO replaced by the
// file), never a read that blocks forever.
TEST(TableIo, FifoInTheCacheIsAMiss) {
  TempDir dir;
  DiskTableCache cache(dir.path().string());
  const ContactGeometryConfig cfg = rbtest::coneConfig();
  ASSERT_EQ(mkfifo(cache.lutPath(cfg).c_str(), 0644), 0);
  EXPECT_FALSE(loadLut(cache.lutPath(cfg), cfg));
  bool built = false;
  EXPECT_TRUE(cache.lut(cfg, &built));
  EXPECT_TRUE(built);
  EXPECT_TRUE(fs::is_regular_file(cache.lutPath(cfg)));
}

// A cache folder that cannot be written: the built table is returned all the same, with the
// reason, instead of being lost to an exception.
TEST(TableIo, UnwritableCacheFolderKeepsTheBuiltTable) {
  DiskTableCache cache("/proc/self");  // exists, not writable even by root
  bool built = false;
  std::string why;
  auto t = cache.lut(rbtest::coneConfig(), &built, &why);
  ASSERT_TRUE(t);
  EXPECT_TRUE(built);
  EXPECT_NE(why.find("/proc/self"), std::string::npos) << why;
  EXPECT_THROW(cache.lut(rbtest::coneConfig()), std::runtime_error);  // without a reason slot
}

}  // namespace
