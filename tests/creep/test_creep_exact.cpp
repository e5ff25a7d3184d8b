// The creep laws against Kalker's exact theory on the patches of the Manchester contact benchmark
// A-2.2 (CONTACT's results, tests/data/contact_benchmark/mbench_a22_tangential_reference.csv):
// combined creepage and spin as CONTACT computed them for S1002 on UIC60 1:40 at wheelset shifts
// 0-10 mm, tread, flange root and flank, a/b up to 20. Each law gets CONTACT's normal force,
// creepages and spin on the ellipse of CONTACT's patch extents (2a = len_x, 2b = len_s of
// mbench_a22_contact_reference.csv) and is compared on |F| / (mu N) and the force's direction.
// docs/creep.md, "Against Kalker's exact theory on the patches", prints the table.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "fixtures.hpp"
#include "workbench/creep/fastsim.hpp"
#include "workbench/creep/polach.hpp"
#include "workbench/creep/shen_hedrick_elkins.hpp"

namespace {

using rb::creep::ContactPatch;
using rb::creep::Creepages;
using rb::creep::CreepParams;

constexpr double kMu = 0.3;  // CONTACT's FSTAT = FKIN
constexpr double kG = 82e9;  // CONTACT's GG [Pa]
constexpr double kNu = 0.28;

struct Row {
  std::string wheel;
  int case_no = 0;
  double fn = 0, sx = 0, sy = 0, phi = 0, fx_ratio = 0, fs_ratio = 0;
  int nadh = 0;
  double len_x = 0, len_s = 0;  // [mm] CONTACT's patch extents
};

std::vector<std::vector<std::string>> csvRows(const std::string& rel) {
  std::ifstream in(std::string(RB_SOURCE_DIR) + "/" + rel);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  bool header = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      header = true;
      continue;
    }
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

std::vector<Row> referenceRows() {
  std::map<std::pair<std::string, int>, std::pair<double, double>> extents;
  for (const auto& c : csvRows("tests/data/contact_benchmark/mbench_a22_contact_reference.csv")) {
    extents[{c[0], std::stoi(c[1])}] = {std::stod(c[14]), std::stod(c[15])};
  }
  std::vector<Row> rows;
  for (const auto& c :
       csvRows("tests/data/contact_benchmark/mbench_a22_tangential_reference.csv")) {
    Row r;
    r.wheel = c[0];
    r.case_no = std::stoi(c[1]);
    r.fn = std::stod(c[2]);
    // CONTACT's creepages of the wheel over the rail, in its patch frame; its forces oppose them
    // as ours do (tested below on the linear rows), CPHI in 1/mm.
    r.sx = std::stod(c[6]);
    r.sy = std::stod(c[7]);
    r.phi = std::stod(c[8]) * 1e3;
    r.fx_ratio = std::stod(c[10]);
    r.fs_ratio = std::stod(c[11]);
    r.nadh = std::stoi(c[13]);
    const auto e = extents.at({r.wheel, r.case_no});
    r.len_x = e.first;
    r.len_s = e.second;
    rows.push_back(r);
  }
  return rows;
}

// Conformal positions (case 1 on both wheels, the right wheel's cases 2 and 3): CONTACT's patch is
// 14-16 mm wide and not an ellipse, so no Hertz patch stands for it
// (tests/contact/test_elastic_search.cpp classifies them the same way).
bool conformal(const Row& r) {
  return r.case_no == 1 || (r.wheel == "right" && (r.case_no == 2 || r.case_no == 3));
}

ContactPatch patchOf(const Row& r) {
  return rb::test::ellipse(0.5e-3 * r.len_x, 0.5e-3 * r.len_s, r.fn, kNu);
}

CreepParams params() {
  CreepParams p;
  p.mu = kMu;
  p.G = kG;
  return p;
}

struct Law {
  const char* name;
  std::pair<double, double> (*force)(const ContactPatch&, const Creepages&);
};

std::pair<double, double> polach(const ContactPatch& patch, const Creepages& s) {
  const auto f = rb::creep::polachForce(params(), patch, s);
  return {f.fx, f.fy};
}
std::pair<double, double> fastsimParabolic(const ContactPatch& patch, const Creepages& s) {
  const auto f = rb::creep::fastsimForce(params(), patch, s);
  return {f.fx, f.fy};
}
std::pair<double, double> fastsimElliptic(const ContactPatch& patch, const Creepages& s) {
  rb::creep::FastsimGrid grid;
  grid.bound = rb::creep::FastsimBound::Elliptic;
  const auto f = rb::creep::fastsimForce(params(), patch, s, grid);
  return {f.fx, f.fy};
}
std::pair<double, double> she(const ContactPatch& patch, const Creepages& s) {
  const auto f = rb::creep::shenHedrickElkinsForce(params(), patch, s);
  return {f.fx, f.fy};
}

const Law kLaws[] = {{"polach", polach},
                     {"fastsim", fastsimParabolic},
                     {"fastsim_elliptic", fastsimElliptic},
                     {"shen_hedrick_elkins", she}};

struct Compared {
  double ratio = 0;  // |F| / (mu N)
  double angle = 0;  // [deg] direction against CONTACT's
};

Compared compare(const Law& law, const Row& r) {
  Creepages s;
  s.sx = r.sx;
  s.sy = r.sy;
  s.phi = r.phi;
  s.v = 2.0;
  const auto [fx, fy] = law.force(patchOf(r), s);
  Compared c;
  c.ratio = std::hypot(fx, fy) / (kMu * r.fn);
  double d = std::atan2(fy, fx) - std::atan2(r.fs_ratio, r.fx_ratio);
  d = std::remainder(d, 2.0 * std::numbers::pi);
  c.angle = d * 180.0 / std::numbers::pi;
  return c;
}

// A patch the exact theory saturates: no adhesion left and |F| >= 0.99 mu N.
bool saturated(const Row& r) {
  return r.nadh == 0 && std::hypot(r.fx_ratio, r.fs_ratio) >= 0.99;
}

// How far the creepage alone takes the patch past the simplified theory's full sliding: the
// linear force of the creepage over 3 mu N (Johnson-Vermeulen: full sliding at 1).
double linearOverFullSliding(const Row& r) {
  const ContactPatch p = patchOf(r);
  const double c2 = p.a * p.b;
  const double fl = kG * c2 * std::hypot(p.c11 * r.sx, p.c22 * r.sy);
  return fl / (3.0 * kMu * r.fn);
}

void writeTable(const std::vector<Row>& rows) {
  const std::string path = std::string(RB_BINARY_DIR) + "/creep_exact_mbench_a22.md";
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) return;
  std::fprintf(
      f,
      "| wheel | case | a/b | phi a / s | lin / 3 mu N | exact | polach | fastsim | "
      "fastsim elliptic | shen_hedrick_elkins |\n|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Row& r : rows) {
    const ContactPatch p = patchOf(r);
    std::fprintf(f, "| %s | %d%s | %.2f | %+.2f | %.2f | %.3f |", r.wheel.c_str(), r.case_no,
                 conformal(r) ? " (conformal)" : "", p.a / p.b,
                 r.phi * p.a / std::hypot(r.sx, r.sy), linearOverFullSliding(r),
                 std::hypot(r.fx_ratio, r.fs_ratio));
    for (const Law& law : kLaws) {
      const Compared c = compare(law, r);
      std::fprintf(f, " %.3f (%+.1f deg) |", c.ratio, c.angle);
    }
    std::fprintf(f, "\n");
  }
  std::fclose(f);
}

TEST(CreepExact, ReferenceConventions) {
  const std::vector<Row> rows = referenceRows();
  ASSERT_EQ(rows.size(), 42u);
  // CONTACT's force opposes the creepage as ours does: on every non-conformal patch the force's
  // direction lies within 30 degrees of -(s_x, s_y).
  for (const Row& r : rows) {
    if (conformal(r)) continue;
    const double dot = r.fx_ratio * r.sx + r.fs_ratio * r.sy;
    EXPECT_LT(dot, -0.85 * std::hypot(r.fx_ratio, r.fs_ratio) * std::hypot(r.sx, r.sy))
        << r.wheel << " " << r.case_no;
  }
}

// Saturated patches (tread, flange root and flank of both wheels): the default law carries mu N
// within 2 % along CONTACT's direction within 3 degrees, where the exact theory's creepage is
// past the simplified theory's full sliding by a third (Polach's curve reaches mu N only
// asymptotically: closer to the onset of full sliding it is below, by at most 6 % here).
TEST(CreepExact, SaturatedPatchesCarryMuN) {
  const std::vector<Row> rows = referenceRows();
  writeTable(rows);
  int checked = 0;
  for (const Row& r : rows) {
    if (conformal(r) || !saturated(r)) continue;
    SCOPED_TRACE(r.wheel + " wheel, case " + std::to_string(r.case_no));
    const double exact = std::hypot(r.fx_ratio, r.fs_ratio);
    const Compared p = compare(kLaws[0], r);
    EXPECT_LT(std::abs(p.angle), 3.0);
    if (linearOverFullSliding(r) >= 4.0 / 3.0) {
      EXPECT_NEAR(p.ratio, exact, 0.02);
      ++checked;
    } else {
      EXPECT_NEAR(p.ratio, exact, 0.06);
    }
    EXPECT_LE(p.ratio, 1.0 + 1e-12);
    // FASTSIM saturates too (its elliptic bound later, 0.960 at left case 3); on the flank its
    // force turns 3.2-3.7 degrees from CONTACT's (the simplified theory's spin coupling).
    for (const Law* law : {&kLaws[1], &kLaws[2]}) {
      const Compared c = compare(*law, r);
      EXPECT_NEAR(c.ratio, exact, linearOverFullSliding(r) >= 4.0 / 3.0 ? 0.02 : 0.04) << law->name;
      EXPECT_LT(std::abs(c.angle), 4.0) << law->name;
    }
  }
  EXPECT_GE(checked, 25);  // the flange's patches among them
}

// The flange (the right wheel from 5 mm on, a/b 4-20, spin of the sign of s_y, phi a / s 0.2-0.35):
// Polach's own divisor s_C lost 14-24 % of mu N there; each patch is now within 2 % of CONTACT
// (case 11, where spin keeps CONTACT's sliding patch at 0.985 mu N, 1.5 % above; the others within
// 0.3 %).
TEST(CreepExact, FlangePatchesWithSpin) {
  int n = 0;
  for (const Row& r : referenceRows()) {
    if (r.wheel != "right" || r.case_no < 11) continue;
    SCOPED_TRACE("case " + std::to_string(r.case_no));
    const Compared p = compare(kLaws[0], r);
    EXPECT_NEAR(p.ratio, std::hypot(r.fx_ratio, r.fs_ratio), r.case_no == 11 ? 0.02 : 0.005);
    ++n;
  }
  EXPECT_EQ(n, 11);
}

// CONTACT's spin example (tests/data/creep/contact_fastsim_example.txt: a = 8 mm, b = 4 mm,
// FN = 82 kN, mu = 0.3, s_y = 6.25e-4 and phi = -0.625 1/m in our frame, phi a / s_y = 8, in the
// transition): the exact theory's F_y = 1.494e4 N (0.607 mu N). Polach gives 0.590 mu N (-2.8 %;
// with Polach's own divisor s_C and unweighted F_yS it gave 0.648, +6.6 %).
TEST(CreepExact, SpinExampleInTheTransition) {
  const ContactPatch c = rb::test::ellipse(8e-3, 4e-3, 8.2e4);
  const auto f = rb::creep::polachForce(params(), c, {0.0, 6.25e-4, -0.625, 2.0});
  const double exact = 1.494e4;
  std::printf("Polach on CONTACT's spin example: F_y %.4f mu N against %.4f exact (%+.1f %%)\n",
              f.fy / (kMu * c.Q), exact / (kMu * c.Q), 100.0 * (f.fy - exact) / exact);
  EXPECT_NEAR(f.fy / exact, 1.0, 0.05);
  EXPECT_NEAR(f.fx, 0.0, 1e-9 * exact);
}

}  // namespace
