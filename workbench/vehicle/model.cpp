#include "workbench/vehicle/model.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "workbench/core/strings.hpp"
#include "workbench/vehicle/names.hpp"

namespace rb::vehicle {

namespace {

std::string_view bodyKindName(BodyKind k) {
  switch (k) {
    case BodyKind::CarBody:
      return "car";
    case BodyKind::Bogie:
      return "bogie";
    case BodyKind::Wheelset:
      return "wheelset";
    case BodyKind::Frame:
      return "frame";
  }
  return "?";
}

bool finite3(const Eigen::Vector3d& v) {
  return v.allFinite();
}

int axisOf(Direction d) {
  switch (d) {
    case Direction::X:
      return 0;
    case Direction::Y:
      return 1;
    case Direction::Z:
      return 2;
    case Direction::Axial:
      return -1;
  }
  return -1;
}

// Nominal relative position r_Q - r_P (straight level track, all coordinates zero).
Eigen::Vector3d nominalDelta(const BodySpec& b1, const BodySpec& b2, const ElementSpec& e) {
  const Eigen::Vector3d p = Eigen::Vector3d(b1.x, 0.0, b1.height) + e.point1;
  const Eigen::Vector3d q = Eigen::Vector3d(b2.x, 0.0, b2.height) + e.point2;
  return q - p;
}

}  // namespace

std::string_view elementKindName(ElementKind kind) {
  switch (kind) {
    case ElementKind::SpringDamper:
      return "spring_damper";
    case ElementKind::SeriesSpringDamper:
      return "series_damper";
    case ElementKind::ShearSpring:
      return "shear_spring";
    case ElementKind::BendingSpring:
      return "bending_spring";
    case ElementKind::Bumpstop:
      return "bumpstop";
  }
  return "?";
}

namespace {

// The parameters of an element's force law (suspension/laws.hpp).
void validateElementLaw(const ElementSpec& e, const std::string& what, Diagnostics& diags) {
  const auto nonneg = [&](double v, const char* key, const char* unit) {
    if (!(std::isfinite(v) && v >= 0.0))
      diags.add(e.loc, what + ": " + key + " must be >= 0 " + unit + ", got " + formatNumber(v));
  };
  const bool axial = e.direction == Direction::Axial;
  switch (e.kind) {
    case ElementKind::SpringDamper:
      nonneg(e.stiffness, "stiffness", "N/m");
      nonneg(e.damping, "damping", "N s/m");
      break;
    case ElementKind::SeriesSpringDamper:
      nonneg(e.stiffness, "stiffness", "N/m");
      if (!(std::isfinite(e.damping) && e.damping > 0.0))
        diags.add(e.loc, what + ": damping must be > 0 N s/m, got " + formatNumber(e.damping));
      if (!(std::isfinite(e.series_stiffness) && e.series_stiffness > 0.0))
        diags.add(e.loc, what + ": series_stiffness must be > 0 N/m, got " +
                             formatNumber(e.series_stiffness));
      break;
    case ElementKind::ShearSpring:
      nonneg(e.stiffness, "stiffness", "N/m");
      if (axial)
        diags.add(e.loc,
                  what + ": direction must be x, y or z (a shear spring acts across its axis)");
      break;
    case ElementKind::BendingSpring:
      nonneg(e.stiffness, "stiffness", "N m/rad");
      if (axial)
        diags.add(e.loc,
                  what + ": direction must be x, y or z (the axis of the relative rotation)");
      break;
    case ElementKind::Bumpstop:
      for (const std::string& m : suspension::BumpstopLaw::check(e.table_d, e.table_f))
        diags.add(e.loc, what + ": " + m);
      break;
  }
}

// One suspension element: name, bodies, attachment points, law, free length.
void validateElement(const VehicleSpec& spec, const ElementSpec& e,
                     const std::map<std::string, int>& bodies, const std::string& body_list,
                     std::map<std::string, SourceLoc>& names, Diagnostics& diags) {
  const std::string what =
      "element '" + e.name + "' (" + std::string(elementKindName(e.kind)) + ")";
  if (e.name.empty())
    diags.add(e.loc, "element (" + std::string(elementKindName(e.kind)) + "): empty name");
  else if (!names.emplace(e.name, e.loc).second)
    diags.add(e.loc, what + ": duplicate element name (also " + names[e.name].str() + ")");
  const auto b1 = bodies.find(e.body1), b2 = bodies.find(e.body2);
  if (b1 == bodies.end())
    diags.add(e.loc,
              what + ": unknown body '" + e.body1 + "' in 'from' (bodies: " + body_list + ")");
  if (b2 == bodies.end())
    diags.add(e.loc, what + ": unknown body '" + e.body2 + "' in 'to' (bodies: " + body_list + ")");
  if (!e.body1.empty() && e.body1 == e.body2)
    diags.add(e.loc, what + ": 'from' and 'to' are the same body '" + e.body1 + "'");
  if (!finite3(e.point1) || !finite3(e.point2))
    diags.add(e.loc, what + ": attachment points must be finite");
  if (!std::isfinite(e.preload)) diags.add(e.loc, what + ": preload must be finite");
  const bool axial = e.direction == Direction::Axial;
  validateElementLaw(e, what, diags);
  const bool uses_length = e.kind == ElementKind::SpringDamper ||
                           e.kind == ElementKind::SeriesSpringDamper ||
                           e.kind == ElementKind::Bumpstop;
  if (!(std::isfinite(e.length0) && e.length0 >= 0.0))
    diags.add(e.loc, what + ": length0 must be >= 0 m, got " + formatNumber(e.length0));
  else if (e.length0 != 0.0 && (!axial || !uses_length))
    diags.add(e.loc, what +
                         ": length0 applies to axial elements only (directional elements are "
                         "undeformed at the nominal relative position; use preload)");
  if (axial && uses_length && b1 != bodies.end() && b2 != bodies.end() && finite3(e.point1) &&
      finite3(e.point2)) {
    const Eigen::Vector3d dn = nominalDelta(spec.bodies[static_cast<std::size_t>(b1->second)],
                                            spec.bodies[static_cast<std::size_t>(b2->second)], e);
    if (!(dn.norm() > 1e-6))
      diags.add(e.loc, what +
                           ": an axial element needs distinct attachment points (their nominal "
                           "distance is " +
                           formatNumber(dn.norm()) + " m); use direction x, y or z");
  }
}

// A point of application farther than this from the body's centre of mass is not on the body
// (the longest rail vehicles are about 30 m): a typing error, whose moment would dwarf the rest.
constexpr double kMaxApplicationDistance = 100.0;  // [m]

// One external force: name, body, point, direction, law.
void validateExternalForce(const VehicleSpec& spec, const ExternalForceSpec& e,
                           const std::map<std::string, int>& bodies,
                           std::map<std::string, SourceLoc>& names, Diagnostics& diags) {
  const std::string what = "element '" + e.name + "' (" + kExternalForceKind + ")";
  if (e.name.empty())
    diags.add(e.loc, std::string("element (") + kExternalForceKind + "): empty name");
  else if (!names.emplace(e.name, e.loc).second)
    diags.add(e.loc, what + ": duplicate element name (also " + names[e.name].str() + ")");
  const auto b = bodies.find(e.body);
  if (b == bodies.end()) {
    std::vector<std::string> known;
    for (const BodySpec& body : spec.bodies) known.push_back(body.name);
    const std::string hint = closestMatch(e.body, known);
    diags.add(e.loc, what + ": unknown body '" + e.body + "' in 'body'" +
                         (hint.empty() ? " (bodies: " + join(known, ", ") + ")"
                                       : " (did you mean '" + hint + "'?)"));
  } else if (spec.bodies[static_cast<std::size_t>(b->second)].kind == BodyKind::Frame) {
    diags.add(e.loc, what + ": body '" + e.body +
                         "' is a frame, whose motion is prescribed: a force on it does nothing");
  }
  if (!finite3(e.point) || !(e.point.cwiseAbs().maxCoeff() <= kMaxApplicationDistance))
    diags.add(e.loc, what + ": the point 'at' must lie within " +
                         formatNumber(kMaxApplicationDistance) +
                         " m of the body's centre of mass in every axis");
  if (!finite3(e.direction) || !(e.direction.norm() > 0.0))
    diags.add(e.loc, what + ": direction must be a vector of length > 0, e.g. {0, 1, 0}");
  for (const std::string& m : suspension::checkForceLaw(e.law))
    diags.add(e.table_loc.line > 0 && m.rfind("table", 0) == 0 ? e.table_loc : e.loc,
              what + ": " + m);
}

// The bodies: names (unique; body_list lists them), masses, inertias, positions.
void validateBodies(const VehicleSpec& spec, std::map<std::string, int>& bodies,
                    std::string& body_list, Diagnostics& diags) {
  for (std::size_t i = 0; i < spec.bodies.size(); ++i) {
    const BodySpec& b = spec.bodies[i];
    const std::string what = "body '" + b.name + "' (" + std::string(bodyKindName(b.kind)) + ")";
    if (b.name.empty())
      diags.add(b.loc, "body " + std::to_string(i + 1) + ": empty name");
    else if (!bodies.emplace(b.name, static_cast<int>(i)).second)
      diags.add(b.loc, what + ": duplicate body name (also " +
                           spec.bodies[static_cast<std::size_t>(bodies[b.name])].loc.str() + ")");
    else
      body_list += (body_list.empty() ? "" : ", ") + b.name;
    if (b.kind != BodyKind::Frame) {
      if (!(std::isfinite(b.mass) && b.mass > 0.0))
        diags.add(b.loc, what + ": mass must be > 0 kg, got " + formatNumber(b.mass));
      if (!(b.inertia.allFinite() && b.inertia.minCoeff() > 0.0))
        diags.add(b.loc, what + ": inertia must be > 0 kg m^2 in every axis, got {" +
                             formatNumber(b.inertia[0]) + ", " + formatNumber(b.inertia[1]) + ", " +
                             formatNumber(b.inertia[2]) + "}");
    }
    if (!std::isfinite(b.x) || !std::isfinite(b.height))
      diags.add(b.loc, what + ": x and height must be finite");
  }
}

// Index of the point pair (body1, u1, body2, u2) of g in `pairs`, appended if new. Exact
// equality: elements written at the same attachment points share their relative motion.
int pointPairIndex(const ElementGeometry& g, std::vector<PointPair>& pairs) {
  const auto same = [&](const PointPair& p) {
    return p.body1 == g.body1 && p.body2 == g.body2 && p.u1 == g.u1 && p.u2 == g.u2;
  };
  const auto it = std::find_if(pairs.begin(), pairs.end(), same);
  if (it != pairs.end()) return static_cast<int>(it - pairs.begin());
  pairs.push_back({g.body1, g.body2, g.pair, g.u1, g.u2});
  return static_cast<int>(pairs.size()) - 1;
}

}  // namespace

void validateVehicle(const VehicleSpec& spec, Diagnostics& diags) {
  const std::string vname = "vehicle '" + spec.name + "'";
  if (spec.bodies.empty()) diags.add(spec.loc, vname + ": no bodies");
  if (!(std::isfinite(spec.speed) && spec.speed >= 0.0))
    diags.add(spec.loc, vname + ": speed must be >= 0 m/s, got " + formatNumber(spec.speed));
  if (!std::isfinite(spec.acceleration))
    diags.add(spec.loc,
              vname + ": acceleration must be finite, got " + formatNumber(spec.acceleration));
  if (!(std::isfinite(spec.wheel_radius) && spec.wheel_radius > 0.0))
    diags.add(spec.loc,
              vname + ": wheel_radius must be > 0 m, got " + formatNumber(spec.wheel_radius));
  if (!std::isfinite(spec.start)) diags.add(spec.loc, vname + ": start must be finite");

  std::map<std::string, int> bodies;
  std::string body_list;
  validateBodies(spec, bodies, body_list, diags);
  std::map<std::string, SourceLoc> names;
  for (const ElementSpec& e : spec.elements)
    validateElement(spec, e, bodies, body_list, names, diags);
  for (const ExternalForceSpec& e : spec.external_forces)
    validateExternalForce(spec, e, bodies, names, diags);
}

VehicleModel compileVehicle(const VehicleSpec& spec, const track::TrackModel& track) {
  Diagnostics diags;
  validateVehicle(spec, diags);
  diags.throwIfAny();

  VehicleModel m;
  m.name = spec.name;
  m.speed = spec.speed;
  m.acceleration = spec.acceleration;
  m.wheel_radius = spec.wheel_radius;
  m.start = spec.start;
  m.geometry = track.geometry();
  m.loc = spec.loc;
  for (const BodySpec& b : spec.bodies) {
    Body body;
    body.name = b.name;
    body.kind = b.kind;
    body.mass = b.mass;
    body.inertia = b.inertia;
    body.x = b.x;
    body.height = b.height;
    body.rotation = b.kind == BodyKind::Wheelset ? RotationSequence::YawRollPitch
                                                 : RotationSequence::YawPitchRoll;
    body.loc = b.loc;
    m.bodies.push_back(body);
  }
  for (const ElementSpec& e : spec.elements) {
    ElementGeometry g;
    g.name = e.name;
    g.loc = e.loc;
    g.body1 = m.findBody(e.body1);
    g.body2 = m.findBody(e.body2);
    g.u1 = e.point1;
    g.u2 = e.point2;
    g.direction = e.direction;
    g.axis = axisOf(e.direction);
    g.delta_nominal = nominalDelta(spec.bodies[static_cast<std::size_t>(g.body1)],
                                   spec.bodies[static_cast<std::size_t>(g.body2)], e);
    g.length0 = e.length0 > 0.0 ? e.length0 : g.delta_nominal.norm();
    const std::array<int, 2> pair{g.body1, g.body2};
    const auto it = std::find(m.body_pairs.begin(), m.body_pairs.end(), pair);
    g.pair = static_cast<int>(it - m.body_pairs.begin());
    if (it == m.body_pairs.end()) m.body_pairs.push_back(pair);
    if (e.kind != ElementKind::BendingSpring) g.point_pair = pointPairIndex(g, m.point_pairs);
    switch (e.kind) {
      case ElementKind::SpringDamper:
        m.spring_dampers.push_back({g, e.stiffness, e.damping, e.preload});
        break;
      case ElementKind::SeriesSpringDamper:
        m.series_dampers.push_back({g, e.stiffness, e.damping, e.series_stiffness, e.preload});
        break;
      case ElementKind::ShearSpring:
        m.shear_springs.push_back({g, e.stiffness, e.preload});
        break;
      case ElementKind::BendingSpring:
        m.bending_springs.push_back({g, e.stiffness, e.preload});
        break;
      case ElementKind::Bumpstop:
        m.bumpstops.push_back({g, suspension::BumpstopLaw(e.table_d, e.table_f)});
        break;
    }
  }
  if (!m.spring_dampers.empty()) m.element_kinds.emplace_back("spring_damper");
  if (!m.series_dampers.empty()) m.element_kinds.emplace_back("series_damper");
  if (!m.shear_springs.empty()) m.element_kinds.emplace_back("shear_spring");
  if (!m.bending_springs.empty()) m.element_kinds.emplace_back("bending_spring");
  if (!m.bumpstops.empty()) m.element_kinds.emplace_back("bumpstop");
  for (const ExternalForceSpec& e : spec.external_forces)
    m.external_forces.push_back(
        {e.name, e.loc, m.findBody(e.body), e.point, e.frame, e.direction.normalized(), e.law});
  if (!m.external_forces.empty()) m.element_kinds.emplace_back(kExternalForceKind);
  return m;
}

int VehicleModel::findBody(std::string_view n) const {
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].name == n) return static_cast<int>(i);
  return -1;
}

std::vector<ElementId> VehicleModel::elements() const {
  std::vector<ElementId> out;
  const auto add = [&](ElementKind k, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) out.push_back({k, static_cast<int>(i)});
  };
  add(ElementKind::SpringDamper, spring_dampers.size());
  add(ElementKind::SeriesSpringDamper, series_dampers.size());
  add(ElementKind::ShearSpring, shear_springs.size());
  add(ElementKind::BendingSpring, bending_springs.size());
  add(ElementKind::Bumpstop, bumpstops.size());
  return out;
}

int VehicleModel::elementCount() const {
  return static_cast<int>(spring_dampers.size() + series_dampers.size() + shear_springs.size() +
                          bending_springs.size() + bumpstops.size());
}

const ElementGeometry& VehicleModel::element(ElementId id) const {
  const auto i = static_cast<std::size_t>(id.index);
  switch (id.kind) {
    case ElementKind::SpringDamper:
      return spring_dampers.at(i).g;
    case ElementKind::SeriesSpringDamper:
      return series_dampers.at(i).g;
    case ElementKind::ShearSpring:
      return shear_springs.at(i).g;
    case ElementKind::BendingSpring:
      return bending_springs.at(i).g;
    case ElementKind::Bumpstop:
      return bumpstops.at(i).g;
  }
  RB_CHECK(false, "unknown element kind");
}

int VehicleModel::findExternalForce(std::string_view n) const {
  for (std::size_t i = 0; i < external_forces.size(); ++i)
    if (external_forces[i].name == n) return static_cast<int>(i);
  return -1;
}

std::optional<ElementId> VehicleModel::findElement(std::string_view n) const {
  for (const ElementId& id : elements())
    if (element(id).name == n) return id;
  return std::nullopt;
}

}  // namespace rb::vehicle
