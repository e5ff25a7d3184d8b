// CONTACT's rail slices-files (profiles/slice_list.hpp) and plain-text slices drawn as CONTACT
// draws profiles (metres, z down): the crossing nose of CONTACT's S&C cases
// (tests/data/contact_sc/cross_nose.slcs, Apache-2.0), and malformed files, each refused at its
// line.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include "workbench/core/error.hpp"
#include "workbench/profiles/profile_io.hpp"
#include "workbench/profiles/slice_list.hpp"

namespace {

using namespace rb::profiles;

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "rb_slice_list_" + name;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  EXPECT_NE(f, nullptr);
  std::fwrite(text.data(), 1, text.size(), f);
  std::fclose(f);
  return path;
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const rb::InputError& e) {
    return e.diagnostics().front().loc.str() + ": " + e.diagnostics().front().message;
  }
  return "no error";
}

TEST(SliceList, ReadsContactsCrossingNose) {
  const SliceList l =
      readSliceList(std::string(RB_SOURCE_DIR) + "/tests/data/contact_sc/cross_nose.slcs");
  ASSERT_EQ(l.slices.size(), 21U);
  // U_OFFSET 0, U_SCALE 1 mm/usr: u from -100 to 100 mm in steps of 10.
  for (std::size_t k = 0; k < l.slices.size(); ++k) {
    EXPECT_NEAR(l.slices[k].u_fc, -0.1 + 0.01 * static_cast<double>(k), 1e-15);
    EXPECT_EQ(l.slices[k].file, "cross_nose/nose_" + std::to_string(k + 1) + ".prr");
  }
  EXPECT_EQ(l.slices.front().line, 12);
  EXPECT_EQ(l.features, 5);
  EXPECT_EQ(l.kinks, 0);
  EXPECT_EQ(l.interpolation, 1);
}

TEST(SliceList, ScaleOffsetAndFortranNumbers) {
  const std::string path = writeTemp("scaled.slcs",
                                     "% header\n\n"
                                     "  2.0  1.0d3   U_OFFSET, U_SCALE: usr = m\n"
                                     "  2   % NSLC\n"
                                     "  0 0 0\n"
                                     "  2  0   U_INTPOL, PERTURB\n"
                                     " -0.5  'a b.txt'\n"
                                     "  1.25 \"c%d.prr\"  % a trailing comment\n");
  const SliceList l = readSliceList(path);
  ASSERT_EQ(l.slices.size(), 2U);
  EXPECT_DOUBLE_EQ(l.slices[0].u_fc, 1.5);  // 1000 mm/m * (2 - 0.5) m in m
  EXPECT_DOUBLE_EQ(l.slices[1].u_fc, 3.25);
  EXPECT_EQ(l.slices[0].file, "a b.txt");
  EXPECT_EQ(l.slices[1].file, "c%d.prr");
  EXPECT_EQ(l.slices[1].line, 8);
  EXPECT_EQ(l.interpolation, 2);
}

TEST(SliceList, MalformedFilesAreRefusedAtTheirLine) {
  const std::string head = "0 1\n2\n0 0 0\n1\n";
  const auto at = [&](const std::string& name, const std::string& text) {
    return errorOf([&] { (void)readSliceList(writeTemp(name, text)); });
  };
  EXPECT_NE(at("short.slcs", "0 1\n").find("short.slcs:1: the slices-file ends before NSLC"),
            std::string::npos);
  EXPECT_NE(at("scale.slcs", "0 -1\n").find("scale.slcs:1: U_SCALE must be > 0"),
            std::string::npos);
  EXPECT_NE(at("nslc.slcs", "0 1\n2.5\n")
                .find("nslc.slcs:2: NSLC must be a whole number in [1, "
                      "2000], got 2.5"),
            std::string::npos);
  EXPECT_NE(at("many.slcs", "0 1\n1e9\n").find("many.slcs:2: NSLC must be a whole number"),
            std::string::npos);
  EXPECT_NE(at("feat.slcs", "0 1\n2\nx\n").find("feat.slcs:3: expected NFEAT NKINK NACCEL"),
            std::string::npos);
  EXPECT_NE(at("perturb.slcs", "0 1\n2\n0 0 0\n1 1\n")
                .find("perturb.slcs:4: PERTURB = 1: surface perturbations"),
            std::string::npos);
  EXPECT_NE(at("name.slcs", head + "0 a.prr\n")
                .find("name.slcs:5: slice 1 of 2 must be: U_SLC "
                      "'profile file'"),
            std::string::npos);
  EXPECT_NE(at("empty.slcs", head + "0 ''\n").find("empty.slcs:5: slice 1 of 2"),
            std::string::npos);
  EXPECT_NE(at("order.slcs", head + "1 'a.prr'\n1.0000001 'b.prr'\n")
                .find("order.slcs:6: slice 2: U_SLC = 1 is not at least 0.001 mm after"),
            std::string::npos);
  EXPECT_NE(at("fewer.slcs", head + "1 'a.prr'\n")
                .find("fewer.slcs:5: the slices-file ends "
                      "before its NSLC slices"),
            std::string::npos);
  EXPECT_NE(at("nan.slcs", "nan 1\n").find("nan.slcs:1: expected U_OFFSET U_SCALE"),
            std::string::npos);
  EXPECT_NE(errorOf([] {
              (void)readSliceList("/nonexistent/x.slcs");
            }).find("cannot read the slices-file"),
            std::string::npos);
}

// A rail head drawn in metres with z down (CONTACT's canonical form) is, read with metres and
// mirrorZ, the same profile as drawn in millimetres with z up.
TEST(SliceList, MetresWithZDownAreTheProfileInMillimetresUp) {
  std::string m, mm;
  for (int i = 0; i <= 60; ++i) {
    const double y = -30.0 + i;                  // [mm]
    const double z = -0.004 * y * y - 0.02 * y;  // [mm], up: a head crowned about y = -2.5 mm
    char line[96];
    std::snprintf(line, sizeof line, "%.9f %.9f\n", y * 1e-3, -z * 1e-3);
    m += line;
    std::snprintf(line, sizeof line, "%.6f %.6f\n", y, z);
    mm += line;
  }
  ProfileReadOptions down;
  down.mirrorZ = true;
  const Profile a =
      readProfileFile(writeTemp("m_down.txt", m), ProfileKind::Rail, LengthUnit::Metre, down);
  const Profile b = readProfileFile(writeTemp("mm_up.txt", mm), ProfileKind::Rail,
                                    LengthUnit::Millimetre, ProfileReadOptions{});
  ASSERT_EQ(a.sMin(), b.sMin());
  ASSERT_EQ(a.sMax(), b.sMax());
  for (double s = a.sMin(); s <= a.sMax(); s += 1e-3) EXPECT_NEAR(a.at(s).h, b.at(s).h, 1e-12);
  // Read without mirrorZ the head would point down.
  const Profile c = readProfileFile(writeTemp("m_down2.txt", m), ProfileKind::Rail,
                                    LengthUnit::Metre, ProfileReadOptions{});
  EXPECT_NEAR(c.at(-2.5e-3).h, -b.at(-2.5e-3).h, 1e-12);
}

}  // namespace
