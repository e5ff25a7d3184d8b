#include "workbench/contact/derived.hpp"

#include <cmath>

namespace rb::contact {

RollingRadiusTable rollingRadiusDifference(const LutTable& lut, double xi_g) {
  RollingRadiusTable t;
  t.xi_g = xi_g;
  const std::size_t ny = lut.ny();
  // Gauge node index when xi_g is (to rounding) a node.
  const GridSpec& g = lut.gaugeGrid();
  long node = -1;
  if (lut.ng() == 1) {
    if (std::abs(xi_g - g.min) < 1e-12) node = 0;
  } else {
    const double k = (xi_g - g.min) / g.step;
    const double kr = std::round(k);
    if (std::abs(k - kr) < 1e-9 && kr >= 0 && kr < static_cast<double>(lut.ng())) {
      node = static_cast<long>(kr);
    }
  }
  auto value = [&](std::size_t c, std::size_t iy) {
    if (node >= 0) return lut.node(c, iy, static_cast<std::size_t>(node));
    return lut.evalChannel(c, lut.yGrid().at(iy), xi_g).v;
  };
  for (std::size_t iy = 0; iy < ny; ++iy) {
    t.y.push_back(lut.yGrid().at(iy));
    t.z.push_back(value(kLutZ, iy));
    t.phi.push_back(value(kLutPhi, iy));
    const double rl = value(lutChannel(Side::Left, TreadQuantity::Radius), iy);
    const double rr = value(lutChannel(Side::Right, TreadQuantity::Radius), iy);
    const double gl = value(lutChannel(Side::Left, TreadQuantity::Gamma), iy);
    const double gr = value(lutChannel(Side::Right, TreadQuantity::Gamma), iy);
    t.r_left.push_back(rl);
    t.r_right.push_back(rr);
    t.delta_r.push_back(rl - rr);
    t.gamma_left.push_back(gl);
    t.gamma_right.push_back(gr);
    t.delta_gamma.push_back(gl - gr);
  }
  return t;
}

}  // namespace rb::contact
