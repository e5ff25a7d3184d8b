#pragma once
// What the creep law tests share: a Hertz patch with Kalker's coefficients, and the rows of
// CONTACT's tractcurv example (tests/data/creep/contact_tractcurv.txt: a/b = 0.5, mu = 0.33, pure
// s_x; series "exact", "fastsim", ...; creepage coefficient cksi, force fx / mu Q).
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "workbench/creep/kalker.hpp"
#include "workbench/creep/polach.hpp"

namespace rb::test {

// The patch of semi-axes a (rolling direction), b [m] under normal load Q [N] with Kalker's
// coefficients for a/b and Poisson's ratio nu.
inline creep::ContactPatch ellipse(double a, double b, double Q, double nu = 0.28) {
  const creep::KalkerCoefficients c = creep::kalkerCoefficients(a / b, nu);
  creep::ContactPatch p;
  p.Q = Q;
  p.a = a;
  p.b = b;
  p.c11 = c.c11;
  p.c22 = c.c22;
  p.c23 = c.c23;
  p.c33 = c.c33;
  return p;
}

struct CurvePoint {
  std::string series;
  double cksi = 0.0, fx = 0.0;
};

// Every row of the file; `series` non-empty: only its rows.
inline std::vector<CurvePoint> tractcurv(const std::string& series = "") {
  std::ifstream in(std::string(RB_SOURCE_DIR) + "/tests/data/creep/contact_tractcurv.txt");
  std::vector<CurvePoint> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream is(line);
    CurvePoint p;
    int id = 0;
    is >> p.series >> id >> p.cksi >> p.fx;
    if (series.empty() || p.series == series) out.push_back(p);
  }
  return out;
}

}  // namespace rb::test
