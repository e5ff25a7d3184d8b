#pragma once
// Stages 5-8 of a ContactVehicleOde evaluation with the elastic contact method
// (docs/elastic_contact.md, "Dynamics"). The wheelset has its full rigid-body freedom: y, z, phi,
// psi and the spin theta are states, and the contact forces are applied forces, so a wheelset's
// equations are M qddot = Q - M_qs a + sum over patches (N g_n + f_x g_x + f_y g_y + m_z g_m),
// without multipliers and without a normal/tangential coupling iteration (the normal force of a
// patch follows from its approach, not from the accelerations).
//
// Per wheel and evaluation:
//   - the contact search (contact/elastic_search.hpp) of the wheel over its rail, the rail
//     displaced by its irregularity (y_l, z_l or y_r, z_r: the rails translate, as in the KEC's
//     constraints, Eq. 22): every penetrating local minimum of the gap is a patch, any number of
//     them, with the exact longitudinal shift of the contact point of a yawed wheelset;
//   - the normal force per patch from Hertz at the search's shared-overlap approach delta, with the
//     curvature policy of contact/elastic_normal.hpp and Hunt-Crossley damping
//       N = K_H(A, B) delta^1.5 max(0, 1 + c_d delta_dot),
//     delta_dot = -(v_wheel - v_rail) . n, v_rail the velocity of the irregular rail's surface
//     under the moving contact (V times its slope along the track); c_d from
//     ElasticContactModel::damping;
//   - the wheel material point at the contact is the locus point (x_w, sigma Lw + s_w, -r cos
//     theta) of the wheelset intermediate frame: the normal force's lever arm includes the
//     contact point's longitudinal shift (the yaw moment of a yawed wheelset's contact forces);
//   - creepages and creep forces in the rail's contact frame: x along the track (tangent to the
//     prismatic rail at every contact; along the rail in the tangent plane where the rail rises or
//     moves sideways, rail_slope.hpp), n the rail normal, y = n x x; the slip relative to the rail
//     (its mass's velocity on a supported track removed, rail_support.hpp).
//
// Wheel lift, flange climb and two-point contact are physics here: a wheel with no penetrating
// minimum has no patch. Derailment stops the run: a wheel whose tape circle has risen above its
// centred height over its rail by more than ElasticContactModel::derailment_lift (flange climb,
// a lifted wheel) is refused as the KEC's wheel lift is (recoverable: an adaptive method retries
// a smaller step; a real derailment stops the run with its time, distance and wheel).
// Internal to workbench/dynamics.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "workbench/contact/elastic_normal.hpp"
#include "workbench/contact/rail_slope.hpp"
#include "workbench/dynamics/augmented.hpp"
#include "workbench/dynamics/contact_coupling.hpp"
#include "workbench/dynamics/contact_patches.hpp"
#include "workbench/dynamics/contact_stages.hpp"
#include "workbench/dynamics/rail_support.hpp"

namespace rb::dynamics::internal {

// The irregular rail of one side at the wheelset: its displacement and slope along the track.
inline RailOffset railOffset(const track::IrregularityPoint& r, int side) {
  return side == 0 ? RailOffset{r.y_l, r.z_l, r.y_l_s, r.z_l_s}
                   : RailOffset{r.y_r, r.z_r, r.y_r_s, r.z_r_s};
}

// One patch: kinematics, Hertz normal force with damping, creepages and load-independent creep
// constants. Returns the normal force.
template <class Law>
double setupElasticPatch(Patch& p, const contact::ElasticPatchGeometry& g, double sigma,
                         const ContactModel& c, const WheelsetFrame& f, double V,
                         const RailOffset& rail) {
  const ElasticContactModel& e = *c.elastic;
  placePatch(p, g.s_w, g.s_r, g.gamma, g.radius, sigma, c);
  p.n = Eigen::Vector3d(g.n_x, g.n_y, g.n_z);
  p.ql.setZero();
  const Eigen::Vector3d u(g.x_w, sigma * c.geometry.wheel_lw + g.s_w,
                          -g.radius * std::cos(g.theta));
  const Eigen::Vector3d au = f.kin->attach.A * u;
  const Eigen::Vector3d sp = f.axle.cross(au);
  p.gn = wheelPointForce(f, au, sp, p.n);
  const Eigen::Vector3d v = vehicle::pointVelocity(*f.kin, au) + sp * f.spin_rate;
  // On a rail that rises or moves sideways the normal leans (n_x = -(y_s n_y + z_s n_z)): the
  // rail's velocity under the contact, V (y_s n_y + z_s n_z), is then exactly -V n_x of the rail
  // material passing at -V e_X, plus the wheel point's own slip along X.
  // The rail mass under a supported rail moves with (vy, vz) (0 on rigid rails).
  double delta_dot = -(v.y() - V * rail.y_s - rail.vy) * p.n.y() -
                     (v.z() - V * rail.z_s - rail.vz) * p.n.z() - v.x() * p.n.x();
  // A rail changing along the track rises under the moving contact at V db/ds rail_rise.
  if (rail.blend_s != 0.0) delta_dot += V * rail.blend_s * g.rail_rise;
  p.k = contact::policyCurvatures(g, e.normal);
  p.shape = c.hertz_shapes->shape(p.k.A, p.k.B);
  const double K = creep::hertzStiffness(c.material, p.k, p.shape);
  const double d = std::max(g.approach, 0.0);
  const double N = K * d * std::sqrt(d) * std::max(0.0, 1.0 + e.damping * delta_dot);
  p.q0 = N;
  if constexpr (Law::kCreep) {
    if (g.n_x == 0.0) {
      p.ex = Eigen::Vector3d::UnitX();
      p.ey = Eigen::Vector3d(0.0, p.n.z(), -p.n.y());  // n x e_x
    } else {
      // Along the rail in the tangent plane: e_x with its normal part removed.
      p.ex = (Eigen::Vector3d::UnitX() - g.n_x * p.n).normalized();
      p.ey = p.n.cross(p.ex);
    }
    p.gx = wheelPointForce(f, au, sp, p.ex);
    p.gy = wheelPointForce(f, au, sp, p.ey);
    const Eigen::Vector3d bgn = f.BG.transpose() * p.n;
    p.gm << 0.0, 0.0, bgn(0), bgn(1), bgn(2);
    // The slip velocity relative to the rail (its mass moves on a supported track).
    const Eigen::Vector3d vr(v.x(), v.y() - rail.vy, v.z() - rail.vz);
    const double vx = g.n_x == 0.0 ? vr.x() : vr.dot(p.ex);
    p.cr = creep::creepagesFromKinematics(vx, vr.dot(p.ey), f.omega.dot(p.n), V);
    p.pc = creep::patchConstants(c.material, p.k, p.shape);
  }
  return N;
}

// Rise of a wheel's tape circle (s_w = 0) above its height in the centred position, over its rail
// (the irregular rail's vertical displacement removed).
inline double wheelLift(const ContactModel& c, const vehicle::Vector6d& q, double height,
                        const RailOffset& rail, double sigma) {
  const double lw = c.geometry.wheel_lw;
  const double z = q[vehicle::kZ] + height + sigma * lw * std::sin(q[vehicle::kRoll]) - rail.z;
  return z - (c.centred_z + sigma * lw * std::sin(c.centred_phi));
}

// The search of one wheel over one rail at the wheelset's s: the pose relative to the rail's
// displaced profile origin (irregularity `irr`, and a sliced rail's offsets toward the field side
// and up at `at`); `rail` receives that displacement.
inline contact::ElasticPose railPose(const contact::SlicedRailSearch::Place& at,
                                     const vehicle::Vector6d& q, double height,
                                     const RailOffset& irr, double sigma, RailOffset& rail) {
  rail = irr;
  rail.y += sigma * at.dy;
  rail.z += at.dz;
  rail.y_s += sigma * at.dy_ds;
  rail.z_s += at.dz_ds;
  rail.blend_s = at.blend_ds;
  contact::ElasticPose pose{q[vehicle::kY] - rail.y, q[vehicle::kZ] + height - rail.z,
                            q[vehicle::kRoll], q[vehicle::kYaw]};
  pose.blend = at.blend;
  return pose;
}

inline void searchRail(const contact::SlicedRailSearch::Place& at, const vehicle::Vector6d& q,
                       double height, const RailOffset& irr, double sigma,
                       contact::ElasticWheelGeometry& out, contact::ElasticSearchWorkspace& sw,
                       contact::SlopedSearchWorkspace& sloped, RailOffset& rail) {
  const contact::ElasticPose pose = railPose(at, q, height, irr, sigma, rail);
  // The slices' slope along the track is in the search's geometry (rail_slope.hpp); the
  // irregularity's is not (its r p^2 / 2 is below a micrometre) and stays in the damping's rail
  // velocity.
  const contact::RailSlope slope{sigma * at.dy_ds, at.dz_ds, at.blend_ds};
  contact::searchSlopedRail(*at.search, pose, slope, out, sw, sloped);
}

// The patches of a further rail (index r + 1 of ElasticWheelWork::patch_rail) join the wheel's;
// beyond kMaxElasticPatches the shallowest kept patch gives way to a deeper one.
inline void mergeRailPatches(const contact::ElasticWheelGeometry& g, int r, ElasticWheelWork& ew) {
  contact::ElasticWheelGeometry& w = ew.geometry;
  w.min_gap = std::min(w.min_gap, g.min_gap);
  w.truncated = w.truncated || g.truncated;
  w.newton_iterations += g.newton_iterations;
  for (int k = 0; k < g.count; ++k) {
    const contact::ElasticPatchGeometry& pg = g.patch[static_cast<std::size_t>(k)];
    int slot = w.count;
    if (slot == contact::kMaxElasticPatches) {
      w.truncated = true;
      slot = 0;
      for (int j = 1; j < w.count; ++j)
        if (w.patch[static_cast<std::size_t>(j)].approach <
            w.patch[static_cast<std::size_t>(slot)].approach)
          slot = j;
      if (!(w.patch[static_cast<std::size_t>(slot)].approach < pg.approach)) continue;
    } else {
      ++w.count;
    }
    w.patch[static_cast<std::size_t>(slot)] = pg;
    ew.patch_rail[static_cast<std::size_t>(slot)] = r + 1;
  }
}

// Every rail of one side under wheel ew: the running rail (prismatic, or its slices) and the
// further rails present at the wheelset's s, their patches in ew.geometry.
inline void searchWheelRails(const ElasticContactModel& e, const vehicle::Vector6d& q,
                             double height, const RailOffset& irr, std::size_t sd,
                             ElasticWheelWork& ew) {
  const double sigma = contact::kSideSign[sd];
  // The running rail: its slices at s, or the prismatic rail (no offset, no blend).
  const contact::SlicedRailSearch::Place running =
      e.sliced[sd] ? e.sliced[sd]->at(q[vehicle::kS])
                   : contact::SlicedRailSearch::Place{&e.search[sd]};
  searchRail(running, q, height, irr, sigma, ew.geometry, ew.search, ew.sloped_search[0],
             ew.rail_offset[0]);
  ew.patch_rail.fill(0);
  for (std::size_t r = 0; r < e.extra[sd].size(); ++r) {
    const contact::SlicedRailSearch::Place at = e.extra[sd][r]->at(q[vehicle::kS]);
    if (at.search == nullptr) continue;
    if (e.extra_check[sd][r] != 0) {
      // A check rail: its contact with the back of the flange (check_rail.hpp). Its slope along
      // the track (a flare) is in the damping's rail velocity, not in the geometry.
      const contact::ElasticPose pose = railPose(at, q, height, irr, sigma, ew.rail_offset[r + 1]);
      contact::searchCheckRail(*at.search, e.flange_back[sd], pose, ew.extra_geometry);
    } else {
      searchRail(at, q, height, irr, sigma, ew.extra_geometry, ew.extra_search[r],
                 ew.sloped_search[r + 1], ew.rail_offset[r + 1]);
    }
    mergeRailPatches(ew.extra_geometry, static_cast<int>(r), ew);
  }
}

// Stage 5 (elastic): the search and every patch of both wheels of wheelset ww, their normal and
// creep forces, summed into the generalised force Q (y, z, phi, theta, psi).
template <class Law>
void elasticPatches(const ContactModels& models, const StageInput& in, WheelsetWork& ww,
                    ContactWorkspace& work, Vec5& Q) {
  const ContactModel& c = *ww.contact;
  const ElasticContactModel& e = *c.elastic;
  const vehicle::Vector6d& q = work.bodies.q[ww.body];
  const WheelsetFrame wf = wheelsetFrame(work.bodies.kin[ww.body], work.bodies.qd[ww.body]);
  resetPatches(ww);
  const vehicle::VehicleLayout& l = models.layout;
  const bool supported = l.rail_masses > 0;
  const int w = l.wheelsetSlot(ww.body);
  const RailSupportPoint support =
      supported ? railSupportAt(e.support, q[vehicle::kS]) : RailSupportPoint{};
  for (int side = 0; side < 2; ++side) {
    ElasticWheelWork& ew = ww.elastic[side];
    const double sigma = contact::kSideSign[side];
    const auto sd = static_cast<std::size_t>(side);
    RailOffset irr = railOffset(ww.irr, side);
    if (supported) {
      // The rail mass under the wheel moves the rail as an irregularity does, and its velocity is
      // the rail surface's.
      for (int k = 0; k < 2; ++k) {
        ew.rail_q[k] = in.y[l.railPosition(w, side, k)];
        ew.rail_qd[k] = in.y[l.railRate(w, side, k)];
        ew.wheel_force[k] = 0.0;
      }
      irr.y += ew.rail_q[0];
      irr.z += ew.rail_q[1];
      irr.vy = ew.rail_qd[0];
      irr.vz = ew.rail_qd[1];
    }
    searchWheelRails(e, q, ww.height, irr, sd, ew);
    ew.lift = wheelLift(c, q, ww.height, irr, sigma);
    const int n = ew.geometry.count;
    ++work.stats.elastic_searches;
    work.stats.elastic_patches += n;
    work.stats.elastic_max_patches = std::max(work.stats.elastic_max_patches, n);
    bool tread = false, flange = false;
    for (int k = 0; k < contact::kMaxElasticPatches; ++k) {
      Patch& p = ew.patch[static_cast<std::size_t>(k)];
      if (k >= n) {
        p.active = false;
        continue;
      }
      const double N = setupElasticPatch<Law>(
          p, ew.geometry.patch[static_cast<std::size_t>(k)], sigma, c, wf, in.speed,
          ew.rail_offset[static_cast<std::size_t>(ew.patch_rail[static_cast<std::size_t>(k)])]);
      Q.noalias() += N * p.gn;
      if constexpr (Law::kCreep) creepForce<Law>(p, N, c, Q);
      (p.on_flange ? flange : tread) = true;
      if (supported) {
        Eigen::Vector3d F = N * p.n;
        if constexpr (Law::kCreep) F += p.fx * p.ex + p.fy * p.ey;
        ew.wheel_force[0] -= F.y();  // the wheel's force on the rail
        ew.wheel_force[1] -= F.z();
      }
    }
    ww.regime[side] = contactRegime(tread, flange);
    if (supported) {
      // The rail mass: m q'' = -k q - c q' + (the wheel's force on it), laterally and vertically.
      const double k[2] = {support.k_y, support.k_z}, cd[2] = {support.c_y, support.c_z};
      for (int j = 0; j < 2; ++j) {
        ew.support_force[j] = -k[j] * ew.rail_q[j] - cd[j] * ew.rail_qd[j];
        ew.rail_qdd[j] = (ew.support_force[j] + ew.wheel_force[j]) / support.mass;
      }
    }
  }
}

// The rates of wheelset w's rail masses (the track under the rail).
inline void writeRailMassRates(const vehicle::VehicleLayout& l, int w, const double* y,
                               const WheelsetWork& ww, double* ydot) {
  for (int side = 0; side < 2; ++side)
    for (int k = 0; k < 2; ++k) {
      ydot[l.railPosition(w, side, k)] = y[l.railRate(w, side, k)];
      ydot[l.railRate(w, side, k)] = ww.elastic[side].rail_qdd[k];
    }
}

// Stage 8 (elastic): derailment of a wheel of wheelset ww (ElasticWheelWork::lift beyond the
// criterion). Rhs and Init evaluations refuse the state (recoverable); Output ones only report.
inline int checkDerailment(const ContactModels& models, const StageInput& in,
                           const WheelsetWork& ww, ContactWorkspace& work) {
  const ElasticContactModel& e = *ww.contact->elastic;
  for (int s = 0; s < 2; ++s) {
    const double lift = ww.elastic[s].lift;
    if (!(std::abs(lift) > e.derailment_lift) || in.mode == EvalMode::Output) continue;
    std::ostringstream os;
    os << "derailment: wheelset '" << models.vehicle.bodies[ww.body].name << "', "
       << (s == 0 ? "left" : "right") << " wheel " << (lift > 0.0 ? "rose " : "dropped ")
       << std::abs(lift) * 1e3 << " mm " << (lift > 0.0 ? "above" : "below")
       << " its centred height over its rail (criterion contact.elastic.derailment_lift = "
       << e.derailment_lift * 1e3 << " mm) at t = " << in.t
       << " s, s = " << work.bodies.q[ww.body][vehicle::kS]
       << " m (lateral position y = " << work.bodies.q[ww.body][vehicle::kY] * 1e3 << " mm)";
    work.fail(ContactFailure::Derailment, models.vehicle.bodies[ww.body].name, os.str());
    return 1;
  }
  return 0;
}

// Stages 6-7 (elastic): the wheelset's accelerations from M qddot = Q (a 5x5 Cholesky; with a
// prescribed spin the spin row becomes theta_ddot = a / r_c and its reaction drops out).
inline int elasticAccelerations(const ContactModels& models, const StageInput& in,
                                const WheelsetWork& ww, ContactWorkspace& work, const Vec5& Q,
                                Vec5& qdd) {
  const vehicle::Matrix6d& mass = work.bodies.mass[ww.body];
  Eigen::Matrix<double, 5, 5> M = mass.block<5, 5>(1, 1);
  Vec5 b = Q;
  if (!models.layout.spinFree()) {
    pinSpinRhs(M.col(3), in.acceleration / ww.contact->centredRadius(), b);
    pinSpinMass(M);
  }
  Cholesky5 llt;
  if (!llt.factor(M)) {
    work.fail(ContactFailure::Singular, models.vehicle.bodies[ww.body].name,
              "wheelset '" + models.vehicle.bodies[ww.body].name +
                  "': mass matrix not positive definite at t = " + std::to_string(in.t) + " s");
    return 1;
  }
  qdd = llt.solve(b);
  if (qdd.allFinite()) return 0;
  work.fail(ContactFailure::NonFinite, models.vehicle.bodies[ww.body].name,
            "wheelset '" + models.vehicle.bodies[ww.body].name +
                "': non-finite accelerations at t = " + std::to_string(in.t) + " s");
  return 1;
}

// The rates of wheelset w's states: positions from the rates, the rates from qdd (y, z, phi,
// theta, psi).
inline void writeElasticRates(const vehicle::VehicleLayout& l, int w, const double* y,
                              const Vec5& qdd, double* ydot) {
  for (int c = 0; c < vehicle::kWheelsetCoordinates; ++c) {
    const int ip = l.wsPosition(w, c);
    if (ip < 0) continue;
    ydot[ip] = y[l.wsRate(w, c)];
    ydot[l.wsRate(w, c)] = qdd(vehicle::kWheelsetCoord[c] - 1);
  }
}

// Outputs of wheelset w (elastic): per wheel the strongest tread patch as patch[0], the strongest
// flange patch as patch[1], the totals over every patch.
void elasticWheelsetOutputs(const StageInput& in, int w, const WheelsetWork& ww, const Vec5& qdd,
                            bool creep, ContactWorkspace& work);

// Stages 5-8 of wheelset w with the elastic method.
template <class Law>
int elasticWheelsetStages(const ContactModels& models, const StageInput& in, int w, double* ydot,
                          ContactWorkspace& work, vehicle::StageClock* clock) {
  using vehicle::Stage;
  WheelsetWork& ww = work.wheelset(w);
  const vehicle::Matrix6d& mass = work.bodies.mass[ww.body];
  Vec5 Q =
      work.bodies.force[ww.body].segment<5>(1) - mass.block<5, 1>(1, vehicle::kS) * in.acceleration;
  elasticPatches<Law>(models, in, ww, work, Q);
  if (clock) clock->mark(Stage::ContactPatches);
  Vec5 qdd;
  if (const int rc = elasticAccelerations(models, in, ww, work, Q, qdd); rc != 0) return rc;
  if (ydot) writeElasticRates(models.layout, w, in.y, qdd, ydot);
  if (ydot && models.layout.rail_masses > 0) writeRailMassRates(models.layout, w, in.y, ww, ydot);
  if (const int rc = checkDerailment(models, in, ww, work); rc != 0) return rc;
  if (fillsOutputs(in.mode)) elasticWheelsetOutputs(in, w, ww, qdd, Law::kCreep, work);
  if (clock) clock->mark(Stage::Checks);
  return 0;
}

}  // namespace rb::dynamics::internal
