// Checks made before a run from the physics of the scene: gauge irregularities against the
// flangeway play of the profiles, and a rail file drawn already inclined against the inclination
// the scenario asks for. Each compiles a short scenario (no run).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "workbench/core/error.hpp"
#include "workbench/run/compile.hpp"

namespace fs = std::filesystem;

namespace {

struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name)
      : path(fs::temp_directory_path() / ("rb_checks_" + name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  std::string write(const std::string& file, const std::string& text) const {
    std::ofstream(path / file) << text;
    return (path / file).string();
  }
};

rb::run::CompileOptions options(const std::string& file, std::vector<std::string> overrides = {}) {
  rb::run::CompileOptions o;
  o.scenario = file;
  o.root = RB_SOURCE_DIR;
  o.overrides = std::move(overrides);
  return o;
}

std::string compileError(const rb::run::CompileOptions& o) {
  try {
    (void)rb::run::compile(o);
  } catch (const rb::InputError& e) {
    return e.what();
  }
  return "<no error>";
}

bool anyContains(const std::vector<std::string>& v, const std::string& needle) {
  for (const auto& s : v)
    if (s.find(needle) != std::string::npos) return true;
  return false;
}

// The Manchester wagon, S1002 on 60E1 at 1:40 (B = 1360 mm, G = 1435 mm), KEC, on the R = 500 m
// track with the given irregularities.
std::string wagon(const std::string& irregularities) {
  return "local lib = require 'tracks.lib'\n"
         "track { segments = lib.manchester_r500(), step = 0.5, irregularities = " +
         irregularities +
         " }\n"
         "require('validation.common').profiles()\n"
         "contact { method = 'kec', creep = 'polach', mu = 0.2364 }\n"
         "vehicle (require 'vehicles.manchester_wagon1' { speed = 20 })\n"
         "solver { method = 'dopri5' }\n"
         "run { duration = 0.2, output = { every = 0.01 } }\n";
}

}  // namespace

// FRA class 5 narrows the gauge by 13 mm on this track, more than the 12.6 mm flangeway play of
// S1002 on 60E1 (6.3 mm to each flange): a warning with the numbers, printed and recorded.
TEST(Checks, GaugeNarrowingBeyondTheFlangewayPlayIsAWarning) {
  TempDir t("gauge");
  const std::string f = t.write("fra5.lua", wagon("psd { spectrum = 'fra_class_5', seed = 42 }"));
  const rb::run::Model m = rb::run::compile(options(f));
  ASSERT_TRUE(m.hasContact());
  EXPECT_NEAR(m.lead().contact->flangeway[0], 6.3e-3, 0.1e-3);
  EXPECT_NEAR(m.lead().contact->flangeway[1], 6.3e-3, 0.1e-3);
  EXPECT_TRUE(anyContains(m.warnings, f + ":2: warning: the gauge irregularity narrows the gauge "
                                          "by 13 mm"));
  EXPECT_TRUE(anyContains(m.run_warnings, "both flanges of a wheelset touch at once"));
  EXPECT_TRUE(anyContains(m.run_warnings, "flangeway play of 12.6 mm"));
  // ORE B176 low stays well inside the play: no warning.
  const std::string low = t.write("low.lua", wagon("psd { spectrum = 'ore_b176_low', seed = 42 }"));
  const rb::run::Model ml = rb::run::compile(options(low));
  EXPECT_FALSE(anyContains(ml.warnings, "gauge irregularity"));
}

// MBench_UIC60_v3.prr is drawn at 1:40: inclining it again is refused naming both settings; as
// drawn (inclination = 0) it compiles.
TEST(Checks, RailFileDrawnInclinedIsNotInclinedAgain) {
  TempDir t("prr");
  const std::string f = t.write(
      "prr.lua",
      "track { segments = { tangent { length = 200 } } }\n"
      "profiles { wheel = 's1002', rail = 'profiles/MBench_UIC60_v3.prr', back_to_back = 1.360,\n"
      "           gauge = 1.435 }\n"
      "contact { method = 'kec' }\n"
      "vehicle (require 'vehicles.manchester_wagon1' { speed = 20 })\n"
      "solver { method = 'dopri5' }\n"
      "run { duration = 0.1 }\n");
  EXPECT_EQ(compileError(options(f)),
            f + ":2: profiles.rail: 'MBench_UIC60_v3.prr' is drawn already inclined (its head is "
                "symmetric about an axis tilted by 0.025 rad, 1:40), and profiles.inclination = "
                "0.025 rad inclines it again: the cant would count twice. Set "
                "profiles.inclination = 0 to use the file as drawn, or give the rail profile "
                "upright");
  EXPECT_EQ(compileError(options(f, {"profiles.inclination=0"})), "<no error>");
}

// Irregularities that begin at s = 0 without a fade-in, the wagon's reference point at s = 0: the
// rear bogie's wheelsets (ws3, ws4) start on the perfect track before s = 0 and meet a step in the
// rails there. Printed for every method; recorded as a warning of the run where wheels can leave
// the rail (elastic). The default fade-in (20 m) ramps from zero: no step, no warning.
TEST(Checks, IrregularityStepUnderRearWheelsetsIsAWarning) {
  TempDir t("irrstep");
  const std::string step = "psd { spectrum = 'ore_b176_low', seed = 42, fade_in = 0 }";
  const std::string kec = t.write("kec.lua", wagon(step));
  const rb::run::Model m = rb::run::compile(options(kec));
  EXPECT_TRUE(anyContains(m.warnings, kec + ":2: warning: track.irregularities begin at s = 0 "
                                            "without a fade-in and ws3, ws4 start before s = 0"));
  EXPECT_FALSE(anyContains(m.run_warnings, "without a fade-in"));
  const rb::run::Model me = rb::run::compile(options(kec, {"contact.method=elastic"}));
  EXPECT_TRUE(anyContains(me.run_warnings, "wheels may lose contact over it and land hard"));
  const std::string ramp =
      t.write("ramp.lua", wagon("psd { spectrum = 'ore_b176_low', seed = 42 }"));
  const rb::run::Model mr = rb::run::compile(options(ramp, {"contact.method=elastic"}));
  EXPECT_FALSE(anyContains(mr.warnings, "without a fade-in"));
  EXPECT_FALSE(anyContains(mr.run_warnings, "without a fade-in"));
}
