// The result file states its own layout (/schema, architecture.md "Output layout"): every dataset
// a vehicle run writes under /time, /vehicle, /bodies, /elements, /contact and /track has one
// /schema row with its unit (the same as the dataset's `units`) and meaning, every row names a
// dataset of the file, and the codes of the code-valued datasets are the C++ name tables.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "tests/run/run_files.hpp"
#include "workbench/creep/hertz.hpp"
#include "workbench/io/result_reader.hpp"
#include "workbench/io/schema.hpp"
#include "workbench/run/channels.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/run/vehicle_run.hpp"
#include "workbench/track/names.hpp"

namespace {

namespace fs = std::filesystem;

struct Row {
  std::string unit, meaning, codes;
};

// A short run of `scenario` written into a result file; returns its path.
std::string runInto(const std::string& scenario, const std::string& name,
                    std::vector<std::string> sets) {
  sets.emplace_back("run.duration=0.02");
  return rb::test::runInto(rb::test::compiled(scenario, sets), "rb_test_result_schema", name).path;
}

using rb::test::datasets;

// Every row of every /schema/<part> table, by dataset path.
std::map<std::string, Row> schemaRows(const rb::io::ResultReader& r) {
  std::map<std::string, Row> out;
  for (const auto& part : r.members("/schema")) {
    if (part == "enums") continue;
    const std::string g = "/schema/" + part + "/";
    const auto path = r.strings(g + "path"), unit = r.strings(g + "unit");
    const auto meaning = r.strings(g + "meaning"), codes = r.strings(g + "codes");
    EXPECT_TRUE(path && unit && meaning && codes) << g;
    if (!path || !unit || !meaning || !codes) continue;
    EXPECT_EQ(unit->size(), path->size()) << g;
    EXPECT_EQ(meaning->size(), path->size()) << g;
    EXPECT_EQ(codes->size(), path->size()) << g;
    for (std::size_t i = 0; i < path->size(); ++i) {
      EXPECT_EQ(out.count((*path)[i]), 0u) << (*path)[i] << " has two rows";
      out[(*path)[i]] = {(*unit)[i], (*meaning)[i], (*codes)[i]};
    }
  }
  return out;
}

// The row of dataset `d`: present, with a unit (its `units`), a meaning and existing codes.
void expectRow(const rb::io::ResultReader& r, const std::map<std::string, Row>& rows,
               const std::string& d) {
  const auto it = rows.find(d);
  ASSERT_NE(it, rows.end()) << d << " has no /schema row";
  EXPECT_FALSE(it->second.unit.empty()) << d;
  EXPECT_FALSE(it->second.meaning.empty()) << d;
  EXPECT_EQ(r.text(d, "units").value_or("?"), it->second.unit) << d;
  if (!it->second.codes.empty()) {
    EXPECT_TRUE(r.text("/schema/enums", it->second.codes)) << d << ": no codes";
  }
}

void expectDescribed(const std::string& file, bool contact) {
  const rb::io::ResultReader r(file);
  ASSERT_TRUE(r.ok()) << file;
  const auto rows = schemaRows(r);
  std::vector<std::string> written;
  for (const char* g : {"/vehicle", "/bodies", "/elements", "/contact", "/track", "/assessment"})
    datasets(r, g, written);
  written.emplace_back("/time");
  std::size_t contact_datasets = 0;
  for (const auto& d : written) {
    if (d.rfind("/contact/", 0) == 0) ++contact_datasets;
    expectRow(r, rows, d);
  }
  EXPECT_EQ(contact_datasets > 0, contact);
  const std::set<std::string> all(written.begin(), written.end());
  for (const auto& [path, row] : rows) EXPECT_TRUE(all.count(path)) << path << " is not written";
}

// "0=a,1=b" -> {0: a, 1: b}
std::map<int, std::string> parseCodes(const std::string& s) {
  std::map<int, std::string> out;
  std::size_t at = 0;
  while (at < s.size()) {
    const std::size_t comma = std::min(s.find(',', at), s.size());
    const std::string item = s.substr(at, comma - at);
    const std::size_t eq = item.find('=');
    EXPECT_NE(eq, std::string::npos) << s;
    if (eq != std::string::npos) out[std::stoi(item.substr(0, eq))] = item.substr(eq + 1);
    at = comma + 1;
  }
  return out;
}

TEST(ResultSchema, ContactRunDescribesEveryDataset) {
  const std::string file = runInto("scenarios/default/case3_kec_fast.lua", "kec.h5", {});
  expectDescribed(file, true);
  const rb::io::ResultReader r(file);
  // The regime's codes are the C++ table: 0 tread only, 1 two-point, 2 flange only (the values
  // of dynamics::WheelOutput::regime, classifyRegimes).
  const auto regime = r.text("/schema/enums", std::string(rb::run::kRegimeEnum));
  ASSERT_TRUE(regime);
  const auto codes = parseCodes(*regime);
  ASSERT_EQ(codes.size(), rb::dynamics::kContactRegimeNames.size());
  for (const auto& e : rb::dynamics::kContactRegimeNames)
    EXPECT_EQ(codes.at(static_cast<int>(e.value)), e.name);
  EXPECT_EQ(codes.at(0), "tread");
  EXPECT_EQ(codes.at(1), "two_point");
  EXPECT_EQ(codes.at(2), "flange");
  // Every regime value written is one of the codes.
  const auto values = r.dataset("/contact/ws1/left/regime");
  ASSERT_TRUE(values && !values->empty());
  for (const double v : *values) EXPECT_TRUE(codes.count(static_cast<int>(v))) << v;
  // The segment kinds: the track's name table, and the /track/segments attribute the same.
  const auto kinds = r.text("/schema/enums", "segment_kind");
  ASSERT_TRUE(kinds);
  EXPECT_EQ(*kinds, rb::io::codesOf<rb::track::SegmentKind>());
  EXPECT_EQ(*kinds, "0=tangent,1=transition,2=curve");
  EXPECT_EQ(r.text("/track/segments", "codes").value_or(""), *kinds);
  EXPECT_EQ(r.text("/schema/enums", "segment_side").value_or(""), "1=left,-1=right");
  EXPECT_EQ(r.number("/schema", "version").value_or(0), rb::io::kSchemaVersion);
}

TEST(ResultSchema, ElasticRunWithoutPatchesDescribesEveryDataset) {
  expectDescribed(
      runInto("scenarios/validation/case2_elastic.lua", "elastic.h5", {"run.output.patches=false"}),
      true);
}

TEST(ResultSchema, GuidedRunWithAccelerationsDescribesEveryDataset) {
  const std::string file = runInto("scenarios/vehicle/manchester_guided_r500.lua", "guided.h5",
                                   {"run.output.body_accelerations=true"});
  expectDescribed(file, false);
  const rb::io::ResultReader r(file);
  EXPECT_FALSE(r.text("/schema/enums", std::string(rb::run::kRegimeEnum)));
}

// The rows the writer sets up and the signal check (signalProblem) read the same registry.
TEST(ResultSchema, ChannelRowsAreComplete) {
  std::set<std::string_view> names;
  for (const auto& c : rb::run::kWheelChannels) {
    EXPECT_TRUE(names.insert(c.name).second) << c.name;
    EXPECT_FALSE(c.unit.empty()) << c.name;
    EXPECT_FALSE(c.meaning.empty()) << c.name;
  }
  names.clear();
  for (const auto& c : rb::run::kPatchChannels) {
    EXPECT_TRUE(names.insert(c.name).second) << c.name;
    EXPECT_FALSE(c.unit.empty()) << c.name;
  }
  names.clear();
  for (const auto& c : rb::run::kRailChannels) {
    EXPECT_TRUE(names.insert(c.name).second) << c.name;
    EXPECT_FALSE(c.unit.empty()) << c.name;
    EXPECT_FALSE(c.meaning.empty()) << c.name;
  }
  for (std::size_t k = 0; k < 6; ++k)
    EXPECT_EQ(rb::run::kBodyCoordChannels[k].name, rb::vehicle::kCoordNames[k]);
}

}  // namespace

namespace rbtest_pressure {

// The max_pressure channel's p0 is the Hertz module's maximum pressure for the patch's semi-axes
// and load (creep::hertz, an independent computation from the curvatures), and 0 for a patch out
// of contact or pulled.
TEST(ResultChannels, PeakPressureIsHertzP0) {
  const rb::creep::Material steel{2.1e11, 0.28};
  // A wheel of radius 0.46 m on a straight rail; crown radii 0.3 m (rail) and flat (wheel).
  const rb::creep::RelativeCurvatures k{1.0 / (2 * 0.46), 1.0 / (2 * 0.3)};
  for (double n : {1e3, 5e4, 1.2e5}) {
    const rb::creep::HertzContact h = rb::creep::hertz(steel, k, n);
    rb::dynamics::PatchOutput p;
    p.active = true;
    p.normal = n;
    p.a = h.a;
    p.b = h.b;
    EXPECT_NEAR(rb::run::peakPressure(p), h.p0, 1e-12 * h.p0) << n;
    p.active = false;
    EXPECT_EQ(rb::run::peakPressure(p), 0.0);
    p.active = true;
    p.normal = -n;
    EXPECT_EQ(rb::run::peakPressure(p), 0.0);
  }
}

}  // namespace rbtest_pressure
