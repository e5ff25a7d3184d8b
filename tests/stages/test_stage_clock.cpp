// vehicle::StageClock: which evaluations are timed, and that the stage names are one table.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "workbench/vehicle/stage_clock.hpp"

namespace {

using rb::vehicle::Stage;
using rb::vehicle::StageClock;

// Runs n evaluations of two stages; returns how many were timed.
long drive(StageClock& c, int n) {
  long timed = 0;
  for (int i = 0; i < n; ++i) {
    if (!c.start()) continue;
    ++timed;
    c.mark(Stage::Coordinates);
    c.mark(Stage::SeriesRates);
    c.finish();
  }
  return timed;
}

TEST(StageClock, TimesOneEvaluationInPeriod) {
  StageClock c;
  c.setPeriod(64);
  EXPECT_EQ(drive(c, 640), 10);
  EXPECT_EQ(c.samples(), 10);
  EXPECT_EQ(c.evaluations(), 640);
  EXPECT_GE(c.sampledSeconds(Stage::Coordinates), 0.0);
  EXPECT_EQ(c.sampledSeconds(Stage::Constraints), 0.0);
}

TEST(StageClock, PeriodOneTimesEveryEvaluationAndZeroNone) {
  StageClock every;
  every.setPeriod(1);
  EXPECT_EQ(drive(every, 100), 100);
  StageClock off;
  off.setPeriod(0);
  EXPECT_EQ(drive(off, 100000), 0);
  EXPECT_EQ(off.samples(), 0);
  EXPECT_EQ(off.evaluations(), 100000);
}

TEST(StageClock, SetPeriodResetsTheCounters) {
  StageClock c;
  c.setPeriod(2);
  drive(c, 10);
  c.setPeriod(2);
  EXPECT_EQ(c.samples(), 0);
  EXPECT_EQ(c.evaluations(), 0);
  EXPECT_EQ(c.sampledSeconds(Stage::Coordinates), 0.0);
}

TEST(StageClock, UsedStages) {
  StageClock c;
  c.use({Stage::Coordinates, Stage::SeriesRates});
  EXPECT_TRUE(c.uses(Stage::Coordinates));
  EXPECT_TRUE(c.uses(Stage::SeriesRates));
  EXPECT_FALSE(c.uses(Stage::Constraints));
}

TEST(StageClock, NameTableCoversEveryStageOnce) {
  std::set<std::string> names;
  for (std::size_t i = 0; i < rb::vehicle::kStageCount; ++i) {
    const auto s = static_cast<Stage>(i);
    const std::string name(rb::nameOf(s));
    EXPECT_NE(name, "?");
    names.insert(name);
    EXPECT_EQ(rb::parse<Stage>(name), s);
  }
  EXPECT_EQ(names.size(), rb::vehicle::kStageCount);
}

TEST(StageClock, AnEvaluationThatFailsBeforeItsEndIsNotKept) {
  StageClock c;
  c.setPeriod(1);
  ASSERT_TRUE(c.start());
  c.mark(Stage::Coordinates);  // fails here: no finish()
  ASSERT_TRUE(c.start());
  c.mark(Stage::Coordinates);
  c.finish();
  EXPECT_EQ(c.samples(), 1);
  EXPECT_EQ(c.evaluations(), 2);
}

}  // namespace
