// The right-hand side must not allocate: count global operator new calls.
#include <gtest/gtest.h>

#include "tests/common/allocation_counter.hpp"

#include "fixtures.hpp"
#include "workbench/vehicle/guided.hpp"

using rbtest::g_allocations;

namespace rb::vehicle {
namespace {

TEST(Allocation, RhsAndOutputsAllocateNothing) {
  const track::TrackModel tm =
      track::compileTrack(rbtest::curveTrack(track::Side::Left, 300.0, 0.1));
  const VehicleModel m = compileVehicle(rbtest::manchesterWagon(20.0, 60.0), tm);
  GuidedVehicleOde ode(m);
  Eigen::VectorXd y = ode.initialState(0.0);
  y[1] += 0.01;
  Eigen::VectorXd yd(ode.size());
  const ElementId ids[2] = {*m.findElement("bump_y_bogie1"), *m.findElement("sec_bend_bogie2_l")};
  ElementValue vals[2];
  double sink = 0.0;
  const long before = g_allocations.load();
  for (int k = 0; k < 100; ++k) {
    const double t = 0.01 * k;
    EXPECT_EQ(ode.rhs(t, y.data(), yd.data()), 0);
    sink += yd[3];
    ode.elementOutputs(t, y.data(), ids, vals);
    sink +=
        vals[0].force + ode.bodyOutput(t, y.data(), 0).traction + ode.energy(t, y.data()).total();
  }
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_TRUE(std::isfinite(sink));
}

}  // namespace
}  // namespace rb::vehicle
