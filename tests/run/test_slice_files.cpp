// A rail read from a CONTACT slices-file (profiles.rail_slices / extra_rails { slcs = ... },
// docs/sliced_rails.md): the crossing nose of CONTACT's S&C cases (21 SIMPACK slices rising 1:10,
// tests/data/contact_sc/cross_nose.slcs) as a further rail. Read from the slices-file it is the
// rail of the same files listed slice by slice, bit for bit; its slices are the nose rising 1:10;
// the features the slices-file defines (and railbench does not use) are a warning.
#include <gtest/gtest.h>

#include <string>

#include "tests/run/run_files.hpp"
#include "workbench/run/compile.hpp"

namespace {

const rb::contact::SlicedRailSearch& nose(const rb::run::Model& m) {
  return *m.lead().contact->elastic->extra[1].at(0);
}

TEST(SliceFiles, ASlicesFileIsItsSlicesListedOneByOne) {
  const rb::run::Model a = rb::test::compiled("tests/data/contact_sc/nose_slcs.lua", {});
  const rb::run::Model b = rb::test::compiled("tests/data/contact_sc/nose_list.lua", {});
  const auto& sa = nose(a).slices();
  const auto& sb = nose(b).slices();
  ASSERT_EQ(sa.size(), 21U);
  ASSERT_EQ(sa.size(), sb.size());
  for (std::size_t k = 0; k < sa.size(); ++k) {
    EXPECT_NEAR(sa[k].s, sb[k].s, 1e-12);  // 50 + u/1000 here, 50 + (u/1000) there
    EXPECT_EQ(sa[k].dy, sb[k].dy);
    EXPECT_EQ(sa[k].dz, -0.05);
    EXPECT_EQ(sa[k].dz, sb[k].dz);
    ASSERT_EQ(sa[k].rail->sMin(), sb[k].rail->sMin());
    ASSERT_EQ(sa[k].rail->sMax(), sb[k].rail->sMax());
    for (double s = sa[k].rail->sMin(); s <= sa[k].rail->sMax(); s += 0.5e-3)
      EXPECT_EQ(sa[k].rail->at(s).h, sb[k].rail->at(s).h);
  }
  // CONTACT's nose rises 1:10 along u: every slice is the middle one (u = 0) raised by u / 10
  // where both have the profile.
  const rb::profiles::Profile& mid = *sa[10].rail;
  for (std::size_t k = 0; k < sa.size(); ++k) {
    const double u = sa[k].s - sa[10].s;
    const rb::profiles::Profile& p = *sa[k].rail;
    const double lo = std::max(p.sMin(), mid.sMin()), hi = std::min(p.sMax(), mid.sMax());
    ASSERT_LT(lo + 5e-3, hi) << k;
    for (double s = lo; s <= hi; s += 0.5e-3)
      EXPECT_NEAR(p.at(s).h - mid.at(s).h, u / 10.0, 1e-7) << "slice " << k + 1 << " at " << s;
  }
  // Its five features are not used: said, with the scenario's line.
  bool warned = false;
  for (const std::string& w : a.lead().contact->warnings)
    warned = warned || (w.find("nose_slcs.lua:9: warning: cross_nose.slcs: its features "
                               "(NFEAT = 5") != std::string::npos);
  EXPECT_TRUE(warned);
}

// The S&C benchmark's UK crossing (profiles/uk_crossing.slcs: 148 slices, wing rail, flangeway
// and nose in one profile) as a scenario reads it: with max_slope = 40 every slice keeps every
// point, so the wheel finds the nose and the wing rail in one profile (the contact itself is
// compared with CONTACT in tests/contact/test_contact_sc.cpp); with the default 10 the cut that
// would keep the nose and drop the wing rail is refused at the slice file's line.
TEST(SliceFiles, TheUkCrossingKeepsBothHeadsWithMaxSlope) {
  const rb::run::Model m = rb::test::compiled("tests/run/data/uk_crossing_through.lua", {});
  const auto& right = m.lead().contact->elastic->sliced[1];
  ASSERT_TRUE(right);
  const auto& sl = right->slices();
  ASSERT_EQ(sl.size(), 148U);
  EXPECT_NEAR(sl.front().s, 80.0 - 75.0, 1e-12);
  EXPECT_NEAR(sl.back().s, 80.0 + 50.0, 1e-12);
  // Slice 70 (u = 0.22871 m): the nose's gauge face (y = -42 mm, 42 mm below the top of the
  // slices' frame, right rail: mirrored) to the wing rail's field-side end (y = 102.6 mm).
  const rb::profiles::Profile& p = *sl[69].rail;
  EXPECT_NEAR(sl[69].s, 80.22871, 1e-9);
  EXPECT_NEAR(p.sMin(), -0.1026, 0.5e-3);
  EXPECT_NEAR(p.sMax(), 0.0420, 0.5e-3);
  EXPECT_NEAR(p.at(28.2e-3).h, -3.42e-3, 0.1e-3);  // the nose's top, 3.4 mm below the frame
  EXPECT_NEAR(p.at(-40.0e-3).h, 1.52e-3, 0.1e-3);  // the wing rail's, 1.5 mm above it
  EXPECT_LT(p.at(0.0).h, -40e-3);                  // the flangeway between them
  std::string without;
  try {
    (void)rb::test::compiled("tests/run/data/uk_crossing_through.lua",
                             {"profiles.rail_slices.right.max_slope=10"});
  } catch (const rb::InputError& e) {
    without = e.what();
  }
  EXPECT_NE(without.find("Crossing_"), std::string::npos) << without;
  EXPECT_NE(without.find("a second rail head or a step would be cut away"), std::string::npos)
      << without;
}

}  // namespace
