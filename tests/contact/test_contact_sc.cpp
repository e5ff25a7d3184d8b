// The switch-and-crossing test cases of CONTACT (tests/data/contact_sc/README.md): a crossing nose
// rising at 1:10, a wing rail moving sideways at 1:10, and a nose with a wing rail, each under the
// right wheel of the Manchester benchmark (S1002, r0 = 460 mm), against CONTACT's results. The
// rails are built as a scenario builds them (sliced_rail.hpp: slices with offsets, or one profile
// file per slice) and searched as the dynamics search them (rail_slope.hpp: the rail's slope along
// the track in the search). docs/sliced_rails.md, "Validation: CONTACT's S&C cases".
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "workbench/contact/elastic_normal.hpp"
#include "workbench/contact/rail_slope.hpp"
#include "workbench/contact/sliced_rail.hpp"
#include "workbench/profiles/profile_io.hpp"
#include "workbench/profiles/slice_list.hpp"

namespace {

using namespace rb::contact;
using rb::profiles::Profile;

std::string dataFile(const std::string& name) {
  return std::string(RB_SOURCE_DIR) + "/tests/data/contact_sc/" + name;
}

// Rows of a CSV file (comment lines start with #; the first other line is the header).
std::vector<std::map<std::string, std::string>> csv(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::map<std::string, std::string>> rows;
  std::vector<std::string> head;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string c;
    while (std::getline(ss, c, ',')) cells.push_back(c);
    if (head.empty()) {
      head = cells;
      continue;
    }
    std::map<std::string, std::string> r;
    for (std::size_t i = 0; i < head.size() && i < cells.size(); ++i) r[head[i]] = cells[i];
    rows.push_back(r);
  }
  return rows;
}

double num(const std::map<std::string, std::string>& r, const std::string& key) {
  return std::stod(r.at(key));
}

// CONTACT's set-up (README): the right wheel, its profile origin 750 mm from the track centre
// (flange back distance 1360 mm, flange back at -70 mm), the rail profile origin at RAILY0 =
// 750 mm, no cant. Our profiles are drawn as left ones and mirrored for the right side.
WheelRailPair rightPair() {
  rb::profiles::ProfileReadOptions wo;
  wo.r0 = 0.46;
  WheelRailPair p;
  p.side = Side::Right;
  p.wheel = std::make_shared<const Profile>(
      rb::profiles::readSimpackProfile(std::string(RB_SOURCE_DIR) + "/profiles/MBench_S1002_v3.prw",
                                       wo)
          .mirrored());
  p.wheel_lw = 0.750;
  p.rail_lr = 0.750;
  p.beta = 0.0;
  return p;
}

// The rail of one part of one case: its slices (slices.csv), the slice files read as rail profiles
// in mm and mirrored to the right side.
std::shared_ptr<const SlicedRailSearch> rail(const std::string& cas, const std::string& part) {
  std::map<std::string, std::shared_ptr<const Profile>> files;
  std::vector<RailSlice> slices;
  for (const auto& r : csv(dataFile("slices.csv"))) {
    if (r.at("case") != cas || r.at("part") != part) continue;
    const std::string f = r.at("file");
    if (!files.count(f)) {
      files[f] = std::make_shared<const Profile>(
          rb::profiles::readTextProfile(dataFile(f), rb::profiles::ProfileKind::Rail,
                                        rb::profiles::LengthUnit::Millimetre)
              .mirrored());
    }
    slices.push_back(
        RailSlice{num(r, "u_mm") * 1e-3, files[f], num(r, "dy_mm") * 1e-3, num(r, "dz_mm") * 1e-3});
  }
  return std::make_shared<const SlicedRailSearch>(rightPair(), slices, ElasticSearchSpec{});
}

struct Ours {
  int patches = 0;
  double N = 0.0, z = 0.0;
  // The deepest patch, track frame (CONTACT's axes: x forward, y toward the field side, z down).
  double x = 0.0, y_r = 0.0, z_r = 0.0, gamma = 0.0, approach = 0.0, a = 0.0, b = 0.0, p0 = 0.0;
};

// The wheel over its rails at track position s and axle height z (Y_WS = 0, no roll, no yaw), as
// the dynamics search it (contact_elastic.hpp, searchRail): the pose relative to each rail's
// displaced profile origin, the rail's slope along the track in the search unless `flat`.
Ours contactAt(const std::vector<std::shared_ptr<const SlicedRailSearch>>& rails, double s,
               double z, bool flat) {
  Ours o;
  o.z = z;
  double deepest = -1.0;
  for (const auto& r : rails) {
    const SlicedRailSearch::Place at = r->at(s);
    if (!at.search) continue;
    const double sigma = at.search->sigma();
    ElasticPose pose{-sigma * at.dy, z - at.dz, 0.0, 0.0};
    pose.blend = at.blend;
    const RailSlope slope = flat ? RailSlope{} : RailSlope{sigma * at.dy_ds, at.dz_ds, at.blend_ds};
    ElasticWheelGeometry g;
    ElasticSearchWorkspace w1;
    SlopedSearchWorkspace w2;
    searchSlopedRail(*at.search, pose, slope, g, w1, w2);
    for (int k = 0; k < g.count; ++k) {
      const ElasticPatchGeometry& p = g.patch[static_cast<std::size_t>(k)];
      const ElasticPatchNormal n = elasticNormal(p, ElasticNormalSpec{});
      o.N += n.N;
      ++o.patches;
      if (p.approach <= deepest) continue;
      deepest = p.approach;
      o.x = p.x;
      // The right rail: CONTACT's YCP(R) = -s_r of our mirrored profile, plus the rail's shift.
      o.y_r = -p.s_r + at.dy;
      o.z_r = -(p.z + at.dz);
      o.gamma = -p.gamma;  // CONTACT's DELTCP of a right wheel
      o.approach = p.gap_depth;
      o.a = n.a;
      o.b = n.b;
      o.p0 = n.p0;
    }
  }
  return o;
}

// The axle height at which the wheel carries CONTACT's normal force FN (bisection).
Ours solveForN(const std::vector<std::shared_ptr<const SlicedRailSearch>>& rails, double s,
               double fn, bool flat) {
  double lo = 0.43, hi = 0.49;
  for (int i = 0; i < 100; ++i) {
    const double z = 0.5 * (lo + hi);
    (contactAt(rails, s, z, flat).N > fn ? lo : hi) = z;
  }
  return contactAt(rails, s, 0.5 * (lo + hi), flat);
}

struct Case {
  std::string name;  // row of contact_sc_reference.csv
  std::vector<std::pair<std::string, std::string>> rails;
};

// Each wheel at CONTACT's normal force FN (CONTACT prescribes the wheel's height; FN is its
// result), compared with CONTACT's patch (table in build/elastic_contact_sc.md, copied to
// docs/sliced_rails.md). Asserted: one patch; the contact point along the track within 0.3 mm (it
// is 45.8 mm ahead of the axle on the rising nose), across within 0.5 mm, its height within
// 0.05 mm; the approach within 10 %; and the wheel's height, CONTACT's input, within 0.01 mm.
// Not asserted: the patch's lateral extent and pressure (Hertz's ellipse against CONTACT's
// non-Hertzian patch on a flat-topped head: our 2b is 0.4-0.7 of CONTACT's) and CONTACT's contact
// angle, an average over its patch (the wing rail's point slope is 0.053, its patch's 0.077).
TEST(ContactSC, CrossingNoseWingRailAndBothAgainstContact) {
  const auto refs = csv(dataFile("contact_sc_reference.csv"));
  ASSERT_EQ(refs.size(), 5u);
  const std::vector<Case> cases = {
      {"cross_brute", {{"cross_nose", "nose"}}},
      {"wing_brute", {{"wing_rail", "wing"}}},
      {"cross+wing", {{"cross+wing", "nose"}, {"cross+wing", "wing"}}},
  };
  const std::string path = std::string(RB_BINARY_DIR) + "/elastic_contact_sc.md";
  std::FILE* f = std::fopen(path.c_str(), "w");
  ASSERT_TRUE(f);
  std::fprintf(
      f,
      "| case | S [mm] | FN [kN] | patches ours / ref | x ours / ref [mm] | y_r ours / ref "
      "[mm] | z_r ours / ref [mm] | gamma ours / ref [rad] | approach ours / ref [um] | "
      "wheel height ours / ref [mm] | 2a ours / ref [mm] | 2b ours / ref [mm] | p0 ours / "
      "ref [MPa] | without the slope: x [mm], wheel height [mm] |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const auto* ref = [&]() -> const std::map<std::string, std::string>* {
      for (const auto& r : refs)
        if (r.at("case") == c.name) return &r;
      return nullptr;
    }();
    ASSERT_TRUE(ref);
    std::vector<std::shared_ptr<const SlicedRailSearch>> rails;
    for (const auto& [cas, part] : c.rails) rails.push_back(rail(cas, part));
    const double s = num(*ref, "s_ws_mm") * 1e-3;
    const double fn = num(*ref, "fn_N");
    const Ours o = solveForN(rails, s, fn, false);
    const Ours flat = solveForN(rails, s, fn, true);
    // CONTACT's Z_WS is the height of the wheel's profile origin (the tape circle's lowest point)
    // above the track, downward: ours is z - r0.
    const double z_ws = -(o.z - 0.46) * 1e3;
    std::fprintf(f,
                 "| %s | %.0f | %.2f | %d / %s | %.2f / %.2f | %.2f / %.2f | %.3f / %.3f | %.4f / "
                 "%.4f | %.1f / %.1f | %.3f / %.3f | %.2f / %.2f | %.2f / %.2f | %.0f / %.0f | "
                 "%.2f, %.3f |\n",
                 c.name.c_str(), s * 1e3, fn * 1e-3, o.patches, ref->at("npatch").c_str(),
                 o.x * 1e3, num(*ref, "xcp_tr_mm"), o.y_r * 1e3, num(*ref, "ycp_r_mm"), o.z_r * 1e3,
                 num(*ref, "zcp_r_mm"), o.gamma, num(*ref, "deltcp_tr_rad"), o.approach * 1e6,
                 num(*ref, "approach_mm") * 1e3, z_ws, num(*ref, "z_ws_mm"), 2e3 * o.a,
                 num(*ref, "len_x_mm"), 2e3 * o.b, num(*ref, "len_s_mm"), o.p0 * 1e-6,
                 num(*ref, "pmax_MPa"), flat.x * 1e3, -(flat.z - 0.46) * 1e3);
    EXPECT_EQ(o.patches, 1);
    EXPECT_NEAR(o.x * 1e3, num(*ref, "xcp_tr_mm"), 0.3);
    EXPECT_NEAR(o.y_r * 1e3, num(*ref, "ycp_r_mm"), 0.5);
    EXPECT_NEAR(o.z_r * 1e3, num(*ref, "zcp_r_mm"), 0.05);
    EXPECT_NEAR(o.approach * 1e3, num(*ref, "approach_mm"), 0.1 * num(*ref, "approach_mm"));
    EXPECT_NEAR(z_ws, num(*ref, "z_ws_mm"), 0.01);
    // Without the slope the nose's rise is missed: the wheel sits r (1 - cos(atan 0.1)) = 2.3 mm
    // too low, its contact under the axle.
    if (c.name == "cross_brute") {
      EXPECT_GT(std::abs(-(flat.z - 0.46) * 1e3 - num(*ref, "z_ws_mm")), 2.0);
      EXPECT_NEAR(flat.x, 0.0, 1e-4);
    }
  }
  std::fclose(f);
}

}  // namespace

namespace {

// ---------------------------------------------------------------------------------------------
// The S&C benchmark's UK crossing (56E1, 1:9.25; profiles/uk_crossing.slcs, tests/data/contact_sc/
// README.md) read through its
// slices-file as a scenario reads it (metres, z down), every slice whole: wing rail, flangeway and
// nose in one profile, kept by max_slope 40 (the gauge face of the wing rail is steeper than 10).

std::shared_ptr<const SlicedRailSearch> ukCrossing(double s_lo, double s_hi) {
  const std::string profiles = std::string(RB_SOURCE_DIR) + "/profiles/";
  const rb::profiles::SliceList list = rb::profiles::readSliceList(profiles + "uk_crossing.slcs");
  rb::profiles::ProfileReadOptions o;
  o.mirrorZ = true;
  o.maxSlope = 40.0;
  std::vector<RailSlice> slices;
  for (const rb::profiles::SliceListEntry& e : list.slices) {
    if (e.u_fc < s_lo || e.u_fc > s_hi) continue;
    slices.push_back(RailSlice{
        e.u_fc,
        std::make_shared<const Profile>(
            rb::profiles::readTextProfile(profiles + e.file, rb::profiles::ProfileKind::Rail,
                                          rb::profiles::LengthUnit::Metre, o)
                .mirrored()),
        0.0, 0.0});
  }
  return std::make_shared<const SlicedRailSearch>(rightPair(), slices, ElasticSearchSpec{});
}

struct UkPatch {
  double N = 0.0, Fz = 0.0, x = 0.0, y_r = 0.0, z_r = 0.0, gamma = 0.0, approach = 0.0, p0 = 0.0;
};

// Every patch of the wheel at CONTACT's lateral position y_ws (to the right, mm) and axle height
// z, with the rail's slope along the track.
std::vector<UkPatch> ukPatches(const SlicedRailSearch& rail, double s, double y_ws, double z) {
  const SlicedRailSearch::Place at = rail.at(s);
  const double sigma = at.search->sigma();
  ElasticPose pose{-y_ws - sigma * at.dy, z - at.dz, 0.0, 0.0};
  pose.blend = at.blend;
  const RailSlope slope{sigma * at.dy_ds, at.dz_ds, at.blend_ds};
  ElasticWheelGeometry g;
  ElasticSearchWorkspace w1;
  SlopedSearchWorkspace w2;
  searchSlopedRail(*at.search, pose, slope, g, w1, w2);
  std::vector<UkPatch> out;
  for (int k = 0; k < g.count; ++k) {
    const ElasticPatchGeometry& p = g.patch[static_cast<std::size_t>(k)];
    const ElasticPatchNormal n = elasticNormal(p, ElasticNormalSpec{});
    out.push_back(UkPatch{n.N, n.N * p.n_z, p.x, -p.s_r + at.dy, -(p.z + at.dz), -p.gamma,
                          p.gap_depth, n.p0});
  }
  return out;
}

// CONTACT's wheel over the S&C benchmark's UK crossing, 239 mm past the slice at u = 0, at FZ =
// 10 kN, moved toward the field side over 0.34 mm (mbench_brute): the load passes from the wing
// rail (its gauge corner, YCP(R) = +38.6 mm, falling away along the track) to the nose (its gauge
// corner, -28.2 mm, rising at about 1:80). Ours: the same wheel at the same Y_WS, its height
// solved for the same normal vertical load (sum of FN cos(DELTCP) of CONTACT's patches: CONTACT's
// FZ includes the tangential forces' share, up to 1.5 % on the nose's 0.31 rad contact angle).
// Table in build/elastic_contact_uk_crossing.md (copied to docs/sliced_rails.md).
//
// Asserted:
// - the rail: our blended surface at each of CONTACT's nose contact points within 0.01 mm of
//   CONTACT's height there; at the wing rail's points it is lower by up to 0.06 mm (our slices
//   blend at a fixed lateral coordinate, and the wing's gauge corner moves 2.1 mm sideways between
//   the two slices around the wheel; CONTACT's spline surface keeps the corner's shape);
// - the contacts: where both have a patch on a head, ours within 1.1 mm (wing) and 0.2 mm (nose)
//   of CONTACT's across the rail and within 0.05 mm in height;
//   the nose's contact ahead of the axle (the nose rises) and the wing's behind it (it falls), each
//   searched with its own slope (with the deeper patch's slope for both, the nose's would sit
//   behind the axle);
// - the transfer: the nose's share rises monotonically from 0 to 1 over the sweep in both, and
//   the wheelset position at which the nose carries half the load is within 0.15 mm of CONTACT's
//   (ours is earlier: the wing rail's corner is lower in our blend);
// - the wheel's height within 0.02 mm.
TEST(ContactSC, UkCrossingWingToNoseTransferAgainstContact) {
  const auto rows = csv(dataFile("uk_crossing_reference.csv"));
  ASSERT_EQ(rows.size(), 61u);
  const auto rail = ukCrossing(0.0, 0.5);
  std::map<int, std::vector<std::map<std::string, std::string>>> cases;
  for (const auto& r : rows) cases[std::stoi(r.at("icase"))].push_back(r);
  ASSERT_EQ(cases.size(), 35u);
  const std::string path = std::string(RB_BINARY_DIR) + "/elastic_contact_uk_crossing.md";
  std::FILE* f = std::fopen(path.c_str(), "w");
  ASSERT_TRUE(f);
  std::fprintf(f,
               "| Y_WS [mm] | nose share ours / ref | FN wing ours / ref [kN] | FN nose ours / ref "
               "[kN] | wheel height ours / ref [mm] | x wing ours / ref [mm] | x nose ours / ref "
               "[mm] | y_r nose ours / ref [mm] |\n|---|---|---|---|---|---|---|---|\n");
  std::vector<double> ys, ours_share, ref_share;
  double worst_wing_height = 0.0;
  for (const auto& [icase, ref] : cases) {
    SCOPED_TRACE("case " + std::to_string(icase));
    const double s = num(ref[0], "s_ws_mm") * 1e-3;
    const double y = num(ref[0], "y_ws_mm") * 1e-3;
    double target = 0.0, ref_wing = 0.0, ref_nose = 0.0;
    const std::map<std::string, std::string>*ref_w = nullptr, *ref_n = nullptr;
    for (const auto& r : ref) {
      target += num(r, "fn_N") * std::cos(num(r, "deltcp_tr_rad"));
      const bool nose = num(r, "ycp_r_mm") < 0.0;
      (nose ? ref_nose : ref_wing) += num(r, "fn_N");
      (nose ? ref_n : ref_w) = &r;
      // The rail at CONTACT's contact point, as our slices blend it there.
      const SlicedRailSearch::Place at = rail->at(s + num(r, "xcp_tr_mm") * 1e-3);
      const double h = at.search->railAt(-num(r, "ycp_r_mm") * 1e-3, at.blend).h;
      const double dz = -h * 1e3 - num(r, "zcp_r_mm");  // > 0: ours lower
      if (nose) {
        EXPECT_NEAR(dz, 0.0, 0.01);
      } else {
        EXPECT_GT(dz, -0.01);
        EXPECT_LT(dz, 0.06);
        worst_wing_height = std::max(worst_wing_height, dz);
      }
    }
    double lo = 0.44, hi = 0.47;
    for (int i = 0; i < 60; ++i) {
      const double z = 0.5 * (lo + hi);
      double fz = 0.0;
      for (const UkPatch& p : ukPatches(*rail, s, y, z)) fz += p.Fz;
      (fz > target ? lo : hi) = z;
    }
    const double z = 0.5 * (lo + hi);
    const auto ours = ukPatches(*rail, s, y, z);
    double wing = 0.0, nose = 0.0;
    const UkPatch *w = nullptr, *n = nullptr;
    for (const UkPatch& p : ours) {
      (p.y_r < 0.0 ? nose : wing) += p.N;
      (p.y_r < 0.0 ? n : w) = &p;
    }
    const double z_ws = -(z - 0.46) * 1e3;
    EXPECT_NEAR(z_ws, num(ref[0], "z_ws_mm"), 0.02);
    // Where both have a patch on a head, the two agree in place.
    if (ref_w && w) {
      EXPECT_NEAR(w->y_r * 1e3, num(*ref_w, "ycp_r_mm"), 1.1);
      EXPECT_NEAR(w->z_r * 1e3, num(*ref_w, "zcp_r_mm"), 0.05);
      EXPECT_LT(w->x, 0.0);
    }
    if (ref_n && n) {
      EXPECT_NEAR(n->y_r * 1e3, num(*ref_n, "ycp_r_mm"), 0.2);
      EXPECT_NEAR(n->z_r * 1e3, num(*ref_n, "zcp_r_mm"), 0.05);
      EXPECT_GT(n->x, 0.0);
    }
    ys.push_back(y);
    ours_share.push_back(nose / (wing + nose));
    ref_share.push_back(ref_nose / (ref_wing + ref_nose));
    auto cell = [](const UkPatch* p, double v) { return p ? v : 0.0; };
    std::fprintf(f,
                 "| %.2f | %.2f / %.2f | %.2f / %.2f | %.2f / %.2f | %.4f / %.4f | %s / %s | %s / "
                 "%s | %s / %s |\n",
                 y * 1e3, ours_share.back(), ref_share.back(), wing * 1e-3, ref_wing * 1e-3,
                 nose * 1e-3, ref_nose * 1e-3, z_ws, num(ref[0], "z_ws_mm"),
                 w ? std::to_string(cell(w, w->x * 1e3)).substr(0, 5).c_str() : "-",
                 ref_w ? ref_w->at("xcp_tr_mm").c_str() : "-",
                 n ? std::to_string(cell(n, n->x * 1e3)).substr(0, 5).c_str() : "-",
                 ref_n ? ref_n->at("xcp_tr_mm").c_str() : "-",
                 n ? std::to_string(cell(n, n->y_r * 1e3)).substr(0, 6).c_str() : "-",
                 ref_n ? ref_n->at("ycp_r_mm").c_str() : "-");
  }
  // The nose's share: monotonic from 0 to 1 in both, its half-load position within 0.15 mm.
  auto half = [&](const std::vector<double>& share) {
    for (std::size_t k = 1; k < share.size(); ++k) {
      EXPECT_GE(share[k], share[k - 1] - 1e-9);
      if (share[k - 1] < 0.5 && share[k] >= 0.5)
        return ys[k - 1] + (0.5 - share[k - 1]) / (share[k] - share[k - 1]) * (ys[k] - ys[k - 1]);
    }
    return -1.0;
  };
  EXPECT_LT(ours_share.front(), 0.5);
  EXPECT_GT(ours_share.back(), 0.999);
  EXPECT_EQ(ref_share.front(), 0.0);
  const double y_ours = half(ours_share), y_ref = half(ref_share);
  EXPECT_NEAR(y_ours, y_ref, 0.15e-3);
  std::fprintf(f,
               "\nThe nose carries half the load at Y_WS = %.3f mm (ours) and %.3f mm (CONTACT); "
               "our wing rail's corner lies up to %.3f mm below CONTACT's surface at CONTACT's "
               "contact points.\n",
               y_ours * 1e3, y_ref * 1e3, worst_wing_height);
  std::fclose(f);
}

}  // namespace
