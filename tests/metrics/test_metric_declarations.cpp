// study.metrics declarations: the good ones parse into MetricSpec, every bad one is a file:line
// error saying what is wrong.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "workbench/scenario/metric_lua.hpp"
#include "workbench/scenario/study.hpp"

namespace fs = std::filesystem;

namespace {

class StudyFile {
 public:
  explicit StudyFile(const std::string& metrics) {
    std::random_device rd;
    dir_ = fs::temp_directory_path() / ("railbench_metric_decl_" + std::to_string(rd()));
    fs::create_directories(dir_);
    path_ = (dir_ / "s.lua").string();
    std::ofstream(path_) << "-- metrics test\nstudy {\n  base = \"" << RB_SOURCE_DIR
                         << "/scenarios/studies/case3_base.lua\",\n  cases = { { role = "
                            "\"reference\" }, { [\"run.distance\"] = 5 } },\n  metrics = {\n"
                         << metrics << "\n  },\n}\n";
  }
  ~StudyFile() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  const std::string& path() const { return path_; }

 private:
  fs::path dir_;
  std::string path_;
};

std::string errorOf(const std::string& metrics) {
  StudyFile f(metrics);
  try {
    rb::scenario::loadStudy(f.path(), RB_SOURCE_DIR);
  } catch (const rb::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(MetricDeclarations, GoodOnesParse) {
  StudyFile f(
      R"(    { name = "y_max", signal = "/bodies/ws1/y", stat = "max_abs", from = 100, to = 400 },
    { name = "y_ss", kind = "steady", signal = "/bodies/ws1/y", length = 50, tolerance = 1e-4 },
    { name = "yq", kind = "assessment", quantity = "y_over_q" },
    { name = "err", kind = "error", signal = "/bodies/ws1/y", along = "time" },
    { name = "vcrit", kind = "linear_critical_speed", speeds = { 20, 80, 4 } },
    { name = "f", fn = function(s) return #s.y end, signals = { y = "/bodies/ws1/y" } },)");
  const auto st = rb::scenario::loadStudy(f.path(), RB_SOURCE_DIR);
  ASSERT_EQ(st.metrics.size(), 6u);
  EXPECT_EQ(st.metrics[0].kind, "signal");
  EXPECT_EQ(st.metrics[0].stat, "max_abs");
  EXPECT_EQ(st.metrics[0].from, 100.0);
  EXPECT_EQ(st.metrics[0].to, 400.0);
  EXPECT_EQ(st.metrics[1].length, 50.0);
  EXPECT_EQ(st.metrics[3].along, "time");
  EXPECT_EQ(st.metrics[4].speeds, 4);
  EXPECT_EQ(st.metrics[5].kind, "lua");
  EXPECT_EQ(st.metrics[5].index, 6);
  ASSERT_EQ(st.metrics[5].signals.size(), 1u);
  EXPECT_NE(st.metrics[0].definition(), st.metrics[1].definition());
}

TEST(MetricDeclarations, BadOnesAreFileLineErrors) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {R"({ name = "a", signal = "/bodies/ws1/y", stat = "maxx" })",
       "unknown stat 'maxx' (did you mean 'max'?)"},
      {R"({ name = "a", stat = "max" })", "needs signal"},
      {R"({ name = "a", signal = "/bodies/ws1/y", stat = "max", from = 5, to = 1 })",
       "from must be less than to"},
      {R"({ name = "a", kind = "rainflow", signal = "/x" })", "unknown kind 'rainflow'"},
      {R"({ name = "a", fn = function(s) return 1 end })", "needs signals"},
      {R"({ name = "a", signal = "bodies/ws1/y", stat = "max" })", "dataset path"},
      {R"({ name = "a b", signal = "/y", stat = "max" })", "name must be letters"},
      {R"({ name = "a", signal = "/y", stat = "max", colour = 1 })", "unknown key 'colour'"},
      {R"({ name = "a", kind = "assessment", quantity = "yq" })", "unknown assessment quantity"},
      {R"({ name = "a", kind = "linear_critical_speed", speeds = { 80, 20, 4 } })", "0 < lo < hi"},
      {R"({ name = "a", kind = "assessment", quantity = "sum_y", from = 3 })",
       "from, to and along apply"},
      {R"({ name = "a", signal = "/y", stat = "max" }, { name = "a", signal = "/y", stat = "min" })",
       "name given twice"},
      // /metrics keeps <name>_why and <name>_note beside the values: a metric of such a name
      // would overwrite another's reason.
      {R"({ name = "y_why", signal = "/y", stat = "max" })", "is reserved"},
      {R"({ name = "y_note", signal = "/y", stat = "max" })", "is reserved"},
      {R"({ name = "definitions_hash", signal = "/y", stat = "max" })", "is reserved"},
  };
  for (const auto& [decl, want] : bad) {
    const std::string e = errorOf("    " + decl + ",");
    EXPECT_NE(e.find(want), std::string::npos) << decl << "\n  gave: " << e;
    // Every message is located at the metric's own line of the study file (line 6: the
    // declaration), not at the study{} block's.
    EXPECT_NE(e.find("s.lua:6: study: metrics["), std::string::npos) << e;
  }
}

TEST(MetricDeclarations, ErrorMetricNeedsAReferenceCase) {
  std::random_device rd;
  const fs::path dir = fs::temp_directory_path() / ("railbench_metric_ref_" + std::to_string(rd()));
  fs::create_directories(dir);
  const std::string p = (dir / "s.lua").string();
  std::ofstream(p) << "study { base = \"" << RB_SOURCE_DIR
                   << "/scenarios/studies/case3_base.lua\", metrics = { { name = \"e\", kind = "
                      "\"error\", signal = \"/bodies/ws1/y\" } } }\n";
  std::string what;
  try {
    rb::scenario::loadStudy(p, RB_SOURCE_DIR);
  } catch (const rb::InputError& e) {
    what = e.what();
  }
  fs::remove_all(dir);
  EXPECT_NE(what.find("s.lua:1: study: metric e: kind error needs a case with role"),
            std::string::npos)
      << what;
}

TEST(MetricDeclarations, LuaFunctionsRunInTheirSandbox) {
  StudyFile f(
      R"(    { name = "n", fn = function(s) return #s.y + s.y[2] end, signals = { y = "/y" } },
    { name = "bad", fn = function(s) error("no good") end, signals = { y = "/y" } },
    { name = "str", fn = function(s) return "x" end, signals = { y = "/y" } },
    { name = "io", fn = function(s) return io.open("/etc/passwd") end, signals = { y = "/y" } },
    { name = "pat", fn = function(s) return ("aaa"):find("a.") end, signals = { y = "/y" } },
    { name = "slow", signals = { y = "/y" },
      fn = function(s) return (("a"):rep(5000)):find("a*a*a*a*b") end },
    { name = "arg", fn = function(s) return ("a"):find() end, signals = { y = "/y" } },)");
  const auto st = rb::scenario::loadStudy(f.path(), RB_SOURCE_DIR);
  rb::scenario::LuaMetrics lua(f.path(), RB_SOURCE_DIR);
  const std::vector<std::pair<std::string, std::vector<double>>> sig = {{"y", {1.0, 2.5, 3.0}}};
  double v = 0;
  std::string why;
  ASSERT_TRUE(lua.call(1, sig, v, why)) << why;
  EXPECT_EQ(v, 5.5);
  EXPECT_FALSE(lua.call(2, sig, v, why));
  EXPECT_NE(why.find("s.lua:"), std::string::npos) << why;
  EXPECT_NE(why.find("no good"), std::string::npos) << why;
  why.clear();
  EXPECT_FALSE(lua.call(3, sig, v, why));
  EXPECT_NE(why.find("returned a string"), std::string::npos) << why;
  why.clear();
  EXPECT_FALSE(lua.call(4, sig, v, why));  // no io library
  EXPECT_NE(why.find("io"), std::string::npos) << why;
  why.clear();
  ASSERT_TRUE(lua.call(5, sig, v, why)) << why;  // an affordable pattern
  EXPECT_EQ(v, 1.0);
  EXPECT_FALSE(lua.call(6, sig, v, why));  // one whose worst case is beyond the bound
  EXPECT_NE(why.find("pattern too costly"), std::string::npos) << why;
  why.clear();
  // A missing argument of a guarded pattern function: the library's message with the function's
  // name and the line (found by tests/fuzz: was "bad argument #1 to '?'" without a line).
  EXPECT_FALSE(lua.call(7, sig, v, why));
  EXPECT_NE(why.find("s.lua:13: bad argument #1 to 'find' (string expected, got no value)"),
            std::string::npos)
      << why;
  why.clear();
  EXPECT_FALSE(lua.call(9, sig, v, why));
  EXPECT_NE(why.find("not a function"), std::string::npos) << why;
}

TEST(MetricDeclarations, ShippedStudiesRunInTheMetricSandbox) {
  // Their require of studies.lib etc. works there too, so a function metric can be added to any.
  for (const auto& e : fs::directory_iterator(std::string(RB_SOURCE_DIR) + "/scenarios/studies")) {
    if (e.path().extension() != ".lua" || e.path().stem() == "lib" ||
        e.path().stem() == "case3_base")
      continue;
    std::string text;
    {
      std::ifstream in(e.path());
      text.assign(std::istreambuf_iterator<char>(in), {});
    }
    if (text.find("study {") == std::string::npos && text.find("study{") == std::string::npos)
      continue;
    EXPECT_NO_THROW(rb::scenario::LuaMetrics(e.path().string(), RB_SOURCE_DIR)) << e.path();
  }
}

// A function that catches its own budget error and tries again (pcall in a loop), or whose xpcall
// message handler loops, still ends with the budget error: once a budget is exceeded the hook
// raises on every instruction and handlers are skipped.
TEST(MetricDeclarations, RetriesInsidePcallCannotEscapeTheBudget) {
  StudyFile f(
      R"(    { name = "retry", signals = { y = "/y" }, fn = function(s)
        while true do pcall(function() while true do end end) end
      end },
    { name = "handler", signals = { y = "/y" }, fn = function(s)
        return xpcall(function() while true do end end, function() while true do end end)
      end },)");
  rb::scenario::LuaMetrics lua(f.path(), RB_SOURCE_DIR);
  const std::vector<std::pair<std::string, std::vector<double>>> sig = {{"y", {1.0, 2.0}}};
  double v = 0;
  std::string why;
  EXPECT_FALSE(lua.call(1, sig, v, why));
  EXPECT_NE(why.find("exceeded its budget"), std::string::npos) << why;
  EXPECT_NE(why.find("line 7"), std::string::npos) << why;  // where the function was stopped
  rb::scenario::LuaMetrics fresh(f.path(), RB_SOURCE_DIR);
  why.clear();
  EXPECT_FALSE(fresh.call(2, sig, v, why));
  EXPECT_NE(why.find("exceeded its budget"), std::string::npos) << why;
}

// A budget of its own (the fuzz harness lowers them so that the guard answers quickly): the
// instruction budget, and the memory budget, each reported with its value.
TEST(MetricDeclarations, ABudgetOfItsOwn) {
  StudyFile f(
      R"(    { name = "loop", signals = { y = "/y" }, fn = function(s) while true do end end },
    { name = "big", signals = { y = "/y" }, fn = function(s) return #string.rep("x", 1 << 26) end },)");
  rb::scenario::MetricBudget budget;
  budget.instructions = 100'000;
  budget.seconds = 5;
  budget.memory = std::size_t{32} << 20;
  const std::vector<std::pair<std::string, std::vector<double>>> sig = {{"y", {1.0, 2.0}}};
  double v = 0;
  std::string why;
  {
    rb::scenario::LuaMetrics lua(f.path(), RB_SOURCE_DIR, budget);
    EXPECT_FALSE(lua.call(1, sig, v, why));
    EXPECT_NE(why.find("exceeded its budget of 100000 Lua instructions or 5 s"), std::string::npos)
        << why;
  }
  rb::scenario::LuaMetrics lua(f.path(), RB_SOURCE_DIR, budget);
  why.clear();
  EXPECT_FALSE(lua.call(2, sig, v, why));
  EXPECT_NE(why.find("not enough memory (memory budget 32 MiB)"), std::string::npos) << why;
}
