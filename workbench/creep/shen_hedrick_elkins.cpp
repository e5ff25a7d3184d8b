#include "workbench/creep/shen_hedrick_elkins.hpp"

#include <cmath>

namespace rb::creep {

double shenHedrickElkinsFactor(double u) {
  if (!(u > 0.0)) return 1.0;
  if (u >= 3.0) return 1.0 / u;
  // (u - u^2/3 + u^3/27) / u, in Horner form.
  return 1.0 + u * (-1.0 / 3.0 + u / 27.0);
}

SaturatedCreepForce shenHedrickElkinsForce(const CreepParams& p, const ContactPatch& patch,
                                           const Creepages& s) {
  SaturatedCreepForce out;
  const double limit = p.mu * patch.Q;
  if (!(limit > 0.0) || !(patch.a > 0.0) || !(patch.b > 0.0)) return out;
  const LinearCreepForce lin = kalkerLinearForce(p.G, patch, s);
  const double resultant = std::hypot(lin.fx, lin.fy);
  const double eps = shenHedrickElkinsFactor(resultant / limit);
  out.fx = eps * lin.fx;
  out.fy = eps * lin.fy;
  out.mz = eps * lin.mz;
  return out;
}

}  // namespace rb::creep
