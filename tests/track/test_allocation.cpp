// Evaluation in the right-hand side must not allocate: count global operator new calls.
#include <gtest/gtest.h>

#include "tests/common/allocation_counter.hpp"

#include "track_test_util.hpp"
#include "workbench/track/track.hpp"

using rbtest::g_allocations;

namespace {

TEST(Allocation, FrameAndIrregularityEvaluationAllocateNothing) {
  rb::track::TrackSpec spec = rbtest::paperCase2(0.1);
  spec.irregularities.source = rb::track::IrregularitySource::Psd;
  spec.irregularities.spectrum = "ore_b176_low";
  const rb::track::TrackModel m = rb::track::compileTrack(spec);
  const auto& g = m.geometry();
  const auto& irr = *m.irregularities();
  double sink = 0.0;
  const long before = g_allocations.load();
  for (double s = -3.0; s < 505.0; s += 0.37) {
    sink += g.at(s).A(0, 1) + g.exactAt(s).R.y() + irr.at(s).delta;
  }
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_TRUE(std::isfinite(sink));
  // The counter works.
  const long b2 = g_allocations.load();
  auto* v = new std::vector<double>(10);
  delete v;
  EXPECT_GE(g_allocations.load() - b2, 2);
}

}  // namespace
