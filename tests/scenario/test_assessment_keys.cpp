// run.assessment: its keys are validated like every key (file:line: message, all at once), the
// defaults are those of the reference, and `run.assessment = true` asks for every group.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "workbench/core/error.hpp"
#include "workbench/scenario/scenario.hpp"

namespace fs = std::filesystem;

namespace {

std::string write(const std::string& name, const std::string& text) {
  const fs::path d = fs::temp_directory_path() / "rb_test_assessment_keys";
  fs::create_directories(d);
  const std::string p = (d / name).string();
  std::ofstream(p) << text;
  return p;
}

rb::scenario::LoadOptions opts() {
  rb::scenario::LoadOptions o;
  o.root = RB_SOURCE_DIR;
  return o;
}

std::string errorsOf(const std::string& file) {
  try {
    rb::scenario::loadScenario(file, opts());
  } catch (const rb::InputError& e) {
    return e.what();
  }
  return "<no error>";
}

const std::string kTrack = "track { segments = { tangent { length = 100 } } }\n";

}  // namespace

TEST(AssessmentKeys, BadKeysAndValuesWithFileLine) {
  const std::string p = write("bad.lua", kTrack +
                                             "run {\n"
                                             "  assessment = { safty = true, comfort = 'yes',\n"
                                             "    sample_every = -1, alpha = 2,\n"
                                             "    floor_positions = { 1, 'x' }, mu = 0,\n"
                                             "    instability_frequency = 1 },\n"
                                             "}\n");
  const std::string e = errorsOf(p);
  for (const std::string& want :
       {p + ":3: run.assessment: unknown key 'safty' (did you mean 'safety'?)",
        p + ":3: run.assessment: comfort must be true or false, got",
        p + ":4: run.assessment: sample_every", p + ":4: run.assessment: alpha",
        p + ":5: run.assessment: floor_positions[2] must be a finite number",
        p + ":5: run.assessment: mu must be in (0, 2] or -1",
        p + ":6: run.assessment: instability_frequency must be in (2, 50] Hz or 0"})
    EXPECT_NE(e.find(want), std::string::npos) << "missing: " << want << "\nin:\n" << e;
}

TEST(AssessmentKeys, NotATable) {
  const std::string p = write("not_table.lua", kTrack + "run { assessment = 3 }\n");
  EXPECT_NE(errorsOf(p).find(p + ":2: run: assessment must be"), std::string::npos) << errorsOf(p);
}

TEST(AssessmentKeys, DefaultsAndTrue) {
  const std::string none = write("none.lua", kTrack + "run { }\n");
  const auto a = rb::scenario::loadScenario(none, opts()).run.assessment;
  EXPECT_FALSE(a.any());
  EXPECT_EQ(a.sample_every, 2.5e-3);
  EXPECT_LT(a.alpha, 0.0);  // from vehicle.category (1.0 when the vehicle states none)
  EXPECT_EQ(a.yq_limit, 0.8);
  EXPECT_EQ(a.comfort_limit, 2.0);
  EXPECT_LT(a.mu, 0.0);  // contact.mu
  EXPECT_TRUE(rb::scenario::loadScenario(none, opts()).run.output_patches);

  const std::string all = write("all.lua", kTrack + "run { assessment = true }\n");
  const auto b = rb::scenario::loadScenario(all, opts()).run.assessment;
  EXPECT_TRUE(b.safety && b.stability && b.comfort && b.wear && b.all);

  const std::string some =
      write("some.lua", kTrack +
                            "run { output = { patches = false }, assessment = { safety = true, "
                            "floor_positions = { -5, 0, 5 }, alpha = 0.85, mu = 0.3, "
                            "instability_frequency = 5, sample_every = 1e-3 } }\n");
  const auto s = rb::scenario::loadScenario(some, opts());
  const auto& c = s.run.assessment;
  EXPECT_TRUE(c.safety);
  EXPECT_FALSE(c.stability || c.comfort || c.wear || c.all);
  EXPECT_EQ(c.floor_positions, (std::vector<double>{-5, 0, 5}));
  EXPECT_EQ(c.alpha, 0.85);
  EXPECT_EQ(c.mu, 0.3);
  EXPECT_EQ(c.instability_frequency, 5.0);
  EXPECT_EQ(c.sample_every, 1e-3);
  EXPECT_FALSE(s.run.output_patches);
}
