// /stats of every vehicle run (docs/run_stats.md): the effects of the compiled model, the shares
// of the rhs stages, and results that do not depend on the stage timing.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <numeric>
#include <string>
#include <vector>

#include "h5read.hpp"
#include "workbench/app/run.hpp"
#include "workbench/io/read_stats.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/run/run_stats.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path& tmp() {
  static const fs::path d = [] {
    fs::path p = fs::temp_directory_path() / "rb_test_stages";
    fs::create_directories(p);
    return p;
  }();
  return d;
}

const char* const kKec = "scenarios/validation/case3_kec.lua";
const char* const kLut = "scenarios/validation/case3_lut.lua";
const char* const kGuided = "scenarios/vehicle/manchester_guided_r500.lua";

rb::run::Model compiled(const std::string& scenario, std::vector<std::string> overrides = {}) {
  rb::run::CompileOptions o;
  o.scenario = scenario;
  o.overrides = std::move(overrides);
  o.root = RB_SOURCE_DIR;
  o.table_cache = (tmp() / ".table-cache").string();
  return rb::run::compile(o);
}

std::vector<std::string> effectLines(const rb::run::Model& m) {
  std::vector<std::string> out;
  for (const auto& e : rb::run::compiledEffects(m)) out.push_back(rb::run::effectLine(e));
  return out;
}

bool has(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}
bool hasPrefix(const std::vector<std::string>& v, const std::string& prefix) {
  return std::any_of(v.begin(), v.end(),
                     [&](const std::string& s) { return s.rfind(prefix, 0) == 0; });
}

// Runs a scenario into tmp()/name.h5 with 1 in `period` rhs evaluations timed.
std::string runInto(const std::string& scenario, const std::string& name, int period,
                    std::vector<std::string> overrides) {
  rb::app::RunOptions o;
  o.scenario = scenario;
  o.root = RB_SOURCE_DIR;
  o.out = (tmp() / (name + ".h5")).string();
  o.overrides = std::move(overrides);
  o.quiet = true;
  o.stage_period = period;
  EXPECT_EQ(rb::app::runScenario(o), 0) << scenario;
  return o.out;
}

std::vector<std::string> stringDataset(hid_t f, const std::string& path) {
  hid_t d = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
  if (d < 0) return {};
  hid_t t = H5Dget_type(d);
  hid_t s = H5Dget_space(d);
  const auto n = static_cast<std::size_t>(H5Sget_simple_extent_npoints(s));
  const std::size_t width = H5Tget_size(t);
  std::string raw(n * width, '\0');
  H5Dread(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, raw.data());
  std::vector<std::string> out;
  for (std::size_t i = 0; i < n; ++i) {
    std::string v = raw.substr(i * width, width);
    out.push_back(v.substr(0, v.find('\0')));
  }
  H5Sclose(s);
  H5Tclose(t);
  H5Dclose(d);
  return out;
}

// Every numeric dataset of a file outside /stats, by path, as raw doubles.
struct Datasets {
  std::vector<std::pair<std::string, std::vector<double>>> all;
};
herr_t collect(hid_t obj, const char* name, const H5O_info_t* info, void* data) {
  if (info->type != H5O_TYPE_DATASET || std::strncmp(name, "stats", 5) == 0) return 0;
  hid_t d = H5Dopen2(obj, name, H5P_DEFAULT);
  hid_t t = H5Dget_type(d);
  const H5T_class_t cls = H5Tget_class(t);
  if (cls == H5T_FLOAT || cls == H5T_INTEGER) {
    hid_t s = H5Dget_space(d);
    std::vector<double> v(static_cast<std::size_t>(H5Sget_simple_extent_npoints(s)));
    if (!v.empty()) H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
    static_cast<Datasets*>(data)->all.emplace_back(name, std::move(v));
    H5Sclose(s);
  }
  H5Tclose(t);
  H5Dclose(d);
  return 0;
}
Datasets datasets(const std::string& path) {
  Datasets out;
  hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(f, 0) << path;
  H5Ovisit2(f, H5_INDEX_NAME, H5_ITER_INC, collect, &out, H5O_INFO_BASIC);
  H5Fclose(f);
  return out;
}

// ---- Effects of the compiled model -------------------------------------------------------------

TEST(RunEffects, KecAndLutDifferInTheirContactMethodAndFlangeContact) {
  const auto kec = effectLines(compiled(kKec));
  const auto lut = effectLines(compiled(kLut));
  EXPECT_TRUE(has(kec, "contact: kec"));
  EXPECT_TRUE(has(kec, "flange_contact: kec_band"));
  EXPECT_TRUE(has(lut, "contact: lut"));
  EXPECT_TRUE(has(lut, "flange_contact: hertz"));
  for (const auto* v : {&kec, &lut}) {
    EXPECT_TRUE(has(*v, "creep_forces: polach"));
    EXPECT_TRUE(has(*v, "normal_forces: consistent"));
    EXPECT_TRUE(has(*v, "wheelset_spin: free"));
    EXPECT_TRUE(has(*v, "irregularities: psd"));
    EXPECT_TRUE(has(*v, "patches"));
    EXPECT_TRUE(hasPrefix(*v, "series_dampers: "));
    EXPECT_TRUE(has(*v, "bump_stops: 2"));
    EXPECT_FALSE(hasPrefix(*v, "guided_wheelsets"));
  }
  // Apart from the method and its flange contact, the two scenarios compile the same effects.
  auto mapped = kec;
  for (auto& line : mapped) {
    if (line == "contact: kec") line = "contact: lut";
    if (line == "flange_contact: kec_band") line = "flange_contact: hertz";
  }
  EXPECT_EQ(mapped, lut);
}

TEST(RunEffects, GuidedVehicleHasNoContactEffects) {
  const rb::run::Model m = compiled(kGuided);
  const auto g = effectLines(m);
  ASSERT_FALSE(g.empty());
  EXPECT_EQ(g.front(), "guided_wheelsets");
  for (const char* p : {"contact", "creep", "normal_forces", "flange_contact", "wheelset_spin",
                        "patches", "irregularities"})
    EXPECT_FALSE(hasPrefix(g, p)) << p;
  EXPECT_TRUE(has(g, "element_outputs: 2"));
  EXPECT_TRUE(has(g, "body_accelerations"));
  EXPECT_TRUE(has(g, "assessment: stability+comfort"));
  EXPECT_EQ(rb::run::effectsSummary(rb::run::compiledEffects(m)).rfind("guided wheelsets, ", 0),
            0u);
}

TEST(RunEffects, DerivedFromTheModelNotTheScenarioText) {
  // Creep "none" evaluates no creep forces, so no coupling either; a prescribed spin and the
  // patch outputs switched off are seen in the list.
  const auto e =
      effectLines(compiled(kKec, {"contact.creep=none", "contact.wheelset_spin=prescribed",
                                  "run.output.patches=false"}));
  EXPECT_FALSE(hasPrefix(e, "creep"));
  EXPECT_FALSE(hasPrefix(e, "normal_forces"));
  EXPECT_FALSE(has(e, "patches"));
  EXPECT_TRUE(has(e, "wheelset_spin: prescribed"));
  // The minimal scene of the effect studies: no irregularities, bump stops or series dampers.
  const auto minimal = effectLines(compiled("scenarios/studies/bases/minimal.lua"));
  EXPECT_FALSE(hasPrefix(minimal, "irregularities"));
  EXPECT_FALSE(hasPrefix(minimal, "bump_stops"));
  EXPECT_FALSE(hasPrefix(minimal, "series_dampers"));
  EXPECT_TRUE(hasPrefix(minimal, "spring_dampers: "));
}

// ---- Stage shares in /stats --------------------------------------------------------------------

void expectShares(const std::string& file, const std::vector<std::string>& stages) {
  hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const auto names = stringDataset(f, "/stats/stage_names");
  const auto share = h5test::dataset(f, "/stats/stage_share");
  const auto seconds = h5test::dataset(f, "/stats/stage_seconds");
  std::vector<std::string> expected = stages;
  expected.emplace_back("integrator");
  expected.emplace_back("observer");
  EXPECT_EQ(names, expected);
  ASSERT_EQ(share.size(), names.size());
  ASSERT_EQ(seconds.size(), names.size());
  for (std::size_t i = 0; i < share.size(); ++i) {
    EXPECT_GE(share[i], 0.0) << names[i];
    EXPECT_GE(seconds[i], 0.0) << names[i];
  }
  EXPECT_NEAR(std::accumulate(share.begin(), share.end(), 0.0), 1.0, 1e-12);
  // Every evaluation of the integrator was timed (period 1), kept or left out as descheduled,
  // but those served by the observer's evaluation of the same state (timed as the observer's).
  const auto shared = h5test::exists(f, "/stats") &&
                              H5Aexists_by_name(f, "/stats", "shared_evaluations", H5P_DEFAULT) > 0
                          ? h5test::numAttr<std::int64_t>(f, "/stats", "shared_evaluations")
                          : 0;
  const auto samples = h5test::numAttr<std::int64_t>(f, "/stats", "stage_samples") +
                       h5test::numAttr<std::int64_t>(f, "/stats", "stage_rejected") + shared;
  EXPECT_EQ(h5test::numAttr<std::int64_t>(f, "/stats", "stage_period"), 1);
  EXPECT_EQ(samples, h5test::numAttr<std::int64_t>(f, "/stats", "rhs_evals") +
                         h5test::numAttr<std::int64_t>(f, "/stats", "rhs_evals_jac"));
  H5Fclose(f);
}

TEST(RunStageShares, ContactRunSharesSumToOne) {
  const std::string out = runInto(kKec, "kec_shares", 1, {"run.distance=2"});
  expectShares(out,
               {"coordinates", "constraints", "vehicle_forces", "free_bodies", "contact_patches",
                "augmented_system", "coupling", "checks_outputs", "series_rates"});
  // /stats/effects is the compiled list, one effect per line.
  std::string lines;
  for (const auto& l : effectLines(compiled(kKec, {"run.distance=2"})))
    lines += (lines.empty() ? "" : "\n") + l;
  hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_EQ(h5test::stringAttr(f, "/stats", "effects"), lines);
  H5Fclose(f);
  // The reader of the studies sees the effects and the shares.
  const auto rec = rb::io::readStats(out);
  ASSERT_TRUE(rec.has_value());
  EXPECT_EQ(rec->text.at("effects"), lines);
  double sum = 0.0;
  for (const auto& [k, v] : rec->number)
    if (k.rfind("stage_share_", 0) == 0) sum += v;
  EXPECT_NEAR(sum, 1.0, 1e-12);
  EXPECT_GT(rec->number.at("stage_share_coupling"), 0.0);
  EXPECT_EQ(rec->number.at("stage_period"), 1.0);
}

TEST(RunStageShares, GuidedRunHasItsOwnStages) {
  const std::string out = runInto(kGuided, "guided_shares", 1, {"run.distance=20"});
  expectShares(out, {"coordinates", "vehicle_forces", "free_bodies", "series_rates"});
}

TEST(RunStageShares, NoTimingWritesNoShares) {
  const std::string out = runInto(kGuided, "guided_off", 0, {"run.distance=5"});
  hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_FALSE(h5test::exists(f, "/stats/stage_share"));
  EXPECT_EQ(h5test::numAttr<std::int64_t>(f, "/stats", "stage_samples"), 0);
  EXPECT_NE(h5test::stringAttr(f, "/stats", "effects"), "");
  H5Fclose(f);
}

// ---- Timing never feeds back into the dynamics -------------------------------------------------

void expectSameResults(const std::string& scenario, const std::string& name,
                       const std::vector<std::string>& overrides) {
  const Datasets off = datasets(runInto(scenario, name + "_off", 0, overrides));
  const Datasets every = datasets(runInto(scenario, name + "_every", 1, overrides));
  ASSERT_EQ(off.all.size(), every.all.size());
  ASSERT_GT(off.all.size(), 10u);
  for (std::size_t i = 0; i < off.all.size(); ++i) {
    const auto& [path, a] = off.all[i];
    const auto& b = every.all[i].second;
    EXPECT_EQ(path, every.all[i].first);
    ASSERT_EQ(a.size(), b.size()) << path;
    EXPECT_TRUE(a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0)
        << path << " differs with stage timing on";
  }
}

TEST(RunStageTiming, KecResultsAreBitIdenticalWithTimingOnAndOff) {
  expectSameResults(kKec, "kec_same", {"run.distance=2"});
}
TEST(RunStageTiming, LutResultsAreBitIdenticalWithTimingOnAndOff) {
  expectSameResults(kLut, "lut_same", {"run.distance=2"});
}
TEST(RunStageTiming, GuidedResultsAreBitIdenticalWithTimingOnAndOff) {
  expectSameResults(kGuided, "guided_same", {"run.distance=10"});
}

}  // namespace
