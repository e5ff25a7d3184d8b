#pragma once
// Plain input structs for wheel/rail profiles and the contact model built by
// workbench/scenario from the profiles{} and contact{} blocks. SI units.
#include <array>
#include <string>
#include <vector>

#include "workbench/contact/interpolation.hpp"
#include "workbench/core/error.hpp"
#include "workbench/creep/fastsim.hpp"
#include "workbench/creep/polach.hpp"
#include "workbench/dynamics/creep_laws.hpp"
#include "workbench/profiles/nominal.hpp"
#include "workbench/track/spec.hpp"

namespace rb::dynamics {

// Wheel and rail profiles and their positioning (paper Table 1, ../docs/profiles.md).
// One rail profile slice of a rail that changes along the track (contact/sliced_rail.hpp).
struct RailSliceSpec {
  double s = 0.0;    // [m] track arc length
  std::string rail;  // "60e1" or a resolved path, drawn as a left rail like ProfilesSpec::rail
  double dy = 0.0;   // [m] offset of its rail frame toward the field side
  double dz = 0.0;   // [m] offset of its rail frame, up
  // A plain-text slice file's length unit and z direction (a slice of a CONTACT slices-file:
  // z down, as CONTACT's canonical profiles; SIMPACK files say both themselves).
  bool metres = false;
  bool z_down = false;
  // [-] the profile reader keeps the longest run of points with |dz/dy| <= max_slope
  // (profile_io.hpp); a slice holding two heads (a wing rail and a crossing nose with the
  // flangeway between them) needs the steepest flank's slope
  double max_slope = 10.0;
  SourceLoc loc;
};

// A CONTACT slices-file (.slcs, profiles/slice_list.hpp) read into rail slices: its path (part of
// a study case's content key) and what of it railbench does not use (warned about at compile).
struct SliceListSpec {
  std::string path;  // resolved
  int features = 0, kinks = 0, accelerations = 0;
  SourceLoc loc;
};

// A further rail on one side (a switch blade, a crossing nose, a check rail): its own slices; it
// exists from its first slice to its last (contact/sliced_rail.hpp).
inline constexpr std::size_t kMaxExtraRails = 3;  // per side
struct ExtraRailSpec {
  std::string name;  // 1-32 letters, digits, '_'; not "rail" (the running rail)
  std::vector<RailSliceSpec> slices;
  // A check rail: it meets the back of the wheel's flange (contact/check_rail.hpp), not its
  // tread or flange face.
  bool check = false;
  SourceLoc loc;
};
// A rail's name in outputs (/contact/<ws>/<side>/rails/<name>).
inline bool validRailName(const std::string& n) {
  if (n.empty() || n.size() > 32) return false;
  for (char c : n)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'))
      return false;
  return true;
}

// One wheelset's own wheels (profiles.wheelsets.<name>): a worn, measured or re-profiled pair on
// one wheelset of the vehicle. Each profile is drawn as a left wheel like ProfilesSpec::wheel;
// an empty one falls back to `wheel` here, then to the vehicle's wheel_left / wheel_right / wheel.
struct WheelsetProfilesSpec {
  std::string wheelset;  // the wheelset body's name
  std::string wheel, wheel_left, wheel_right;
  SourceLoc loc;
};

struct ProfilesSpec {
  std::string wheel = "s1002";  // built-in "s1002", or a resolved path to a .prw / text file
  // The left and right wheels' own profiles (a wheelset with two different wheels: worn,
  // measured, another diameter), each drawn as a left wheel like `wheel`; empty: `wheel`.
  std::string wheel_left, wheel_right;
  std::string rail = "60e1";    // built-in "60e1", or a resolved path to a .prr / text file
  double back_to_back = 1.360;  // [m] B; Lw = B/2 + flange-back distance (70 mm for S1002)
  // [m] G measured 14 mm below the rail top; Lr = G/2 + offset
  double gauge = track::kStandardGauge;
  double r0 = profiles::kNominalWheelRadius;  // [m] nominal rolling radius
  double inclination = 1.0 / 40.0;            // [rad] rail inclination beta
  double lw = 0.0;                            // [m] explicit Lw (0: from back_to_back)
  double lr = 0.0;                            // [m] explicit Lr (0: from gauge)
  bool refined_tables = false;                // paper Tables 9-10 refined grids
  // Rails that change along the track (elastic contact only): per side (left, right) the rail
  // profile slices at strictly increasing s, linearly blended between (sliced_rail.hpp); empty:
  // `rail` everywhere. The positioning (Lr from the gauge) stays that of `rail`.
  std::array<std::vector<RailSliceSpec>, 2> rail_slices;
  // Further rails per side, each its own slices, searched by the elastic method with the running
  // rail (their patches are the wheel's patches too).
  std::array<std::vector<ExtraRailSpec>, 2> extra_rails;
  // Wheelsets with wheels of their own (each wheelset at most once); the others run on the
  // profiles above.
  std::vector<WheelsetProfilesSpec> wheelsets;
  // The slices-files the slices above were read from.
  std::vector<SliceListSpec> slice_lists;
  SourceLoc loc;
};

// Kec, Lut: constraint contact (the wheelset's height and roll follow from the constraints);
// Elastic: the wheelset has its full rigid-body freedom on an online multi-point contact search
// with a Hertz normal force per patch (docs/elastic_contact.md).
enum class ContactMethod { Kec, Lut, Elastic };
enum class NormalForceCoupling { Lagged, Consistent };
// Free: the wheelset spin theta is a degree of freedom driven by the creep forces (its creep mode
// is stiff, ~ -2400 1/s at 20 m/s, docs/contact_dynamics.md section 7). Prescribed: the spin rate
// is kinematic, theta_dot = V(t) / r_c (constant-rotational-speed assumption); theta is not a
// state and the spin reaction torque (traction/braking at the wheel) is a constraint reaction.
enum class WheelsetSpin { Free, Prescribed };

// The track under the rail at a track position (contact.elastic.rail_support; docs/
// track_support.md): per wheel a rail mass travelling with its wheelset on a spring and a damper to
// the ground, laterally and vertically.
struct RailSupportPoint {
  double s = 0.0;               // [m] track arc length (one point: everywhere)
  double mass = 0.0;            // [kg] rail mass moving with the wheel
  double k_y = 0.0, c_y = 0.0;  // [N/m], [N s/m] lateral support
  double k_z = 0.0, c_z = 0.0;  // [N/m], [N s/m] vertical support
  SourceLoc loc;
};

// The elastic contact method's parameters (contact.elastic{}; docs/elastic_contact.md).
struct ElasticSpec {
  // Damping of the normal contact (Hunt-Crossley: N = K_H delta^1.5 (1 + c_d delta_dot)), given
  // as the damping ratio of a wheel's vertical oscillation on its Hertz contact at the static
  // wheel load; c_d follows from it, the wheel's mass share and the Hertz stiffness (compiled).
  double damping_ratio = 0.1;
  double sample_step = 0.25e-3;  // [m] wheel sampling of the contact search's scan
  // [m] Derailment: a wheel whose tape circle has risen by more than this above its rail (flange
  // climb, a lifted wheel) stops the run; < 0: half the wheel's flange height.
  double derailment_lift = -1.0;
  double min_curvature_ratio = 0.1;  // lateral relative curvature floored smoothly at this * A
  // The track under the rail: empty (default) rigid rails; one point, the same support everywhere;
  // several, strictly increasing s, linear between them and the end points' beyond.
  std::vector<RailSupportPoint> rail_support;
  SourceLoc loc;
};

struct ContactSpec {
  ContactMethod method = ContactMethod::Kec;
  ElasticSpec elastic;
  double kec_dhat = 0.5e-3;        // [m] KEC tread-flange transition lengths (paper section 2.4)
  double kec_dbar = 1.0e-3;        // [m]
  double flange_stiffness = 1e10;  // [N/m^1.5] LUT Hertz flange K (paper Table 3; validation 1e10)
  double flange_damping = -1.0;    // [N s/m^2] LUT flange D; < 0: K / 100 as in paper Table 3
  CreepModel creep = CreepModel::Polach;
  creep::FastsimGrid fastsim;      // creep = fastsim: its grid and traction bound (fastsim.hpp)
  double mu = creep::kDefaultMu;   // [-] friction coefficient (paper section 5.1)
  double youngs_modulus = 2.1e11;  // [Pa] (paper section 5.3)
  double poisson = 0.28;           // [-]
  // Lagged: creep forces use the previous evaluation's constraint normal forces (the paper,
  // section 2.5). Consistent: normal and tangential forces solved together at every evaluation.
  // Consistent is the default because it is the one that converges under step refinement: the
  // lag makes the rhs depend on the previous stage, a first-order perturbation of the creep
  // forces (Eq. 24-25) that dominates the error where the normal forces change fast (two-point
  // contact onset; docs/contact_dynamics.md section 4.1).
  NormalForceCoupling normal_forces = NormalForceCoupling::Consistent;
  WheelsetSpin wheelset_spin = WheelsetSpin::Free;
  // [N] A wheel whose constraint normal force falls below this stops the run: a constraint
  // contact keeps the wheel on the rail by pulling when the load would lift it, which no real
  // wheel/rail pair can do, so results past that point are not physical.
  double min_normal_force = 0.0;
  // Interpolation of the contact table between its nodes (contact/interpolation.hpp): cubic
  // (C1) or the paper's linear (section 5.5).
  contact::TableInterpolation table_interpolation = contact::TableInterpolation::Cubic;
  SourceLoc loc;
};

}  // namespace rb::dynamics
