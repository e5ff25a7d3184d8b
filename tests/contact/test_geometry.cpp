// Contact-geometry solver (Eq. 12, 15, 21): closed-form cases, symmetry, flange indentation.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>

#include "contact_test_util.hpp"
#include "workbench/contact/geometry.hpp"
#include "workbench/contact/kec.hpp"
#include "workbench/contact/lut.hpp"
#include "workbench/core/error.hpp"

namespace {

using namespace rb::contact;

// ---- Semi-analytic reference: a wheel that is a circle (or a line) on a rail-head circle --------
//
// With the linearised A of Eq. (9), A = sqrt(1 + phi^2) Rot(atan(phi)), so a wheel circle of radius
// Rw maps to a circle of radius Rw sqrt(1 + phi^2) and a conical wheel to a line. The rail head of
// radius R is a circle with centre C = (sigma (Lr + xi/2 + R sin beta), -R cos beta). Contact on a
// side is the tangency of the two curves, a closed-form condition on (y, z, phi); both sides give
// two equations for z and phi at given y, solved here to machine precision by a 2x2 Newton with a
// central-difference Jacobian.
struct ArcCase {
  double r0 = 0.46;
  double lambda = 0.0;  // cone: wheel radius r0 - sigma lambda s (rw = 0)
  double rw = 0.0;      // wheel circle radius: > 0 convex, < 0 concave (hollow), 0: cone
  double R = 0.3;       // rail head radius
  double lw = 0.75, lr = 0.7535, beta = 0.0, xi = 0.0;
};

struct RefSide {
  double s_w, s_r;
  double py, pz;  // contact point
};
struct RefSolution {
  double z, phi;
  RefSide side[2];
};

// Tangency residual of one side, and its contact point.
double tangency(const ArcCase& c, double sigma, double y, double z, double phi, RefSide* out) {
  const double cb = std::cos(c.beta), sb = sigma * std::sin(c.beta);
  const double lr = c.lr + 0.5 * c.xi;
  const Eigen::Vector2d C(sigma * lr - sb * (-c.R), cb * (-c.R));
  const Eigen::Vector2d r(y, z);
  Eigen::Matrix2d A;
  A << 1.0, -phi, phi, 1.0;
  Eigen::Vector2d P;
  double res;
  if (c.rw == 0.0) {
    // Line through W(0) = r + A (sigma Lw, -r0) with direction A (1, sigma lambda) (h' = -sigma
    // lambda, tangent (1, -h')).
    const Eigen::Vector2d W0 = r + A * Eigen::Vector2d(sigma * c.lw, -c.r0);
    Eigen::Vector2d t = A * Eigen::Vector2d(1.0, sigma * c.lambda);
    Eigen::Vector2d n(-t.y(), t.x());
    n.normalize();
    res = (W0 - C).dot(n) - c.R;
    P = C + c.R * n;
  } else {
    // Wheel circle: centre at (sigma Lw, -(r0 - rw)) in the wI frame for both signs of rw.
    const double k = std::sqrt(1.0 + phi * phi);
    const Eigen::Vector2d Cw = r + A * Eigen::Vector2d(sigma * c.lw, -(c.r0 - c.rw));
    const Eigen::Vector2d d = Cw - C;
    const double rwk = std::abs(c.rw) * k;
    if (c.rw > 0) {
      res = d.norm() - (rwk + c.R);  // external tangency
      P = C + c.R * d.normalized();
    } else {
      res = d.norm() - (rwk - c.R);  // internal: rail circle inside the hollow wheel circle
      P = Cw - rwk * d.normalized();
    }
  }
  if (out) {
    out->py = P.x();
    out->pz = P.y();
    // Rail parameter: rail-frame coordinates of P.
    const double dy = P.x() - sigma * lr, dz = P.y();
    out->s_r = cb * dy + sb * dz;
    // Wheel parameter: u = A^-1 (P - r), s_w = u_Y - sigma Lw.
    const Eigen::Vector2d u = A.inverse() * (P - r);
    out->s_w = u.x() - sigma * c.lw;
  }
  return res;
}

RefSolution reference(const ArcCase& c, double y, double z0) {
  Eigen::Vector2d x(z0, 0.0);
  auto F = [&](const Eigen::Vector2d& v) {
    return Eigen::Vector2d(tangency(c, 1.0, y, v(0), v(1), nullptr),
                           tangency(c, -1.0, y, v(0), v(1), nullptr));
  };
  for (int it = 0; it < 50; ++it) {
    const Eigen::Vector2d f = F(x);
    if (f.cwiseAbs().maxCoeff() < 1e-15) break;
    Eigen::Matrix2d J;
    for (int k = 0; k < 2; ++k) {
      Eigen::Vector2d e = Eigen::Vector2d::Zero();
      e(k) = 1e-7;
      J.col(k) = (F(x + e) - F(x - e)) / 2e-7;
    }
    x -= J.partialPivLu().solve(f);
  }
  RefSolution s;
  s.z = x(0);
  s.phi = x(1);
  tangency(c, 1.0, y, s.z, s.phi, &s.side[0]);
  tangency(c, -1.0, y, s.z, s.phi, &s.side[1]);
  return s;
}

ContactGeometryConfig arcConfig(const ArcCase& c) {
  rbtest::ProfilePtr wheel = c.rw == 0.0 ? rbtest::coneWheel(c.r0, c.lambda, 0.05, 1e-4)
                                         : rbtest::arcWheel(c.r0, c.rw, c.lambda, 0.0, 0.04, 1e-4);
  ContactGeometryConfig cfg =
      rbtest::symmetricConfig(wheel, rbtest::arcRail(c.R, 0.03, 1e-4), c.lw, c.lr, c.beta);
  return cfg;
}

void expectMatchesReference(const ArcCase& c, double tol, double y_max = 8e-3) {
  const ContactSolver solver(arcConfig(c));
  EXPECT_FALSE(solver.hasFlange(Side::Left));
  TreadContact prev;
  bool have = false;
  double worst = 0.0;
  for (double y = 0.0; y <= y_max + 1e-12; y += 0.5e-3) {
    const TreadContact t = solver.solveTread(y, c.xi, have ? &prev : nullptr);
    ASSERT_TRUE(t.converged) << "y = " << y;
    const RefSolution r = reference(c, y, t.z);
    const double errs[] = {t.z - r.z,
                           (t.phi - r.phi) * c.lw,
                           t.s[0] - r.side[0].s_w,
                           t.s[1] - r.side[0].s_r,
                           t.s[2] - r.side[1].s_w,
                           t.s[3] - r.side[1].s_r,
                           t.left.y - r.side[0].py,
                           t.left.z - r.side[0].pz,
                           t.right.y - r.side[1].py,
                           t.right.z - r.side[1].pz};
    for (double e : errs) {
      EXPECT_LT(std::abs(e), tol) << "y = " << y;
      worst = std::max(worst, std::abs(e));
    }
    prev = t;
    have = true;
  }
  std::printf("    worst deviation from the closed form: %.2e m\n", worst);
}

TEST(ContactGeometry, ConeOnArcRailMatchesClosedForm) {
  ArcCase c;
  c.lambda = 1.0 / 20.0;
  expectMatchesReference(c, 1e-9);
  c.lambda = 1.0 / 40.0;
  c.beta = 1.0 / 40.0;
  c.xi = 2e-3;
  expectMatchesReference(c, 1e-9);
}

TEST(ContactGeometry, ArcOnArcMatchesClosedForm) {
  ArcCase c;
  c.rw = 0.5;  // convex wheel tread of radius 0.5 m on a 0.3 m rail head
  expectMatchesReference(c, 1e-9);
  c.rw = -0.5;  // hollow wheel tread (conformal side), rails inclined 1:40
  c.beta = 1.0 / 40.0;
  // Conformal contact migrates fast (the inclined rails put the centred contact 26 mm off the tape
  // circle): beyond ~4.5 mm the right rail contact leaves the 60 mm wide test rail head.
  expectMatchesReference(c, 1e-9, 4e-3);
}

TEST(ContactGeometry, HollowWheelContactMigration) {
  // A hollow wheel of radius Rw on a rail head Rr: the contact lies on the line of the two circle
  // centres, so the rail contact point moves by -Rr / (Rw - Rr) per unit of lateral motion of the
  // wheel circle centre (opposite to it: the centre lies far below the rail head).
  ArcCase c;
  c.rw = -0.5;
  c.R = 0.3;
  const ContactSolver solver(arcConfig(c));
  const TreadContact a = solver.solveTread(0.0, 0.0);
  const TreadContact b = solver.solveTread(1e-4, 0.0, &a);
  ASSERT_TRUE(a.converged && b.converged);
  // Lateral motion of the left wheel circle centre: dy + dphi (r0 - rw) (roll moves it too).
  const double dcentre = 1e-4 + (b.phi - a.phi) * (c.r0 - c.rw);
  const double migration = (b.left.y - a.left.y) / dcentre;
  EXPECT_NEAR(migration, -c.R / (-c.rw - c.R), 2e-3);
}

TEST(ContactGeometry, ResidualVanishesAtSolution) {
  const ContactSolver solver(rbtest::s1002On60E1());
  TreadContact prev;
  bool have = false;
  for (double y = 0.0; y <= 10e-3; y += 0.25e-3) {
    const TreadContact t = solver.solveTread(y, 0.0, have ? &prev : nullptr);
    ASSERT_TRUE(t.converged) << y;
    ContactState x;
    x.y = y;
    x.z = t.z;
    x.phi = t.phi;
    x.s = t.s;
    const auto f = solver.residual(x, 0.0);
    for (std::size_t k = 0; k < 6; ++k) {
      if ((k == 2 && t.mode[0] == ContactMode::Edge) ||
          (k == 5 && t.mode[1] == ContactMode::Edge)) {
        continue;  // the tangency row is replaced by s_w = boundary
      }
      EXPECT_LT(std::abs(f[k]), 1e-12) << "y = " << y << " row " << k;
    }
    EXPECT_LE(t.penetration, 1e-9);
    prev = t;
    have = true;
  }
}

TEST(ContactGeometry, LeftRightSymmetryS1002) {
  const ContactSolver solver(rbtest::s1002On60E1());
  for (double y : {0.1e-3, 0.7e-3, 2.5e-3, 4.0e-3, 5.5e-3, 6.1e-3, 9e-3, 15e-3}) {
    // Continuation from the centre on both sides.
    TreadContact p = solver.solveTread(0.0, 0.0), m = p;
    for (int i = 1; i <= 40; ++i) {
      p = solver.solveTread(y * i / 40.0, 0.0, &p);
      m = solver.solveTread(-y * i / 40.0, 0.0, &m);
    }
    ASSERT_TRUE(p.converged && m.converged);
    EXPECT_NEAR(p.z, m.z, 1e-12) << y;
    EXPECT_NEAR(p.phi, -m.phi, 1e-12) << y;
    // Mirror conventions: h_rw(s) = h_lw(-s), h_rr(s) = h_lr(-s), so s_lw(-y) = -s_rw(y).
    EXPECT_NEAR(m.s[0], -p.s[2], 1e-10) << y;
    EXPECT_NEAR(m.s[1], -p.s[3], 1e-10) << y;
    EXPECT_NEAR(m.s[2], -p.s[0], 1e-10) << y;
    EXPECT_NEAR(m.left.gamma, p.right.gamma, 1e-10) << y;
    EXPECT_NEAR(m.left.radius, p.right.radius, 1e-12) << y;
  }
}

TEST(ContactGeometry, CentredS1002TouchesNearTheTapeCircle) {
  const ContactGeometryConfig cfg = rbtest::s1002On60E1();
  const ContactSolver solver(cfg);
  const TreadContact t = solver.solveTread(0.0, 0.0);
  ASSERT_TRUE(t.converged);
  // z is the axle height: r0 plus the (small) offset of the contact from the tape circle and the
  // rail crown, z = h_w(s_w) + Z_contact for phi = 0.
  EXPECT_NEAR(t.phi, 0.0, 1e-15);
  EXPECT_NEAR(t.z, t.left.radius + t.left.z, 1e-12);
  EXPECT_NEAR(t.z - cfg.r0, 0.0, 0.2e-3);
  EXPECT_LT(std::abs(t.s[0]), 5e-3);  // contact within 5 mm of the tape circle
  EXPECT_NEAR(t.left.gamma, t.right.gamma, 1e-14);
  std::printf(
      "    S1002/60E1 centred: z - r0 = %.4f mm, s_lw = %.3f mm, s_lr = %.3f mm, "
      "gamma = %.3f deg\n",
      (t.z - cfg.r0) * 1e3, t.s[0] * 1e3, t.s[1] * 1e3, t.left.gamma * 180 / M_PI);
}

TEST(ContactGeometry, CurvaturesAndRollingRadius) {
  // Cone on arc: wheel transverse curvature 0, rail transverse 1/R, wheel rolling-direction
  // curvature cos(alpha)/r with alpha the cone angle.
  ArcCase c;
  c.lambda = 0.05;
  const ContactSolver solver(arcConfig(c));
  const TreadContact t = solver.solveTread(1e-3, 0.0);
  ASSERT_TRUE(t.converged);
  EXPECT_NEAR(t.left.k_wheel_trans, 0.0, 1e-6);
  EXPECT_NEAR(t.left.k_rail_trans, 1.0 / c.R, 1e-6);
  EXPECT_NEAR(t.left.k_rail_long, 0.0, 0.0);
  EXPECT_NEAR(t.left.radius, c.r0 - c.lambda * t.s[0], 1e-12);
  EXPECT_NEAR(t.left.k_wheel_long, std::cos(std::atan(c.lambda)) / t.left.radius, 1e-12);
  // Contact angle: the rail normal at the contact is the cone normal, leaning atan(lambda) toward
  // the track centre, turned by the roll (the linearised A rotates by atan(phi); phi > 0 lifts the
  // left wheel and turns its normal further toward the centre).
  EXPECT_NEAR(t.left.gamma, std::atan(c.lambda) + std::atan(t.phi), 1e-9);
  EXPECT_NEAR(t.right.gamma, std::atan(c.lambda) - std::atan(t.phi), 1e-9);
}

TEST(ContactGeometry, FlangeIndentationAndItsDerivatives) {
  const ContactGeometryConfig cfg = rbtest::s1002On60E1();
  const ContactSolver solver(cfg);
  TreadContact t = solver.solveTread(0.0, 0.0);
  for (int i = 1; i <= 70; ++i) t = solver.solveTread(i * 0.1e-3, 0.0, &t);  // y = 7 mm
  ASSERT_TRUE(t.converged);
  const WheelsetPose pose{7e-3, t.z, t.phi};
  const FlangeContact f = solver.flange(Side::Left, pose, 0.0);
  ASSERT_TRUE(f.exists && f.converged);
  EXPECT_EQ(f.mode, ContactMode::Tangent);
  EXPECT_GT(f.delta, 0.0);  // the tread constraint pushes the flange into the rail beyond ~6.3 mm
  EXPECT_NEAR(f.point.gamma, 70.0 * M_PI / 180.0, 0.02);  // S1002 flank, 70 deg
  // Eq. (15): the distance vector is along the wheel normal, normals parallel.
  EXPECT_NEAR(f.nw_y * f.point.n_z - f.nw_z * f.point.n_y, 0.0, 1e-10);
  // Envelope theorem: derivatives equal finite differences of the re-solved indentation.
  const double h = 1e-7;
  auto delta = [&](double dy, double dz, double dphi, double dxi) {
    const WheelsetPose p{pose.y + dy, pose.z + dz, pose.phi + dphi};
    return solver.flange(Side::Left, p, dxi, &f).delta;
  };
  EXPECT_NEAR((delta(h, 0, 0, 0) - delta(-h, 0, 0, 0)) / (2 * h), f.ddelta_dy, 1e-6);
  EXPECT_NEAR((delta(0, h, 0, 0) - delta(0, -h, 0, 0)) / (2 * h), f.ddelta_dz, 1e-6);
  EXPECT_NEAR((delta(0, 0, h, 0) - delta(0, 0, -h, 0)) / (2 * h), f.ddelta_dphi, 1e-6);
  EXPECT_NEAR((delta(0, 0, 0, h) - delta(0, 0, 0, -h)) / (2 * h), f.ddelta_dxi, 1e-6);
  // Right flange far away: a gap (negative indentation).
  const FlangeContact fr = solver.flange(Side::Right, pose, 0.0);
  ASSERT_TRUE(fr.exists && fr.converged);
  EXPECT_LT(fr.delta, -5e-3);
}

TEST(ContactGeometry, KnifePointInvertsTheWheelsetTransformation) {
  // The knife point in equivalent-profile coordinates maps back onto the rail origin by Eq. (22).
  const double lr = 0.753, r0 = 0.46;
  const double y = 3e-3, z = 0.4601, phi = 2e-3, yir = 1e-3, zir = -0.5e-3;
  for (double sigma : {1.0, -1.0}) {
    const KnifePoint k = knifePoint(sigma, lr, r0, y, z, phi, yir, zir);
    EXPECT_NEAR(y + k.s_k + phi * (r0 + k.f_k) - yir, 0.0, 1e-15);
    EXPECT_NEAR(z + phi * (sigma * lr + k.s_k) - r0 - k.f_k - zir, 0.0, 1e-15);
  }
}

TEST(ContactGeometry, ConfigValidationAndHash) {
  ContactGeometryConfig cfg = rbtest::s1002On60E1();
  const auto h0 = configHash(cfg);
  EXPECT_EQ(h0, configHash(rbtest::s1002On60E1()));
  ContactGeometryConfig c2 = cfg;
  c2.kec_dhat = 0.4e-3;
  EXPECT_NE(configHash(c2), h0);
  c2 = cfg;
  c2.left_rail = rbtest::arcRail(0.3);
  EXPECT_NE(configHash(c2), h0);
  c2 = cfg;
  c2.right_wheel.reset();
  c2.lut_y.step = 0.3e-3 * 1.01;
  try {
    checkConfig(c2);
    FAIL() << "expected an InputError";
  } catch (const rb::InputError& e) {
    EXPECT_EQ(e.diagnostics().size(), 2u);
    EXPECT_NE(std::string(e.what()).find("missing right wheel profile"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("LUT lateral grid"), std::string::npos);
  }
  EXPECT_EQ(table10LateralGrid().count(), 361u);
  EXPECT_EQ(table10LateralGridRefined().count(), 721u);
  EXPECT_EQ(table10GaugeGrid().count(), 11u);
  EXPECT_EQ(table9KecGrid().count(), 465u);
  EXPECT_EQ(table9KecGridRefined().count(), 5001u);
}

}  // namespace

namespace {

TEST(ContactGeometry, WheelsNotOverTheRailsIsAnInputError) {
  rb::contact::ContactGeometryConfig cfg = rbtest::s1002On60E1();
  cfg.wheel_lw = 0.60;  // wheels 150 mm inside the rails
  cfg.lut_gauge = {0.0, 0.0, 1e-3};
  EXPECT_THROW(rb::contact::buildLut(cfg), rb::InputError);
  EXPECT_THROW(rb::contact::buildKec(cfg), rb::InputError);
  const rb::contact::ContactSolver solver(cfg);
  EXPECT_FALSE(solver.solveTread(0.0, 0.0).converged);
}

}  // namespace
