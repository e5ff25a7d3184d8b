// Linearised stability of the Manchester wagon on S1002/60E1 (workbench/stability): the steady
// state, the finite-difference Jacobian's step check, the modes an engineer expects and their
// frequencies, and (long) the linear critical speed and its dependence on the primary
// longitudinal (yaw) stiffness.
#include "tests/modes/modes_fixture.hpp"

using namespace rb;
using namespace rb::modes_test;

namespace {

const stability::Mode* find(const stability::Analysis& a, const std::string& label) {
  const stability::Mode* best = nullptr;
  for (const auto& m : a.modes)
    if (m.label == label && (best == nullptr || m.damping_ratio < best->damping_ratio)) best = &m;
  return best;
}

void expectWagonModes(const stability::Analysis& a) {
  // Steady state on tangent: centred (symmetric vehicle and track) and a small residual.
  EXPECT_LT(a.steady.max_ws_lateral, 1e-6);
  EXPECT_LT(a.steady.residual, 1e-6);
  EXPECT_TRUE(a.step_check_ok) << "step check " << a.step_check;
  EXPECT_LT(a.step_check, 1e-2);
  // Car body on its secondary suspension (Kz 430 kN/m x 4 under 32 t: bounce ~ 1.2 Hz): the
  // lateral (sway) modes of a coach lie between 0.3 and 2.5 Hz.
  const auto* lower = find(a, "car body lower sway");
  const auto* upper = find(a, "car body upper sway");
  ASSERT_NE(lower, nullptr);
  ASSERT_NE(upper, nullptr);
  EXPECT_GT(lower->frequency_hz, 0.3);
  EXPECT_LT(lower->frequency_hz, 2.5);
  EXPECT_GT(upper->frequency_hz, 0.3);
  EXPECT_LT(upper->frequency_hz, 3.5);
  // Lower sway is mostly lateral: its roll centre lies below the CoM, the upper sway's above.
  EXPECT_LT(lower->roll_centre, 0.0);
  EXPECT_GT(upper->roll_centre, 0.0);
  const auto* bounce = find(a, "car body bounce");
  ASSERT_NE(bounce, nullptr);
  EXPECT_GT(bounce->frequency_hz, 0.7);
  EXPECT_LT(bounce->frequency_hz, 2.0);
  // Kinematic (Klingel) frequency at 20 m/s: V / (2 pi) sqrt(lambda / (r0 b)) with lambda ~ 0.1 to
  // 0.4 of S1002/60E1 1:40, r0 = 0.46, b = 0.75: 1.5 to 3 Hz for the free wheelset; the bogie's
  // primary stiffness raises it. Both hunting modes below 15 Hz, damped at 20 m/s.
  const auto* ws = find(a, "wheelset hunting");
  const auto* bogie = find(a, "bogie hunting");
  ASSERT_NE(ws, nullptr);
  ASSERT_NE(bogie, nullptr);
  EXPECT_GT(ws->frequency_hz, 0.5);
  EXPECT_LT(ws->frequency_hz, 15.0);
  EXPECT_GT(bogie->frequency_hz, 0.5);
  EXPECT_LT(bogie->frequency_hz, 15.0);
  EXPECT_GT(a.huntingDamping(), 0.0);
  EXPECT_GT(a.rhs_evaluations, 0);
}

}  // namespace

TEST(Modes, WagonKecAt20) {
  const stability::Analysis a = stability::analyse(wagon("kec"), 20.0);
  EXPECT_EQ(a.method, "kec");
  expectWagonModes(a);
}

TEST(Modes, WagonLutAt20) {
  const stability::Analysis a = stability::analyse(wagon("lut"), 20.0);
  EXPECT_EQ(a.method, "lut");
  expectWagonModes(a);
}

// The damping of wheelset hunting falls with speed: the creep forces' damping goes as 1 / V.
TEST(Modes, HuntingDampingFallsWithSpeed) {
  stability::Analyser an(wagon("kec"), {});
  const stability::Analysis a = an.analyse(20.0);
  const stability::Analysis b = an.analyse(40.0);
  ASSERT_GE(a.least_hunting, 0);
  ASSERT_GE(b.least_hunting, 0);
  EXPECT_LT(b.huntingDamping(), a.huntingDamping());
}

// The steady state and modes at a speed the scene cannot run (no contact block) are refused
// with the reason.
TEST(Modes, NeedsContact) {
  scenario::ScenarioSpec s = wagon("kec");
  s.has_contact = false;
  EXPECT_THROW(stability::analyse(s, 20.0), stability::Failure);
}
