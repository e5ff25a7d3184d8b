#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "workbench/core/spline.hpp"

namespace {

double cubic(double x) {
  return 0.5 - 1.5 * x + 0.25 * x * x - 0.125 * x * x * x;
}
double cubic1(double x) {
  return -1.5 + 0.5 * x - 0.375 * x * x;
}
double cubic2(double x) {
  return 0.5 - 0.75 * x;
}

std::vector<double> sampleAt(const std::vector<double>& x, double (*f)(double)) {
  std::vector<double> y;
  for (const double v : x) y.push_back(f(v));
  return y;
}

// Not-a-knot reproduces any cubic exactly, on uniform and non-uniform grids.
TEST(CubicSpline, NotAKnotReproducesCubicExactly) {
  const std::vector<double> grids[] = {
      {-1.0, 0.0, 1.0, 2.0, 3.0, 4.0}, {-1.0, -0.3, 0.1, 1.7, 2.0, 3.9, 4.0}, {0.0, 1.0, 2.5, 3.0}};
  for (const auto& x : grids) {
    rb::CubicSpline sp(x, sampleAt(x, cubic));
    for (double t = x.front(); t <= x.back(); t += 0.01) {
      EXPECT_NEAR(sp(t), cubic(t), 1e-12) << t;
      EXPECT_NEAR(sp.deriv1(t), cubic1(t), 1e-11) << t;
      EXPECT_NEAR(sp.deriv2(t), cubic2(t), 1e-10) << t;
    }
  }
}

// Three points: the interpolating parabola; two points: the line.
TEST(CubicSpline, FewPoints) {
  const std::vector<double> x3 = {0.0, 1.0, 3.0};
  rb::CubicSpline p(x3, {1.0, 2.0, 10.0});  // y = 1 + 0 x + x^2 ... check: 1+a+b=2, 1+3a+9b=10
  // a + b = 1, 3a + 9b = 9 -> b = 1, a = 0: y = 1 + x^2.
  EXPECT_NEAR(p(2.0), 5.0, 1e-12);
  EXPECT_NEAR(p.deriv1(2.0), 4.0, 1e-12);
  EXPECT_NEAR(p.deriv2(0.5), 2.0, 1e-12);
  rb::CubicSpline l({0.0, 2.0}, {1.0, 5.0});
  EXPECT_NEAR(l(0.5), 2.0, 1e-15);
  EXPECT_NEAR(l.deriv1(1.7), 2.0, 1e-15);
  EXPECT_EQ(l.deriv2(1.0), 0.0);
}

// Natural spline: zero second derivative at both ends, reproduces straight lines.
TEST(CubicSpline, NaturalEnds) {
  const std::vector<double> x = {0.0, 0.5, 1.5, 2.0, 3.0};
  const std::vector<double> y = {0.0, 1.0, -1.0, 0.5, 2.0};
  rb::CubicSpline sp(x, y, rb::SplineEnd::Natural);
  EXPECT_NEAR(sp.deriv2(0.0), 0.0, 1e-12);
  EXPECT_NEAR(sp.deriv2(3.0), 0.0, 1e-12);
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(sp(x[i]), y[i], 1e-14);
  rb::CubicSpline line(x, {1.0, 2.0, 4.0, 5.0, 7.0}, rb::SplineEnd::Natural);
  EXPECT_NEAR(line(2.7), 1.0 + 2.0 * 2.7, 1e-12);
}

// Interpolates the data and is C2 at the knots.
TEST(CubicSpline, InterpolatesAndIsC2) {
  std::vector<double> x, y;
  for (int i = 0; i < 12; ++i) {
    x.push_back(i * i * 0.1);
    y.push_back(std::sin(x.back()));
  }
  rb::CubicSpline sp(x, y);
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(sp(x[i]), y[i], 1e-13);
  for (std::size_t i = 1; i + 1 < x.size(); ++i) {
    const double e = 1e-9;
    EXPECT_NEAR(sp.deriv1(x[i] - e), sp.deriv1(x[i] + e), 1e-7);
    EXPECT_NEAR(sp.deriv2(x[i] - e), sp.deriv2(x[i] + e), 1e-6);
  }
}

// O(h^4) convergence of values and O(h^3) of derivatives on a smooth function; fourth-order
// error is tiny at a modest grid.
TEST(CubicSpline, ConvergenceOrderAndDerivativeAccuracy) {
  auto maxErr = [](int n, int order) {
    const double h = 2.0 / n;
    std::vector<double> x, y;
    for (int i = 0; i <= n; ++i) {
      x.push_back(i * h);
      y.push_back(std::exp(-x.back()) * std::sin(3.0 * x.back()));
    }
    rb::CubicSpline sp(x, y);
    double e = 0.0;
    for (double t = 0.0; t <= 2.0; t += 1e-3) {
      const double f = std::exp(-t) * std::sin(3.0 * t);
      const double f1 = std::exp(-t) * (3.0 * std::cos(3.0 * t) - std::sin(3.0 * t));
      const double f2 = std::exp(-t) * (-8.0 * std::sin(3.0 * t) - 6.0 * std::cos(3.0 * t));
      const double v = order == 0 ? sp(t) - f : order == 1 ? sp.deriv1(t) - f1 : sp.deriv2(t) - f2;
      e = std::max(e, std::abs(v));
    }
    return e;
  };
  const double r0 = maxErr(40, 0) / maxErr(80, 0);
  const double r1 = maxErr(40, 1) / maxErr(80, 1);
  const double r2 = maxErr(40, 2) / maxErr(80, 2);
  EXPECT_GT(r0, 12.0);  // ~16
  EXPECT_GT(r1, 6.0);   // ~8
  EXPECT_GT(r2, 3.0);   // ~4
  EXPECT_LT(maxErr(80, 0), 2e-6);
  EXPECT_LT(maxErr(80, 1), 5e-4);  // largest at the ends (not-a-knot)
}

// Uniform grids are detected and give the same interval as binary search, including at knots
// and outside the range (clamped).
TEST(SplineGrid, UniformLookupMatchesSearch) {
  const rb::SplineGrid u = rb::SplineGrid::uniform(-3.0, 0.1, 101);
  EXPECT_TRUE(u.isUniform());
  std::vector<double> xs = u.knots();
  xs[50] += 1e-3;  // no longer uniform
  const rb::SplineGrid nu(xs);
  EXPECT_FALSE(nu.isUniform());
  for (std::size_t i = 0; i < u.size(); ++i) {
    const std::size_t expect = std::min(i, u.size() - 2);
    EXPECT_EQ(u.interval(u[i]), expect) << i;
    if (i != 50 && i != 51) {
      EXPECT_EQ(nu.interval(u[i]), expect) << i;
    }
  }
  for (double x = -3.5; x < 7.5; x += 0.00731) {
    const std::size_t i = u.interval(x);
    EXPECT_LE(i, u.size() - 2);
    if (x >= u.front() && x < u.back()) {
      EXPECT_LE(u[i], x);
      EXPECT_LT(x, u[i + 1]);
    }
  }
  EXPECT_EQ(u.interval(-100.0), 0u);
  EXPECT_EQ(u.interval(100.0), u.size() - 2);
  EXPECT_EQ(nu.interval(-100.0), 0u);
  EXPECT_EQ(nu.interval(100.0), nu.size() - 2);
}

// Channels of a set are independent splines sharing one grid.
TEST(CubicSplineSet, ChannelsMatchScalarSplines) {
  std::vector<double> x;
  std::vector<std::vector<double>> ys(3);
  for (int i = 0; i < 30; ++i) {
    x.push_back(0.5 * i);
    ys[0].push_back(std::sin(x.back()));
    ys[1].push_back(x.back() * x.back());
    ys[2].push_back(std::cos(0.3 * x.back()));
  }
  const rb::CubicSplineSet set(rb::SplineGrid(x), ys);
  ASSERT_EQ(set.channels(), 3u);
  for (double t = -1.0; t < 16.0; t += 0.37) {
    std::array<double, 3> v{}, d1{}, d2{};
    set.eval(t, v, d1, d2);
    for (std::size_t c = 0; c < 3; ++c) {
      const rb::CubicSpline sc(x, ys[c]);
      EXPECT_DOUBLE_EQ(v[c], sc(t));
      EXPECT_DOUBLE_EQ(d1[c], sc.deriv1(t));
      EXPECT_DOUBLE_EQ(d2[c], sc.deriv2(t));
      EXPECT_DOUBLE_EQ(v[c], set.value(c, t));
    }
  }
  // Quadratic channel is reproduced exactly, also when extrapolating.
  EXPECT_NEAR(set.value(1, 15.2), 15.2 * 15.2, 1e-9);
}

TEST(CubicSpline, RejectsBadGrids) {
  EXPECT_THROW(rb::SplineGrid({1.0}), std::logic_error);
  EXPECT_THROW(rb::SplineGrid({0.0, 1.0, 1.0}), std::logic_error);
  EXPECT_THROW(rb::CubicSpline({0.0, 1.0, 2.0}, {1.0, 2.0}), std::logic_error);
}

}  // namespace
