// contact.table_interpolation: the paper's linear (KEC) / bilinear (LUT) interpolation between the
// stored nodes (section 5.5) against the default cubic Hermite, and the cache keeping them apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>

#include "contact_tables.hpp"
#include "workbench/contact/table_io.hpp"

namespace {

using namespace rb::contact;
namespace fs = std::filesystem;

ContactGeometryConfig linearCone() {
  ContactGeometryConfig c = rbtest::coneConfig();
  c.interpolation = TableInterpolation::Linear;
  return c;
}
const KecTable& linearConeKec() {
  static const KecTable t = buildKec(linearCone());
  return t;
}
const LutTable& linearConeLut() {
  static const LutTable t = buildLut(linearCone());
  return t;
}

// The local coordinate the tables compute for x on a uniform grid: exactly 0 when x maps to an
// integer (then a node must be reproduced bit for bit), else within rounding of it.
bool mapsToNode(double x, const GridSpec& g, std::size_t i) {
  return (x - g.min) / g.step == static_cast<double>(i);
}

constexpr std::size_t kQ = kKecQuantities;

TEST(TableInterpolation, NamesAndDefault) {
  EXPECT_EQ(ContactGeometryConfig{}.interpolation, TableInterpolation::Cubic);
  EXPECT_EQ(rb::nameOf(TableInterpolation::Cubic), "cubic");
  EXPECT_EQ(rb::nameOf(TableInterpolation::Linear), "linear");
  EXPECT_EQ(rb::parse<TableInterpolation>("linear"), TableInterpolation::Linear);
  EXPECT_FALSE(rb::parse<TableInterpolation>("bilinear").has_value());
  EXPECT_EQ(rbtest::coneKec().interpolation(), TableInterpolation::Cubic);
  EXPECT_EQ(linearConeKec().interpolation(), TableInterpolation::Linear);
  EXPECT_EQ(linearConeLut().interpolation(), TableInterpolation::Linear);
}

TEST(TableInterpolation, SameNodesEitherWay) {
  // The interpolation does not change what is stored, only how it is read.
  const KecTable& c = rbtest::coneKec();
  const KecTable& l = linearConeKec();
  ASSERT_EQ(c.grid().count(), l.grid().count());
  for (Side side : {Side::Left, Side::Right})
    for (std::size_t i = 0; i < c.grid().count(); ++i)
      for (std::size_t q = 0; q < kQ; ++q)
        ASSERT_EQ(c.node(side, static_cast<KecQuantity>(q), i),
                  l.node(side, static_cast<KecQuantity>(q), i));
  const LutTable& cl = rbtest::coneLut();
  const LutTable& ll = linearConeLut();
  for (std::size_t ig = 0; ig < cl.ng(); ++ig)
    for (std::size_t iy = 0; iy < cl.ny(); ++iy)
      for (std::size_t ch = 0; ch < kLutChannels; ++ch)
        ASSERT_EQ(cl.node(ch, iy, ig), ll.node(ch, iy, ig));
}

TEST(TableInterpolation, KecLinearReproducesTheNodes) {
  const KecTable& t = linearConeKec();
  const GridSpec& g = t.grid();
  std::size_t exact = 0;
  for (Side side : {Side::Left, Side::Right}) {
    for (std::size_t i = 0; i < g.count(); ++i) {
      const double s = g.at(i);
      KecPoint p;
      t.eval(side, s, p);
      const bool on_node = mapsToNode(s, g, i);
      exact += on_node ? 1 : 0;
      for (std::size_t q = 0; q < kQ; ++q) {
        const double node = t.node(side, static_cast<KecQuantity>(q), i);
        if (on_node) {
          ASSERT_EQ(p.value[q], node) << kecQuantityName(static_cast<KecQuantity>(q)) << " " << i;
        } else {
          ASSERT_NEAR(p.value[q], node, 4e-16 * std::max(1.0, std::abs(node)));
        }
      }
      ASSERT_EQ(t.f(side, s), p.value[0]);
    }
  }
  EXPECT_GT(exact, g.count());  // most nodes map exactly
  // The last node (the clamped end interval at t = 1).
  KecPoint p;
  t.eval(Side::Left, g.max, p);
  EXPECT_NEAR(p.value[0], t.node(Side::Left, KecQuantity::F, g.count() - 1), 1e-15);
}

TEST(TableInterpolation, KecLinearIsLinearBetweenNodes) {
  const KecTable& t = linearConeKec();
  const GridSpec& g = t.grid();
  for (Side side : {Side::Left, Side::Right}) {
    for (std::size_t i = 0; i + 1 < g.count(); i += 7) {
      const double h = g.step;
      KecPoint mid, a, b, vals;
      t.eval(side, g.at(i) + 0.5 * h, mid);
      t.eval(side, g.at(i) + 0.2 * h, a);
      t.eval(side, g.at(i) + 0.8 * h, b);
      for (std::size_t q = 0; q < kQ; ++q) {
        const auto Q = static_cast<KecQuantity>(q);
        const double v0 = t.node(side, Q, i), v1 = t.node(side, Q, i + 1);
        const double tol =
            1e-10 * std::abs(v1 - v0) + 4e-16 * std::max(std::abs(v0), std::abs(v1)) + 1e-18;
        EXPECT_NEAR(mid.value[q], 0.5 * (v0 + v1), tol) << kecQuantityName(Q) << " " << i;
        EXPECT_NEAR(a.value[q], v0 + 0.2 * (v1 - v0), tol);
        // The derivative is the slope of the segment, the same everywhere inside it.
        EXPECT_EQ(a.d_ds[q], (v1 - v0) / h);
        EXPECT_EQ(b.d_ds[q], a.d_ds[q]);
      }
      EXPECT_EQ(mid.d2f, 0.0);
      double df = 0.0, d2f = 1.0;
      EXPECT_EQ(t.f(side, g.at(i) + 0.2 * h, &df, &d2f), a.value[0]);
      EXPECT_EQ(df, a.d_ds[0]);
      EXPECT_EQ(d2f, 0.0);
      // evalValues: the same values, F and the derivatives untouched.
      vals.value[0] = -1.0;
      vals.d_ds[1] = -2.0;
      t.evalValues(side, g.at(i) + 0.2 * h, vals);
      EXPECT_EQ(vals.value[0], -1.0);
      EXPECT_EQ(vals.d_ds[1], -2.0);
      for (std::size_t q = 1; q < kQ; ++q) EXPECT_EQ(vals.value[q], a.value[q]);
      EXPECT_EQ(vals.inside, a.inside);
    }
  }
}

TEST(TableInterpolation, KecCubicIsNotLinear) {
  // The cubic table is C1 and curved between nodes where the data are (the rail parameter of a
  // cone on an arc rail); the linear one is the chord.
  const KecTable& c = rbtest::coneKec();
  const KecTable& l = linearConeKec();
  const GridSpec& g = c.grid();
  const std::size_t i = g.count() / 2 + 3;
  KecPoint pc, pl;
  c.eval(Side::Left, g.at(i) + 0.5 * g.step, pc);
  l.eval(Side::Left, g.at(i) + 0.5 * g.step, pl);
  const auto q = static_cast<std::size_t>(KecQuantity::Sr);
  EXPECT_NE(pc.value[q], pl.value[q]);
  EXPECT_NEAR(pc.value[q], pl.value[q], 1e-6);
}

TEST(TableInterpolation, KecNewtonConvergesOnLinearTables) {
  // Knife positions on nodes, between nodes, and sweeps across many nodes with a warm start
  // (as the dynamics calls it).
  const KecTable& l = linearConeKec();
  KecSolution warm;
  bool have = false;
  int worst = 0;
  for (double y = -4e-3; y <= 4e-3; y += 0.0137e-3) {
    KecInput in;
    in.y = y;
    in.y_lir = 0.3e-3;
    in.z_lir = -0.1e-3;
    const KecSolution s = solveKec(l, in, have ? &warm : nullptr);
    ASSERT_EQ(s.status, KecStatus::Ok) << y << " residual " << s.residual;
    worst = std::max(worst, s.iterations);
    warm = s;
    have = true;
    // The solution is that of the piecewise-linear equivalent profile (Eq. 22).
    EXPECT_NEAR(s.f_lk, l.f(Side::Left, s.s_lk), 1e-15);
    EXPECT_EQ(s.d2f_lk, 0.0);
    const KecSolution cold = solveKec(l, in);
    ASSERT_EQ(cold.status, KecStatus::Ok) << y;
    EXPECT_NEAR(cold.z, s.z, 1e-12);
    EXPECT_NEAR(cold.phi, s.phi, 1e-12);
  }
  EXPECT_LE(worst, 6);
  // A root with the left knife on a node (a kink of f_lk): y adjusted until s_lk is the node
  // (ds_lk/dy ~ -1 by the first row of Eq. 22).
  const GridSpec& g = l.grid();
  const double s_node = g.at(g.count() / 2 + 5);
  KecInput in;
  in.y = -s_node;
  KecSolution s;
  for (int k = 0; k < 8; ++k) {
    s = solveKec(l, in);
    ASSERT_EQ(s.status, KecStatus::Ok);
    in.y += s.s_lk - s_node;
  }
  s = solveKec(l, in);
  ASSERT_EQ(s.status, KecStatus::Ok);
  EXPECT_NEAR(s.s_lk, s_node, 1e-15);
  EXPECT_LE(s.iterations, 8);
}

// ---- LUT ----------------------------------------------------------------------------------------

TEST(TableInterpolation, LutBilinearReproducesTheNodes) {
  const LutTable& t = linearConeLut();
  const GridSpec &gy = t.yGrid(), &gg = t.gaugeGrid();
  std::size_t exact = 0;
  for (std::size_t ig = 0; ig < t.ng(); ++ig) {
    for (std::size_t iy = 0; iy < t.ny(); iy += 3) {
      const double y = gy.at(iy), xi = gg.at(ig);
      LutSample p;
      t.eval(y, xi, p);
      const bool on_node = mapsToNode(y, gy, iy) && mapsToNode(xi, gg, ig);
      exact += on_node ? 1 : 0;
      for (std::size_t ch = 0; ch < kLutChannels; ++ch) {
        const double node = t.node(ch, iy, ig);
        if (on_node) {
          ASSERT_EQ(p.value[ch], node) << lutChannelName(ch) << " " << iy << " " << ig;
        } else {
          ASSERT_NEAR(p.value[ch], node, 4e-16 * std::max(1.0, std::abs(node)));
        }
      }
    }
  }
  EXPECT_GT(exact, 0u);
}

TEST(TableInterpolation, LutIsBilinearInACell) {
  const LutTable& t = linearConeLut();
  const GridSpec &gy = t.yGrid(), &gg = t.gaugeGrid();
  const double hy = gy.step, hg = gg.step;
  for (std::size_t ig = 0; ig + 1 < t.ng(); ++ig) {
    for (std::size_t iy = 0; iy + 1 < t.ny(); iy += 11) {
      const double y0 = gy.at(iy), x0 = gg.at(ig);
      LutSample mid, edge, a, b;
      t.eval(y0 + 0.5 * hy, x0 + 0.5 * hg, mid);
      t.eval(y0 + 0.5 * hy, x0, edge);
      t.eval(y0 + 0.25 * hy, x0 + 0.6 * hg, a);
      t.eval(y0 + 0.75 * hy, x0 + 0.6 * hg, b);
      for (std::size_t ch = 0; ch < kLutChannels; ++ch) {
        const double f00 = t.node(ch, iy, ig), f10 = t.node(ch, iy + 1, ig);
        const double f01 = t.node(ch, iy, ig + 1), f11 = t.node(ch, iy + 1, ig + 1);
        const double scale = std::max({std::abs(f00), std::abs(f10), std::abs(f01), std::abs(f11)});
        const double tol = 1e-10 * scale + 1e-18;
        // Cell centre = mean of the four nodes, edge midpoint = mean of its two.
        EXPECT_NEAR(mid.value[ch], 0.25 * (f00 + f10 + f01 + f11), tol) << lutChannelName(ch);
        EXPECT_NEAR(edge.value[ch], 0.5 * (f00 + f10), tol) << lutChannelName(ch);
        const double u = 0.6, tt = 0.25;
        const double bil = (1 - u) * ((1 - tt) * f00 + tt * f10) + u * ((1 - tt) * f01 + tt * f11);
        EXPECT_NEAR(a.value[ch], bil, tol) << lutChannelName(ch);
        // d/dy is constant along y in a cell (the slope at this xi_g), d/dxi_g linear in y.
        EXPECT_NEAR(a.d_dy[ch], b.d_dy[ch], 1e-9 * std::abs(a.d_dy[ch]) + 1e-15);
        EXPECT_NEAR(a.d_dy[ch], ((1 - u) * (f10 - f00) + u * (f11 - f01)) / hy,
                    1e-9 * std::abs(a.d_dy[ch]) + 1e-12);
        EXPECT_NEAR(a.d_dxi[ch], ((1 - tt) * (f01 - f00) + tt * (f11 - f10)) / hg,
                    1e-9 * std::abs(a.d_dxi[ch]) + 1e-12);
        // One channel with second derivatives: zero pure second derivatives, the constant cross
        // term, and the same value and slopes.
        const LutValue v = t.evalChannel(ch, y0 + 0.25 * hy, x0 + 0.6 * hg);
        EXPECT_EQ(v.v, a.value[ch]);
        EXPECT_EQ(v.dy, a.d_dy[ch]);
        EXPECT_EQ(v.dxi, a.d_dxi[ch]);
        EXPECT_EQ(v.dyy, 0.0);
        EXPECT_EQ(v.dxixi, 0.0);
        EXPECT_EQ(v.dyxi, (f11 - f10 - f01 + f00) / (hy * hg));
      }
      // evalValues gives eval's values; evalZPhi its z and phi.
      LutSample vals;
      t.evalValues(y0 + 0.25 * hy, x0 + 0.6 * hg, vals);
      for (std::size_t ch = 0; ch < kLutChannels; ++ch) EXPECT_EQ(vals.value[ch], a.value[ch]);
      LutValue z, phi;
      t.evalZPhi(y0 + 0.25 * hy, x0 + 0.6 * hg, z, phi);
      EXPECT_EQ(z.v, a.value[kLutZ]);
      EXPECT_EQ(phi.dy, a.d_dy[kLutPhi]);
    }
  }
}

TEST(TableInterpolation, LutWithOneGaugeNodeIsLinearInY) {
  ContactGeometryConfig c = linearCone();
  c.lut_gauge = {0.0, 0.0, 1e-3};
  c.lut_y = {-0.004, 0.004, 0.2e-3};
  const LutTable t = buildLut(c);
  ASSERT_EQ(t.ng(), 1u);
  const GridSpec& gy = t.yGrid();
  for (std::size_t iy = 0; iy + 1 < t.ny(); iy += 5) {
    LutSample node, mid;
    t.eval(gy.at(iy), 0.0, node);
    t.eval(gy.at(iy) + 0.5 * gy.step, 0.0, mid);
    for (std::size_t ch = 0; ch < kLutChannels; ++ch) {
      const double f0 = t.node(ch, iy, 0), f1 = t.node(ch, iy + 1, 0);
      if (mapsToNode(gy.at(iy), gy, iy)) {
        EXPECT_EQ(node.value[ch], f0);
      }
      EXPECT_NEAR(mid.value[ch], 0.5 * (f0 + f1),
                  1e-10 * std::abs(f1 - f0) + 4e-16 * std::max(std::abs(f0), std::abs(f1)) + 1e-18);
      EXPECT_EQ(mid.d_dy[ch], (f1 - f0) / gy.step);
      EXPECT_EQ(mid.d_dxi[ch], 0.0);
      const LutValue v = t.evalChannel(ch, gy.at(iy) + 0.5 * gy.step, 0.0);
      EXPECT_EQ(v.dyy, 0.0);
    }
  }
}

TEST(TableInterpolation, LutCubicIsUnchangedAndDiffers) {
  // The cubic LUT is the bicubic Hermite of the stored node data (value and slopes), C1.
  const LutTable& c = rbtest::coneLut();
  const LutTable& l = linearConeLut();
  const GridSpec& gy = c.yGrid();
  const std::size_t iy = c.ny() / 2 + 4;
  LutSample pc, pl;
  c.eval(gy.at(iy) + 0.5 * gy.step, 0.5e-3, pc);
  l.eval(gy.at(iy) + 0.5 * gy.step, 0.5e-3, pl);
  const std::size_t sr = lutChannel(Side::Left, TreadQuantity::Sr);
  EXPECT_NE(pc.value[sr], pl.value[sr]);
  EXPECT_NEAR(pc.value[sr], pl.value[sr], 1e-6);
  // C1 across a y node line (cubic) against the kink of the linear table.
  LutSample a, b;
  const double y = gy.at(iy);
  c.eval(y - 1e-9, 0.5e-3, a);
  c.eval(y + 1e-9, 0.5e-3, b);
  EXPECT_NEAR(a.d_dy[sr], b.d_dy[sr], 1e-4 * std::abs(a.d_dy[sr]));
}

// ---- Keys and cache -----------------------------------------------------------------------------

TEST(TableInterpolation, HashAndKeyTellTheInterpolationsApart) {
  const ContactGeometryConfig c = rbtest::coneConfig();
  ContactGeometryConfig explicit_cubic = c;
  explicit_cubic.interpolation = TableInterpolation::Cubic;
  const ContactGeometryConfig l = linearCone();
  EXPECT_EQ(configHash(explicit_cubic), configHash(c));
  EXPECT_NE(configHash(l), configHash(c));
  for (TableKind kind : {TableKind::Lut, TableKind::Kec}) {
    EXPECT_EQ(tableInputKey(explicit_cubic, kind), tableInputKey(c, kind));
    EXPECT_NE(tableInputKey(l, kind), tableInputKey(c, kind));
  }
  EXPECT_EQ(linearConeKec().configHash(), configHash(l));
  EXPECT_EQ(linearConeLut().configHash(), configHash(l));
}

class TempDir {
 public:
  TempDir() {
    std::random_device rd;
    path_ = fs::temp_directory_path() /
            ("railbench_interp_" + hashHex((std::uint64_t{rd()} << 32) ^ rd()));
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string str() const { return path_.string(); }

 private:
  fs::path path_;
};

TEST(TableInterpolation, CacheNeverServesOneInterpolationForTheOther) {
  TempDir dir;
  const DiskTableCache cache(dir.str());
  const ContactGeometryConfig c = rbtest::coneConfig();
  const ContactGeometryConfig l = linearCone();
  EXPECT_NE(cache.kecPath(c), cache.kecPath(l));
  EXPECT_NE(cache.lutPath(c), cache.lutPath(l));
  bool built = false;
  // Cubic first: the linear request must not load it.
  auto kc = cache.kec(c, &built);
  EXPECT_TRUE(built);
  auto kl = cache.kec(l, &built);
  EXPECT_TRUE(built);
  EXPECT_EQ(kl->interpolation(), TableInterpolation::Linear);
  // Linear first for the LUT: the cubic request must not load it.
  auto ll = cache.lut(l, &built);
  EXPECT_TRUE(built);
  auto lc = cache.lut(c, &built);
  EXPECT_TRUE(built);
  EXPECT_EQ(lc->interpolation(), TableInterpolation::Cubic);
  // Each file loads for its own interpolation and evaluates as that one.
  for (const auto& [cfg, mode] :
       {std::pair{c, TableInterpolation::Cubic}, std::pair{l, TableInterpolation::Linear}}) {
    auto k = cache.kec(cfg, &built);
    EXPECT_FALSE(built);
    EXPECT_EQ(k->interpolation(), mode);
    auto t = cache.lut(cfg, &built);
    EXPECT_FALSE(built);
    EXPECT_EQ(t->interpolation(), mode);
    EXPECT_EQ(t->configHash(), configHash(cfg));
  }
  // A file of one interpolation does not load for the other, even under the other's name.
  EXPECT_FALSE(loadKec(cache.kecPath(c), l).has_value());
  EXPECT_FALSE(loadKec(cache.kecPath(l), c).has_value());
  EXPECT_FALSE(loadLut(cache.lutPath(c), l).has_value());
  EXPECT_FALSE(loadLut(cache.lutPath(l), c).has_value());
  fs::copy_file(cache.kecPath(c), cache.kecPath(l), fs::copy_options::overwrite_existing);
  auto again = cache.kec(l, &built);
  EXPECT_TRUE(built);
  EXPECT_EQ(again->interpolation(), TableInterpolation::Linear);
  // Loaded tables evaluate bit-identically to the built ones.
  const double s = 0.3e-3 + 0.37 * kl->grid().step;
  KecPoint a, b;
  kl->eval(Side::Left, s, a);
  again->eval(Side::Left, s, b);
  for (std::size_t q = 0; q < kQ; ++q) {
    EXPECT_EQ(a.value[q], b.value[q]);
    EXPECT_EQ(a.d_ds[q], b.d_ds[q]);
  }
}

}  // namespace
