#pragma once
// CONTACT's tractcurv example (tests/data/creep/contact_tractcurv.txt: a/b = 0.5, mu = 0.33, pure
// s_x): its rows (series "exact", "fastsim", ...; creepage coefficient cksi, force fx / mu Q),
// read by the creep law tests that compare with it.
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace rb::test {

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
