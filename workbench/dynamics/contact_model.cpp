#include "workbench/dynamics/contact_model.hpp"

#include "workbench/contact/table_io.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/dynamics/limits.hpp"
#include "workbench/dynamics/names.hpp"
#include "workbench/dynamics/rails_along_track.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <numbers>

#include "workbench/profiles/positioning.hpp"
#include "workbench/profiles/profile_io.hpp"
#include "workbench/profiles/rail60e1.hpp"
#include "workbench/profiles/s1002.hpp"

namespace rb::dynamics {

namespace {

// Left profile of one kind: built-in or from a file. File problems are added to `d` at the
// profiles{} block, followed by the reader's own file:line diagnostics.
std::shared_ptr<const profiles::Profile> loadProfile(const std::string& source,
                                                     profiles::ProfileKind kind, double r0,
                                                     const SourceLoc& loc, Diagnostics& d,
                                                     const char* key = nullptr,
                                                     const RailSliceSpec* slice = nullptr) {
  const bool wheel = kind == profiles::ProfileKind::Wheel;
  const std::string builtin = wheel ? "s1002" : "60e1";
  try {
    if (source.empty() || source == builtin) {
      return std::make_shared<const profiles::Profile>(
          wheel ? profiles::s1002Wheel(r0, profiles::Side::Left)
                : profiles::rail60E1(profiles::Side::Left));
    }
    profiles::ProfileReadOptions opt;
    if (wheel) opt.r0 = r0;
    if (slice != nullptr) {
      opt.mirrorZ = slice->z_down;
      opt.maxSlope = slice->max_slope;
    }
    const profiles::LengthUnit unit = slice != nullptr && slice->metres
                                          ? profiles::LengthUnit::Metre
                                          : profiles::LengthUnit::Millimetre;
    return std::make_shared<const profiles::Profile>(
        profiles::readProfileFile(source, kind, unit, opt));
  } catch (const InputError& e) {
    d.add(loc, std::string("profiles.") +
                   (key != nullptr ? key
                    : wheel        ? "wheel"
                                   : "rail") +
                   ": cannot use '" + source + "'");
    d.add(e);
  }
  return nullptr;
}

// A rail file drawn already inclined (its head symmetric about a tilted axis; the benchmark's
// MBench_UIC60_v3.prr is drawn at 1:40) gets the cant profiles.inclination on top: the cant
// would count twice (S1002 on that file: equivalent conicity at 2 mm 0.009 instead of 0.229).
// Refused unless the file is used as drawn (inclination = 0); half the asked inclination is the
// threshold, far above the asymmetry of a worn head and far below a doubled cant.
void checkDrawnInclination(const ProfilesSpec& p, const profiles::Profile& rail, Diagnostics& d) {
  if (p.rail.empty() || p.rail == "60e1" || !(p.inclination > 0.0)) return;
  const auto drawn = profiles::drawnInclination(rail);
  if (!drawn || std::abs(*drawn) <= 0.5 * p.inclination) return;
  d.add(p.loc, "profiles.rail: '" + std::filesystem::path(p.rail).filename().string() +
                   "' is drawn already inclined (its head is symmetric about an axis tilted by " +
                   formatNumber(std::abs(*drawn), 3) +
                   " rad, 1:" + formatNumber(1.0 / std::tan(std::abs(*drawn)), 3) +
                   "), and profiles.inclination = " + formatNumber(p.inclination, 4) +
                   " rad inclines it again: the cant would count twice. Set profiles.inclination "
                   "= 0 to use the file as drawn, or give the rail profile upright");
}

}  // namespace

HertzShapeTable::HertzShapeTable() {
  constexpr std::size_t n = 2401;
  const double u0 = std::log(1e-6);
  u_min_ = u0;
  const double h = -u0 / static_cast<double>(n - 1);
  std::vector<std::vector<double>> ch(5, std::vector<double>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const double u = i + 1 == n ? 0.0 : u0 + static_cast<double>(i) * h;
    const creep::HertzShape s = creep::hertzShape(std::exp(u), 1.0);
    ch[0][i] = s.g;
    ch[1][i] = s.m;
    ch[2][i] = s.n;
    ch[3][i] = s.K;
    ch[4][i] = s.E;
  }
  spline_ = CubicSplineSet(SplineGrid::uniform(u0, h, n), ch);
}

creep::HertzShape HertzShapeTable::shape(double A, double B) const {
  const double rho = A <= B ? A / B : B / A;
  const double u = std::log(rho);
  if (!(u >= u_min_)) return creep::hertzShape(A, B);
  double v[5];
  spline_.eval(std::min(u, 0.0), v);
  creep::HertzShape s;
  s.g = std::min(v[0], 1.0);
  s.m = v[1];
  s.n = v[2];
  s.K = v[3];
  s.E = v[4];
  s.rolling_major = A <= B;
  s.iterations = 0;
  return s;
}

std::shared_ptr<const HertzShapeTable> HertzShapeTable::shared() {
  static const std::shared_ptr<const HertzShapeTable> table =
      std::make_shared<const HertzShapeTable>();
  return table;
}

const contact::TableBuildStats& ContactModel::tableStats() const {
  static const contact::TableBuildStats kEmpty;
  if (kec) return kec->stats();
  if (lut) return lut->stats();
  return kEmpty;
}

// The names of dynamics/names.hpp; the tables' entries are string literals, so data() ends in '\0'.
const char* ContactModel::methodName(ContactMethod m) {
  return nameOf(m).data();
}
const char* ContactModel::creepName(CreepModel c) {
  return nameOf(c).data();
}
const char* ContactModel::spinName(WheelsetSpin s) {
  return nameOf(s).data();
}
const char* ContactModel::couplingName(NormalForceCoupling c) {
  return nameOf(c).data();
}

void TableCache::diskProblem(const std::string& why) {
  if (disk_failed_) return;
  disk_failed_ = true;
  warnings_.push_back("the table cache folder '" + disk_dir_ + "' cannot be used (" + why +
                      "); tables are built in memory for this run");
}

std::vector<std::string> TableCache::takeWarnings() {
  std::vector<std::string> out;
  out.swap(warnings_);
  return out;
}

namespace {

// From the disk cache when it is usable, else built in memory; rb::InputError (a bad
// configuration) passes through, any other problem with the folder only disables it.
template <class Table, class FromDisk, class Build>
std::shared_ptr<const Table> tableFor(const std::string& dir, bool& disk_failed,
                                      const std::function<void(const std::string&)>& problem,
                                      FromDisk from_disk, Build build, bool& built) {
  built = true;
  if (!dir.empty() && !disk_failed) {
    std::string save_error;
    std::shared_ptr<const Table> t;
    try {
      t = from_disk(contact::DiskTableCache(dir), built, save_error);
    } catch (const InputError&) {
      throw;
    } catch (const std::exception& e) {
      problem(e.what());
    }
    if (!save_error.empty()) problem(save_error);
    if (t) return t;
  }
  built = true;
  return std::make_shared<const Table>(build());
}

}  // namespace

std::shared_ptr<const contact::KecTable> TableCache::kec(
    const contact::ContactGeometryConfig& config) {
  const std::uint64_t h = contact::configHash(config);
  auto it = kec_.find(h);
  if (it != kec_.end()) return it->second;
  bool built = true;
  auto t = tableFor<contact::KecTable>(
      disk_dir_, disk_failed_, [this](const std::string& why) { diskProblem(why); },
      [&](const contact::DiskTableCache& disk, bool& b, std::string& err) {
        return disk.kec(config, &b, &err);
      },
      [&] { return contact::buildKec(config); }, built);
  builds_ += built ? 1 : 0;
  kec_.emplace(h, t);
  return t;
}

std::shared_ptr<const contact::LutTable> TableCache::lut(
    const contact::ContactGeometryConfig& config) {
  const std::uint64_t h = contact::configHash(config);
  auto it = lut_.find(h);
  if (it != lut_.end()) return it->second;
  bool built = true;
  auto t = tableFor<contact::LutTable>(
      disk_dir_, disk_failed_, [this](const std::string& why) { diskProblem(why); },
      [&](const contact::DiskTableCache& disk, bool& b, std::string& err) {
        return disk.lut(config, &b, &err);
      },
      [&] { return contact::buildLut(config); }, built);
  builds_ += built ? 1 : 0;
  lut_.emplace(h, t);
  return t;
}

contact::ContactGeometryConfig contactGeometryConfig(const ProfilesSpec& p, const ContactSpec& c) {
  Diagnostics d;
  // The ranges of the scenario schema (dynamics/limits.hpp), for callers without a scenario.
  if (!kR0Range.contains(p.r0))
    d.add(p.loc, "profiles.r0: " + formatNumber(p.r0) + " m is not a wheel radius (" +
                     kR0Range.text() + " m)");
  if (!kInclinationRange.contains(p.inclination))
    d.add(p.loc, "profiles.inclination: " + formatNumber(p.inclination) + " rad outside " +
                     kInclinationRange.text());
  if (!kLwRange.contains(p.lw) || !kLrRange.contains(p.lr))
    d.add(p.loc, "profiles.lw / profiles.lr must be in " + kLwRange.text() +
                     " m (0: from back_to_back / gauge)");
  if (p.lw == 0.0 && !kBackToBackRange.contains(p.back_to_back))
    d.add(p.loc, "profiles.back_to_back: " + formatNumber(p.back_to_back) + " m outside " +
                     kBackToBackRange.text() + " m");
  if (p.lr == 0.0 && !kGaugeRange.contains(p.gauge))
    d.add(p.loc,
          "profiles.gauge: " + formatNumber(p.gauge) + " m outside " + kGaugeRange.text() + " m");
  if (c.method == ContactMethod::Kec &&
      (!kKecTransitionRange.contains(c.kec_dhat) || !kKecTransitionRange.contains(c.kec_dbar)))
    d.add(c.loc, "contact.dhat / contact.dbar: the KEC transition lengths must be in " +
                     kKecTransitionRange.text() + " m");
  d.throwIfAny();

  auto lw = loadProfile(p.wheel, profiles::ProfileKind::Wheel, p.r0, p.loc, d);
  // A wheelset of two different wheels: each side's own profile, drawn as a left wheel.
  auto own = [&](const std::string& source, const char* key) {
    return source.empty() || source == p.wheel
               ? lw
               : loadProfile(source, profiles::ProfileKind::Wheel, p.r0, p.loc, d, key);
  };
  auto left_wheel = own(p.wheel_left, "wheel_left");
  auto right_wheel = own(p.wheel_right, "wheel_right");
  auto lr = loadProfile(p.rail, profiles::ProfileKind::Rail, p.r0, p.loc, d);
  d.throwIfAny();
  checkDrawnInclination(p, *lr, d);
  d.throwIfAny();

  contact::ContactGeometryConfig g;
  g.left_wheel = left_wheel;
  g.right_wheel = std::make_shared<const profiles::Profile>(right_wheel->mirrored());
  g.left_rail = lr;
  g.right_rail = std::make_shared<const profiles::Profile>(lr->mirrored());
  g.beta = p.inclination;
  g.r0 = p.r0;
  // Positioning: Lw = B/2 + flange-back distance (70 mm: S1002 and every wheel drawn in the
  // EN 13715 coordinates, origin at the tape circle), Lr = G/2 + gauge-point offset of the rail
  // (14 mm below its highest point, computed for the rail in use).
  double pos_lw = p.lw, pos_lr = p.lr;
  if (pos_lw == 0.0) pos_lw = 0.5 * p.back_to_back + profiles::kS1002FlangeBackDistance;
  if (pos_lr == 0.0) {
    try {
      const double off =
          std::abs(profiles::gaugePoint(*lr, profiles::RailSide::Left, p.inclination).y);
      pos_lr = 0.5 * p.gauge + off;
    } catch (const std::exception& e) {
      throw InputError(p.loc, std::string("profiles: no gauge point on the rail profile (") +
                                  e.what() + "); give profiles.lr");
    }
  }
  g.wheel_lw = pos_lw;
  g.rail_lr = pos_lr;
  g.kec_dhat = c.kec_dhat;
  g.kec_dbar = c.kec_dbar;
  g.interpolation = c.table_interpolation;
  if (p.refined_tables) g.useRefinedGrids();
  try {
    contact::checkConfig(g);
  } catch (const InputError& e) {
    Diagnostics dd;
    dd.add(c.loc, "contact: invalid contact geometry configuration");
    dd.add(e);
    dd.throwIfAny();
  }
  return g;
}

namespace {

// Lateral displacement [m] of the wheelset from the centre until the flange of `side` touches its
// rail (flange indentation, Eq. 21, reaches 0) at gauge variation xi_g, scanning in 0.05 mm steps
// with the rigid tread contact (Eq. 12) as pose; NaN when there is no touch within 30 mm.
double flangewayPlay(const contact::ContactSolver& s, contact::Side side, double xi_g) {
  constexpr double kStep = 0.05e-3, kMax = 30e-3;
  const double sign = side == contact::Side::Left ? 1.0 : -1.0;
  contact::TreadContact warm;
  bool have = false;
  contact::FlangeContact fwarm;
  bool fhave = false;
  for (double a = 0.0; a <= kMax; a += kStep) {
    const contact::TreadContact t = s.solveTread(sign * a, xi_g, have ? &warm : nullptr);
    if (!t.converged) return std::numeric_limits<double>::quiet_NaN();
    warm = t;
    have = true;
    const contact::WheelsetPose pose{t.y, t.z, t.phi};
    const contact::FlangeContact f = s.flange(side, pose, xi_g, fhave ? &fwarm : nullptr);
    if (!f.exists) return std::numeric_limits<double>::quiet_NaN();
    if (f.converged) {
      fwarm = f;
      fhave = true;
    }
    // The tread contact reaching the flange boundary (Edge) is flange contact too.
    const bool edge = t.mode[side == contact::Side::Left ? 0 : 1] == contact::ContactMode::Edge;
    if (edge || f.delta >= 0.0) return a;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

std::string mm(double x) {
  return formatNumber(x * 1e3, 3) + " mm";
}

// The gauge irregularity against what the profiles admit. Gauge variation xi_g moves each rail
// by xi_g / 2 (config.hpp: rails at +-(Lr + xi_g / 2)). A narrowing by more than the flangeway
// play (left + right play of the centred wheelset) leaves no lateral freedom: both flanges touch
// at once and the wheelset is squeezed between the rails (large Y on both wheels). A widening
// lets the wheelset move play + xi_g / 2 to one side before its flange touches; where the rigid
// tread contact (Eq. 12) has no solution there, the other wheel runs off its tread.
void gaugeWarnings(ContactModel& m, const track::TrackModel& track) {
  m.flangeway[0] = flangewayPlay(*m.solver, contact::Side::Left, 0.0);
  m.flangeway[1] = flangewayPlay(*m.solver, contact::Side::Right, 0.0);
  if (!track.irregularities()) return;
  const auto& tab = track.irregularities()->samples();
  const auto& g = tab.channel[static_cast<std::size_t>(track::Channel::Gauge)];
  if (g.empty()) return;
  const auto [lo, hi] = std::minmax_element(g.begin(), g.end());
  const double s_lo = tab.s[static_cast<std::size_t>(lo - g.begin())];
  const double s_hi = tab.s[static_cast<std::size_t>(hi - g.begin())];
  const double play = m.flangeway[0] + m.flangeway[1];
  if (!std::isfinite(play)) return;
  const std::string profiles = "the wheel/rail profiles leave a flangeway play of " + mm(play) +
                               " (centred wheelset: " + mm(m.flangeway[0]) +
                               " to the left flange, " + mm(m.flangeway[1]) + " to the right)";
  if (*lo < 0.0 && -*lo >= play)
    m.gauge_warnings.push_back(
        "the gauge irregularity narrows the gauge by " + mm(-*lo) +
        " (at s = " + formatNumber(s_lo, 4) + " m), more than " + profiles +
        ": both flanges of a wheelset touch at once there (large lateral forces on both wheels); "
        "lower psd.scale or check the spectrum");
  if (*hi > 0.0) {
    const double y = m.flangeway[0] + 0.5 * *hi;
    const contact::TreadContact t = m.solver->solveTread(y, *hi);
    // The profiles are extended beyond their ends (profile.hpp): a contact point there is not
    // on the wheel or the rail.
    const auto& cfg = m.solver->config();
    const bool onProfiles = cfg.right_wheel->inside(t.right.s_w) &&
                            cfg.right_rail->inside(t.right.s_r) &&
                            cfg.left_wheel->inside(t.left.s_w) && cfg.left_rail->inside(t.left.s_r);
    if (!t.converged || t.penetration > 1e-4 || !onProfiles)
      m.gauge_warnings.push_back("the gauge irregularity widens the gauge by " + mm(*hi) +
                                 " (at s = " + formatNumber(s_hi, 4) +
                                 " m): against its flange (y = " + mm(y) +
                                 ") the wheelset has no tread contact on the other rail (" +
                                 profiles + "); the wheel may drop between the rails");
  }
}

// The wheel's flange height: its largest radius (the flange tip) above the radius at s_w = 0.
double flangeHeight(const profiles::Profile& wheel) {
  double top = wheel.at(0.0).h;
  for (double s = wheel.sMin(); s <= wheel.sMax(); s += 0.1e-3) top = std::max(top, wheel.at(s).h);
  return top - wheel.at(0.0).h;
}

// The elastic method's searches, normal policy, Hertz-derived damping and derailment criterion
// (ElasticContactModel).
// One rail of slices (profiles.rail_slices.<side> or an extra rail's slices; `key` names it in
// messages), the right side's profiles mirrored as the rail is; profiles read once per file.
std::shared_ptr<const contact::SlicedRailSearch> slicedRail(
    const ProfilesSpec& p, const std::vector<RailSliceSpec>& spec, std::size_t side,
    const std::string& key, bool bounded, const contact::WheelRailPair& pair,
    const contact::ElasticSearchSpec& search,
    std::map<std::string, std::shared_ptr<const profiles::Profile>>& loaded) {
  Diagnostics d;
  std::vector<contact::RailSlice> slices;
  for (const RailSliceSpec& sl : spec) {
    auto& left = loaded[sl.rail + (sl.metres ? "|m" : "|mm") + (sl.z_down ? "|down" : "|up") + "|" +
                        formatNumber(sl.max_slope)];
    if (!left)
      left = loadProfile(sl.rail, profiles::ProfileKind::Rail, p.r0, sl.loc, d, "rail_slices", &sl);
    if (!left) continue;
    slices.push_back(
        {sl.s, side == 0 ? left : std::make_shared<const profiles::Profile>(left->mirrored()),
         sl.dy, sl.dz});
  }
  d.throwIfAny();
  for (std::size_t k = 1; k < slices.size(); ++k) {
    const profiles::Profile& a = *slices[k - 1].rail;
    const profiles::Profile& b = *slices[k].rail;
    if (std::max(a.sMin(), b.sMin()) < std::min(a.sMax(), b.sMax())) continue;
    d.add(spec[k].loc,
          key + "[" + std::to_string(k + 1) +
              "]: its rail and the slice before it (at s = " + formatNumber(spec[k - 1].s) +
              " m) cover no common part of the profile (lateral) parameter: there is "
              "nothing to blend between them");
  }
  d.throwIfAny();
  try {
    return std::make_shared<const contact::SlicedRailSearch>(pair, std::move(slices), search,
                                                             bounded);
  } catch (const InputError& err) {
    d.add(spec.front().loc, key + ": " + err.diagnostics().front().message);
  }
  d.throwIfAny();
  return nullptr;
}

// The rails of profiles.rail_slices and profiles.extra_rails (ElasticContactModel::sliced,
// ::extra).
void compileSlicedRails(const ProfilesSpec& p, const contact::ElasticSearchSpec& search,
                        const ContactModel& m, ElasticContactModel& e) {
  std::map<std::string, std::shared_ptr<const profiles::Profile>> loaded;
  const std::array<contact::WheelRailPair, 2> pairs = contact::wheelRailPairs(m.geometry);
  for (std::size_t side = 0; side < 2; ++side) {
    const std::string name = side == 0 ? "left" : "right";
    if (!p.rail_slices[side].empty())
      e.sliced[side] = slicedRail(p, p.rail_slices[side], side, "profiles.rail_slices." + name,
                                  false, pairs[side], search, loaded);
    for (std::size_t k = 0; k < p.extra_rails[side].size(); ++k) {
      const ExtraRailSpec& r = p.extra_rails[side][k];
      e.extra[side].push_back(
          slicedRail(p, r.slices, side,
                     "profiles.extra_rails." + name + "[" + std::to_string(k + 1) + "].slices",
                     true, pairs[side], search, loaded));
      e.extra_names[side].push_back(r.name);
      e.extra_check[side].push_back(r.check ? 1 : 0);
    }
  }
}

// A check rail lies on the track-centre side of the flange back: at every slice the centred
// wheelset (no irregularity) must clear it, or the rail stands where the wheel is (under its
// tread or flange) and the lateral search of check_rail.hpp would press the wheel out of it.
void checkRailClearances(const ProfilesSpec& p, const ContactModel& m,
                         const ElasticContactModel& e) {
  Diagnostics d;
  for (std::size_t side = 0; side < 2; ++side)
    for (std::size_t r = 0; r < e.extra[side].size(); ++r) {
      if (e.extra_check[side][r] == 0) continue;
      const ExtraRailSpec& spec = p.extra_rails[side][r];
      for (std::size_t k = 0; k < spec.slices.size(); ++k) {
        const contact::SlicedRailSearch::Place at = e.extra[side][r]->at(spec.slices[k].s);
        if (at.search == nullptr) continue;
        contact::ElasticWheelGeometry g;
        contact::searchCheckRail(*at.search, e.flange_back[side], m.centredPoseOver(at, side), g);
        if (g.min_gap > 0.0) continue;
        d.add(spec.slices[k].loc,
              "profiles.extra_rails." + std::string(side == 0 ? "left" : "right") + "[" +
                  std::to_string(r + 1) + "] (check rail '" + spec.name + "'), slice " +
                  std::to_string(k + 1) + " at s = " + formatNumber(spec.slices[k].s) +
                  " m: it reaches " + formatNumber(-g.min_gap * 1e3, 4) +
                  " mm into the back of the centred wheel's flange; a check rail lies on the "
                  "track-centre side of the flange back (move it by dy < 0)");
        break;
      }
    }
  d.throwIfAny();
}

std::shared_ptr<const ElasticContactModel> compileElastic(const ProfilesSpec& p,
                                                          const ContactSpec& c,
                                                          const vehicle::VehicleModel& v,
                                                          const ContactModel& m) {
  auto e = std::make_shared<ElasticContactModel>();
  contact::ElasticSearchSpec search;
  // The wheelset's intermediate frame is Rz(psi) Rx(phi) (vehicle/kinematics.hpp).
  search.angles = contact::EulerOrder::YawRoll;
  search.sample_step = c.elastic.sample_step;
  for (const contact::WheelRailPair& pair : contact::wheelRailPairs(m.geometry))
    e->search.emplace_back(pair, search);
  compileSlicedRails(p, search, m, *e);
  // The flange backs (check rails): each wheel drawn as a left wheel, its back face at the
  // flange-back distance of the positioning (Lw = B/2 + 70 mm).
  for (std::size_t side = 0; side < 2; ++side) {
    const profiles::Profile& w = *e->search[side].pair().wheel;
    e->flange_back[side] =
        contact::FlangeBack(side == 0 ? w : w.mirrored(), -profiles::kS1002FlangeBackDistance);
  }
  checkRailClearances(p, m, *e);
  e->normal.material = m.material;
  e->normal.min_ratio = c.elastic.min_curvature_ratio;
  e->damping_ratio = c.elastic.damping_ratio;
  e->support = c.elastic.rail_support;

  // Nominal static wheel load and the centred tread's Hertz contact at it.
  double mass = 0.0, ws_mass = 0.0;
  for (const vehicle::Body& b : v.bodies) {
    if (b.kind == vehicle::BodyKind::Frame) continue;
    mass += b.mass;
    if (b.kind == vehicle::BodyKind::Wheelset) ws_mass += b.mass;
  }
  // Kinematic frames carry no weight but may press on the vehicle through preloaded vertical
  // elements (a directional element's force f acts as +f e_z on its body1 and -f e_z on its
  // body2, vehicle/dynamics.cpp): their preloads add to the wheel loads.
  double frame_load = 0.0;
  const auto framePreload = [&](const vehicle::ElementGeometry& g, double preload) {
    if (g.axis != 2) return;
    const bool f1 = v.bodies[static_cast<std::size_t>(g.body1)].kind == vehicle::BodyKind::Frame;
    const bool f2 = v.bodies[static_cast<std::size_t>(g.body2)].kind == vehicle::BodyKind::Frame;
    if (f1 && !f2) frame_load += preload;
    if (f2 && !f1) frame_load -= preload;
  };
  for (const auto& el : v.spring_dampers) framePreload(el.g, el.preload);
  for (const auto& el : v.series_dampers) framePreload(el.g, el.preload);
  for (const auto& el : v.shear_springs) framePreload(el.g, el.preload);
  const double wheels = 2.0 * static_cast<double>(m.wheelsets.size());
  e->static_load = (mass * v.gravity + frame_load) / wheels;
  // Sunk by 10 um: at the touching height itself the approach is zero and there is no patch.
  const contact::ElasticPose centred{0.0, m.centred_z - 1e-5, m.centred_phi, 0.0};
  const contact::ElasticWheelGeometry g = e->search[0].search(centred);
  double K = 0.0;
  if (g.count > 0) {
    const creep::RelativeCurvatures k = contact::policyCurvatures(g.patch[0], e->normal);
    K = creep::hertzStiffness(m.material, k);
  }
  if (!(K > 0.0) || !(e->static_load > 0.0))
    throw InputError(c.loc, "contact: elastic: no Hertz tread contact for the centred wheelset");
  e->tread_stiffness = K;
  e->static_approach = std::cbrt(std::pow(e->static_load / K, 2.0));
  const double k_lin = 1.5 * K * std::sqrt(e->static_approach);
  const double m_w = 0.5 * ws_mass / static_cast<double>(m.wheelsets.size());
  e->vertical_frequency = std::sqrt(k_lin / m_w) / (2.0 * std::numbers::pi);
  e->damping = 2.0 * e->damping_ratio * std::sqrt(k_lin * m_w) / e->static_load;
  // The lower flange of the two wheels: a wheel risen by half of it has left its rail.
  e->flange_height =
      std::min(flangeHeight(*m.geometry.left_wheel), flangeHeight(*m.geometry.right_wheel));
  e->derailment_lift =
      c.elastic.derailment_lift < 0.0 ? 0.5 * e->flange_height : c.elastic.derailment_lift;
  return e;
}

// What of a CONTACT slices-file railbench does not use: its surface is built along the
// features' parts and through kinks, ours is the linear blend at a fixed lateral coordinate.
void sliceListWarnings(const ProfilesSpec& p, std::vector<std::string>& warnings) {
  for (const SliceListSpec& l : p.slice_lists)
    if (l.features > 1 || l.kinks > 0 || l.accelerations > 0)
      warnings.push_back(
          l.loc.str() + ": warning: " + std::filesystem::path(l.path).filename().string() +
          ": its features (NFEAT = " + std::to_string(l.features) +
          ", NKINK = " + std::to_string(l.kinks) + ", NACCEL = " + std::to_string(l.accelerations) +
          ") are not used: the slices are blended linearly at a fixed lateral coordinate "
          "(docs/sliced_rails.md); a rail that moves sideways between slices differs from "
          "CONTACT's surface there");
}

// The model of one wheel pair: compileContact without profiles.wheelsets.
ContactModel compilePair(const ProfilesSpec& p, const ContactSpec& c,
                         const vehicle::VehicleModel& v, const track::TrackModel& track,
                         TableCache* cache) {
  Diagnostics d;
  ContactModel m;
  m.wheel_sources = {p.wheel_left.empty() ? p.wheel : p.wheel_left,
                     p.wheel_right.empty() ? p.wheel : p.wheel_right};
  sliceListWarnings(p, m.warnings);
  m.method = c.method;
  m.creep = c.creep;
  m.coupling = c.normal_forces;
  m.spin = c.wheelset_spin;
  m.min_normal_force = c.min_normal_force;
  m.loc = c.loc;
  for (std::size_t b = 0; b < v.bodies.size(); ++b)
    if (v.bodies[b].kind == vehicle::BodyKind::Wheelset) m.wheelsets.push_back(static_cast<int>(b));
  if (m.wheelsets.empty())
    d.add(c.loc, "contact: vehicle '" + v.name +
                     "' has no wheelset (a body with kind = \"wheelset\"): nothing to put on the "
                     "rails");
  if (c.method != ContactMethod::Elastic && railsAlongTrack(p))
    d.add(
        p.loc,
        std::string("profiles.rail_slices / extra_rails: a rail that changes along the track needs "
                    "contact.method = \"elastic\" (the ") +
            ContactModel::methodName(c.method) +
            " method's tables hold one rail profile for the whole track)");
  // The ranges of the scenario schema (dynamics/limits.hpp), for callers without a scenario.
  const auto check = [&](const char* key, double value, const Range& r) {
    if (!r.contains(value))
      d.add(c.loc, std::string("contact.") + key + " must be in " + r.text() + " (got " +
                       formatNumber(value) + ")");
  };
  check("youngs_modulus", c.youngs_modulus, kYoungsModulusRange);
  check("poisson", c.poisson, kPoissonRange);
  check("mu", c.mu, kMuRange);
  check("min_normal_force", c.min_normal_force, kMinNormalForceRange);
  if (c.creep == CreepModel::Fastsim) {
    check("fastsim.strips", c.fastsim.strips, creep::kFastsimStripsRange);
    check("fastsim.elements", c.fastsim.elements, creep::kFastsimElementsRange);
  }
  if (c.method == ContactMethod::Lut) {
    check("flange_stiffness", c.flange_stiffness, kFlangeStiffnessRange);
    check("flange_damping", c.flange_damping, kFlangeDampingRange);
  }
  if (c.method == ContactMethod::Elastic) {
    check("elastic.damping_ratio", c.elastic.damping_ratio, kElasticDampingRatioRange);
    check("elastic.sample_step", c.elastic.sample_step, kElasticSampleStepRange);
    check("elastic.min_curvature_ratio", c.elastic.min_curvature_ratio,
          kElasticCurvatureRatioRange);
    if (!(c.elastic.derailment_lift < 0.0))
      check("elastic.derailment_lift", c.elastic.derailment_lift, kDerailmentLiftRange);
  }
  for (const vehicle::Body& b : v.bodies) {
    if (b.kind == vehicle::BodyKind::Wheelset && std::abs(b.height - p.r0) > 0.05)
      d.add(b.loc, "wheelset '" + b.name + "': centre height " + formatNumber(b.height) +
                       " m is far from the wheel radius profiles.r0 = " + formatNumber(p.r0) +
                       " m (the wheelset centre is the axle)");
  }
  d.throwIfAny();

  m.geometry = contactGeometryConfig(p, c);
  m.config_hash = contact::configHash(m.geometry);

  m.material.E = c.youngs_modulus;
  m.material.nu = c.poisson;
  m.creep_params.mu = c.mu;
  m.creep_params.G = creep::shearModulus(m.material);
  if (const std::string problem = creep::creepParamsProblem(m.creep_params); !problem.empty())
    throw InputError(c.loc, "contact: creep parameters: " + problem);
  m.fastsim = c.fastsim;
  m.flange_stiffness = c.flange_stiffness;
  m.flange_damping = c.flange_damping < 0.0 ? c.flange_stiffness / 100.0 : c.flange_damping;

  try {
    m.solver = std::make_shared<const contact::ContactSolver>(m.geometry);
    if (m.method == ContactMethod::Kec) {
      m.kec = cache ? cache->kec(m.geometry)
                    : std::make_shared<const contact::KecTable>(contact::buildKec(m.geometry));
    } else if (m.method == ContactMethod::Lut) {
      m.lut = cache ? cache->lut(m.geometry)
                    : std::make_shared<const contact::LutTable>(contact::buildLut(m.geometry));
    }
  } catch (const InputError& e) {
    Diagnostics dd;
    dd.add(c.loc, std::string("contact: the ") + (m.method == ContactMethod::Kec ? "KEC" : "LUT") +
                      " table could not be built for these profiles and positions (Lw = " +
                      formatNumber(m.geometry.wheel_lw) +
                      " m, Lr = " + formatNumber(m.geometry.rail_lr) + " m)");
    dd.add(e);
    dd.throwIfAny();
  }
  for (const std::string& w : m.tableStats().warnings)
    m.warnings.push_back(c.loc.str() + ": warning: " + w);
  if (cache)
    for (const std::string& w : cache->takeWarnings())
      m.warnings.push_back(c.loc.str() + ": warning: " + w);
  m.flange_boundary[0] = m.solver->flangeBoundary(contact::Side::Left);
  m.flange_boundary[1] = m.solver->flangeBoundary(contact::Side::Right);

  // Centred wheelset: Eq. (12) at y = 0.
  const contact::TreadContact c0 = m.solver->solveTread(0.0, 0.0);
  if (!c0.converged)
    throw InputError(c.loc, "contact: no contact solution for the centred wheelset");
  m.centred_z = c0.z;
  m.centred_phi = c0.phi;
  m.centred_radius[0] = c0.left.radius;
  m.centred_radius[1] = c0.right.radius;

  gaugeWarnings(m, track);
  if (m.method == ContactMethod::Elastic) m.elastic = compileElastic(p, c, v, m);

  // Gauge variation beyond the LUT's xi_g range is extrapolated (and reported by the rhs as a
  // recoverable failure); say so before the run.
  if (m.lut && track.irregularities()) {
    const auto& tab = track.irregularities()->samples();
    double gmax = 0.0;
    for (double g : tab.channel[static_cast<std::size_t>(track::Channel::Gauge)])
      gmax = std::max(gmax, std::abs(g));
    const contact::GridSpec& gg = m.lut->gaugeGrid();
    if (gmax > std::min(-gg.min, gg.max))
      m.warnings.push_back(c.loc.str() + ": warning: the gauge irregularity reaches " +
                           formatNumber(gmax * 1e3) + " mm, beyond the LUT gauge range [" +
                           formatNumber(gg.min * 1e3) + ", " + formatNumber(gg.max * 1e3) + "] mm");
  }
  return m;
}

// The warnings of the wheelsets' own models (each with the wheelsets it serves, in the order of
// their first wheelset) that the vehicle's model does not give already: the vehicle's too, with
// the wheelsets they concern.
void noteOwnWheelWarnings(
    const std::vector<std::pair<const ContactModel*, std::vector<std::string>>>& users,
    ContactModel& m) {
  const std::vector<std::string> vehicle_warnings = m.warnings;
  const std::vector<std::string> vehicle_gauge = m.gauge_warnings;
  for (const auto& [model, ws] : users) {
    std::string who;
    for (const std::string& n : ws) who += (who.empty() ? "" : ", ") + n;
    const auto note = [&](const std::vector<std::string>& from, std::vector<std::string>& into,
                          const std::vector<std::string>& vehicle) {
      for (const std::string& w : from)
        if (std::find(vehicle.begin(), vehicle.end(), w) == vehicle.end())
          into.push_back(w + " (wheelset " + who + ", on its own wheels)");
    };
    note(model->warnings, m.warnings, vehicle_warnings);
    note(model->gauge_warnings, m.gauge_warnings, vehicle_gauge);
  }
}

// profiles.wheelsets: the model of each wheelset with wheels of its own (ContactModel::own_wheels).
// Each entry's profiles fall back to the vehicle's; a pair equal to the vehicle's needs no model
// of its own, and equal pairs share one; their warnings join the vehicle's
// (noteOwnWheelWarnings).
void compileOwnWheels(const ProfilesSpec& p, const ContactSpec& c, const vehicle::VehicleModel& v,
                      const track::TrackModel& track, TableCache* cache, ContactModel& m) {
  Diagnostics d;
  std::vector<std::string> names;
  for (int b : m.wheelsets) names.push_back(v.bodies[static_cast<std::size_t>(b)].name);
  std::vector<bool> given(names.size(), false);
  // The model of each pair; null for a pair that failed (reported once, at its first wheelset).
  std::map<std::array<std::string, 2>, std::shared_ptr<const ContactModel>> pairs;
  // The wheelsets of each own model, in the order of their first wheelset.
  std::vector<std::pair<const ContactModel*, std::vector<std::string>>> users;
  for (const WheelsetProfilesSpec& e : p.wheelsets) {
    const auto it = std::find(names.begin(), names.end(), e.wheelset);
    if (it == names.end()) {
      const std::string hint = closestMatch(e.wheelset, names);
      d.add(e.loc, "profiles.wheelsets: vehicle '" + v.name + "' has no wheelset named '" +
                       e.wheelset + "'" + (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
      continue;
    }
    const auto w = static_cast<std::size_t>(it - names.begin());
    if (given[w]) {
      d.add(e.loc, "profiles.wheelsets: wheelset '" + e.wheelset + "' is given twice");
      continue;
    }
    given[w] = true;
    const auto pick = [&](const std::string& own, std::size_t side) {
      return !own.empty() ? own : !e.wheel.empty() ? e.wheel : m.wheel_sources[side];
    };
    const std::array<std::string, 2> pair = {pick(e.wheel_left, 0), pick(e.wheel_right, 1)};
    if (pair == m.wheel_sources) continue;
    const auto [at, fresh] = pairs.try_emplace(pair);
    std::shared_ptr<const ContactModel>& model = at->second;
    if (fresh) {
      ProfilesSpec q = p;
      q.wheelsets.clear();
      q.wheel_left = pair[0];
      q.wheel_right = pair[1];
      q.loc = e.loc;
      try {
        model = std::make_shared<const ContactModel>(compilePair(q, c, v, track, cache));
      } catch (const InputError& err) {
        d.add(e.loc, "profiles.wheelsets." + e.wheelset + ": these wheels give no contact model");
        d.add(err);
      }
    }
    if (!model) continue;
    m.own_wheels.resize(names.size());
    m.own_wheels[w] = model;
    const auto user = std::find_if(users.begin(), users.end(),
                                   [&](const auto& u) { return u.first == model.get(); });
    if (user == users.end())
      users.push_back({model.get(), {e.wheelset}});
    else
      user->second.push_back(e.wheelset);
  }
  d.throwIfAny();
  noteOwnWheelWarnings(users, m);
}

}  // namespace

ContactModel compileContact(const ProfilesSpec& p, const ContactSpec& c,
                            const vehicle::VehicleModel& v, const track::TrackModel& track,
                            TableCache* cache) {
  ContactModel m = compilePair(p, c, v, track, cache);
  if (!p.wheelsets.empty()) compileOwnWheels(p, c, v, track, cache, m);
  return m;
}

}  // namespace rb::dynamics
