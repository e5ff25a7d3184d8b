#include <gtest/gtest.h>

#include <cstdio>

#include "tests/wickens/wickens_linear.hpp"

namespace rbtest::wickens {
namespace {

TEST(Wickens, Probe) {
  for (const char* method : {"kec", "lut"})
    for (const char* incl : {"0.05", "0.0333333333333", "0.025", "0.0166666666667"}) {
      Case c = compileCase({std::string("contact.method=") + method,
                            std::string("profiles.inclination=") + incl});
      for (double dy : {1e-6, 1e-5, 1e-4}) {
        const CentredParameters p = centredParameters(c, dy);
        const Springs s = springs(c);
        std::printf(
            "%s incl %s dy %g: patches %d r0 %.6f l0 %.6f lambda %.5f dgam %.4f gam0 %.5f N %.1f "
            "a %.3e b %.3e c11 %.3f c22 %.3f c23 %.3f f11 %.4e f22 %.4e f23 %.4e kg %.4e ks %.4e "
            "ky %.3e kpsi %.3e Vw %.2f Vwg %.2f\n",
            method, incl, dy, p.patches_per_wheel, p.r0, p.l0, p.lambda, p.dgamma_dy, p.gamma0,
            p.normal, p.a, p.b, p.c11, p.c22, p.c23, p.f11, p.f22, p.f23, p.k_gravity, p.k_spin,
            s.ky, s.kpsi, closedFormCriticalSpeed(p, s),
            closedFormCriticalSpeed(p, s, p.k_gravity + p.k_spin));
      }
      for (double v : {20.0, 40.0, 80.0, 160.0}) {
        const Linearisation lin = linearise(c, v);
        std::printf("  V %.0f res %.2e evals %ld:", v, lin.residual, lin.evaluations);
        for (auto e : lin.eigenvalues) std::printf(" (%.4g %+.4gi)", e.real(), e.imag());
        const CentredParameters p = centredParameters(c);
        std::printf("\n   2dof:");
        for (auto e : twoDofEigenvalues(p, springs(c), v, p.k_gravity + p.k_spin))
          std::printf(" (%.4g %+.4gi)", e.real(), e.imag());
        std::printf("\n   2dof no kg:");
        for (auto e : twoDofEigenvalues(p, springs(c), v))
          std::printf(" (%.4g %+.4gi)", e.real(), e.imag());
        std::printf("\n");
      }
    }
}

}  // namespace
}  // namespace rbtest::wickens
