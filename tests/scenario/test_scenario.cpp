// Scenario host: every class of bad input is reported as file:line: message (asserted exactly),
// all problems at once, and the sandbox holds.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "workbench/dynamics/names.hpp"
#include "workbench/integrators/registry.hpp"
#include "workbench/scenario/lua_host.hpp"
#include "workbench/scenario/scenario.hpp"
#include "workbench/scenario/schema.hpp"
#include "workbench/track/names.hpp"
#include "workbench/track/track.hpp"
#include "workbench/vehicle/names.hpp"

using rb::scenario::LoadOptions;
using rb::scenario::loadScenario;

namespace {

const std::string kBad = "tests/scenario/bad/";

LoadOptions opts(std::vector<std::string> overrides = {}) {
  LoadOptions o;
  o.root = RB_SOURCE_DIR;
  o.overrides = std::move(overrides);
  return o;
}

// All diagnostics of a failing load, one per line.
std::string errorsOf(const std::string& file, const LoadOptions& o = opts()) {
  try {
    loadScenario(file, o);
  } catch (const rb::InputError& e) {
    return e.what();
  }
  return "<no error>";
}

}  // namespace

TEST(ScenarioErrors, SyntaxError) {
  EXPECT_EQ(errorsOf(kBad + "syntax.lua"),
            kBad + "syntax.lua:3: '}' expected (to close '{' at line 2) near 'step'");
}

TEST(ScenarioErrors, UnknownKeyWithHintAndMissingRequired) {
  EXPECT_EQ(errorsOf(kBad + "unknown_key.lua"),
            kBad +
                "unknown_key.lua:3: track.segments[1] (tangent): unknown key 'lenght' (did you "
                "mean 'length'?)\n" +
                kBad +
                "unknown_key.lua:3: track.segments[1] (tangent): missing required key 'length'");
}

TEST(ScenarioErrors, WrongType) {
  EXPECT_EQ(errorsOf(kBad + "wrong_type.lua"),
            kBad +
                "wrong_type.lua:4: track.segments[2] (curve): length must be a number [m], got "
                "string \"forty\"");
}

TEST(ScenarioErrors, OutOfRange) {
  EXPECT_EQ(errorsOf(kBad + "out_of_range.lua"),
            kBad + "out_of_range.lua:3: track: step must be > 0 m, got -0.5\n" + kBad +
                "out_of_range.lua:4: track: rail_inclination must be <= 0.1 rad, got 0.5");
}

TEST(ScenarioErrors, MissingFile) {
  EXPECT_EQ(errorsOf(kBad + "missing_file.lua"),
            kBad +
                "missing_file.lua:3: track.irregularities (measured): file: file 'nowhere.csv' not "
                "found (looked in " +
                kBad + "nowhere.csv (the scene's folder), " + RB_SOURCE_DIR +
                "/nowhere.csv (the data directory))");
}

TEST(ScenarioErrors, ConflictingOptions) {
  EXPECT_EQ(errorsOf(kBad + "conflict.lua"),
            kBad +
                "conflict.lua:2: solver: rtol has no effect with method 'rk4' (its options: step, "
                "stiff, accept_unstable_step)");
}

TEST(ScenarioErrors, UnknownConstructorName) {
  EXPECT_EQ(errorsOf(kBad + "unknown_name.lua"),
            kBad + "unknown_name.lua:3: unknown name 'tangnet' (did you mean 'tangent'?)");
}

TEST(ScenarioErrors, NotATable) {
  EXPECT_EQ(errorsOf(kBad + "not_a_table.lua"),
            kBad +
                "not_a_table.lua:2: tangent expects one table of named values, e.g. tangent { ... "
                "}, got number");
}

TEST(ScenarioErrors, DuplicateBlock) {
  EXPECT_EQ(
      errorsOf(kBad + "duplicate.lua"),
      kBad + "duplicate.lua:2: track block given twice (first at " + kBad + "duplicate.lua:1)");
}

TEST(ScenarioErrors, ManyProblemsReportedAtOnce) {
  EXPECT_EQ(
      errorsOf(kBad + "many.lua"),
      kBad + "many.lua:7: track: unknown key 'stepp' (did you mean 'step'?)\n" + kBad +
          "many.lua:4: track.segments[1] (tangent): length must be > 0 m, got 0\n" + kBad +
          "many.lua:5: track.segments[2] (curve): unknown key 'raduis' (did you mean 'radius'?)\n" +
          kBad + "many.lua:5: track.segments[2] (curve): missing required key 'radius'\n" + kBad +
          "many.lua:9: solver: method: unknown value 'rk5' (did you mean 'rk4'?); valid: rk4, abm, "
          "dopri5, bdf, ida\n" +
          kBad + "many.lua:10: run: distance must be >= 0 m, got -1");
}

TEST(ScenarioErrors, UserPsdFunctionMustBeNonNegative) {
  std::string e = errorsOf(kBad + "user_psd_negative.lua");
  EXPECT_EQ(e.rfind(kBad + "user_psd_negative.lua:5: track.irregularities (psd): alignment: PSD "
                           "function returned -1e-07 at omega = ",
                    0),
            0u)
      << e;
}

TEST(ScenarioErrors, UserPsdNeedsUserSpectrum) {
  EXPECT_EQ(
      errorsOf(kBad + "user_psd_wrong_spectrum.lua"),
      kBad +
          "user_psd_wrong_spectrum.lua:4: track.irregularities (psd): spectrum: unknown value "
          "'ore_b176_lo' (did you mean 'ore_b176_low'?); valid: ore_b176_low, ore_b176_high, "
          "fra_class_1, fra_class_2, fra_class_3, fra_class_4, fra_class_5, fra_class_6, user\n" +
          kBad +
          "user_psd_wrong_spectrum.lua:5: track.irregularities (psd): vertical gives a user PSD "
          "but spectrum is 'ore_b176_lo'; set spectrum = \"user\" or remove it");
}

TEST(ScenarioSandbox, NoOsNoIoNoEscapeByRequire) {
  EXPECT_EQ(errorsOf(kBad + "sandbox_os.lua"), kBad + "sandbox_os.lua:1: unknown name 'os'");
  EXPECT_FALSE(std::filesystem::exists("/tmp/railbench_sandbox_escape"));
  EXPECT_EQ(errorsOf(kBad + "sandbox_io.lua"), kBad + "sandbox_io.lua:1: unknown name 'io'");
  EXPECT_EQ(errorsOf(kBad + "sandbox_require.lua"),
            kBad +
                "sandbox_require.lua:1: require \"../../../etc/passwd\": module names are names "
                "separated by dots (letters, digits and '_', not starting with a digit), e.g. "
                "\"vehicles.wagon\"");
}

TEST(ScenarioSandbox, EndlessLoopStopsWithBudgetError) {
  LoadOptions o = opts();
  o.instruction_limit = 5'000'000;
  EXPECT_EQ(errorsOf(kBad + "endless.lua", o), kBad +
                                                   "endless.lua:2: scenario exceeded its budget of "
                                                   "5000000 Lua instructions (endless loop?)");
}

TEST(ScenarioErrors, MissingScenarioFile) {
  EXPECT_EQ(errorsOf("tests/scenario/bad/does_not_exist.lua"),
            "tests/scenario/bad/does_not_exist.lua: cannot open scenario file: no such file");
}

TEST(ScenarioOverrides, SetValuesAndReportBadOnes) {
  auto spec = loadScenario("scenarios/tracks/manchester_r500_irregular.lua",
                           opts({"track.irregularities.seed=7", "track.segments[3].length=200"}));
  EXPECT_EQ(spec.track.irregularities.seed, 7u);
  EXPECT_DOUBLE_EQ(spec.track.segments[2].length, 200.0);
  spec = loadScenario("tests/scenario/good/vehicle.lua",
                      opts({"solver.method=bdf", "solver.rtol=1e-5"}));
  EXPECT_TRUE(spec.has_solver);
  EXPECT_EQ(spec.solver.method, "bdf");
  EXPECT_DOUBLE_EQ(spec.solver.rtol, 1e-5);

  EXPECT_EQ(errorsOf("scenarios/tracks/manchester_r500.lua",
                     opts({"solver.stpe=1e-3", "trak.step=1", "track.segments[9].length=1",
                           "track.step=abc", "nonsense"})),
            "<command line>: --set trak.step=1: unknown block 'trak' (did you mean 'track'?)\n"
            "<command line>: --set track.segments[9].length=1: list position 9 out of range 1..3\n"
            "<command line>: --set nonsense: expected key=value, e.g. solver.step=5e-4\n"
            "<command line>: track: step must be a number [m], got string \"abc\"\n"
            "<command line>: solver: unknown key 'stpe' (did you mean 'step'?)\n"
            "<command line>: solver{} has no effect without a vehicle{} block (nothing is "
            "integrated)");
}

// A key that holds a file or profile name takes the text as given: "60e1" is the built-in rail,
// not the number 600 (the schema's String keys, and keys the scenario gave text).
TEST(ScenarioOverrides, NamesThatReadAsNumbersStayNames) {
  auto spec = loadScenario("tests/run/data/worn_wheels_tangent.lua",
                           opts({"profiles.rail=60e1", "profiles.wheel_right=s1002"}));
  EXPECT_EQ(spec.profiles.rail, "60e1");
  EXPECT_EQ(spec.profiles.wheel_right, "s1002");
  // A number key still reads numbers.
  spec = loadScenario("tests/run/data/worn_wheels_tangent.lua", opts({"profiles.r0=46e-2"}));
  EXPECT_DOUBLE_EQ(spec.profiles.r0, 0.46);
  // A train vehicle's own profiles{}: its block by name.
  spec = loadScenario("scenarios/train/three_wagons.lua",
                      opts({"train.vehicles[3].profiles.rail=60e1"}));
  ASSERT_EQ(spec.train.size(), 3U);
  EXPECT_EQ(spec.train[2].profiles.rail, "60e1");
}

TEST(ScenarioGood, UserPsdFunctionTableLoopsAndRequire) {
  auto spec = loadScenario("tests/scenario/good/user_psd.lua", opts());
  const auto& irr = spec.track.irregularities;
  EXPECT_EQ(irr.spectrum, "user");
  EXPECT_EQ(irr.seed, 3u);
  ASSERT_EQ(irr.user[0].omega.size(), 400u);  // tabulated Lua function
  ASSERT_EQ(irr.user[1].omega.size(), 21u);   // table of pairs
  EXPECT_TRUE(irr.enabled[0] && irr.enabled[1] && !irr.enabled[2] && !irr.enabled[3]);
  // The tabulated function reproduces the ORE formula it was written from.
  double om = irr.user[0].omega[200], A = 2.119e-7, Oc = 0.8246, Or = 0.0206;
  EXPECT_NEAR(irr.user[0].value[200], A * Oc * Oc / ((om * om + Or * Or) * (om * om + Oc * Oc)),
              1e-20);
  EXPECT_EQ(spec.solver.method, "bdf");
  EXPECT_DOUBLE_EQ(spec.run.distance, 300.0);
  EXPECT_DOUBLE_EQ(spec.run.output_every, 0.005);
}

TEST(ScenarioGood, ShippedTracksLoadThroughRequire) {
  for (int R : {300, 500, 700, 900}) {
    auto spec =
        loadScenario("scenarios/tracks/wheelset_validation_R" + std::to_string(R) + ".lua", opts());
    ASSERT_EQ(spec.track.segments.size(), 3u);
    EXPECT_DOUBLE_EQ(spec.track.segments[2].radius, R);
    EXPECT_EQ(spec.track.irregularities.source, rb::track::IrregularitySource::None);
  }
}

TEST(ScenarioVehicle, VehicleFileThroughRequire) {
  auto spec = loadScenario("tests/scenario/good/vehicle.lua", opts());
  ASSERT_TRUE(spec.has_vehicle);
  const auto& v = spec.vehicle;
  EXPECT_EQ(v.name, "two_body");
  EXPECT_DOUBLE_EQ(v.speed, 12.0);
  ASSERT_EQ(v.bodies.size(), 2u);
  EXPECT_EQ(v.bodies[0].kind, rb::vehicle::BodyKind::Frame);
  EXPECT_EQ(v.bodies[1].kind, rb::vehicle::BodyKind::Wheelset);
  EXPECT_DOUBLE_EQ(v.bodies[1].inertia[1], 112.0);
  ASSERT_EQ(v.elements.size(), 4u);
  EXPECT_EQ(v.elements[1].name, "primary_2");
  EXPECT_DOUBLE_EQ(v.elements[1].point1[1], -1.0);
  EXPECT_EQ(v.elements[1].direction, rb::vehicle::Direction::Z);
  EXPECT_EQ(v.elements[2].kind, rb::vehicle::ElementKind::SeriesSpringDamper);
  EXPECT_DOUBLE_EQ(v.elements[2].series_stiffness, 1e6);
  EXPECT_EQ(v.elements[3].kind, rb::vehicle::ElementKind::Bumpstop);
  EXPECT_EQ(v.elements[3].table_f, (std::vector<double>{0, 600}));
  EXPECT_EQ(v.elements[0].loc.file, "tests/scenario/good/vehicles/two_body.lua");
  EXPECT_EQ(v.elements[0].loc.line, 6);
}

TEST(ScenarioVehicle, BadVehicleReportsEveryProblem) {
  const std::string f = kBad + "vehicle.lua";
  EXPECT_EQ(errorsOf(f),
            f + ":5: vehicle.bodies[1] (body): mass must be > 0 kg, got -1\n" + f +
                ":5: vehicle.bodies[1] (body): inertia must be > 0 kg m^2 in every axis\n" + f +
                ":6: vehicle.bodies[2] (body): kind: unknown value 'carbody'; valid: car, bogie, "
                "wheelset, frame\n" +
                f +
                ":6: vehicle.bodies[2] (body): inertia must be {x, y, z} of numbers [kg m^2], got "
                "table\n" +
                f +
                ":9: vehicle.elements[1] (spring_damper): unknown key 'stiffnes' (did you mean "
                "'stiffness'?)\n" +
                f +
                ":9: vehicle.elements[1] (spring_damper): direction: unknown value 'q' (did you "
                "mean 'x'?); valid: axial, x, y, z\n" +
                f +
                ":10: vehicle.elements[2] (bumpstop): table[1] must be a pair of numbers {a, b}");
}

TEST(ScenarioContact, ProfilesAndContactBlocks) {
  auto spec = loadScenario("tests/scenario/good/contact.lua", opts());
  ASSERT_TRUE(spec.has_profiles && spec.has_contact);
  EXPECT_EQ(spec.profiles.wheel, "s1002");
  EXPECT_EQ(std::filesystem::path(spec.profiles.rail).filename(), "MBench_UIC60_v3.prr");
  EXPECT_TRUE(std::filesystem::path(spec.profiles.rail).is_absolute());
  EXPECT_DOUBLE_EQ(spec.profiles.lw, 0.7515);
  EXPECT_DOUBLE_EQ(spec.profiles.r0, 0.457);
  EXPECT_EQ(spec.contact.method, rb::dynamics::ContactMethod::Lut);
  EXPECT_DOUBLE_EQ(spec.contact.flange_stiffness, 7.075e13);
  EXPECT_DOUBLE_EQ(spec.contact.mu, 0.3);
}

TEST(ScenarioContact, ConflictsAndMissingProfileFile) {
  const std::string f = kBad + "contact_conflicts.lua";
  EXPECT_EQ(errorsOf(f),
            f + ":2: profiles: rail: file 'missing.prr' not found (looked in " + kBad +
                "missing.prr (the scene's folder), " + RB_SOURCE_DIR +
                "/missing.prr (the data directory))\n" + f +
                ":2: profiles: give either lr or gauge, not both (lr overrides the positioning)\n" +
                f +
                ":2: profiles: rail position and inclination come from profiles{}; remove "
                "track.rail_lr / track.rail_inclination\n" +
                f +
                ":3: contact: flange_stiffness applies to method 'lut' only (KEC treats the flange "
                "as a constraint)");
}

// ---------------------------------------------------------------------------------------------
// Hostile input: each class is bounded with a file:line error (the corpus in tests/hostile/ runs
// the same classes through the command line).

namespace {

namespace fs = std::filesystem;

// A fresh folder per test, removed at the end.
struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name)
      : path(fs::temp_directory_path() /
             ("rb_hostile_" + name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  std::string write(const std::string& file, const std::string& text) const {
    fs::path p = path / file;
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return p.string();
  }
};

const std::string kTrack = "track { segments = { tangent { length = 100 } } }\n";

}  // namespace

TEST(ScenarioHostile, DeepNestingIsAnErrorNotACrash) {
  TempDir t("nesting");
  std::string f = t.write("deep.lua",
                          "local t = {}\nfor i = 1, 200 do t = { t } end\n"
                          "track { segments = { tangent { length = 100 } }, deep = t }\n");
  std::string e = errorsOf(f);
  EXPECT_NE(e.find(f + ":3: track.deep"), std::string::npos) << e;
  EXPECT_NE(e.find("tables nested more than 32 levels deep"), std::string::npos) << e;
}

TEST(ScenarioHostile, ConversionLimitsValuesAndStrings) {
  TempDir t("values");
  std::string wide = t.write("wide.lua",
                             "local row = {}\nfor i = 1, 1000 do row[i] = i end\n"
                             "local g = {}\nfor i = 1, 1000 do g[i] = row end\n"
                             "track { segments = { tangent { length = 100 } }, g = g }\n");
  EXPECT_NE(errorsOf(wide).find("more than 500000 values"), std::string::npos);
  std::string str = t.write("str.lua",
                            "track { segments = { tangent { length = 100 } }, name = "
                            "string.rep('x', 2 << 20) }\n");
  EXPECT_NE(errorsOf(str).find(str + ":1: track.name: string of 2097152 bytes"), std::string::npos);
  // One string of almost 1 MiB used for 4000 values: within the Lua state's memory (Lua keeps
  // one copy) but 4 GB as the tree's copies (found by tests/fuzz: out of memory).
  std::string many = t.write("many.lua",
                             "local s = string.rep('x', (1 << 20) - 16)\nlocal v = {}\n"
                             "for i = 1, 4000 do v[i] = s end\n"
                             "track { segments = { tangent { length = 100 } }, names = v }\n");
  const std::string e = errorsOf(many);
  EXPECT_NE(e.find(many + ":4: track.names[65]: the scenario's strings hold more than 67108864 "
                          "bytes together"),
            std::string::npos)
      << e;
}

TEST(ScenarioHostile, BudgetErrorCannotBeSwallowedByPcall) {
  TempDir t("pcall");
  LoadOptions o = opts();
  o.instruction_limit = 5'000'000;
  std::string loop =
      t.write("loop.lua", "while true do\n  pcall(function() while true do end end)\nend\n");
  EXPECT_NE(errorsOf(loop, o).find("scenario exceeded its budget of 5000000 Lua instructions"),
            std::string::npos);
  // Caught, and the script then ends normally: still an error, at the loop's line.
  std::string caught =
      t.write("caught.lua", "pcall(function()\n  while true do end\nend)\n" + kTrack);
  EXPECT_EQ(
      errorsOf(caught, o),
      caught + ":2: scenario exceeded its budget of 5000000 Lua instructions (endless loop?)");
}

TEST(ScenarioHostile, FinalizersAndCostlyPatternsRefused) {
  TempDir t("gc");
  std::string gc = t.write("gc.lua", "setmetatable({}, { __gc = function() end })\n");
  EXPECT_EQ(errorsOf(gc), gc + ":1: setmetatable: finalizers (__gc) are not allowed in a scenario");
  std::string pat =
      t.write("pat.lua",
              "local s = string.rep('a', 5000)\nlocal i = s:find(string.rep('a*', 30) .. 'b')\n");
  EXPECT_NE(errorsOf(pat).find(pat + ":2: string.find: pattern too costly"), std::string::npos);
  // A missing argument of a guarded pattern function: the library's message, with the function's
  // name and the script's line (found by tests/fuzz: was "bad argument #2 to '?'").
  std::string arg = t.write("arg.lua", "local n = 1\nlocal x = string.gsub('a')\n");
  EXPECT_EQ(errorsOf(arg), arg + ":2: bad argument #2 to 'gsub' (string expected, got no value)");
  std::string ok = t.write("ok.lua",
                           "assert(('  ab  '):gsub('^%s*(.-)%s*$', '%1') == 'ab')\n"
                           "assert(select(2, string.rep('w ', 2000):gsub('%s+', ' ')) == 2000)\n" +
                               kTrack);
  EXPECT_NO_THROW(loadScenario(ok, opts()));
}

TEST(ScenarioHostile, MemoryExhaustedAtTheEndOfTheScriptIsAnInputError) {
  TempDir t("memory");
  std::string f = t.write(
      "mem.lua",
      "local hold = {}\n"
      "pcall(function() while true do hold[#hold + 1] = string.rep('y', 1 << 16) .. #hold end "
      "end)\n"
      "track { segments = { tangent { length = 400 } }, irregularities = psd { spectrum = 'user',\n"
      "  channels = { 'alignment' }, alignment = function(om) return 1e-7 end } }\n");
  rb::scenario::HostOptions ho;
  ho.memory_limit = std::size_t{32} << 20;
  rb::scenario::LuaHost host(ho);
  try {
    host.runFile(f);
    ADD_FAILURE() << "no error";
  } catch (const rb::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("scenario exceeded its memory budget of 32 MiB"),
              std::string::npos)
        << e.what();
    EXPECT_EQ(e.diagnostics().front().loc.file, f);
  }
}

TEST(ScenarioHostile, ErrorValuesKeepTheirLine) {
  TempDir t("errors");
  std::string a = t.write("a.lua", "local x = 1\nerror({})\n");
  EXPECT_EQ(errorsOf(a), a + ":2: error called with a table value (no message)");
  std::string b = t.write("b.lua", "\n\nerror(nil)\n");
  EXPECT_EQ(errorsOf(b), b + ":3: error called with nil (no message)");
  std::string c = t.write("c.lua", "error(42)\n");
  EXPECT_EQ(errorsOf(c), c + ":1: error 42");
  std::string psd =
      t.write("psd.lua",
              "track {\n  segments = { tangent { length = 400 } },\n"
              "  irregularities = psd { spectrum = 'user', channels = { 'vertical' },\n"
              "    vertical = function(om)\n      error('bad omega')\n    end },\n}\n");
  EXPECT_EQ(errorsOf(psd), psd + ":5: track.irregularities (psd): vertical: bad omega");
}

TEST(ScenarioHostile, RequireAcceptsOnlyPlainNamesInsideTheAllowedFolders) {
  TempDir t("require");
  TempDir outside("require_outside");
  outside.write("secret.lua", "return 'SECRET'\n");
  outside.write("pkg/secret.lua", "return 'SECRET'\n");
  fs::create_directory_symlink(outside.path / "pkg", t.path / "pkg");
  fs::create_symlink(outside.path / "secret.lua", t.path / "evil.lua");
  t.write("real.lua", "return { tangent { length = 100 } }\n");
  fs::create_symlink("real.lua", t.path / "alias.lua");
  for (const char* name : {"evil", "pkg.secret"}) {
    std::string f = t.write("s.lua", std::string("error(require '") + name + "')\n");
    std::string e = errorsOf(f);
    EXPECT_NE(e.find(f + ":1: require \"" + name + "\": "), std::string::npos) << e;
    EXPECT_NE(e.find("leads outside the folders modules may come from"), std::string::npos) << e;
  }
  for (const std::string& name : {std::string(".etc.passwd"), std::string("a..b"),
                                  std::string("1a"), std::string(5000, 'a')}) {
    std::string f = t.write("n.lua", "require '" + name + "'\n");
    std::string e = errorsOf(f);
    EXPECT_EQ(e.rfind(f + ":1: require", 0), 0u) << e;
  }
  std::string ok = t.write("ok.lua", "track { segments = require 'alias' }\n");
  EXPECT_NO_THROW(loadScenario(ok, opts()));
  t.write("a.lua", "return require 'b'\n");
  t.write("b.lua", "return require 'a'\n");
  std::string cyc = t.write("cyc.lua", "require 'a'\n");
  EXPECT_NE(errorsOf(cyc).find("require cycle: a -> b -> a"), std::string::npos) << errorsOf(cyc);
}

// A user's scene in a folder outside the checkout requires the shipped turnout library (whose
// 36 rail slices it names as slices/head_wNN.txt, relative to scenarios/turnout/), a shipped
// vehicle and the validation set-up: every file resolves beside the library that names it.
TEST(ScenarioDataFiles, ShippedLibrariesCarryTheirOwnFilesIntoAUsersFolder) {
  TempDir t("user_turnout");
  const std::string f =
      t.write("crossing.lua",
              "local c = require 'validation.common'\n"
              "local wagon = require 'vehicles.manchester_wagon1'\n"
              "local turnout = require 'turnout.lib'\n"
              "local wing, nose = turnout.crossing_rails(60, 200)\n"
              "local stock, blade = turnout.switch_rails(10, 40)\n"
              "track { segments = { tangent { length = 200 } }, step = 0.25 }\n"
              "profiles { wheel = 's1002', rail = '60e1', back_to_back = 1.360, gauge = 1.435,\n"
              "  r0 = 0.46, inclination = 0.025, rail_slices = { right = wing, left = stock },\n"
              "  extra_rails = { right = { nose }, left = { blade } } }\n"
              "contact { method = 'elastic', creep = 'polach', mu = 0.2364 }\n"
              "vehicle (wagon { speed = 20, start = 30 })\n"
              "c.abm(20, 1e-4)\n"
              "run { distance = 1 }\n");
  const auto spec = loadScenario(f, opts());
  const fs::path slices = fs::canonical(fs::path(RB_SOURCE_DIR) / "scenarios/turnout/slices");
  ASSERT_FALSE(spec.profiles.rail_slices[1].empty());
  for (const auto& sl : spec.profiles.rail_slices[1])
    EXPECT_EQ(fs::path(sl.rail).parent_path(), slices) << sl.rail;
  ASSERT_FALSE(spec.profiles.extra_rails[0].empty());
  for (const auto& sl : spec.profiles.extra_rails[0].front().slices)
    EXPECT_EQ(fs::path(sl.rail).parent_path(), slices) << sl.rail;
}

// Order of the places: beside the library whose text wrote the name (a constructor's table), then
// the scene's folder, then beside each library (a name in a library's plain table), then the data
// directory; two libraries with different files of the name are an error, not a guess.
TEST(ScenarioDataFiles, ALibrarysOwnFolderComesFirstAndAmbiguityIsAnError) {
  TempDir t("library_data");
  const std::string csv = "s [m], vertical [mm]\n0, 0\n100, 0\n200, 0\n300, 0\n400, 0\n500, 0\n";
  t.write("data.csv", csv);
  t.write("lib/data.csv", csv);
  t.write("lib/track.lua", "return measured { file = 'data.csv', unit = 'mm' }\n");
  const std::string own =
      t.write("own.lua",
              "track { segments = { tangent { length = 300 } }, irregularities = require "
              "'lib.track' }\n");
  EXPECT_EQ(loadScenario(own, opts()).track.irregularities.csv_path,
            fs::canonical(t.path / "lib/data.csv").string());

  // A plain table's name carries the scene's location: the scene's folder first, then the
  // libraries'.
  t.write("a/wheel.lua", "return { wheel = 'w.txt' }\n");
  t.write("a/w.txt", "0 0\n1 1\n");
  const std::string plain =
      t.write("plain.lua", kTrack + "local a = require 'a.wheel'\nprofiles { wheel = a.wheel }\n");
  EXPECT_EQ(loadScenario(plain, opts()).profiles.wheel, fs::canonical(t.path / "a/w.txt").string());
  t.write("b/wheel.lua", "return { wheel = 'w.txt' }\n");
  t.write("b/w.txt", "0 0\n2 2\n");
  const std::string two =
      t.write("two.lua", kTrack +
                             "local a = require 'a.wheel'\nlocal b = require 'b.wheel'\n"
                             "profiles { wheel = a.wheel }\n");
  std::string e = errorsOf(two);
  EXPECT_NE(e.find(two + ":4: profiles: wheel: file 'w.txt' is in the folder of "),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("the scene does not show which library named it"), std::string::npos) << e;
  t.write("w.txt", "0 0\n3 3\n");  // the scene's own file settles it
  EXPECT_EQ(loadScenario(two, opts()).profiles.wheel, fs::canonical(t.path / "w.txt").string());
}

// A name not found says where it was looked for and names the shipped file of that name.
TEST(ScenarioDataFiles, NotFoundListsThePlacesAndSuggestsTheShippedFile) {
  TempDir t("not_found_hint");
  t.write("lib/x.lua", "return 1\n");
  const std::string f = t.write("worn.lua", kTrack +
                                                "local x = require 'lib.x'\n"
                                                "profiles { wheel = 's1002_worn_0.3mm.txt' }\n");
  const std::string e = errorsOf(f);
  EXPECT_NE(e.find(f + ":3: profiles: wheel: file 's1002_worn_0.3mm.txt' not found (looked in " +
                   (t.path / "s1002_worn_0.3mm.txt").string() + " (the scene's folder), " +
                   (t.path / "lib/s1002_worn_0.3mm.txt").string() + " (the folder of "),
            std::string::npos)
      << e;
  EXPECT_NE(e.find(std::string(RB_SOURCE_DIR) + "/s1002_worn_0.3mm.txt (the data directory))"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("; did you mean 'profiles/s1002_worn_0.3mm.txt' (shipped in the data "
                   "directory)?"),
            std::string::npos)
      << e;
  // The suggestion resolves.
  const std::string fixed =
      t.write("fixed.lua", kTrack + "profiles { wheel = 'profiles/s1002_worn_0.3mm.txt' }\n");
  EXPECT_EQ(errorsOf(fixed).find("not found"), std::string::npos) << errorsOf(fixed);
}

TEST(ScenarioOverrides, BadListPositionsAreCommandLineErrors) {
  EXPECT_EQ(errorsOf("scenarios/tracks/manchester_r500.lua",
                     opts({"track.segments[-1].length=5",
                           "track.segments[99999999999999999999999].length=5"})),
            "<command line>: --set track.segments[-1].length=5: '-1' is neither a key name nor a "
            "list position (1, 2, ...)\n"
            "<command line>: --set track.segments[99999999999999999999999].length=5: list "
            "position 99999999999999999999999 out of range 1..3");
}

TEST(ScenarioErrors, StudyBlockAndSolverWithoutVehicleAreErrors) {
  TempDir t("blocks");
  std::string f =
      t.write("s.lua", kTrack + "study { base = 'x.lua' }\nsolver { method = 'rk4' }\n");
  EXPECT_EQ(errorsOf(f),
            f +
                ":2: study{} belongs in a study file of its own, run with `workbench study FILE`; "
                "a scenario cannot hold one\n" +
                f + ":3: solver{} has no effect without a vehicle{} block (nothing is integrated)");
}

TEST(ScenarioSchema, HelpAndValidatorAgreeOnRanges) {
  const std::string help = rb::scenario::referenceText();
  EXPECT_NE(help.find("rtol (number) default 1e-06, range (0, 1)\n"), std::string::npos);
  EXPECT_NE(help.find("components (integer) default 2000, range [1, 100000]\n"), std::string::npos);
  TempDir t("ranges");
  std::string f =
      t.write("r.lua",
              "track { segments = { tangent { length = 400 } },\n"
              "  irregularities = psd { spectrum = 'ore_b176_low', components = 100001 } }\n"
              "vehicle (require 'vehicles.manchester_wagon1' { speed = 10 })\n"
              "solver { method = 'bdf', rtol = 1 }\n"
              "contact { method = 'guided' }\n");
  EXPECT_EQ(errorsOf(f), f +
                             ":2: track.irregularities (psd): components must be <= 100000, got "
                             "100001\n" +
                             f + ":4: solver: rtol must be < 1, got 1");
}

namespace {

// Every entry of an enum's name table parses back to its value, and the schema key that offers
// the enum's names offers exactly the table's names.
template <class E>
void expectTableIsSchemaChoice(const std::string& block, const std::string& key,
                               std::vector<std::string> extra = {}) {
  for (const auto& e : nameTable(E{})) {
    EXPECT_EQ(rb::parse<E>(e.name), e.value) << e.name;
    EXPECT_EQ(rb::nameOf(e.value), e.name);
  }
  const rb::scenario::KeySpec* k = rb::scenario::block(block).key(key);
  ASSERT_NE(k, nullptr) << block << "." << key;
  std::vector<std::string> names = rb::namesOf<E>();
  names.insert(names.end(), extra.begin(), extra.end());
  EXPECT_EQ(k->choices, names) << block << "." << key;
}

}  // namespace

TEST(ScenarioSchema, ChoicesComeFromTheNameTables) {
  // contact.method also offers "guided": no contact model (scenario.hpp).
  expectTableIsSchemaChoice<rb::dynamics::ContactMethod>("contact", "method",
                                                         {rb::scenario::kGuidedContact});
  expectTableIsSchemaChoice<rb::dynamics::CreepModel>("contact", "creep");
  expectTableIsSchemaChoice<rb::creep::FastsimBound>("contact.fastsim", "bound");
  expectTableIsSchemaChoice<rb::dynamics::NormalForceCoupling>("contact", "normal_forces");
  expectTableIsSchemaChoice<rb::dynamics::WheelsetSpin>("contact", "wheelset_spin");
  expectTableIsSchemaChoice<rb::vehicle::BodyKind>("body", "kind");
  expectTableIsSchemaChoice<rb::vehicle::Direction>("spring_damper", "direction");
  expectTableIsSchemaChoice<rb::track::Side>("curve", "side");
  expectTableIsSchemaChoice<rb::track::CsvUnit>("measured", "unit");
  expectTableIsSchemaChoice<rb::track::Beyond>("measured", "beyond");
  expectTableIsSchemaChoice<rb::track::Spectrum>("psd", "spectrum");
  expectTableIsSchemaChoice<rb::track::Channel>("psd", "channels");
  expectTableIsSchemaChoice<rb::integ::JacobianMode>("solver", "jacobian");
  EXPECT_EQ(rb::scenario::block("track").key("segments")->kinds,
            rb::namesOf<rb::track::SegmentKind>());
  expectTableIsSchemaChoice<rb::vehicle::ForceFrame>("external_force", "frame");
  expectTableIsSchemaChoice<rb::suspension::ForceLawKind>("external_force", "law");
  expectTableIsSchemaChoice<rb::suspension::ForceAbscissa>("external_force", "over");
  // The suspension elements, then the external force (not an ElementKind: vehicle/names.hpp).
  std::vector<std::string> elements = rb::namesOf<rb::vehicle::ElementKind>();
  elements.emplace_back(rb::vehicle::kExternalForceKind);
  EXPECT_EQ(rb::scenario::block("vehicle").key("elements")->kinds, elements);
  // The spectra of the table are the ones the track module parses.
  for (const auto& e : rb::track::kSpectrumNames)
    EXPECT_EQ(rb::track::parseSpectrum(e.name), e.value) << e.name;
}

TEST(ScenarioSchema, SolverMethodsComeFromTheRegistry) {
  std::vector<std::string> names;
  for (const auto& m : rb::integ::methods()) names.push_back(m.name);
  EXPECT_EQ(rb::scenario::block("solver").key("method")->choices, names);
  EXPECT_TRUE(rb::integ::isFixedStep("rk4"));
  EXPECT_TRUE(rb::integ::isFixedStep("abm"));
  EXPECT_FALSE(rb::integ::isFixedStep("bdf"));
  EXPECT_FALSE(rb::integ::isFixedStep("nonsense"));
  for (const auto& m : rb::integ::methods()) {
    rb::integ::SolverSpec s;
    s.method = m.name;
    EXPECT_EQ(rb::integ::makeIntegrator(s)->name(), m.name);
    EXPECT_EQ(rb::integ::makeIntegrator(s)->isFixedStep(), m.fixed_step) << m.name;
  }
}

TEST(ScenarioSchema, ReferenceShowsTheHelpOfEveryChoice) {
  const std::string help = rb::scenario::referenceText();
  for (const auto& e : rb::dynamics::kWheelsetSpinNames)
    EXPECT_NE(help.find(std::string(e.name) + ": " + std::string(e.help)), std::string::npos)
        << e.name;
}

// A vehicle with wheelsets and no contact{} block is an error at the vehicle, never a silent
// guided run; guided wheelsets are asked for by name, and then take no contact keys or profiles.
TEST(ScenarioContact, WheelsetsWithoutContactBlockAreAnError) {
  TempDir t("guided");
  const std::string wagon = "vehicle (require 'vehicles.manchester_wagon1' { speed = 10 })\n";
  const std::string missing = t.write("missing.lua", kTrack + wagon);
  EXPECT_EQ(errorsOf(missing),
            missing +
                ":2: vehicle: 4 wheelsets and no contact{} block: give contact { method = "
                "\"kec\" } (or \"lut\") for wheel/rail contact, or contact { method = \"guided\" } "
                "for wheelsets that follow the track kinematically (no wheel/rail forces)");
  const std::string guided =
      t.write("guided.lua", kTrack + wagon + "contact { method = 'guided' }\n");
  auto spec = loadScenario(guided, opts());
  EXPECT_TRUE(spec.guided);
  EXPECT_FALSE(spec.has_contact);
  const std::string extra = t.write("extra.lua", kTrack + wagon +
                                                     "profiles { wheel = 's1002' }\n"
                                                     "contact { method = 'guided', mu = 0.3 }\n");
  EXPECT_EQ(errorsOf(extra),
            extra +
                ":4: contact: mu has no effect with method = \"guided\" (the wheelsets follow the "
                "track kinematically, no wheel/rail forces)\n" +
                extra +
                ":3: profiles{} has no effect with contact { method = \"guided\" } (no wheel/rail "
                "contact); remove it or choose a contact method");
  // A vehicle without wheelsets (a frame alone) needs no contact model.
  const std::string frame = t.write(
      "frame.lua", kTrack +
                       "vehicle { speed = 10, bodies = { body { name = 'f', kind = 'frame', mass = "
                       "1, inertia = {1, 1, 1} } } }\n");
  EXPECT_NO_THROW(loadScenario(frame, opts()));
}

// A built-in profile name in the wrong case is not a file: the error points to the built-in.
TEST(ScenarioContact, ProfileNameInTheWrongCaseGetsADidYouMean) {
  TempDir t("profile_case");
  const std::string f = t.write("p.lua", kTrack + "profiles { wheel = 'S1002', rail = '60E1' }\n");
  const std::string e = errorsOf(f);
  EXPECT_NE(e.find(f + ":2: profiles: wheel: file 'S1002' not found"), std::string::npos) << e;
  EXPECT_NE(e.find("(did you mean the built-in profile 's1002'?)"), std::string::npos) << e;
  EXPECT_NE(e.find(f + ":2: profiles: rail: file '60E1' not found"), std::string::npos) << e;
  EXPECT_NE(e.find("(did you mean the built-in profile '60e1'?)"), std::string::npos) << e;
}

// Synthesised irregularities fade in over track.irregularities.fade_in (default 20 m) with a
// raised cosine: no step at s = 0, where the perfect track before the start meets the synthesis
// (an FRA class 4 wagon could not even start: its KEC constraints had no solution at t = 0).
TEST(ScenarioTrack, IrregularitiesFadeInFromTheStart) {
  TempDir t("fade");
  const std::string f =
      t.write("f.lua",
              "track { segments = { tangent { length = 100 } },\n"
              "  irregularities = psd { spectrum = 'fra_class_4', seed = 3 } }\n");
  const auto on = loadScenario(f, opts());
  EXPECT_DOUBLE_EQ(on.track.irregularities.fade_in, 20.0);
  const auto off = loadScenario(f, opts({"track.irregularities.fade_in=0"}));
  const auto a = rb::track::compileTrack(on.track);
  const auto b = rb::track::compileTrack(off.track);
  const auto& ia = *a.irregularities();
  const auto& ib = *b.irregularities();
  double step0 = 0.0;
  for (double x : ib.at(0.0).xi) step0 = std::max(step0, std::abs(x));
  EXPECT_GT(step0, 1e-4);  // today's start: a step of a tenth of a millimetre or more
  for (int c = 0; c < rb::track::kChannels; ++c) {
    const auto k = static_cast<std::size_t>(c);
    EXPECT_EQ(ia.at(0.0).xi[k], 0.0);
    EXPECT_NEAR(ia.at(10.0).xi[k], 0.5 * ib.at(10.0).xi[k], 1e-12);  // half-way: (1 - cos)/2
    EXPECT_NEAR(ia.at(5.0).xi[k], 0.5 * (1 - std::cos(M_PI / 4)) * ib.at(5.0).xi[k], 1e-12);
    EXPECT_NEAR(ia.at(40.0).xi[k], ib.at(40.0).xi[k], 1e-12);  // unchanged beyond the fade-in
  }
  EXPECT_NE(errorsOf(f, opts({"track.irregularities.fade_in=-1"})).find("fade_in must be >= 0"),
            std::string::npos);
}

// A mistyped require is collected like any other problem: the rest of the file runs on a
// stand-in, its other errors are reported with it, and only the blocks made from the missing
// module are left unchecked (no error about them being absent).
TEST(ScenarioErrors, MissingModuleDoesNotHideTheOtherErrors) {
  TempDir t("require");
  const std::string f =
      t.write("r.lua",
              "local wagon = require 'vehicles.manchester_wagn1'\n"
              "local lib = require 'tracks.lib'\n"
              "track { segments = lib.manchester_r500(), stpe = 0.5 }\n"
              "vehicle (wagon { speed = 20 })\n"
              "contact { method = 'kec', mu = -1 }\n"
              "for i, b in ipairs(wagon.bodies) do error('a stand-in is an empty list') end\n"
              "local n = #wagon.bodies + wagon.x * 2\n"
              "solver { method = 'dopri5', rtol = 2 }\n");
  const std::string e = errorsOf(f);
  EXPECT_EQ(e.rfind(f + ":1: require \"vehicles.manchester_wagn1\": module not found (did you "
                        "mean \"vehicles.manchester_wagon1\"?); tried:",
                    0),
            0u)
      << e;
  EXPECT_NE(e.find(f + ":3: track: unknown key 'stpe' (did you mean 'step'?)"), std::string::npos)
      << e;
  EXPECT_NE(e.find(f + ":5: contact: mu must be"), std::string::npos) << e;
  EXPECT_NE(e.find(f + ":8: solver: rtol must be < 1, got 2"), std::string::npos) << e;
  EXPECT_EQ(e.find("vehicle"), e.find("vehicles.manchester_wagn1")) << e;  // nothing else on it
  EXPECT_EQ(e.find("solver{} has no effect"), std::string::npos) << e;
  // A script error after a missing module keeps the module's error first.
  const std::string g = t.write("g.lua",
                                "local m = require 'nope.nothing'\n"
                                "track { segments = { tangent { length = 100 } } }\n"
                                "local x = math.floor(m.value)\n");
  const std::string eg = errorsOf(g);
  EXPECT_EQ(eg.rfind(g + ":1: require \"nope.nothing\": module not found", 0), 0u) << eg;
  EXPECT_NE(eg.find(g + ":3:"), std::string::npos) << eg;
}

// contact.creep = "fastsim" with its grid (contact.fastsim, creep/fastsim.hpp defaults), and the
// grid refused out of range, with another creep law, or with an unknown key, at file:line.
TEST(ScenarioContact, FastsimCreepLawAndGrid) {
  const std::string f = "scenarios/validation/case1_R500_lut.lua";
  auto spec = loadScenario(f, opts({"contact.creep=fastsim"}));
  EXPECT_EQ(spec.contact.creep, rb::dynamics::CreepModel::Fastsim);
  EXPECT_EQ(spec.contact.fastsim.strips, rb::creep::FastsimGrid{}.strips);
  EXPECT_EQ(spec.contact.fastsim.elements, rb::creep::FastsimGrid{}.elements);
  spec = loadScenario(f, opts({"contact.creep=fastsim", "contact.fastsim.strips=8",
                               "contact.fastsim.elements=64", "contact.fastsim.bound=elliptic"}));
  EXPECT_EQ(spec.contact.fastsim.strips, 8);
  EXPECT_EQ(spec.contact.fastsim.elements, 64);
  EXPECT_EQ(spec.contact.fastsim.bound, rb::creep::FastsimBound::Elliptic);
  EXPECT_EQ(errorsOf(f, opts({"contact.creep=fastsim", "contact.fastsim.strips=0",
                              "contact.fastsim.elements=2.5", "contact.fastsim.bound=flat"})),
            "<command line>: contact.fastsim: strips must be >= 1, got 0\n"
            "<command line>: contact.fastsim: elements must be a whole number, got 2.5\n"
            "<command line>: contact.fastsim: bound: unknown value 'flat'; valid: parabolic, "
            "elliptic");
  EXPECT_EQ(errorsOf(f, opts({"contact.fastsim.elements=16"})),
            "<command line>: contact: fastsim applies to creep = \"fastsim\" only (creep = "
            "\"polach\")");
}

TEST(ScenarioExternalForce, TheLuaElementBecomesItsSpec) {
  // tests/run/data/external_force_tangent.lua: the wagon's 50 suspension elements and one
  // external_force{} in vehicle.elements, a ramp at 5 kN/s from 0.5 s to 10 kN.
  const std::string scene = "tests/run/data/external_force_tangent.lua";
  const rb::scenario::ScenarioSpec s = loadScenario(scene, opts());
  EXPECT_EQ(s.vehicle.elements.size(), 50u);
  ASSERT_EQ(s.vehicle.external_forces.size(), 1u);
  const rb::vehicle::ExternalForceSpec& f = s.vehicle.external_forces[0];
  EXPECT_EQ(f.name, "push");
  EXPECT_EQ(f.body, "car");
  EXPECT_EQ(f.point, Eigen::Vector3d(0.0, 0.0, -0.9725));
  EXPECT_EQ(f.frame, rb::vehicle::ForceFrame::Track);
  EXPECT_EQ(f.direction, Eigen::Vector3d(0.0, 1.0, 0.0));
  EXPECT_EQ(f.law.kind, rb::suspension::ForceLawKind::Ramp);
  EXPECT_EQ(f.law.value, 10e3);
  EXPECT_EQ(f.law.initial, 0.0);
  EXPECT_EQ(f.law.start, 0.5);
  EXPECT_EQ(f.law.duration, 2.0);  // |value - initial| / rate
  EXPECT_TRUE(std::isinf(f.law.hold));
  EXPECT_EQ(f.loc.line, 14);
  // Its keys by name from the command line, as any element's.
  const auto set =
      loadScenario(scene, opts({"vehicle.elements.push.value=5e3", "vehicle.elements.push.hold=1.5",
                                "vehicle.elements.push.frame=body"}))
          .vehicle.external_forces[0];
  EXPECT_EQ(set.law.duration, 1.0);
  EXPECT_EQ(set.law.hold, 1.5);
  EXPECT_EQ(set.frame, rb::vehicle::ForceFrame::Body);
  EXPECT_EQ(errorsOf(scene, opts({"vehicle.elements.push.duration=2"})),
            "<command line>: vehicle.elements[51] (external_force): give rate or duration, not "
            "both");
}
