// EN 14363 per track section, Q0 from the statics and positions per wheel
// (docs/assessment.md, "Track sections and test zones", "Static wheel loads Q0", "Positions"):
// the sections follow the track's segments (or run.assessment.sections) with their test zones;
// the quasi-static guiding force of a curve does not depend on how much tangent was simulated;
// Q0 is the static wheel load of the vehicle on perfect tangent track (the masses' share), not
// the load of a run's first state on an irregular curve; every position is the wheel's own.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "h5read.hpp"
#include "scenario_run.hpp"
#include "workbench/app/run.hpp"
#include "workbench/core/error.hpp"
#include "workbench/run/assessment_run.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/run/vehicle_run.hpp"

namespace {

namespace fs = std::filesystem;
using rb::assessment::SectionKind;
using rb::assessment::TestZone;

constexpr double kG = 9.81;  // [m/s^2] gravity of the vehicle model (vehicle/model.hpp)

rb::run::Model compileCase3(const std::string& method, std::vector<std::string> sets = {}) {
  rb::run::CompileOptions o;
  o.scenario = "scenarios/validation/case3_" + method + ".lua";
  o.root = RB_SOURCE_DIR;
  o.overrides = std::move(sets);
  o.overrides.emplace_back("run.distance=20");
  return rb::run::compile(o);
}

double totalMass(const rb::run::Model& m) {
  double mass = 0.0;
  for (const auto& b : m.lead().vehicle.bodies) mass += b.mass;
  return mass;
}

// A synthetic run at 20 m/s sampled at 400 Hz over [0, length) of the leading wheelset.
rb::run::AssessmentSignals signals(double length) {
  rb::run::AssessmentSignals s;
  s.dt = 2.5e-3;
  const double v = 20.0;
  for (double t = 0.0; v * t < length; t += s.dt) {
    s.time.push_back(t);
    s.distance.push_back(v * t);
  }
  return s;
}

rb::assessment::TrackSection section(const std::string& name, SectionKind kind, double from,
                                     double to, double radius) {
  rb::assessment::TrackSection t;
  t.name = name;
  t.kind = kind;
  t.from = from;
  t.to = to;
  t.radius = radius;
  t.zone = rb::assessment::testZone(radius);
  return t;
}

const rb::run::SummaryItem* item(const rb::run::AssessmentResult& r, const std::string& key) {
  for (const auto& it : r.summary)
    if (it.key == key) return &it;
  return nullptr;
}

rb::assessment::AssessmentSpec safety() {
  rb::assessment::AssessmentSpec spec;
  spec.safety = true;
  return spec;
}

}  // namespace

TEST(TestZones, ByRadius) {
  EXPECT_EQ(rb::assessment::testZone(INFINITY), TestZone::Zone1);
  EXPECT_EQ(rb::assessment::testZone(8000), TestZone::Zone1);
  EXPECT_EQ(rb::assessment::testZone(1000), TestZone::Zone2);
  EXPECT_EQ(rb::assessment::testZone(600), TestZone::Zone2);
  EXPECT_EQ(rb::assessment::testZone(500), TestZone::Zone3);
  EXPECT_EQ(rb::assessment::testZone(300), TestZone::Zone4);
  EXPECT_EQ(rb::assessment::testZone(250), TestZone::Zone4);
  EXPECT_EQ(rb::assessment::testZone(200), TestZone::Zone5);
  EXPECT_EQ(rb::assessment::testZone(NAN), TestZone::None);
}

TEST(Sections, FollowTheTrackSegments) {
  const rb::run::Model m = compileCase3("kec");
  const auto s = rb::run::assessmentSections(m);
  ASSERT_EQ(s.size(), 3u);  // case 3: 100 m tangent, 50 m transition, R = 500 m curve
  EXPECT_EQ(s[0].name, "tangent1");
  EXPECT_EQ(s[0].kind, SectionKind::Tangent);
  EXPECT_EQ(s[0].zone, TestZone::Zone1);
  EXPECT_EQ(s[1].name, "transition2");
  EXPECT_EQ(s[1].zone, TestZone::None);
  EXPECT_DOUBLE_EQ(s[1].from, 100.0);
  EXPECT_DOUBLE_EQ(s[1].to, 150.0);
  EXPECT_EQ(s[2].name, "curve3");
  EXPECT_EQ(s[2].kind, SectionKind::Curve);
  EXPECT_DOUBLE_EQ(s[2].radius, 500.0);
  EXPECT_EQ(s[2].zone, TestZone::Zone3);
}

// EN 14363 evaluates Y_qst per curve section: 20 kN on the curve whatever the tangent before it
// (over the whole run the 50 % value would be that of the tangent once the tangent is longer).
TEST(Sections, QuasiStaticForceOfACurveDoesNotDependOnTheTangentLength) {
  for (const double tangent : {100.0, 600.0}) {
    rb::run::AssessmentSignals s = signals(tangent + 300.0);
    s.sections = {section("tangent1", SectionKind::Tangent, 0, tangent, INFINITY),
                  section("curve2", SectionKind::Curve, tangent, tangent + 300.0, 300.0)};
    for (const char* side : {"left", "right"}) {
      rb::run::WheelSignals w;
      w.wheelset = "ws1";
      w.side = side;
      w.q0 = 50e3;
      for (const double x : s.distance) {
        w.Y.push_back(x < tangent ? 0.0 : 20e3);
        w.Q.push_back(50e3);
        w.y_track.push_back(x < tangent ? 0.0 : 20e3);
      }
      s.wheels.push_back(std::move(w));
    }
    const auto r = rb::run::assess(s, safety(), 0.36);
    const auto* y = item(r, "y_qst");
    ASSERT_NE(y, nullptr) << tangent;
    EXPECT_NEAR(y->a.check.value, 20e3, 1.0) << tangent;
    EXPECT_NE(y->a.where.find("in curve2"), std::string::npos) << y->a.where;
    ASSERT_EQ(r.sections.size(), 2u);
    EXPECT_EQ(r.sections[0].summary.size(), 4u);  // no Y_qst, Q_qst on the tangent
  }
}

// A wheel 10 m behind the leading one unloads at the same track position: both report it there.
TEST(Positions, EveryWheelAtItsOwnDistance) {
  rb::run::AssessmentSignals s = signals(200.0);
  for (const double offset : {0.0, -10.0}) {
    rb::run::WheelSignals w;
    w.wheelset = offset == 0.0 ? "ws1" : "ws2";
    w.side = "left";
    w.q0 = 50e3;
    w.s_offset = offset;
    for (const double x : s.distance) {
      const double own = x + offset;
      w.Y.push_back(0.0);
      w.Q.push_back(50e3 - 20e3 * std::exp(-(own - 120.0) * (own - 120.0) / 4.0));
      w.y_track.push_back(0.0);
    }
    s.wheels.push_back(w);
    w.side = "right";
    s.wheels.push_back(std::move(w));
  }
  const auto r = rb::run::assess(s, safety(), 0.36);
  ASSERT_EQ(r.wheel_safety.size(), 4u);
  for (const auto& ws : r.wheel_safety) EXPECT_NEAR(ws.dq.at_s, 120.0, 1.0) << ws.dq.where;
}

// Q0 of the Manchester wagon (symmetric) is an eighth of its weight on every wheel, for KEC and
// LUT alike, although case 3 starts on an irregular track where the start loads differ by 10 %.
TEST(StaticWheelLoads, Case3EveryWheelCarriesItsShareOfTheWeight) {
  for (const char* method : {"kec", "lut"}) {
    const rb::run::Model m = compileCase3(method);
    const auto q0 = rb::run::staticWheelLoads(m);
    ASSERT_EQ(q0.load.size(), 8u);
    const double share = totalMass(m) * kG / 8.0;
    for (const double q : q0.load) EXPECT_NEAR(q / share, 1.0, 1e-3) << method;
    EXPECT_NE(q0.source.find("perfect level tangent"), std::string::npos);
  }
}

TEST(StaticWheelLoads, TheRunAssessesAgainstThem) {
  const auto o = h5test::quietRun("scenarios/validation/case3_kec.lua",
                                  h5test::freshResult("rb_test_sections", "q0.h5"),
                                  {"run.distance=20", "run.assessment.comfort=false"});
  hid_t f = h5test::runAndOpen(o);
  ASSERT_GE(f, 0);
  const double share = totalMass(compileCase3("kec")) * kG / 8.0;
  double spread = 0.0;
  for (const char* ws : {"ws1", "ws2", "ws3", "ws4"})
    for (const char* side : {"left", "right"}) {
      const std::string g = std::string("/assessment/safety/") + ws + "/" + side;
      EXPECT_NEAR(h5test::numAttr<double>(f, g, "q0") / share, 1.0, 1e-3) << g;
      const auto q = h5test::dataset(f, std::string("/contact/") + ws + "/" + side + "/Q");
      spread = std::max(spread, std::abs(q.front() / share - 1.0));
    }
  EXPECT_GT(spread, 0.01);  // the start state on the irregular track is not the statics
  EXPECT_NE(h5test::stringAttr(f, "/assessment", "q0_source").find("tangent"), std::string::npos);
  // The contact figures draw Nadal's limit of the same flange angle as the assessment.
  EXPECT_NEAR(h5test::numAttr<double>(f, "/contact", "flange_angle"), 1.2217, 1e-9);
  // The trailing wheelset's position is its own: 21.56 m behind the leading one.
  EXPECT_NEAR(h5test::numAttr<double>(f, "/assessment/safety/ws4/left", "s_offset"), -21.56, 1e-9);
  H5Fclose(f);
}

TEST(VehicleCategory, SetsAlphaAndAnUnstatedOneIsSaid) {
  rb::run::AssessmentSignals s = signals(50.0);
  for (const char* side : {"left", "right"}) {
    rb::run::WheelSignals w;
    w.wheelset = "ws1";
    w.side = side;
    w.q0 = 50e3;
    w.Y.assign(s.time.size(), 0.0);
    w.Q.assign(s.time.size(), 50e3);
    w.y_track.assign(s.time.size(), 0.0);
    s.wheels.push_back(std::move(w));
  }
  auto spec = safety();
  spec.category = rb::assessment::VehicleCategory::Freight;
  auto r = rb::run::assess(s, spec, 0.36);
  EXPECT_DOUBLE_EQ(r.spec.alpha, 0.85);
  EXPECT_NEAR(r.wheelset_safety[0].sum_y.check.limit, 0.85 * (10e3 + 2.0 * 50e3 / 3.0), 1e-6);
  spec.category = rb::assessment::VehicleCategory::Unstated;
  r = rb::run::assess(s, spec, 0.36);
  EXPECT_DOUBLE_EQ(r.spec.alpha, 1.0);
  bool said = false;
  for (const auto& n : r.notes) said = said || n.find("vehicle.category") != std::string::npos;
  EXPECT_TRUE(said);
  spec.alpha = 0.9;  // given: no note
  r = rb::run::assess(s, spec, 0.36);
  EXPECT_DOUBLE_EQ(r.spec.alpha, 0.9);
  for (const auto& n : r.notes) EXPECT_EQ(n.find("vehicle.category"), std::string::npos) << n;
}

namespace {

std::string writeScenario(const std::string& name, const std::string& run_block) {
  const fs::path d = fs::temp_directory_path() / "rb_test_sections";
  fs::create_directories(d);
  const std::string p = (d / name).string();
  std::ofstream(p) << "local common = require \"validation.common\"\n"
                      "local lib = require \"tracks.lib\"\n"
                      "track { segments = lib.manchester_r500(), step = 0.5 }\n"
                      "common.profiles()\ncommon.contact(\"kec\")\n"
                      "vehicle (require \"vehicles.manchester_wagon1\" { speed = 20 })\n"
                      "common.abm(20)\n"
                   << run_block;
  return p;
}

std::string checkErrors(const std::string& file) {
  rb::app::RunOptions o;
  o.scenario = file;
  o.root = RB_SOURCE_DIR;
  try {
    rb::app::checkScenario(o);
  } catch (const rb::InputError& e) {
    return e.what();
  }
  return "<no error>";
}

}  // namespace

TEST(GivenSections, BadOnesAreRefusedWithFileLine) {
  const std::string p = writeScenario(
      "bad_sections.lua",
      "run { distance = 50, assessment = { safety = true, sections = {\n"
      "  { name = \"a\", from = 10, to = 5 }, { name = \"a b\", from = 0, to = 5 },\n"
      "  { name = \"c\", from = 0 }, { name = \"d\", from = 0, to = 1, radius = 3 },\n"
      "  { name = \"e\", from = 0, to = 9e9 } } } }\n");
  const std::string e = checkErrors(p);
  for (const std::string& want :
       {std::string("sections[1] needs 0 <= from < to"), std::string("sections[2].name 'a b'"),
        std::string("sections[3] needs name, from and to"),
        std::string("sections[4].radius is not a key")})
    EXPECT_NE(e.find(want), std::string::npos) << "missing: " << want << "\nin:\n" << e;
  EXPECT_NE(e.find(p + ":"), std::string::npos) << e;
  const std::string q =
      writeScenario("far_section.lua",
                    "run { distance = 50, assessment = { safety = true, sections = {\n"
                    "  { name = \"far\", from = 0, to = 9e5 } } } }\n");
  const std::string e2 = checkErrors(q);
  EXPECT_NE(e2.find("section 'far' ends at 900000 m, beyond the track's end"), std::string::npos)
      << e2;
}

TEST(GivenSections, AreAssessedAsGiven) {
  const auto o =
      h5test::quietRun("scenarios/validation/case2_kec.lua",
                       h5test::freshResult("rb_test_sections", "given.h5"), {"run.distance=40"});
  // A scenario text with given sections (--set cannot give a table).
  const std::string p = writeScenario(
      "given.lua",
      "run { distance = 40, output = { every = 5e-3 }, assessment = { safety = true, "
      "sections = { { name = \"first\", from = 0, to = 25 }, { name = \"second\", from = 25, to "
      "= 60 } } } }\n");
  auto given = o;
  given.scenario = p;
  given.overrides.clear();
  hid_t f = h5test::runAndOpen(given);
  ASSERT_GE(f, 0);
  EXPECT_EQ(h5test::stringAttr(f, "/assessment/sections", "names"), "first\nsecond");
  EXPECT_EQ(h5test::stringAttr(f, "/assessment/sections/first", "kind"), "given");
  EXPECT_EQ(h5test::stringAttr(f, "/assessment/sections/first", "zone"), "zone 1");
  EXPECT_DOUBLE_EQ(h5test::numAttr<double>(f, "/assessment/sections/second", "to"), 60.0);
  H5Fclose(f);
}

// Work bounded before it starts, and nothing assessed that is not there.
TEST(AssessmentSettings, RefusedBeforeTheRun) {
  rb::app::RunOptions o;
  o.root = RB_SOURCE_DIR;
  o.scenario = "scenarios/validation/case2_kec.lua";
  o.overrides = {"run.assessment.sample_every=1e-9", "solver.method=dopri5"};
  try {
    rb::app::checkScenario(o);
    ADD_FAILURE() << "no error";
  } catch (const rb::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sample_every: 1e-09 s over"), std::string::npos)
        << e.what();
  }
  const std::string far = writeScenario(
      "far_floor.lua",
      "run { distance = 50, assessment = { comfort = true, floor_positions = { 0, 1e9 } } }\n");
  EXPECT_NE(checkErrors(far).find("floor_positions: 1e+09 m is not on the vehicle"),
            std::string::npos)
      << checkErrors(far);
  const fs::path d = fs::temp_directory_path() / "rb_test_sections";
  const std::string track_only = (d / "track_only.lua").string();
  std::ofstream(track_only) << "track { segments = { tangent { length = 100 } } }\n"
                               "run { assessment = true }\n";
  EXPECT_NE(checkErrors(track_only)
                .find("track_only.lua:2: run.assessment: the scenario has no "
                      "vehicle to assess"),
            std::string::npos)
      << checkErrors(track_only);
}

// N_MV from fewer than the 60 blocks of 5 s EN 12299 asks for is said to be indicative, in the
// quantity's place and in a note of the summary.
TEST(ComfortBlocks, FewerThanTheStandardAsksForAreSaid) {
  rb::run::AssessmentSignals s = signals(400.0);  // 20 s: 4 blocks
  rb::run::FloorPointSignals p;
  p.name = "centre";
  for (const double t : s.time) {
    p.ax.push_back(0.0);
    p.ay.push_back(0.3 * std::sin(2.0 * std::numbers::pi * 1.0 * t));
    p.az.push_back(0.2 * std::sin(2.0 * std::numbers::pi * 3.0 * t));
  }
  s.floor.push_back(std::move(p));
  rb::assessment::AssessmentSpec spec;
  spec.comfort = true;
  const auto r = rb::run::assess(s, spec, 0.36);
  const auto* n = item(r, "n_mv");
  ASSERT_NE(n, nullptr);
  EXPECT_NE(n->a.where.find("4 of the 60 5 s blocks EN 12299 asks for: indicative"),
            std::string::npos)
      << n->a.where;
  bool noted = false;
  for (const auto& note : r.notes)
    noted = noted || note.find("indicative only") != std::string::npos;
  EXPECT_TRUE(noted);
  bool printed = false;
  for (const auto& line : rb::run::summaryLines(r))
    printed = printed || line.find("indicative") != std::string::npos;
  EXPECT_TRUE(printed);
}

// The instability frequency of several bogie signals in one pass over the frequencies: the same
// frequency, bit for bit, as the DFT of each series by std::complex.
TEST(SpectrumPeak, SharedPassEqualsOneComplexDftPerSeries) {
  constexpr double dt = 2.5e-3, f_low = 3.0, f_high = 9.0, df = 0.05;
  std::vector<std::vector<double>> xs(3, std::vector<double>(4000));
  for (std::size_t i = 0; i < xs.size(); ++i)
    for (std::size_t k = 0; k < xs[i].size(); ++k) {
      const double t = static_cast<double>(k) * dt;
      xs[i][k] = std::sin(2.0 * std::numbers::pi * (4.1 + 1.3 * static_cast<double>(i)) * t) +
                 0.3 * std::sin(2.0 * std::numbers::pi * 7.7 * t + static_cast<double>(i)) + 0.1;
    }
  const auto reference = [&](const std::vector<double>& x) {
    double mean = 0.0;
    for (const double v : x) mean += v;
    mean /= static_cast<double>(x.size());
    double best = -1.0, f_best = f_low;
    for (double f = f_low; f <= f_high + 1e-9; f += df) {
      const std::complex<double> step = std::polar(1.0, -2.0 * std::numbers::pi * f * dt);
      std::complex<double> rot(1.0, 0.0), sum(0.0, 0.0);
      for (const double v : x) {
        sum += (v - mean) * rot;
        rot *= step;
      }
      if (std::norm(sum) > best) {
        best = std::norm(sum);
        f_best = f;
      }
    }
    return f_best;
  };
  const std::vector<double> peaks =
      rb::run::spectrumPeaks({&xs[0], &xs[1], &xs[2]}, dt, f_low, f_high, df);
  ASSERT_EQ(peaks.size(), xs.size());
  for (std::size_t i = 0; i < xs.size(); ++i) {
    EXPECT_EQ(peaks[i], reference(xs[i])) << "series " << i;
    EXPECT_EQ(rb::run::spectrumPeak(xs[i], dt, f_low, f_high, df), peaks[i]) << "series " << i;
  }
}
