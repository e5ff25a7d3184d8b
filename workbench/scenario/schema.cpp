#include "workbench/scenario/schema.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "workbench/assessment/spec.hpp"
#include "workbench/contact/interpolation.hpp"
#include "workbench/core/names.hpp"
#include "workbench/core/range.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/dynamics/limits.hpp"
#include "workbench/dynamics/names.hpp"
#include "workbench/dynamics/spec.hpp"
#include "workbench/integrators/registry.hpp"
#include "workbench/profiles/nominal.hpp"
#include "workbench/scenario/effect_names.hpp"
#include "workbench/suspension/external_force.hpp"
#include "workbench/track/names.hpp"
#include "workbench/train/longitudinal.hpp"
#include "workbench/vehicle/names.hpp"

namespace rb::scenario {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

KeySpec num(std::string name, std::string unit, double def, std::string help, double min = -kInf,
            double max = kInf, bool minExclusive = false) {
  KeySpec k;
  k.name = std::move(name);
  k.type = ValueType::Number;
  k.unit = std::move(unit);
  k.def = formatNumber(def);
  k.num_default = def;
  k.help = std::move(help);
  k.min = min;
  k.max = max;
  k.min_exclusive = minExclusive;
  return k;
}

// A number in a range that a compiled module also guards (core/range.hpp).
KeySpec num(std::string name, std::string unit, double def, std::string help, const Range& r) {
  KeySpec k =
      num(std::move(name), std::move(unit), def, std::move(help), r.min, r.max, r.min_exclusive);
  k.max_exclusive = r.max_exclusive;
  return k;
}

// A key whose valid set is its range and the value `x`, a stand-in for "the default".
KeySpec sentinel(KeySpec k, double x) {
  k.sentinels.push_back(x);
  return k;
}

KeySpec required(KeySpec k) {
  k.required = true;
  k.def.clear();
  return k;
}

// A key that is absent unless given (its default would read as a value: a ramp's rate, a hold).
KeySpec withoutDefault(KeySpec k) {
  k.def.clear();
  return k;
}

KeySpec integer(std::string name, double def, std::string help, double min, double max) {
  KeySpec k = num(std::move(name), "-", def, std::move(help), min, max);
  k.type = ValueType::Integer;
  return k;
}

KeySpec choice(std::string name, std::vector<std::string> choices, std::string def,
               std::string help) {
  KeySpec k;
  k.name = std::move(name);
  k.type = ValueType::Choice;
  k.unit = "-";
  k.choices = std::move(choices);
  k.def = std::move(def);
  k.help = std::move(help);
  return k;
}

// A choice among the names of E's table (core/names.hpp), each with its one-line help.
template <class E>
KeySpec enumChoice(std::string name, E def, std::string help) {
  KeySpec k = choice(std::move(name), namesOf<E>(), std::string(nameOf(def)), std::move(help));
  for (const auto& entry : nameTable(E{})) k.choice_help.emplace_back(entry.help);
  return k;
}

KeySpec boolean(std::string name, bool def, std::string help) {
  KeySpec k;
  k.name = std::move(name);
  k.type = ValueType::Bool;
  k.unit = "-";
  k.def = def ? "true" : "false";
  k.num_default = def ? 1.0 : 0.0;
  k.help = std::move(help);
  return k;
}

KeySpec typed(std::string name, ValueType t, std::string unit, std::string help, bool req = false) {
  KeySpec k;
  k.name = std::move(name);
  k.type = t;
  k.unit = std::move(unit);
  k.help = std::move(help);
  k.required = req;
  return k;
}

KeySpec blockKey(std::string name, ValueType t, std::vector<std::string> kinds, std::string help,
                 std::string sub = {}) {
  KeySpec k;
  k.name = std::move(name);
  k.type = t;
  k.kinds = std::move(kinds);
  k.sub = std::move(sub);
  k.help = std::move(help);
  return k;
}

// track{} and its segment constructors (paper section 5.2).
void addTrackBlocks(std::vector<BlockSpec>& s) {
  const std::string gradientHelp =
      "vertical gradient rise/run, positive uphill, at the segment end (slope angle = -atan)";
  s.push_back({"track",
               "Track centreline as a sequence of segments, preprocessed into cubic splines of "
               "position and Euler angles versus arc length (paper Eq. 1-2, Fig. 4).",
               {blockKey("segments", ValueType::BlockList, namesOf<track::SegmentKind>(),
                         "segments in running order (required)"),
                num("step", "m", 0.5, "spline sampling step of the centreline (paper: 0.5 m)", 0,
                    kInf, true),
                num("cant_base", "m", 1.5, "lateral base over which cant height is measured", 0,
                    kInf, true),
                num("gauge", "m", track::kStandardGauge, "nominal track gauge", 1.0, 2.0),
                num("rail_lr", "m", 0.7555,
                    "Lr: lateral position of the rail profile frames (paper Table 1)", 0.5, 1.0),
                num("rail_inclination", "rad", 0.025,
                    "beta: rail inclination (paper Table 1: 1/40)", 0.0, 0.1),
                integer("max_points", 1e6,
                        "work and memory bound: most knots of one spline (centreline, "
                        "irregularities, CSV rows; ~0.4 kB each) and a PSD synthesis of at most "
                        "max_points x 8000 cosine terms; raise it for longer or finer tracks",
                        2, 1e12),
                blockKey("irregularities", ValueType::Block, {"psd", "measured"},
                         "track irregularities; none if absent (costs nothing)")}});
  s.push_back({std::string(nameOf(track::SegmentKind::Tangent)),
               "Straight segment: zero curvature and zero cant.",
               {required(num("length", "m", 0, "arc length", 0, kInf, true)),
                num("gradient", "-", 0, gradientHelp, -0.1, 0.1)}});
  s.push_back(
      {std::string(nameOf(track::SegmentKind::Transition)),
       "Clothoid: curvature, cant and gradient change linearly in arc length from the previous "
       "segment's end values to the values given here.",
       {required(num("length", "m", 0, "arc length", 0, kInf, true)),
        num("radius", "m", 0, "radius at the end; 0 means the transition ends straight", 0),
        enumChoice("side", track::Side::Left, "direction of the curve at the end"),
        num("cant", "m", 0, "superelevation height at the end", -0.3, 0.3),
        num("gradient", "-", 0, gradientHelp, -0.1, 0.1)}});
  s.push_back({std::string(nameOf(track::SegmentKind::Curve)),
               "Circular curve of constant radius and cant.",
               {required(num("length", "m", 0, "arc length", 0, kInf, true)),
                required(num("radius", "m", 0, "curve radius", 0, kInf, true)),
                enumChoice("side", track::Side::Left, "direction of the curve"),
                num("cant", "m", 0, "superelevation height", -0.3, 0.3),
                num("gradient", "-", 0, gradientHelp, -0.1, 0.1)}});
}

// psd{} and measured{} (paper Fig. 3, 15).
void addIrregularityBlocks(std::vector<BlockSpec>& s) {
  KeySpec wl;
  wl.name = "wavelengths";
  wl.type = ValueType::Pair;
  wl.unit = "m";
  wl.def = "{3, 70}";
  wl.help = "synthesis band {shortest, longest} wavelength (EN 13848 D1+D2: 3..70 m)";
  wl.min = 0;
  wl.min_exclusive = true;
  KeySpec channels;
  channels.name = "channels";
  channels.type = ValueType::StringList;
  channels.unit = "-";
  channels.choices = namesOf<track::Channel>();
  for (const auto& entry : track::kChannelNames) channels.choice_help.emplace_back(entry.help);
  channels.def = "all four";
  channels.help = "which irregularities to synthesise";
  auto psdInput = [](track::Channel c) {
    KeySpec k;
    k.name = nameOf(c);
    k.type = ValueType::PsdInput;
    k.unit = "m^2/(rad/m)";
    k.help = "user PSD (spectrum = \"user\"): function(omega) or {{omega, G}, ...}, one-sided";
    return k;
  };
  s.push_back(
      {"psd",
       "Irregularities synthesised from power spectral densities by a sum of cosines with random "
       "phases (paper Fig. 3, 15). One-sided PSDs over spatial angular frequency.",
       {required(enumChoice("spectrum", track::Spectrum{},
                            "named PSD (FRA values UNVERIFIED, see docs) or \"user\"")),
        integer("seed", 1, "random seed of the phases (recorded in the output)", 0,
                9.007199254740992e15),
        wl, integer("components", 2000, "cosines per channel", 1, track::kMaxPsdComponents),
        num("step", "m", 0.1, "spline sampling step (paper: 0.1 m)", 0, kInf, true),
        num("scale", "-", 1, "amplitude factor on every channel", 0, 100), channels,
        num("fade_in", "m", track::kDefaultFadeIn,
            "raised-cosine fade-in of every channel from s = 0 over this length, (1 - cos(pi s / "
            "fade_in)) / 2, so the vehicle meets no step where the irregularities begin (recorded "
            "in /track/irregularities@fade_in); 0 = none (the paper's validation cases)",
            0, 1e5),
        boolean("randomize_frequencies", true,
                "draw each cosine's frequency inside its band (false: band centres, periodic)"),
        psdInput(track::Channel::Alignment), psdInput(track::Channel::Vertical),
        psdInput(track::Channel::Gauge), psdInput(track::Channel::CrossLevel)}});
  KeySpec file;
  file.name = "file";
  file.type = ValueType::String;
  file.required = true;
  file.help =
      "CSV file relative to the scenario: a header naming s and any of alignment, vertical, "
      "gauge, cross_level (any order; missing channels are zero), then one row per s";
  s.push_back(
      {"measured",
       "Measured irregularities from a CSV file, splined through its rows (docs/track.md). Every "
       "problem of the file is reported at check as file:line.",
       {file,
        enumChoice("unit", track::CsvUnit::Metre,
                   "unit of the irregularity columns (s is always in m); values above 0.1 m are "
                   "refused as implausible"),
        enumChoice("beyond", track::Beyond::Error,
                   "where the file does not cover the track [0, length]"),
        num("fade_in", "m", 0,
            "raised-cosine fade-in of every channel from s = 0 over this length, (1 - cos(pi s / "
            "fade_in)) / 2 (recorded in /track/irregularities@fade_in); 0 = the record as "
            "measured",
            0, 1e5)}});
}

// contact.method: the contact methods, and "guided" for wheelsets without contact asked by name.
KeySpec contactMethod() {
  KeySpec k = enumChoice("method", dynamics::ContactMethod::Kec,
                         "constraint contact method, or \"guided\": no wheel/rail contact");
  k.choices.emplace_back(kGuidedContact);
  k.choice_help.emplace_back(
      "no contact model: the wheelsets follow the track centreline kinematically (no wheel/rail "
      "forces, no creep, no flange); the block then takes no other key. A vehicle with "
      "wheelsets needs a contact{} block, so guided wheelsets are always asked for by name");
  return k;
}

// profiles{} and contact{} (paper Table 1, sections 2.3-2.5).
void addContactBlocks(std::vector<BlockSpec>& s) {
  s.push_back(
      {"profiles",
       "Wheel and rail profiles and their positioning (paper Table 1). Built-in profiles: S1002 "
       "wheel (EN 13715) and 60E1 rail (EN 13674-1); the paper's LB-140-Area rail has no public "
       "geometry, so 60E1 at 1:40 is the default (docs/profiles.md).",
       {typed("wheel", ValueType::String, "-",
              "\"s1002\" or a wheel profile file (SIMPACK .prw, MiniProf .whl / .mpt or two-column "
              "text) below the scenario"),
        typed("wheel_left", ValueType::String, "-",
              "the left wheels' own profile (default: wheel), drawn as a left wheel like wheel"),
        typed("wheel_right", ValueType::String, "-",
              "the right wheels' own profile (default: wheel), drawn as a left wheel like wheel "
              "and mirrored (a wheelset with two different wheels: docs/profiles.md)"),
        typed("rail", ValueType::String, "-",
              "\"60e1\" or a rail profile file (SIMPACK .prr, MiniProf .ban / .mpt or two-column "
              "text) below the scenario"),
        num("back_to_back", "m", 1.36, "back-to-back distance B (Lw = B/2 + 70 mm for S1002)",
            dynamics::kBackToBackRange),
        num("gauge", "m", track::kStandardGauge,
            "track gauge G, 14 mm below the rail top (sets Lr)", dynamics::kGaugeRange),
        num("r0", "m", profiles::kNominalWheelRadius,
            "nominal rolling radius (Manchester vehicle 1: 0.46 m; paper Table 1: "
            "0.457 m)",
            dynamics::kR0Range),
        num("inclination", "rad", 0.025, "rail inclination beta (1:40 = 0.025)",
            dynamics::kInclinationRange),
        num("lw", "m", 0, "explicit Lw, 0 = from back_to_back (paper Table 1: 0.7515)",
            dynamics::kLwRange),
        num("lr", "m", 0, "explicit Lr, 0 = from gauge (paper Table 1: 0.7555)",
            dynamics::kLrRange),
        boolean("refined_tables", false, "use the refined LUT/KEC grids of paper Tables 9-10"),
        typed(
            "rail_slices", ValueType::Table, "-",
            "a rail that changes along the track (elastic contact only): { left = { { s = 0, "
            "rail = \"60e1\" }, { s = 12, rail = \"blade.txt\" }, ... }, right = { ... } }, "
            "profile slices at strictly increasing track arc lengths s [m], each drawn as a "
            "left rail like rail, blended linearly between slices at fixed lateral "
            "coordinate; before the first and after the last slice the rail is that slice "
            "(docs/sliced_rails.md); a slice may move its rail by dy (toward the field side) and "
            "dz (up) [m], interpolated between slices; or, per side, a CONTACT slices-file { "
            "slcs = "
            "\"file.slcs\", s = <m> (track position of its u = 0), units = \"mm\" | \"m\", "
            "z = \"down\" | \"up\" (its plain-text slices; default CONTACT's mm, z down) }; either "
            "form takes max_slope (1-100, default 10: each slice keeps its longest run of points "
            "no steeper; 40 keeps a wing rail, flangeway and nose in one slice)"),
        typed("extra_rails", ValueType::Table, "-",
              "further rails per side (elastic contact only), each with its own slices and "
              "present from its first slice to its last: { right = { { name = \"nose\", slices "
              "= { { s = 10, rail = \"nose.txt\", dz = -0.01 }, ... } } } }; at most 3 per "
              "side; their normal forces are written per rail; check = true makes one a check "
              "rail, met by the back of the wheel's flange (docs/sliced_rails.md)"),
        typed("wheelsets", ValueType::Table, "-",
              "wheelsets with wheels of their own (worn, measured, re-profiled), by the "
              "wheelset's name: { ws2 = { wheel_right = \"worn.txt\" }, ws3 = { wheel = "
              "\"b.prw\" } }; each of wheel, wheel_left, wheel_right as the keys above, the "
              "ones not given are the wheelset's wheel, then the vehicle's (docs/profiles.md)")}});
  s.push_back(
      {"contact",
       "Wheel/rail contact: constraint method (paper section 2.3-2.4), LUT flange Hertz contact "
       "(Table 3, Eq. 20), tangential forces (section 2.5).",
       {contactMethod(),
        num("dhat", "m", 0.5e-3, "KEC tread-flange transition length on the flange side",
            dynamics::kKecTransitionRange),
        num("dbar", "m", 1e-3, "KEC tread-flange transition length on the tread side",
            dynamics::kKecTransitionRange),
        num("flange_stiffness", "N/m^1.5", 1e10, "LUT Hertz flange stiffness K (Table 3)",
            dynamics::kFlangeStiffnessRange),
        num("flange_damping", "N s/m^2", -1, "LUT flange damping D; default K/100 as in Table 3",
            dynamics::kFlangeDampingRange),
        enumChoice("creep", dynamics::CreepModel::Polach, "tangential force law (paper: Polach)"),
        blockKey("fastsim", ValueType::Block, {},
                 "FASTSIM's grid and traction bound, for creep = \"fastsim\" (docs/creep.md)",
                 "contact.fastsim"),
        blockKey("elastic", ValueType::Block, {},
                 "the elastic contact method's damping, search step and derailment criterion, for "
                 "method = \"elastic\" (docs/elastic_contact.md)",
                 "contact.elastic"),
        num("mu", "-", creep::kDefaultMu, "friction coefficient (paper section 5.1)",
            dynamics::kMuRange),
        num("youngs_modulus", "Pa", 2.1e11, "Young's modulus of wheel and rail",
            dynamics::kYoungsModulusRange),
        num("poisson", "-", 0.28, "Poisson ratio", dynamics::kPoissonRange),
        enumChoice("normal_forces", dynamics::NormalForceCoupling::Consistent,
                   "normal forces the creep forces use"),
        enumChoice("wheelset_spin", dynamics::WheelsetSpin::Free, "wheelset spin"),
        enumChoice("table_interpolation", contact::TableInterpolation::Cubic,
                   "interpolation of the KEC / LUT table between its stored nodes (paper: "
                   "linear, section 5.5)"),
        num("min_normal_force", "N", 0,
            "a wheel whose constraint normal force falls below this stops the run (exit 2): a "
            "constraint contact cannot lift the wheel, so results past wheel lift are not "
            "physical",
            dynamics::kMinNormalForceRange)}});
  const dynamics::ElasticSpec elastic;  // the defaults live in dynamics/spec.hpp
  s.push_back(
      {"contact.elastic",
       "Elastic contact (a plain table inside contact{}, method = \"elastic\"): the normal "
       "damping, the contact search's scan step, the curvature floor of the Hertz patches and the "
       "derailment criterion (docs/elastic_contact.md).",
       {num("damping_ratio", "-", elastic.damping_ratio,
            "damping ratio of a wheel's vertical oscillation on its Hertz contact at the static "
            "load (Hunt-Crossley damping N = K delta^1.5 (1 + c_d delta_dot)); the rigid rails "
            "stand in for the track, so this is an assumption, stated in the results",
            dynamics::kElasticDampingRatioRange),
        num("sample_step", "m", elastic.sample_step,
            "wheel sampling step of the contact search's scan (patches narrower than about two "
            "steps can be missed)",
            dynamics::kElasticSampleStepRange),
        sentinel(num("derailment_lift", "m", elastic.derailment_lift,
                     "a wheel whose tape circle rises more than this above its centred height "
                     "over its rail has derailed: the run stops (exit 2); -1 = half the wheel's "
                     "flange height",
                     dynamics::kDerailmentLiftRange),
                 -1.0),
        num("min_curvature_ratio", "-", elastic.min_curvature_ratio,
            "the lateral relative curvature of a patch is floored smoothly at this times its "
            "rolling curvature (near-conformal contact, docs/elastic_contact.md)",
            dynamics::kElasticCurvatureRatioRange),
        blockKey("rail_support", ValueType::Block, {},
                 "the track under the rail: per wheel a rail mass on a spring and a damper, "
                 "travelling with the wheelset (docs/track_support.md); absent: rigid rails",
                 "contact.elastic.rail_support")}});
  const auto supportKeys = [](bool along) {
    std::vector<KeySpec> k;
    if (along) k.push_back(num("s", "m", 0, "track arc length of this point", 0.0, 1e7));
    const std::string dflt = along ? " (default: the block's)" : "";
    k.push_back(num("mass", "kg", 0, "rail mass moving with each wheel" + dflt,
                    dynamics::kRailSupportMassRange));
    k.push_back(num("k_z", "N/m", 0, "vertical support stiffness under each wheel" + dflt,
                    dynamics::kRailSupportStiffnessRange));
    k.push_back(num("c_z", "N s/m", 0, "vertical support damping under each wheel" + dflt,
                    dynamics::kRailSupportDampingRange));
    k.push_back(num("k_y", "N/m", 0, "lateral support stiffness under each wheel" + dflt,
                    dynamics::kRailSupportStiffnessRange));
    k.push_back(num("c_y", "N s/m", 0, "lateral support damping under each wheel" + dflt,
                    dynamics::kRailSupportDampingRange));
    return k;
  };
  std::vector<KeySpec> support = supportKeys(false);
  support.push_back(typed("along", ValueType::Table, "-",
                          "support that varies along the track: a list of points { s = <m>, "
                          "mass = .., k_z = .., ... } (keys not given: the block's values), "
                          "linear between them, the end points' values beyond"));
  s.push_back({"contact.elastic.rail_support",
               "The track under the rail (a plain table inside contact.elastic{}): per wheel a "
               "rail mass that travels with its wheelset on a spring and a damper to the ground, "
               "laterally and vertically; mass, k_z and k_y are required (docs/track_support.md).",
               support});
  s.push_back({"contact.elastic.rail_support.along",
               "One point of contact.elastic.rail_support.along.", supportKeys(true)});
  const creep::FastsimGrid fastsim;  // the defaults live in creep/fastsim.hpp
  s.push_back(
      {"contact.fastsim",
       "FASTSIM discretisation (a plain table inside contact{}, creep = \"fastsim\"): strips "
       "across the ellipse, elements along each strip (Kalker 1982; accuracy in docs/creep.md).",
       {integer("strips", fastsim.strips, "strips across the contact ellipse",
                creep::kFastsimStripsRange.min, creep::kFastsimStripsRange.max),
        integer("elements", fastsim.elements,
                "elements along each strip (the transition range converges as 1/elements)",
                creep::kFastsimElementsRange.min, creep::kFastsimElementsRange.max),
        enumChoice("bound", fastsim.bound, "normal pressure of the traction bound mu p")}});
}

// Schema block of the per-body tables of vehicle.initial (read by build_vehicle.cpp).
constexpr const char* kInitialBlock = "vehicle.initial.<body>";

struct InitialCoordinate {
  const char* key;
  const char* unit;
  const char* what;
  double max_offset;  // plausibility bound of |offset| [m or rad]
  double max_rate;    // and of |rate| [m/s or rad/s]
};
// The coordinates of vehicle.initial.<body>, in vehicle::Coord order from kY.
// The bounds (ASSUMPTION, docs/scenarios.md "vehicle.initial"): an initial offset is a small
// disturbance of the static equilibrium. 0.1 m is beyond any flange clearance (about 7 mm for
// S1002 on 60E1) and suspension travel; 0.1 rad of roll or yaw beyond anything a vehicle on its
// track reaches; 2 m/s and 5 rad/s are some ten times the rates of hunting at 80 m/s (about
// 0.2 m/s and 0.1-0.5 rad/s). A wheelset's pitch is its spin angle (any angle within one turn)
// and its rate a spin-rate offset (bounded by 50 rad/s, a third of V/r0 at 70 m/s). Beyond these
// the start is not a disturbance of the equilibrium, and the stiff start fails later with a
// message about the step instead of about the value.
constexpr double kPi = 3.141592653589793;
constexpr InitialCoordinate kInitialCoordinates[] = {
    {"y", "m", "lateral displacement y", 0.1, 2.0},
    {"z", "m", "vertical displacement z (up)", 0.1, 2.0},
    {"roll", "rad", "roll angle phi", 0.1, 5.0},
    {"pitch", "rad", "pitch angle theta (a wheelset: spin angle)", kPi, 50.0},
    {"yaw", "rad", "yaw angle psi", 0.1, 5.0}};

// The constructors of vehicle.elements: the suspension elements, then the external force.
std::vector<std::string> elementConstructors() {
  std::vector<std::string> out = namesOf<vehicle::ElementKind>();
  out.emplace_back(vehicle::kExternalForceKind);
  return out;
}

// external_force{}: a force on a body from outside the vehicle model (vehicle::ExternalForceSpec,
// suspension/external_force.hpp).
BlockSpec externalForceBlock() {
  using suspension::ForceAbscissa;
  using suspension::ForceLawKind;
  return {
      vehicle::kExternalForceKind,
      "A force on one body from outside the vehicle model (a wind gust, a wheel-climb rig's "
      "lateral push, the coupler load of a vehicle that is not simulated): F(t) or F(s) along a "
      "direction of the body's track frame or of the body, applied at a point of the body, so "
      "that its moment about the centre of mass acts too. Written to /elements/NAME/force and "
      "force_x, force_y, force_z (docs/vehicle.md, External forces).",
      {typed("name", ValueType::String, "-", "element name (for outputs)", true),
       typed("body", ValueType::String, "-", "the body the force acts on", true),
       typed("at", ValueType::Vec3, "m",
             "point of application in the body's frame (a wheelset: its axle-box frame), "
             "relative to the centre of mass; default the centre of mass"),
       enumChoice("frame", vehicle::ForceFrame::Track, "the frame direction is fixed in"),
       typed("direction", ValueType::Vec3, "-",
             "direction of the force in `frame`, e.g. {0, 1, 0} (to the left); normalised, so "
             "only its direction counts",
             true),
       enumChoice("law", ForceLawKind::Constant, "how the force's value F changes"),
       withoutDefault(num(
           "value", "N", 0,
           "F along direction (constant), or the value the ramp goes to (ramp); required by both",
           suspension::kForceValueRange)),
       num("initial", "N", 0, "ramp: F before start and after the ramp back",
           suspension::kForceValueRange),
       num("start", "s", 0, "ramp: time at which F leaves initial", suspension::kForceStartRange),
       withoutDefault(num("rate", "N/s", 0,
                          "ramp: rate of change |dF/dt| (give rate or duration, not both)",
                          suspension::kForceRateRange)),
       withoutDefault(num("duration", "s", 0,
                          "ramp: time from initial to value (give rate or duration)",
                          suspension::kForceDurationRange)),
       withoutDefault(
           num("hold", "s", 0,
               "ramp: time at value before F ramps back to initial over the same time; absent: F "
               "stays at value to the end of the run",
               suspension::kForceHoldRange)),
       enumChoice("over", ForceAbscissa::Time, "table: the abscissa of the table"),
       typed("table", ValueType::PairList, "s or m, N",
             "table: {{t, F}, ...} (over = \"time\") or {{s, F}, ...} (over = \"distance\"), "
             "abscissae strictly increasing, linear between points, the end values beyond the "
             "ends")}};
}

void addVehicleBlocks(std::vector<BlockSpec>& s) {
  // Vehicle: bodies in track-frame coordinates and suspension elements (Appendix A).
  s.push_back(
      {"vehicle",
       "A vehicle: rigid bodies with coordinates relative to their own track frames (paper Eq. "
       "2-3) joined by suspension elements (Appendix A, Eq. 27-31). Usually made by a vehicle "
       "file: "
       "vehicle (require \"vehicles.manchester_wagon1\" { speed = 20 }).",
       {typed("name", ValueType::String, "-", "vehicle name"),
        required(num("speed", "m/s", 0,
                     "forward velocity V0 at t = 0 (constant unless acceleration)", 0, 200)),
        num("acceleration", "m/s^2", 0,
            "constant longitudinal acceleration a: V(t) = V0 + a t (speed ramp); V must stay >= 0 "
            "over the run",
            -20, 20),
        num("wheel_radius", "m", profiles::kNominalWheelRadius,
            "nominal rolling radius r0 of the wheelsets", dynamics::kR0Range),
        enumChoice("category", assessment::VehicleCategory::Unstated,
                   "kind of vehicle (EN 14363): sets alpha of the track shift limit of "
                   "run.assessment (1.0 passenger and locomotive, 0.85 freight)"),
        num("start", "m", 0, "arc length of the vehicle reference point at t = 0", 0),
        required(blockKey("bodies", ValueType::BlockList, {"body"},
                          "rigid bodies; --set vehicle.bodies.NAME.KEY sets a key of the body "
                          "named NAME (or by list position, vehicle.bodies[2].KEY)")),
        blockKey("elements", ValueType::BlockList, elementConstructors(),
                 "suspension elements and external forces; --set vehicle.elements.NAME.KEY sets "
                 "a key of the element named NAME (or by list position, "
                 "vehicle.elements[5].KEY)"),
        typed("groups", ValueType::Table, "-",
              "named sets of suspension elements for --set: { GROUP = { \"prim_x_*\", "
              "\"sec_y_bogie1_l\", ... }, ... }, element names or globs ('*' = any characters); "
              "each entry must match an element. --set vehicle.groups.GROUP.KEY=VALUE sets KEY "
              "in every member (an error naming the member whose kind has no KEY). Groups do not "
              "change the model. `workbench help vehicle SCENARIO.lua` lists a vehicle's "
              "bodies, elements, their keys and its groups"),
        typed("initial", ValueType::Table, "-",
              "initial conditions { BODY = { y = 3e-3, yaw_dot = 0.01, ... }, ... } keyed by "
              "body name: offsets added to the start state (static equilibrium, wheelsets "
              "centred) in each body's track frame; keys in vehicle.initial.<body>. Only states "
              "of the model: not the z and roll of a wheelset on contact (the contact "
              "constraints give them), nothing of frames and guided wheelsets, no wheelset pitch "
              "with contact.wheelset_spin = prescribed. --set vehicle.initial.ws1.y=0.003 adds "
              "one")}});
  // Coordinates relative to the body track frame (paper Eq. 2-3) and their rates.
  std::vector<KeySpec> initial;
  for (const bool rate : {false, true})
    for (const auto& [key, unit, what, max_offset, max_rate] : kInitialCoordinates) {
      const std::string k = std::string(key) + (rate ? "_dot" : "");
      const std::string u = std::string(unit) + (rate ? "/s" : "");
      const double bound = rate ? max_rate : max_offset;
      initial.push_back(num(k, u, 0,
                            rate ? "initial rate of " + std::string(what) + " (added)"
                                 : "initial " + std::string(what) + " (added)",
                            -bound, bound));
    }
  s.push_back({std::string(kInitialBlock),
               "Initial offsets of one body (vehicle.initial.BODY), in its track frame, added to "
               "the static-equilibrium start state; SI units; recorded in /initial_conditions.",
               std::move(initial)});
  s.push_back(
      {"body",
       "A rigid body.",
       {typed("name", ValueType::String, "-", "unique body name", true),
        enumChoice("kind", vehicle::BodyKind::CarBody, "what the body is"),
        required(num("mass", "kg", 0, "mass", 0, kInf, true)),
        typed("inertia", ValueType::Vec3, "kg m^2", "principal inertias {Ixx, Iyy, Izz}", true),
        num("x", "m", 0, "longitudinal position of the centre of mass, positive forward"),
        num("height", "m", 0, "height of the centre of mass above the top of rail", -1, 10)}});
  auto elementKeys = [&](std::vector<KeySpec> extra) {
    std::vector<KeySpec> keys = {
        typed("name", ValueType::String, "-", "element name (for outputs)", true),
        typed("from", ValueType::String, "-", "master body (its track frame is used, Eq. 28)",
              true),
        typed("to", ValueType::String, "-", "second body", true),
        typed("at_from", ValueType::Vec3, "m", "attachment point in the master body's frame"),
        typed("at_to", ValueType::Vec3, "m", "attachment point in the second body's frame"),
        enumChoice("direction", vehicle::Direction::Axial, "how the deformation is measured")};
    for (auto& e : extra) keys.push_back(std::move(e));
    return keys;
  };
  s.push_back({std::string(nameOf(vehicle::ElementKind::SpringDamper)),
               "Spring and damper in parallel: f = K d + D d_dot (Appendix A).",
               elementKeys({num("stiffness", "N/m", 0, "K", 0), num("damping", "N s/m", 0, "D", 0),
                            num("length0", "m", 0, "undeformed length (axial)", 0),
                            num("preload", "N", 0, "force at zero deformation")})});
  s.push_back({std::string(nameOf(vehicle::ElementKind::SeriesSpringDamper)),
               "Damper D in series with a spring K_series: f_dot + (K_series/D) f = K_series d_dot "
               "(Appendix A); f is a state.",
               elementKeys({required(num("damping", "N s/m", 0, "D", 0, kInf, true)),
                            required(num("series_stiffness", "N/m", 0, "K_series", 0, kInf, true)),
                            num("stiffness", "N/m", 0, "optional spring K in parallel", 0),
                            num("preload", "N", 0, "force at zero deformation"),
                            num("length0", "m", 0, "undeformed length (axial)", 0)})});
  s.push_back({std::string(nameOf(vehicle::ElementKind::ShearSpring)),
               "Shear spring: f = K_shear d (Appendix A).",
               elementKeys({required(num("stiffness", "N/m", 0, "K_shear", 0)),
                            num("preload", "N", 0, "force at zero deformation")})});
  s.push_back({std::string(nameOf(vehicle::ElementKind::BendingSpring)),
               "Bending spring: M = K_bend theta (Appendix A).",
               elementKeys({required(num("stiffness", "N m/rad", 0, "K_bend", 0))})});
  s.push_back({std::string(nameOf(vehicle::ElementKind::Bumpstop)),
               "Nonlinear bumpstop: force from a cubic spline through a table of deformation and "
               "force (paper Table 4, Fig. 27), symmetric in the sign of d.",
               elementKeys({typed(
                   "table", ValueType::PairList, "m, N",
                   "{{d, F}, ...} with d increasing, e.g. {{0.025, 0}, {0.030, 600}}", true)})});
  s.push_back(externalForceBlock());
}

void addStudyBlock(std::vector<BlockSpec>& s) {
  s.push_back(
      {"study",
       "A study: a matrix of variations over a base scenario. `workbench study FILE` "
       "runs every case (in parallel, each its own HDF5), skips cases already finished with "
       "the same inputs, and writes a summary (CSV and HDF5). Keys of matrix and cases are --set "
       "paths.",
       {typed("base", ValueType::String, "-", "base scenario file, relative to the study file",
              true),
        typed("matrix", ValueType::Table, "-",
              "{ [\"solver.method\"] = {\"rk4\", \"abm\"}, ... }: every combination is a case"),
        typed("cases", ValueType::Table, "-",
              "{ { [\"solver.method\"] = \"bdf\", [\"solver.rtol\"] = 1e-6 }, ... }: explicit "
              "variants, combined with every matrix combination"),
        typed("metrics", ValueType::Table, "-",
              "{ { name = \"y_max\", signal = \"/bodies/ws1/y\", stat = \"max_abs\", from = "
              "100, to = 400 }, ... }: numbers extracted from every case into the summaries "
              "(docs/studies.md, Metrics)"),
        choice("output", {"compact", "full"}, "compact",
               "what each case writes: compact = its signals and metrics (no per-patch "
               "series, compressed), the track once per distinct track in tracks/<hash>.h5; "
               "full = everything a plain `workbench run` writes"),
        integer("repeats", 1, "runs per case (CPU time is reported as the median)", 1, 100),
        integer("jobs", 0, "cases run at once, 0 = number of cores", 0, 64),
        integer("max_cases", 10000,
                "largest number of cases (matrix combinations x cases) the study may expand to; "
                "a bigger study is refused before anything runs",
                1, 100000000)}});
}

// "dopri5, bdf, ida": the registry's methods that use the solver{} key `key`.
std::string methodsUsing(const std::string& key) {
  std::vector<std::string> out;
  for (const auto& m : integ::methods())
    for (const auto& o : m.options)
      if (o.key == key) out.push_back(m.name);
  return join(out, ", ");
}

// "rk4, abm": the registry's fixed-step methods.
std::string fixedStepMethods() {
  std::vector<std::string> out;
  for (const auto& m : integ::methods())
    if (m.fixed_step) out.push_back(m.name);
  return join(out, ", ");
}

// solver{}: the methods, their descriptions and options from the integrator registry.
void addSolverBlock(std::vector<BlockSpec>& s) {
  std::vector<std::string> methodNames;
  std::string methodHelp = "integrator:";
  for (const auto& m : integ::methods()) {
    methodNames.push_back(m.name);
    methodHelp += " " + m.name + " = " + m.description + ";";
  }
  KeySpec stiff = enumChoice("stiff", integ::SolverSpec{}.stiff,
                             "how the fixed-step methods (" + methodsUsing("stiff") +
                                 ") integrate the model's stiff components");
  KeySpec accept = boolean(
      "accept_unstable_step", false,
      "run a fixed step beyond the stability limit of the model's stiffest mode at the start (" +
          methodsUsing("accept_unstable_step") +
          "); without it check and run refuse such a step, naming the mode and the largest stable "
          "step");
  KeySpec jac = enumChoice(
      "jacobian", integ::JacobianMode::Auto,
      "where the Newton iterations take the Jacobian from (" + methodsUsing("jacobian") + ")");
  s.push_back(
      {"solver",
       "Time integrator (paper section 4) and its options.",
       {choice("method", methodNames, integ::SolverSpec{}.method, methodHelp),
        num("step", "s", 1e-3,
            "fixed step (" + fixedStepMethods() +
                "); for adaptive methods the initial step, automatic when not given",
            0, 1.0),
        num("rtol", "-", 1e-6, "relative tolerance (" + methodsUsing("rtol") + ")",
            integ::kRtolRange),
        num("atol", "-", 1e-6, "absolute tolerance in state units (" + methodsUsing("atol") + ")",
            integ::kAtolRange),
        num("max_step", "s", 0, "largest step, 0 = unlimited (" + methodsUsing("max_step") + ")",
            0),
        integer("max_order", 5, "maximum BDF order (" + methodsUsing("max_order") + ")",
                integ::kMaxOrderRange.min, integ::kMaxOrderRange.max),
        integer("max_steps", 0, "internal steps per output interval, 0 = default", 0, 1e12), jac,
        stiff, accept}});
}

void addAssessmentBlock(std::vector<BlockSpec>& s) {
  s.push_back(
      {"run.assessment",
       "Engineering assessment of a vehicle run (a plain table inside run{}, or true for every "
       "group that applies: safety and wear need wheel/rail contact, stability a bogie, comfort a "
       "car body). Signals are sampled at sample_every independently of run.output and assessed "
       "after the run into /assessment; a limit exceeded is a result (warning), not a failure. "
       "Formulas, limits and assumptions: docs/assessment.md.",
       {boolean("safety", false,
                "running safety and track loading (EN 14363): Y/Q, sum Y, dQ/Q, quasi-static and "
                "maximum wheel forces per wheel; needs wheel/rail contact"),
        boolean("stability", false,
                "running stability, simplified method (EN 14363): sliding rms of the band-passed "
                "bogie-frame lateral acceleration above each wheelset"),
        boolean("comfort", false,
                "ride comfort at the car-body floor points: EN 12299 N_MV and continuous comfort, "
                "Sperling's Wz lateral and vertical"),
        boolean("wear", false, "wear number T gamma and frictional power per wheel and patch"),
        num("sample_every", "s", assessment::kDefaultSampleEvery,
            "sample interval of the assessment signals (400 Hz: the comfort weightings and the "
            "20 Hz force low-pass need fs >= 20 x their highest frequency); with a fixed-step "
            "solver rounded down to a multiple of solver.step",
            0, 0.02, true),
        typed("floor_positions", ValueType::Table, "m",
              "floor points of the car body, x offsets from its centre of mass {x1, x2, ...}; "
              "default: over the two bogie centres and mid-car (front, centre, rear)"),
        sentinel(num("alpha", "-", -1,
                     "track shift factor of Prud'homme's limit alpha (10 kN + 2 Q0 / 3): 1.0 for "
                     "locomotives and passenger vehicles, 0.85 for freight wagons (EN 14363); "
                     "default (-1): from vehicle.category (1.0 assumed, and said in the summary, "
                     "when the vehicle states no category)",
                     0, 1, true),
                 -1),
        typed("sections", ValueType::Table, "-",
              "track sections assessed on their own (EN 14363 evaluates per section): a list "
              "{ { name = \"curve\", from = 120, to = 480 }, ... } of arc-length ranges [m]; "
              "default: one section per track segment (tangent, transition, constant-radius "
              "curve body), each with its EN 14363 test zone by radius"),
        num("flange_angle", "rad", assessment::kS1002FlangeAngle,
            "flange angle of Nadal's flange-climbing limit (default: S1002, about 70 deg)", 0,
            1.5707963267948966, true),
        sentinel(num("mu", "-", -1,
                     "friction coefficient of Nadal's limit; default (-1): contact.mu", 0, 2, true),
                 -1),
        num("yq_limit", "-", 0.8,
            "limit of the derailment quotient (Y/Q)_2m (EN 14363, R >= 250 m)", 0, 10, true),
        sentinel(num("instability_frequency", "Hz", 0,
                     "centre f0 of the f0 +- 2 Hz band-pass of the stability criterion (above 2 "
                     "Hz, the band's half width); 0 = the peak of the bogie-frame lateral "
                     "acceleration spectrum between 3 and 9 Hz",
                     2, 50, true),
                 0),
        num("comfort_limit", "-", 2,
            "target of N_MV (EN 12299 sets none; 2 is the upper bound of \"comfortable\")", 0, kInf,
            true)}});
}

// run.effects: one boolean per switch of the effect table (effect_names.hpp).
void addEffectsBlock(std::vector<BlockSpec>& s) {
  BlockSpec b{"run.effects",
              "Optional effects of the scene, each on by default when the scene has it (a plain "
              "table inside run{}, e.g. effects = { irregularities = false }; --set "
              "run.effects.bump_stops=false). A switched-off effect is left out of the compiled "
              "model, so it costs nothing; false for an effect the scene does not have is an "
              "error. `workbench effects SCENARIO.lua` measures what each costs and changes "
              "(docs/effects.md).",
              {}};
  for (const auto& e : kEffectSwitches)
    b.keys.push_back(boolean(std::string(nameOf(e.effect)), true, std::string(e.help)));
  s.push_back(std::move(b));
}

void addRunBlocks(std::vector<BlockSpec>& s) {
  s.push_back({"run",
               "What to simulate and what to write.",
               {num("distance", "m", 0, "distance to travel, 0 = to the end of the track", 0),
                num("duration", "s", 0, "simulated time, 0 = distance / speed", 0),
                blockKey("output", ValueType::Block, {}, "output options", "run.output"),
                blockKey("assessment", ValueType::Block, {},
                         "engineering assessment of the run (EN 14363, EN 12299, Sperling, wear) "
                         "written to /assessment; true = every group that applies to the vehicle",
                         "run.assessment"),
                blockKey("effects", ValueType::Block, {},
                         "switches of the optional effects of the scene (default on when the "
                         "scene has them); false leaves an effect out of the compiled model",
                         "run.effects")}});
  addEffectsBlock(s);
  s.push_back({"run.output",
               "Output options (a plain table inside run{}).",
               {num("every", "s", 0.01, "output interval", 0, kInf, true),
                typed("elements", ValueType::StringList, "-",
                      "suspension elements whose deflection and force are written, by name"),
                boolean("body_accelerations", false,
                        "write body accelerations (ride analysis) for every body"),
                num("max_samples", "-", 1e7,
                    "largest number of output times a run may write (a bound on memory and "
                    "disk; raise it for long, finely sampled runs)",
                    1, 1e12),
                boolean("patches", true,
                        "write the per-patch datasets /contact/<ws>/<side>/patch0, patch1 (23 "
                        "series per patch: about 2.7 times the file size of a short contact "
                        "run)")}});
  addAssessmentBlock(s);
}

// train{}: several vehicles on one track (a run of vehicles, run/compile.hpp).
void addTrainBlocks(std::vector<BlockSpec>& s) {
  s.push_back(
      {"train",
       "Several vehicles on one track, front to rear, instead of one vehicle{} block. Each runs at "
       "its own place (its vehicle's start) on the track section it is on, with its own profiles "
       "and contact model if it gives them, starting at the first one's speed. Buffers and draw "
       "gear between neighbours (connections) act on their car bodies; with longitudinal{} every "
       "vehicle's motion along the track is a state driven by its traction or braking, running "
       "resistance, the track's slope and the connections (else the speed is prescribed). "
       "Outputs and assessment of each vehicle go to /vehicles/<name>, the connections' to "
       "/train/connections/<front>-<rear> (docs/trains.md).",
       {typed("vehicles", ValueType::Table, "-",
              "the vehicles, front to rear: { { name = \"loco\", vehicle = v1 }, { name = "
              "\"wagon1\", vehicle = v2, contact = { method = \"elastic\" } }, ... } (2 to "
              "100 entries, train.vehicle)",
              true),
        typed("connections", ValueType::Table, "-",
              "buffers and draw gear between neighbouring vehicles: { { front = \"loco\", rear = "
              "\"wagon1\", front_end = -6.5, rear_end = 6.5, buffers = {...}, draw_gear = {...} "
              "}, ... } (train.connection); default: none, the vehicles do not interact"),
        blockKey("longitudinal", ValueType::Block, {},
                 "the vehicles' motion along the track as states (train.longitudinal); default: "
                 "the speed prescribed by the vehicles' speed and acceleration",
                 "train.longitudinal")}});
  s.push_back(
      {"train.connection",
       "One connection of train.connections (a plain table): buffers and draw gear between the "
       "car bodies of two neighbouring vehicles, their headstocks at front_end and rear_end. The "
       "gap between the buffer faces is zero when they touch; the vehicles' starts place them.",
       {typed("front", ValueType::String, "-", "the front vehicle's name", true),
        typed("rear", ValueType::String, "-", "the name of the vehicle right behind it", true),
        typed("front_body", ValueType::String, "-",
              "the front vehicle's car body the connection acts on (default: its only car body)"),
        typed("rear_body", ValueType::String, "-",
              "the rear vehicle's car body (default: its only)"),
        required(num("front_end", "m", 0.0,
                     "x of the front vehicle's rear headstock (buffer faces) from its car body's "
                     "centre of mass, < 0",
                     -50.0, 0.0, false)),
        required(num("rear_end", "m", 0.0,
                     "x of the rear vehicle's front headstock from its car body's centre, > 0", 0.0,
                     50.0, false)),
        blockKey("buffers", ValueType::Block, {}, "side buffers (train.buffers)", "train.buffers"),
        blockKey("draw_gear", ValueType::Block, {}, "draw gear (train.draw_gear)",
                 "train.draw_gear"),
        blockKey("coupler", ValueType::Block, {},
                 "a coupler link with angling stops instead of the draw gear (train.coupler)",
                 "train.coupler")}});
  s.push_back(
      {"train.buffers",
       "The side buffers of a connection (a plain table): one buffer's force against its stroke, "
       "loading and unloading; the two buffers of each side act in series.",
       {typed("loading", ValueType::PairList, "m, N",
              "{{stroke, force}, ...} while the buffer is pressed, from {0, 0}", true),
        typed("unloading", ValueType::PairList, "m, N",
              "{{stroke, force}, ...} while it is released, at most the loading force", true),
        required(
            num("spacing", "m", 0.0, "lateral distance between the two buffers", 0.0, 5.0, true)),
        required(num("height", "m", 0.0, "buffer height above the top of rail", 0.0, 5.0, true)),
        num("friction", "-", 0.0, "buffer-head friction coefficient", 0.0, 1.0)}});
  s.push_back(
      {"train.draw_gear",
       "The draw gear of a connection (a plain table): tension once the gap between the buffer "
       "faces exceeds the slack.",
       {required(num("stiffness", "N/m", 0.0, "stiffness in tension", 0.0, kInf, true)),
        num("slack", "m", 0.0, "gap at which the draw gear takes tension", 0.0, 1.0),
        num("friction", "-", 0.0,
            "hysteresis ratio: the force is k e (1 + friction) stretching, (1 - friction) "
            "releasing",
            0.0, 1.0),
        required(
            num("height", "m", 0.0, "draw gear height above the top of rail", 0.0, 5.0, true))}});
  s.push_back(
      {"train.coupler",
       "The coupler of a connection (a plain table), instead of a draw gear: a link between two "
       "pivots behind the headstocks, its axial force along the link (so it pushes or pulls the "
       "car bodies sideways when they are offset or in a curve), its angle to each car body free "
       "up to the stops (docs/trains.md).",
       {required(num("stiffness", "N/m", 0.0, "axial stiffness", 0.0, kInf, true)),
        num("slack", "m", 0.0, "free play of the link's length, each way", 0.0, 1.0),
        num("friction", "-", 0.0,
            "hysteresis ratio: the force is k e (1 + friction) loading, (1 - friction) releasing",
            0.0, 1.0),
        required(num("height", "m", 0.0, "coupler height above the top of rail", 0.0, 5.0, true)),
        required(num("pivot", "m", 0.0,
                     "each pivot's distance behind its headstock (the link is 2 pivot long when "
                     "the faces touch)",
                     0.0, 5.0, true)),
        boolean("compression", true,
                "the coupler carries compression too (a central coupler); false: tension only"),
        required(num("angle_stop", "rad", 0.0,
                     "free angle each way between the link and each car body's axis", 0.0, 1.0,
                     true)),
        num("stop_stiffness", "N m/rad", 0.0,
            "torque of a stop per radian past angle_stop (0: no stops)", 0.0, kInf)}});
  s.push_back({"train.longitudinal",
               "The vehicles' motion along the track as states (a plain table): each vehicle a "
               "rigid mass driven by its traction, resistance, the track's slope and the "
               "connections.",
               {num("min_speed", "m/s", 1.0,
                    "a vehicle slower than this ends the run (the creepages are referred to the "
                    "forward speed)",
                    0.1, kInf),
                enumChoice("traction_at", train::TractionPath::Wheelsets,
                           "where traction and braking act (docs/trains.md)")}});
  s.push_back({"train.resistance",
               "Running resistance of a vehicle in the Davis form a + b v + c v^2 (a plain "
               "table).",
               {num("a", "N", 0.0, "constant term", 0.0, kInf),
                num("b", "N s/m", 0.0, "term in v", 0.0, kInf),
                num("c", "N s^2/m^2", 0.0, "term in v^2", 0.0, kInf)}});
  s.push_back(
      {"train.vehicle",
       "One vehicle of train.vehicles (a plain table).",
       {typed("name", ValueType::String, "-",
              "the vehicle's name in the run: 1-64 letters, digits, '_' or '-', each its own",
              true),
        typed("vehicle", ValueType::Table, "-",
              "the vehicle, as a vehicle{} block takes it (require \"vehicles.manchester_wagon1\" "
              "{ speed = 20, start = 60 }); its start places it",
              true),
        blockKey("profiles", ValueType::Block, {},
                 "its own wheel/rail profiles (a plain table with the keys of profiles{}); "
                 "default: the scenario's profiles{}",
                 "profiles"),
        blockKey("contact", ValueType::Block, {},
                 "its own contact model (a plain table with the keys of contact{}); default: the "
                 "scenario's contact{}",
                 "contact"),
        typed("traction", ValueType::PairList, "s, N",
              "{{t, force}, ...}: traction (> 0) or braking (< 0) at the rails against time, "
              "linear between points, held beyond (train.longitudinal only)"),
        typed("traction_by_distance", ValueType::PairList, "m, N",
              "{{distance travelled, force}, ...}: the same against the distance"),
        blockKey("resistance", ValueType::Block, {}, "running resistance (train.resistance)",
                 "train.resistance")}});
}

std::vector<BlockSpec> build() {
  std::vector<BlockSpec> s;
  addTrackBlocks(s);
  addIrregularityBlocks(s);
  addContactBlocks(s);
  addVehicleBlocks(s);
  addTrainBlocks(s);
  addStudyBlock(s);
  addSolverBlock(s);
  addRunBlocks(s);
  return s;
}

}  // namespace

const KeySpec* BlockSpec::key(const std::string& k) const {
  for (const auto& ks : keys)
    if (ks.name == k) return &ks;
  return nullptr;
}

std::vector<std::string> BlockSpec::keyNames() const {
  std::vector<std::string> out;
  for (const auto& k : keys) out.push_back(k.name);
  return out;
}

const std::vector<BlockSpec>& schema() {
  static const std::vector<BlockSpec> s = build();
  return s;
}

const BlockSpec& block(const std::string& name) {
  for (const auto& b : schema())
    if (b.name == name) return b;
  throw std::logic_error("no schema block '" + name + "'");
}

namespace {
const char* typeText(ValueType t) {
  switch (t) {
    case ValueType::Number:
      return "number";
    case ValueType::Integer:
      return "integer";
    case ValueType::String:
      return "string";
    case ValueType::Choice:
      return "choice";
    case ValueType::Bool:
      return "boolean";
    case ValueType::Pair:
      return "{min, max}";
    case ValueType::Block:
      return "block";
    case ValueType::BlockList:
      return "list of blocks";
    case ValueType::StringList:
      return "list of names";
    case ValueType::PsdInput:
      return "function or table";
    case ValueType::Vec3:
      return "{x, y, z}";
    case ValueType::PairList:
      return "{{a, b}, ...}";
    case ValueType::Table:
      return "table";
  }
  return "?";
}
}  // namespace

namespace {
// `x` as a message shows it: 6 digits, or every digit where 6 would make it read as the bound
// ("must be <= 0.1 m, got 0.1" for 0.1000001).
std::string shown(double x, double bound) {
  return formatNumber(x) == formatNumber(bound) ? formatNumberExact(x) : formatNumber(x);
}
}  // namespace

std::optional<std::string> rangeProblem(const KeySpec& k, double x) {
  const std::string u = (k.unit.empty() || k.unit == "-") ? "" : " " + k.unit;
  if (!std::isfinite(x)) return "finite, got " + formatNumber(x);
  if (std::find(k.sentinels.begin(), k.sentinels.end(), x) != k.sentinels.end())
    return std::nullopt;
  if (!k.sentinels.empty()) {
    // "in [0.001, 0.1] m or -1": the interval alone would hide the sentinel.
    Range r{k.min, k.max, k.min_exclusive, k.max_exclusive};
    if (r.contains(x)) return std::nullopt;
    std::string alternatives;
    for (const double s : k.sentinels) alternatives += " or " + formatNumber(s);
    return "in " + r.text() + u + alternatives + ", got " + formatNumber(x);
  }
  if (k.min_exclusive ? !(x > k.min) : !(x >= k.min))
    return std::string(k.min_exclusive ? "> " : ">= ") + formatNumber(k.min) + u + ", got " +
           shown(x, k.min);
  if (k.max_exclusive ? !(x < k.max) : !(x <= k.max))
    return std::string(k.max_exclusive ? "< " : "<= ") + formatNumber(k.max) + u + ", got " +
           shown(x, k.max);
  return std::nullopt;
}

std::string rangeText(const KeySpec& k) {
  const bool numeric = k.type == ValueType::Number || k.type == ValueType::Integer;
  if (!numeric || (k.min == -kInf && k.max == kInf)) return {};
  std::string out = std::string(k.min_exclusive ? "(" : "[") + formatNumber(k.min) + ", " +
                    formatNumber(k.max) + (k.max < kInf && !k.max_exclusive ? "]" : ")");
  for (const double s : k.sentinels) out += " or " + formatNumber(s);
  return out;
}

namespace {

// One key of the reference: type, unit, default, range, help, choices and constructors.
void writeKey(std::ostream& os, const KeySpec& k) {
  os << "  " << k.name << " (" << typeText(k.type);
  if (!k.unit.empty() && k.unit != "-") os << ", " << k.unit;
  os << ")";
  if (k.required)
    os << " required";
  else if (!k.def.empty())
    os << " default " << k.def;
  if (const std::string range = rangeText(k); !range.empty()) os << ", range " << range;
  os << "\n      " << k.help << "\n";
  if (!k.choices.empty()) os << "      one of: " << join(k.choices, " ") << "\n";
  for (std::size_t i = 0; i < k.choice_help.size() && i < k.choices.size(); ++i)
    if (!k.choice_help[i].empty())
      os << "        " << k.choices[i] << ": " << k.choice_help[i] << "\n";
  if (!k.kinds.empty()) {
    os << "      made by:";
    for (const auto& c : k.kinds) os << " " << c << "{}";
    os << "\n";
  }
}

}  // namespace

std::string referenceText() {
  std::ostringstream os;
  os << "Scenario reference (generated from the schema the validator uses).\n"
        "A scenario is a Lua 5.4 file of constructor calls with named tables; plain Lua\n"
        "(locals, loops, arithmetic, require of shared files) is allowed. Units are SI.\n"
        "Any value can be overridden with --set block.key=value (lists: block.list[2].key).\n";
  for (const auto& b : schema()) {
    os << "\n"
       << b.name << (b.name.find('.') == std::string::npos ? " { ... }" : " = { ... }") << "\n  "
       << b.help << "\n";
    for (const auto& k : b.keys) writeKey(os, k);
  }
  return os.str();
}

}  // namespace rb::scenario
