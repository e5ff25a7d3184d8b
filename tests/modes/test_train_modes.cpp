// The modes of a train (workbench/stability on train{}): two Manchester wagons on a tangent, their
// linearisation as one system. Uncoupled, every eigenvalue of one wagon appears twice; coupled by
// buffers and a slack-free screw coupling at zero force, the in-phase copy of each stays and only
// motions that press one buffer against the other change: the anti-phase car-body yaw and pitch,
// stiffened by the buffers (their faces 1.75 m apart, 1.06 m above the rail). A train the steady
// state cannot exist for, or one with guided wheelsets, is refused with the reason.
#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "tests/modes/modes_fixture.hpp"

using namespace rb;
using namespace rb::modes_test;

namespace {

const std::string kTrain = kRoot + "/tests/modes/data/train_coupled_tangent.lua";
constexpr double kSpeed = 30.0;

scenario::ScenarioSpec train(const std::vector<std::string>& overrides = {}) {
  scenario::LoadOptions lo;
  lo.root = kRoot;
  lo.overrides = overrides;
  return scenario::loadScenario(kTrain, lo);
}

// The train's eigenvalues nearest to lam, relative to |lam|, in increasing order.
std::vector<double> nearest(const stability::Analysis& a, std::complex<double> lam) {
  std::vector<double> d;
  for (const auto& m : a.modes) d.push_back(std::abs(m.eigenvalue - lam) / std::abs(lam));
  std::sort(d.begin(), d.end());
  return d;
}

TEST(TrainModes, UncoupledWagonsHaveEachWagonsModesTwice) {
  scenario::ScenarioSpec one = train();
  one.train.clear();  // the leading wagon alone (its vehicle{} is the first entry's)
  scenario::ScenarioSpec two = train();
  two.train_connections.clear();
  const stability::Analysis a = stability::analyse(one, kSpeed);
  const stability::Analysis b = stability::analyse(two, kSpeed);
  EXPECT_EQ(b.states, 2 * a.states);
  EXPECT_EQ(b.coordinates.size(), 2 * a.coordinates.size());
  EXPECT_EQ(b.coordinates.front().name, "w1." + a.coordinates.front().name);
  EXPECT_EQ(b.coordinates.back().name, "w2." + a.coordinates.back().name);
  for (const auto& m : a.modes) {
    const auto d = nearest(b, m.eigenvalue);
    ASSERT_GE(d.size(), 2U);
    EXPECT_LT(d[1], 1e-4) << stability::describe(m);
  }
  EXPECT_EQ(b.method, "kec");
  EXPECT_TRUE(b.step_check_ok) << b.step_check;
}

TEST(TrainModes, BuffersStiffenTheAntiPhaseCarBodyYawAndPitch) {
  scenario::ScenarioSpec one = train();
  one.train.clear();
  const stability::Analysis a = stability::analyse(one, kSpeed);
  const stability::Analysis b = stability::analyse(train(), kSpeed);
  int stiffened = 0;
  for (const auto& m : a.modes) {
    const auto d = nearest(b, m.eigenvalue);
    EXPECT_LT(d[0], 1e-4) << "no in-phase copy of " << stability::describe(m);
    // The other copy moved (the series dampers' relaxation through the car bodies by less than
    // 1e-3, the buffers' car-body yaw and pitch by about 1 %): a car-body yaw or pitch mode, to a
    // higher frequency.
    if (d[1] < 1e-3) continue;
    ++stiffened;
    EXPECT_TRUE(m.label == "car body yaw" || m.label == "car body pitch") << m.label;
    double best = 1e300, freq = 0.0;
    for (const auto& n : b.modes)
      if (const double e = std::abs(n.eigenvalue - m.eigenvalue);
          e > 1e-4 * std::abs(m.eigenvalue) && e < best) {
        best = e;
        freq = n.frequency_hz;
      }
    EXPECT_GT(freq, m.frequency_hz * 1.005) << m.label;
  }
  EXPECT_EQ(stiffened, 2) << "the car-body yaw and pitch pairs";
}

TEST(TrainModes, NoSteadyStateWithTheVehiclesOnDifferentCurvesOrWithGuidedWheelsets) {
  // A curve of R = 500 m for the first 67.5 m, then the tangent: the leading wagon (69 to 91 m) on
  // the tangent, the second (44 to 66 m) in the curve: no fixed point of the train.
  scenario::ScenarioSpec s = train();
  track::SegmentSpec curve = s.track.segments.front();
  curve.kind = track::SegmentKind::Curve;
  curve.length = 67.5;
  curve.radius = 500.0;
  s.track.segments.front().length -= 67.5;
  s.track.segments.insert(s.track.segments.begin(), curve);
  try {
    (void)stability::analyse(s, kSpeed);
    FAIL() << "a train across a change of curvature analysed";
  } catch (const stability::Failure& e) {
    EXPECT_NE(std::string(e.what()).find("not on one tangent or constant-radius curve ('w2'"),
              std::string::npos)
        << e.what();
  }
  scenario::ScenarioSpec g = train();
  g.train[1].has_contact = false;
  g.train[1].guided = true;
  try {
    (void)stability::analyse(g, kSpeed);
    FAIL() << "a train with guided wheelsets analysed";
  } catch (const stability::Failure& e) {
    EXPECT_NE(std::string(e.what()).find("'w2' of the train has guided wheelsets"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
