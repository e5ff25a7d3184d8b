// The per-evaluation structures shared by several suspension elements (VehicleModel::point_pairs,
// Workspace::point_motion) and the directional force assembly: at a random state of the Manchester
// wagon on a curved, canted track they must equal the per-element computation of Eq. (28)-(29)
// bit for bit, and the relative motion must equal the global positions of the points.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include "fixtures.hpp"
#include "workbench/vehicle/dynamics.hpp"
#include "workbench/vehicle/kinematics.hpp"
#include "workbench/vehicle/model.hpp"

namespace rb::vehicle {
namespace {

const track::TrackModel& curve() {
  static const track::TrackModel tm =
      track::compileTrack(rbtest::curveTrack(track::Side::Left, 500.0, 0.1));
  return tm;
}

// The wagon plus two axial elements (the wagon's own elements are all directional), one of them
// at the same points as another so that they share a point pair.
VehicleSpec wagonWithAxialElements() {
  VehicleSpec v = rbtest::manchesterWagon(20.0, 30.0);
  ElementSpec e;
  e.kind = ElementKind::SpringDamper;
  e.body1 = "car";
  e.body2 = "bogie1";
  e.point1 = Eigen::Vector3d(8.7, 0.4, -1.1);
  e.point2 = Eigen::Vector3d(-0.3, -0.2, 0.15);
  e.direction = Direction::Axial;
  e.stiffness = 2e5;
  e.damping = 3e3;
  e.name = "axial_a";
  v.elements.push_back(e);
  e.kind = ElementKind::Bumpstop;
  e.name = "axial_b";
  e.stiffness = e.damping = 0.0;
  e.length0 = 1.4;
  e.table_d = {0.0, 0.01, 0.02, 0.05};
  e.table_f = {0.0, 0.0, 1e3, 1e5};
  v.elements.push_back(e);
  return v;
}

// A random state: every body's s on its own track frame, small random displacements, rotations
// and rates; the wheelset spin angle anywhere.
void randomState(const VehicleModel& m, std::mt19937& rng, Workspace& ws,
                 std::vector<double>& series_f) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    Vector6d q, qd;
    q << m.bodyS(static_cast<int>(b), 0.37), 0.01 * u(rng), 0.01 * u(rng), 0.02 * u(rng),
        0.02 * u(rng), 0.02 * u(rng);
    if (m.bodies[b].kind == BodyKind::Wheelset) q[kPitch] = 3.0 * u(rng);
    qd << 20.0 + u(rng), 0.1 * u(rng), 0.1 * u(rng), 0.2 * u(rng), 0.2 * u(rng), 0.2 * u(rng);
    if (m.bodies[b].kind == BodyKind::Wheelset) qd[kPitch] = 43.0 + u(rng);
    ws.q[b] = q;
    ws.qd[b] = qd;
  }
  series_f.resize(m.series_dampers.size());
  for (double& f : series_f) f = 1e3 * u(rng);
}

void expectSame(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const std::string& what) {
  for (int c = 0; c < 3; ++c) EXPECT_EQ(a[c], b[c]) << what << " component " << c;
}

bool samePoints(const PointPair& p, const PointPair& q) {
  return p.body1 == q.body1 && p.body2 == q.body2 && p.u1 == q.u1 && p.u2 == q.u2;
}

// The point pair of element g holds g's bodies, body pair and attachment points.
void expectElementsPointPair(const VehicleModel& m, const ElementGeometry& g) {
  ASSERT_GE(g.point_pair, 0) << g.name;
  ASSERT_LT(g.point_pair, static_cast<int>(m.point_pairs.size())) << g.name;
  const PointPair& p = m.point_pairs[static_cast<std::size_t>(g.point_pair)];
  EXPECT_TRUE(samePoints(p, {g.body1, g.body2, g.pair, g.u1, g.u2})) << g.name;
  EXPECT_EQ(p.pair, g.pair) << g.name;
}

TEST(SharedPointPairs, TheWagonsPointElementsJoinSixteenPairs) {
  const VehicleModel m = compileVehicle(rbtest::manchesterWagon(), curve());
  // 8 axle boxes (primary x, y, z), 4 secondary spring locations (z, shear x, shear y, lateral
  // damper), 2 traction links, 2 bump stops.
  EXPECT_EQ(m.point_pairs.size(), 16u);
  for (const ElementId& id : m.elements()) {
    const ElementGeometry& g = m.element(id);
    if (id.kind == ElementKind::BendingSpring)
      EXPECT_EQ(g.point_pair, -1) << g.name;
    else
      expectElementsPointPair(m, g);
  }
  for (std::size_t a = 0; a < m.point_pairs.size(); ++a)
    for (std::size_t b = a + 1; b < m.point_pairs.size(); ++b)
      EXPECT_FALSE(samePoints(m.point_pairs[a], m.point_pairs[b])) << a << " " << b;
  const VehicleModel ma = compileVehicle(wagonWithAxialElements(), curve());
  EXPECT_EQ(ma.point_pairs.size(), 17u);
}

TEST(SharedPointPairs, SharedMotionEqualsThePerElementMotionAndTheGlobalPoints) {
  const VehicleModel m = compileVehicle(wagonWithAxialElements(), curve());
  Workspace ws = makeWorkspace(m);
  std::mt19937 rng(20261202);
  std::vector<double> series_f;
  for (int trial = 0; trial < 5; ++trial) {
    randomState(m, rng, ws, series_f);
    evaluate(m, 0.0, series_f.data(), ws);
    for (const ElementId& id : m.elements()) {
      if (id.kind == ElementKind::BendingSpring) continue;
      const ElementGeometry& g = m.element(id);
      const PointPairMotion ref = pointPairMotion(g, ws);
      const PointPairMotion& sh = ws.point_motion[static_cast<std::size_t>(g.point_pair)];
      expectSame(sh.aui, ref.aui, g.name + " aui");
      expectSame(sh.auj, ref.auj, g.name + " auj");
      expectSame(sh.delta, ref.delta, g.name + " delta");
      expectSame(sh.delta_dot, ref.delta_dot, g.name + " delta_dot");
      expectSame(sh.w_delta, ref.w_delta, g.name + " w_delta");
      // Independent of Eq. (28): the global points, projected on the master track frame.
      const BodyKinematics& ki = ws.kin[static_cast<std::size_t>(g.body1)];
      const BodyKinematics& kj = ws.kin[static_cast<std::size_t>(g.body2)];
      const Eigen::Vector3d rP = ki.tf.R + ki.tf.A * pointPosition(ki, g.u1);
      const Eigen::Vector3d rQ = kj.tf.R + kj.tf.A * pointPosition(kj, g.u2);
      EXPECT_LT((ki.tf.A.transpose() * (rQ - rP) - sh.delta).norm(), 1e-12) << g.name;
    }
  }
}

// Generalised forces of the point elements assembled with the general form of Eq. (29)
// (F_i = grad f, F_j = -A_ij^T F_i, full cross products), element by element in the order of
// evaluate(), plus the bending springs' moments: the same numbers as evaluate().
TEST(SharedPointPairs, ForceAssemblyEqualsTheGeneralForm) {
  const VehicleModel m = compileVehicle(wagonWithAxialElements(), curve());
  Workspace ws = makeWorkspace(m);
  std::mt19937 rng(7);
  std::vector<double> series_f;
  for (int trial = 0; trial < 5; ++trial) {
    randomState(m, rng, ws, series_f);
    evaluate(m, 0.0, series_f.data(), ws);
    const std::size_t n = m.bodies.size();
    std::vector<Eigen::Vector3d> F(n, Eigen::Vector3d::Zero()), M(n, Eigen::Vector3d::Zero());
    const auto add = [&](const ElementGeometry& g, const ElementValue& v) {
      const PointPairMotion p = pointPairMotion(g, ws);
      const Eigen::Vector3d grad =
          g.axis < 0 ? Eigen::Vector3d(p.delta / p.delta.norm()) : Eigen::Vector3d::Unit(g.axis);
      const auto i = static_cast<std::size_t>(g.body1), j = static_cast<std::size_t>(g.body2);
      const Eigen::Vector3d Fi = grad * v.force;
      const Eigen::Vector3d Fj = -(ws.pair_A[static_cast<std::size_t>(g.pair)].transpose() * Fi);
      F[i] += Fi;
      M[i] += p.aui.cross(Fi);
      F[j] += Fj;
      M[j] += p.auj.cross(Fj);
    };
    for (const ElementKind k : {ElementKind::SpringDamper, ElementKind::SeriesSpringDamper,
                                ElementKind::ShearSpring, ElementKind::Bumpstop})
      for (const ElementId& id : m.elements())
        if (id.kind == k) add(m.element(id), ws.value(id));
    for (std::size_t e = 0; e < m.bending_springs.size(); ++e) {
      const BendingSpringElement& el = m.bending_springs[e];
      const Eigen::Matrix3d& Aij = ws.pair_A[static_cast<std::size_t>(el.g.pair)];
      const BodyKinematics& ki = ws.kin[static_cast<std::size_t>(el.g.body1)];
      const BodyKinematics& kj = ws.kin[static_cast<std::size_t>(el.g.body2)];
      const Eigen::Matrix3d R = (Aij * kj.attach.A) * ki.attach.A.transpose();
      const double tr = R.trace();
      const Eigen::Matrix3d T1 = 0.5 * (tr * Eigen::Matrix3d::Identity() - R);
      const Eigen::Matrix3d T2 = 0.5 * (tr * Eigen::Matrix3d::Identity() - R.transpose());
      const double Mb = ws.bending_spring[e].force;
      M[static_cast<std::size_t>(el.g.body1)] += T2.row(el.g.axis).transpose() * Mb;
      M[static_cast<std::size_t>(el.g.body2)] -=
          (Aij.transpose() * T1.row(el.g.axis).transpose()) * Mb;
    }
    for (std::size_t b = 0; b < n; ++b) {
      expectSame(ws.susp_force[b], F[b], m.bodies[b].name + " force");
      expectSame(ws.susp_moment[b], M[b], m.bodies[b].name + " moment");
    }
  }
}

Eigen::Matrix3d rx(double a) {
  Eigen::Matrix3d m;
  m << 1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a);
  return m;
}
Eigen::Matrix3d ry(double a) {
  Eigen::Matrix3d m;
  m << std::cos(a), 0, std::sin(a), 0, 1, 0, -std::sin(a), 0, std::cos(a);
  return m;
}
Eigen::Matrix3d rz(double a) {
  Eigen::Matrix3d m;
  m << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  return m;
}

// The rotations written out entry by entry (kinematics.cpp) are the numbers of the products of
// the elementary rotations, for small and large angles.
TEST(SharedPointPairs, WrittenOutRotationsEqualTheProducts) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> small(-0.05, 0.05), large(-4.0, 4.0);
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Vector3d a = trial % 2 ? Eigen::Vector3d(small(rng), large(rng), small(rng))
                                        : Eigen::Vector3d(large(rng), large(rng), large(rng));
    const Eigen::Vector3d rates(0.1, 0.2, 0.3);
    const Eigen::Matrix3d ypr = rz(a[2]) * ry(a[1]) * rx(a[0]);
    const Eigen::Matrix3d yr = rz(a[2]) * rx(a[0]);
    const Eigen::Matrix3d yrp = yr * ry(a[1]);
    const Eigen::Matrix3d e1 = eulerKinematics(RotationSequence::YawPitchRoll, a, rates).A;
    const Eigen::Matrix3d e2 = eulerKinematics(RotationSequence::YawRollPitch, a, rates).A;
    const Eigen::Matrix3d e3 = intermediateKinematics(a, rates).A;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(e1(r, c), ypr(r, c)) << r << c;
        EXPECT_EQ(e2(r, c), yrp(r, c)) << r << c;
        EXPECT_EQ(e3(r, c), yr(r, c)) << r << c;
      }
  }
}

}  // namespace
}  // namespace rb::vehicle
