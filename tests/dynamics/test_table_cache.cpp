// dynamics::TableCache with a disk folder that cannot be used: the tables are built in memory,
// the model compiles, and the problem is one warning, never an exception that aborts the run.
#include <gtest/gtest.h>

#include <string>

#include "dyn_fixtures.hpp"

namespace rbtest {
namespace {

TEST(TableCache, UnusableFolderIsOneWarning) {
  for (const char* dir : {"/proc/self/railbench-cache", "/proc/self"}) {
    dynamics::TableCache cache(dir);
    dynamics::ContactSpec cs;
    const auto track = track::compileTrack(tangentTrack(100));
    const auto veh = vehicle::compileVehicle(freeWheelset(10), track);
    const auto m1 = dynamics::compileContact({}, cs, veh, track, &cache);
    ASSERT_TRUE(m1.kec);
    EXPECT_FALSE(cache.diskUsable());
    int warnings = 0;
    for (const auto& w : m1.warnings)
      warnings += w.find(std::string("table cache folder '") + dir + "' cannot be used") !=
                  std::string::npos;
    EXPECT_EQ(warnings, 1) << dir;
    dynamics::ProfilesSpec other;
    other.gauge = 1.437;
    const auto m2 = dynamics::compileContact(other, cs, veh, track, &cache);
    for (const auto& w : m2.warnings) EXPECT_EQ(w.find("table cache"), std::string::npos) << w;
    EXPECT_EQ(cache.builds(), 2);
  }
}

}  // namespace
}  // namespace rbtest
