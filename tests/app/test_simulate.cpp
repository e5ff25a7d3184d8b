// simulate(): output series, /stats, and failure as a result with partial output kept.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "h5read.hpp"
#include "workbench/run/simulate.hpp"

namespace fs = std::filesystem;

namespace {

// x'' = -x, failing fatally (or producing NaN) from t_fail on.
class Oscillator : public rb::integ::OdeSystem {
 public:
  double t_fail = 1e9;
  bool nan = false;
  int size() const override { return 2; }
  int rhs(double t, const double* y, double* yd) override {
    if (t >= t_fail && !nan) return -1;
    yd[0] = y[1];
    yd[1] = (t >= t_fail && nan) ? std::nan("") : -y[0];
    return 0;
  }
  std::string componentName(int i) const override { return i == 0 ? "x" : "v"; }
  std::string lastError() const override { return "contact point left its table"; }
};

std::string tmpFile(const std::string& name) {
  fs::path d = fs::temp_directory_path() / "rb_test_app";
  fs::create_directories(d);
  return (d / name).string();
}

rb::run::SimulationRequest request(Oscillator& sys, const std::string& method) {
  rb::run::SimulationRequest r;
  r.system = &sys;
  r.solver.method = method;
  r.solver.step = 1e-3;
  r.solver.rtol = 1e-8;
  r.solver.atol = 1e-10;
  r.y0 = Eigen::Vector2d(1.0, 0.0);
  r.t_end = 2.0;
  r.output_every = 0.01;
  r.outputs = {{"/bodies/mass/x", "m", "position", ""}, {"/bodies/mass/v", "m/s", "velocity", ""}};
  r.sample = [](double, const Eigen::VectorXd& y, double* v) {
    v[0] = y[0];
    v[1] = y[1];
  };
  r.distance = [](double t, const Eigen::VectorXd&) { return 20.0 * t; };
  return r;
}

}  // namespace

TEST(Simulate, WritesSeriesAndStats) {
  for (std::string method : {"rk4", "abm", "dopri5", "bdf"}) {
    Oscillator sys;
    std::string path = tmpFile("ok_" + method + ".h5");
    {
      rb::io::ResultFile f(path);
      auto res = rb::run::simulate(request(sys, method), f);
      EXPECT_TRUE(res.ok) << res.message;
      f.finalize();
    }
    hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    auto t = h5test::dataset(f, "/time");
    auto x = h5test::dataset(f, "/bodies/mass/x");
    ASSERT_EQ(t.size(), 201u) << method;  // t0 and 200 outputs
    ASSERT_EQ(x.size(), 201u);
    EXPECT_NEAR(t.back(), 2.0, 1e-12);
    EXPECT_NEAR(x.back(), std::cos(2.0), 1e-6) << method;
    EXPECT_EQ(h5test::stringAttr(f, "/stats", "status"), "ok");
    EXPECT_EQ(h5test::stringAttr(f, "/stats", "method"), method);
    EXPECT_GT(h5test::numAttr<std::int64_t>(f, "/stats", "rhs_evals"), 0);
    EXPECT_EQ(h5test::stringAttr(f, "/bodies/mass/v", "units"), "m/s");
    H5Fclose(f);
  }
}

TEST(Simulate, FatalFailureKeepsPartialOutputAndSaysWhere) {
  Oscillator sys;
  sys.t_fail = 0.5;
  std::string path = tmpFile("fail.h5");
  rb::integ::RunResult res;
  {
    rb::io::ResultFile f(path);
    res = rb::run::simulate(request(sys, "abm"), f);
    f.finalize();
  }
  EXPECT_FALSE(res.ok);
  EXPECT_NE(res.message.find("t = 0.49"), std::string::npos) << res.message;
  EXPECT_NE(res.message.find("(leading wheelset at s = 9.98 m)"), std::string::npos) << res.message;
  hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  auto t = h5test::dataset(f, "/time");
  ASSERT_EQ(t.size(), 50u);  // 0 .. 0.49 s kept
  EXPECT_EQ(h5test::stringAttr(f, "/stats", "status"), "failed");
  EXPECT_EQ(h5test::stringAttr(f, "/stats", "message"), res.message);
  H5Fclose(f);
}

TEST(Simulate, NanIsCaughtAndNamed) {
  for (std::string method : {"rk4", "bdf"}) {
    Oscillator sys;
    sys.t_fail = 0.5;
    sys.nan = true;
    std::string path = tmpFile("nan_" + method + ".h5");
    rb::io::ResultFile f(path);
    auto res = rb::run::simulate(request(sys, method), f);
    f.finalize();
    EXPECT_FALSE(res.ok) << method;
    EXPECT_NE(res.message.find("NaN"), std::string::npos) << res.message;
    EXPECT_NE(res.message.find("v"), std::string::npos) << res.message;
    EXPECT_LE(res.t_reached, 0.5 + 1e-9);
  }
}

TEST(Simulate, OutputIntervalMustFitFixedStep) {
  Oscillator sys;
  auto r = request(sys, "rk4");
  r.solver.step = 3e-3;  // 0.01 s is not a multiple of 3 ms
  rb::io::ResultFile f(tmpFile("grid.h5"));
  EXPECT_THROW(rb::run::simulate(r, f), rb::InputError);
  f.finalize();
}

TEST(Simulate, ProgressLineIsOneLineRewrittenInPlace) {
  // Shown from the start and at every output time here (the app shows it after 2 s of a run, at
  // most every 0.25 s, and only when stderr is a terminal).
  const std::string path = tmpFile("progress.h5");
  auto stderrOf = [&](bool progress, double after) {
    Oscillator sys;
    rb::run::SimulationRequest r = request(sys, "abm");
    r.progress = progress;
    r.progress_after = after;
    r.progress_every = 0.0;
    rb::io::ResultFile f(path);
    testing::internal::CaptureStderr();
    const auto res = rb::run::simulate(r, f);
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_TRUE(res.ok) << res.message;
    f.finalize();
    return err;
  };
  const std::string line = stderrOf(true, 0.0);
  EXPECT_EQ(std::count(line.begin(), line.end(), '\r'), 200);  // one per output time after t0
  EXPECT_EQ(std::count(line.begin(), line.end(), '\n'), 1);    // ended once, after the run
  ASSERT_FALSE(line.empty());
  EXPECT_EQ(line.back(), '\n');
  const std::string last = line.substr(line.rfind('\r'));
  EXPECT_NE(last.find("t =    2.000 s"), std::string::npos) << last;
  EXPECT_NE(last.find("s =     40.0 m"), std::string::npos) << last;  // distance 20 t
  EXPECT_NE(last.find("x real time"), std::string::npos) << last;
  EXPECT_NE(last.find(" evaluations"), std::string::npos) << last;
  // Not asked, or a run shorter than the delay: nothing at all.
  EXPECT_EQ(stderrOf(false, 0.0), "");
  EXPECT_EQ(stderrOf(true, 1e9), "");
}
