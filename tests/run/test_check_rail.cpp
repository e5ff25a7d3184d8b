// A check rail in a sharp curve (tests/run/data/check_rail_common.lua; docs/sliced_rails.md,
// "Check rails"): in the R = 150 m curve without cant the leading wheelsets of the Manchester
// wagon run against the outer rail's flange. A check rail beside the inner rail, meeting the back
// of the inner wheels' flanges (contact/check_rail.hpp), stops them where the flange back
// reaches it, the clearance of the centred wheelset, and takes the guiding force off the outer
// flange: what check rails in sharp curves are laid for. A check rail the wheels never reach
// changes nothing, bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "tests/run/run_files.hpp"
#include "workbench/contact/check_rail.hpp"
#include "workbench/io/result_reader.hpp"
#include "workbench/run/compile.hpp"

namespace {

struct Steady {
  std::vector<double> y, outer_Y, check_N;   // per wheelset, mean over the last second
  std::vector<double> first_contact, start;  // the run's answer [m] (NaN: none), the first s
};

using rb::test::lastSecondMean;

Steady run(const std::string& scene, const std::vector<std::string>& overrides,
           const std::string& name, bool check) {
  const rb::test::RunFile f =
      rb::test::runInto(rb::test::compiled(scene, overrides), "rb_test_check_rail", name + ".h5");
  EXPECT_TRUE(f.result.result.ok) << f.result.result.message;
  const rb::io::ResultReader r(f.path);
  const auto t = *r.dataset("/time");
  Steady s;
  for (const char* ws : {"ws1", "ws2", "ws3", "ws4"}) {
    const std::string w = ws;
    s.y.push_back(lastSecondMean(t, *r.dataset("/bodies/" + w + "/y")));
    s.outer_Y.push_back(lastSecondMean(t, *r.dataset("/contact/" + w + "/right/Y")));
    if (check) {
      s.check_N.push_back(
          lastSecondMean(t, *r.dataset("/contact/" + w + "/left/rails/check/normal_force")));
      // A check rail's answer is where it first touched, not where it outcarried the running
      // rail.
      const std::string rails = "/contact/" + w + "/left/rails";
      EXPECT_FALSE(r.number(rails, "transfer_s_check").has_value());
      s.first_contact.push_back(r.number(rails, "first_contact_s_check").value_or(std::nan("")));
      s.start.push_back(r.dataset("/bodies/" + w + "/s")->front());
    }
  }
  return s;
}

const std::string kCheck = "tests/run/data/check_rail_curve.lua";
const std::string kNone = "tests/run/data/check_rail_none.lua";

TEST(CheckRail, ACheckRailTakesTheGuidingForceOffTheOuterFlange) {
  // The clearance between the check rail and the flange back of the centred wheelset.
  const rb::run::Model m = rb::test::compiled(kCheck, {});
  const auto& e = *m.lead().contact->elastic;
  const auto at = e.extra[0].at(0)->at(50.0);
  ASSERT_NE(at.search, nullptr);
  rb::contact::ElasticWheelGeometry g;
  // The pose relative to the check rail's profile origin, moved by its slices' offset toward the
  // field side (dy < 0: toward the track centre).
  rb::contact::ElasticPose centred{-at.dy, m.lead().contact->centred_z - at.dz, 0.0, 0.0};
  rb::contact::searchCheckRail(*at.search, e.flange_back[0], centred, g);
  const double clearance = g.min_gap;
  EXPECT_NEAR(clearance, 3.5e-3, 1e-3);  // 41 mm flangeway, as laid

  const Steady none = run(kNone, {}, "none", false);
  const Steady with = run(kCheck, {}, "check", true);
  for (std::size_t w : {0U, 2U}) {  // the leading wheelset of each bogie
    SCOPED_TRACE(w);
    // Without: against the outer (right) flange, well beyond the check rail's clearance.
    EXPECT_LT(none.y[w], -clearance - 1.5e-3);
    EXPECT_GT(none.outer_Y[w], 15e3);
    // With: held where the flange back meets the check rail (its approach and yaw within 1 mm),
    // the check rail carrying more than 10 kN, the outer wheel's lateral force gone from the
    // flange (less than half of what it was, here of the other sign).
    EXPECT_NEAR(with.y[w], -clearance, 1e-3);
    EXPECT_GT(with.check_N[w], 10e3);
    EXPECT_LT(with.outer_Y[w], 0.5 * none.outer_Y[w]);
  }
  // The trailing wheelsets run toward the inner rail: they do not reach the check rail.
  EXPECT_EQ(with.check_N[1], 0.0);
  EXPECT_EQ(with.check_N[3], 0.0);
  EXPECT_TRUE(std::isnan(with.first_contact[1]));
  // The leading ones touch it where the curve's transition has moved them 3.5 mm out.
  EXPECT_GT(with.first_contact[0], with.start[0] + 1.0);
  EXPECT_GT(with.first_contact[2], with.start[2] + 1.0);

  // A check rail 100 mm further inside (never reached) changes nothing.
  const Steady far = run(kCheck,
                         {"profiles.extra_rails.left[1].slices[1].dy=-0.2125",
                          "profiles.extra_rails.left[1].slices[2].dy=-0.2125"},
                         "far", true);
  EXPECT_EQ(far.y, none.y);
  EXPECT_EQ(far.outer_Y, none.outer_Y);
  for (double n : far.check_N) EXPECT_EQ(n, 0.0);
}

}  // namespace
