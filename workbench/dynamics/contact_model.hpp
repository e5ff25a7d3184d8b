#pragma once
// The compiled wheel/rail contact model (docs/contact_dynamics.md): ProfilesSpec +
// ContactSpec + the vehicle and track -> ContactModel (immutable, validated). It holds the four
// profiles and their positioning (paper Table 1, Eq. 5, 10), the contact geometry configuration
// and ONLY the table the chosen method needs (KEC table for "kec", LUT for "lut"), shared through
// std::shared_ptr<const ...> so an application can cache tables by contact::configHash
// (TableCache below), plus the creep law parameters (paper section 2.5) and the LUT flange Hertz
// parameters (Eq. 20, Table 3).
//
// Validation (compileContact): every problem is reported as one rb::InputError at the location of
// the block it belongs to (contact{} or profiles{}): a vehicle without wheelsets, profile files
// that cannot be read, non-physical parameters, a table build that fails (for instance profiles
// that do not touch when centred). Table build problems that do not stop the build (short KEC
// transitions, unresolved jumps) are kept as warnings in ContactModel::warnings, with the table
// statistics (build time, bytes) in tableStats().
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "workbench/contact/check_rail.hpp"
#include "workbench/contact/config.hpp"
#include "workbench/contact/elastic_normal.hpp"
#include "workbench/contact/elastic_search.hpp"
#include "workbench/contact/geometry.hpp"
#include "workbench/contact/kec.hpp"
#include "workbench/contact/lut.hpp"
#include "workbench/contact/sliced_rail.hpp"
#include "workbench/core/spline.hpp"
#include "workbench/creep/hertz.hpp"
#include "workbench/creep/polach.hpp"
#include "workbench/dynamics/spec.hpp"
#include "workbench/track/track.hpp"
#include "workbench/vehicle/model.hpp"

namespace rb::dynamics {

// The load-independent Hertz ellipse shape (creep::hertzShape: a secant iteration, ~0.7 us) as a
// function of the curvature ratio rho = min(A, B) / max(A, B), tabulated once: not-a-knot cubic
// splines of g, m, n, K(e), E(e) over ln(rho) on [ln 1e-6, 0] (2400 intervals); below 1e-6 the
// exact solver is called. Relative error < 1e-8 (tests/dynamics), ~30 ns. Immutable, shared.
class HertzShapeTable {
 public:
  HertzShapeTable();
  creep::HertzShape shape(double A, double B) const;       // A, B > 0; allocation-free
  static std::shared_ptr<const HertzShapeTable> shared();  // one instance per process

 private:
  CubicSplineSet spline_;
  double u_min_ = 0.0;
};

// The compiled data of the elastic contact method (docs/elastic_contact.md, "Dynamics"): the
// contact search of each wheel over its rail, the normal problem's policy, the normal damping and
// the derailment criterion.
struct ElasticContactModel {
  std::vector<contact::ElasticContactSearch> search;  // [side]: left, right
  // [side]: the rail as slices along the track (profiles.rail_slices; null: the prismatic rail of
  // `search`, which then also serves the compile-time quantities below).
  std::array<std::shared_ptr<const contact::SlicedRailSearch>, 2> sliced;
  // [side]: further rails (profiles.extra_rails: blades, noses, check rails), each present from
  // its first slice to its last, with their names (outputs /contact/<ws>/<side>/rails/<name>).
  std::array<std::vector<std::shared_ptr<const contact::SlicedRailSearch>>, 2> extra;
  std::array<std::vector<std::string>, 2> extra_names;
  // [side][rail]: 1 for a check rail (its contact is with the back of the wheel's flange,
  // contact/check_rail.hpp), 0 for a rail under the tread and flange.
  std::array<std::vector<int>, 2> extra_check;
  // [side]: the back of the wheel's flange, for check rails.
  std::array<contact::FlangeBack, 2> flange_back;
  contact::ElasticNormalSpec normal;
  // Hunt-Crossley damping N = K_H delta^1.5 (1 + damping delta_dot) [s/m], derived from
  // ElasticSpec::damping_ratio at the nominal static wheel load of the centred tread contact:
  // a wheel of mass m_w (half its wheelset) on the linearised Hertz spring k = 1.5 K_H delta0^0.5
  // has the damping c = 2 zeta sqrt(k m_w) = damping * N0.
  double damping = 0.0;
  double damping_ratio = 0.0;
  double static_load = 0.0;         // [N] nominal wheel load N0 = vehicle weight / wheels
  double static_approach = 0.0;     // [m] Hertz approach delta0 of the centred tread at N0
  double tread_stiffness = 0.0;     // [N/m^1.5] K_H of the centred tread contact
  double vertical_frequency = 0.0;  // [Hz] sqrt(k / m_w) / 2 pi of that wheel at N0
  double flange_height = 0.0;       // [m] wheel radius at the flange tip minus r(s_w = 0)
  double derailment_lift = 0.0;     // [m] a wheel risen more than this above its rail derails
  // The track under the rail (contact.elastic.rail_support; empty: rigid rails): a rail mass per
  // wheel on its support, by track position (railSupportAt, rail_support.hpp).
  std::vector<RailSupportPoint> support;
};

struct ContactModel {
  ContactMethod method = ContactMethod::Kec;
  CreepModel creep = CreepModel::Polach;
  NormalForceCoupling coupling = NormalForceCoupling::Consistent;  // as ContactSpec
  WheelsetSpin spin = WheelsetSpin::Free;  // spin a state, or theta_dot = V(t) / centredRadius()
  double min_normal_force = 0.0;  // [N] below it a wheel has lifted: the rhs refuses the state

  // Profiles, positioning (Lw, Lr, beta, r0), grids and KEC transition lengths.
  contact::ContactGeometryConfig geometry;
  std::uint64_t config_hash = 0;  // contact::configHash(geometry)
  // Exactly one of these is set, for the chosen method.
  std::shared_ptr<const contact::KecTable> kec;
  std::shared_ptr<const contact::LutTable> lut;
  // Contact point geometry at given surface parameters (KEC branch points A and B of Eq. 26).
  std::shared_ptr<const contact::ContactSolver> solver;
  double flange_boundary[2] = {0.0, 0.0};  // s_w of the tread/flange split, left and right wheel

  // Centred wheelset (y = 0, no irregularity): axle height, roll, rolling radii.
  double centred_z = 0.0;
  double centred_phi = 0.0;
  double centred_radius[2] = {0.0, 0.0};
  double centredRadius() const { return 0.5 * (centred_radius[0] + centred_radius[1]); }
  // The track under the rail: elastic contact with rail masses (ElasticContactModel::support).
  bool railSupport() const { return elastic && !elastic->support.empty(); }

  // Tangential forces (section 2.5).
  creep::Material material;
  creep::CreepParams creep_params;
  // Hertz needs positive relative curvatures; conformal zones (concave wheel root on the rail
  // gauge corner) are clamped to this floor [1/m] (an equivalent radius of 10 m).
  double min_relative_curvature = 0.05;
  std::shared_ptr<const HertzShapeTable> hertz_shapes = HertzShapeTable::shared();

  // LUT flange (Eq. 20): f = K delta^1.5 + D delta_dot delta for delta > 0, f >= 0.
  double flange_stiffness = 1e10;  // [N/m^1.5]
  double flange_damping = 1e8;     // [N s/m^2] (K/100 unless given)

  // NormalForceCoupling::Consistent: iteration on the two normal-force multipliers of a wheelset
  // (fixed point, Newton with a finite-difference 2x2 Jacobian when it contracts slowly) until
  // |Phi(lambda) - lambda| <= consistent_tol * (|lambda| + 1), at most consistent_max_iter
  // evaluations of Phi (creep forces + back substitution) per wheelset.
  double consistent_tol = 1e-10;
  int consistent_max_iter = 50;

  std::vector<int> wheelsets;         // body indices of the vehicle's wheelsets, in body order
  std::vector<std::string> warnings;  // table warnings and other notes for the user
  // Flangeway play of the profiles on the nominal gauge: how far [m] the centred wheelset moves
  // to the left (y > 0) and to the right until that side's flange touches its rail (NaN when no
  // flange contact within 30 mm), and the warnings on the track's gauge irregularity against it
  // (messages without location: narrowing beyond the play, widening beyond tread contact).
  double flangeway[2] = {0.0, 0.0};
  std::vector<std::string> gauge_warnings;
  SourceLoc loc;  // the contact{} block
  // CreepModel::Fastsim: grid and bound (as ContactSpec). Last, so that the members the other
  // laws' evaluations read keep their offsets.
  creep::FastsimGrid fastsim;
  // ContactMethod::Elastic: its searches, normal policy, damping and derailment criterion (null
  // for the constraint methods).
  std::shared_ptr<const ElasticContactModel> elastic;
  // The wheel profiles' sources, left and right ("s1002" or a resolved file path).
  std::array<std::string, 2> wheel_sources;
  // Wheelsets with wheels of their own (profiles.wheelsets), by wheelset index (the order of
  // `wheelsets`): the model compiled for that pair, with everything that follows from the
  // profiles (positions, tables, centred pose and radii, elastic searches, flange height); null
  // or beyond the end: this model. Wheelsets with the same pair share one model.
  std::vector<std::shared_ptr<const ContactModel>> own_wheels;
  const ContactModel& forWheelset(std::size_t w) const {
    return w < own_wheels.size() && own_wheels[w] ? *own_wheels[w] : *this;
  }
  // The centred wheelset (centred_z, centred_phi, no yaw, no irregularity) over the rail of side
  // `side` at `at`: its pose relative to that rail's displaced profile origin, with its blend.
  contact::ElasticPose centredPoseOver(const contact::SlicedRailSearch::Place& at,
                                       std::size_t side) const {
    contact::ElasticPose pose{-contact::kSideSign[side] * at.dy, centred_z - at.dz, centred_phi,
                              0.0};
    pose.blend = at.blend;
    return pose;
  }

  // Build statistics of the table in use (time, bytes, warnings, notes).
  const contact::TableBuildStats& tableStats() const;
  // The names of dynamics/names.hpp (nameOf): "kec" / "lut" / "elastic", the creep laws of
  // creep_laws.hpp
  // ("polach", "kalker", "fastsim", "none"), "lagged" / "consistent".
  static const char* methodName(ContactMethod m);
  static const char* creepName(CreepModel c);
  static const char* couplingName(NormalForceCoupling c);
  static const char* spinName(WheelsetSpin s);  // "free" / "prescribed"
};

// Tables by content (contact::configHash in memory, contact::tableInputKey on disk):
// compileContact builds a table only when the cache does not hold one for the same configuration.
// Not thread-safe; the tables themselves are immutable and may be shared by any number of models
// and threads.
//
// The disk folder is only an optimisation: when it cannot be created, read or written (read-only,
// a file in its place, full disk), tables are built in memory and the run goes on; the problem is
// reported once, as a warning taken by takeWarnings(), and the folder is not tried again by this
// cache.
class TableCache {
 public:
  TableCache() = default;
  // With a folder, tables missing from memory are loaded from (or built and saved to) it through
  // contact::DiskTableCache, so separate runs of a study share them.
  explicit TableCache(std::string disk_dir) : disk_dir_(std::move(disk_dir)) {}
  std::shared_ptr<const contact::KecTable> kec(const contact::ContactGeometryConfig& config);
  std::shared_ptr<const contact::LutTable> lut(const contact::ContactGeometryConfig& config);
  std::size_t size() const { return kec_.size() + lut_.size(); }
  int builds() const { return builds_; }  // tables built (cache misses)
  bool diskUsable() const { return !disk_dir_.empty() && !disk_failed_; }
  // Warnings not yet handed out (at most one about the folder per cache), then cleared.
  std::vector<std::string> takeWarnings();

 private:
  void diskProblem(const std::string& why);
  std::map<std::uint64_t, std::shared_ptr<const contact::KecTable>> kec_;
  std::map<std::uint64_t, std::shared_ptr<const contact::LutTable>> lut_;
  int builds_ = 0;
  std::string disk_dir_;
  bool disk_failed_ = false;
  std::vector<std::string> warnings_;
};

// The four profiles and their positioning, grids and KEC transition lengths of a scenario:
// built-in "s1002" / "60e1" (right profiles mirrored) or files (profiles::readProfileFile; text
// files in millimetres, wheels with h = r0 + z); Lw, Lr from back_to_back and gauge by
// profiles::positionS1002On60E1 unless lw / lr are given (> 0). Throws rb::InputError.
contact::ContactGeometryConfig contactGeometryConfig(const ProfilesSpec& profiles,
                                                     const ContactSpec& contact);

// Validates and compiles (see the header comment). `cache` may be null.
ContactModel compileContact(const ProfilesSpec& profiles, const ContactSpec& contact,
                            const vehicle::VehicleModel& vehicle, const track::TrackModel& track,
                            TableCache* cache = nullptr);

}  // namespace rb::dynamics
