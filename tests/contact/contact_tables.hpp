#pragma once
// Tables shared by several tests (built once per test executable).
#include "contact_test_util.hpp"
#include "workbench/contact/kec.hpp"
#include "workbench/contact/lut.hpp"

namespace rbtest {

// Cone 1:20 on a R = 0.3 m rail head, beta = 1/40, a small LUT grid (y +-8 mm, xi_g -2..2 mm).
inline rb::contact::ContactGeometryConfig coneConfig() {
  rb::contact::ContactGeometryConfig c = symmetricConfig(
      coneWheel(0.46, 1.0 / 20.0, 0.05, 1e-4), arcRail(0.3, 0.03, 1e-4), 0.75, 0.7535, 1.0 / 40.0);
  c.lut_y = {-0.008, 0.008, 0.1e-3};
  c.lut_gauge = {-0.002, 0.002, 1e-3};
  c.kec_s = {-0.012, 0.012, 0.2e-3};
  return c;
}

inline const rb::contact::LutTable& coneLut() {
  static const rb::contact::LutTable t = rb::contact::buildLut(coneConfig());
  return t;
}
inline const rb::contact::KecTable& coneKec() {
  static const rb::contact::KecTable t = rb::contact::buildKec(coneConfig());
  return t;
}

// S1002 / 60E1 1:40 with the default (Table 9/10) grids.
inline const rb::contact::LutTable& s1002Lut() {
  static const rb::contact::LutTable t = rb::contact::buildLut(s1002On60E1());
  return t;
}
inline const rb::contact::KecTable& s1002Kec() {
  static const rb::contact::KecTable t = rb::contact::buildKec(s1002On60E1());
  return t;
}

}  // namespace rbtest
