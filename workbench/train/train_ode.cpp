#include "workbench/train/train_ode.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace rb::train {

double longitudinalMass(const vehicle::VehicleModel& m, bool rotating) {
  double mass = 0.0;
  for (const auto& b : m.bodies) {
    if (b.kind == vehicle::BodyKind::Frame) continue;
    mass += b.mass;
    if (rotating && b.kind == vehicle::BodyKind::Wheelset)
      mass += b.inertia.y() / (m.wheel_radius * m.wheel_radius);
  }
  return mass;
}

namespace {

// The generalised force on s of point loads on one body (addPointForce's s row).
double sForce(const vehicle::BodyKinematics& k, const std::vector<vehicle::AppliedLoad>& loads) {
  vehicle::Vector6d Q = vehicle::Vector6d::Zero();
  for (const auto& l : loads)
    vehicle::addPointForce(k, k.attach.A * l.u, k.tf.A.transpose() * l.force, Q);
  return Q[vehicle::kS];
}

// Each wheelset of m with the body its primary suspension hangs from (the first element joining it
// to a body that is not a wheelset); -1 when none does.
std::vector<std::array<int, 2>> drivesOf(const vehicle::VehicleModel& m) {
  std::vector<std::array<int, 2>> out;
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    if (m.bodies[b].kind != vehicle::BodyKind::Wheelset) continue;
    int carrier = -1;
    for (const vehicle::ElementId id : m.elements()) {
      const vehicle::ElementGeometry& g = m.element(id);
      const int other = g.body1 == static_cast<int>(b)   ? g.body2
                        : g.body2 == static_cast<int>(b) ? g.body1
                                                         : -1;
      if (other >= 0 &&
          m.bodies[static_cast<std::size_t>(other)].kind != vehicle::BodyKind::Wheelset) {
        carrier = other;
        break;
      }
    }
    out.push_back({static_cast<int>(b), carrier});
  }
  return out;
}

// The body a vehicle's slope is read under: its first car body, else its first body.
int slopeBody(const vehicle::VehicleModel& m) {
  for (std::size_t b = 0; b < m.bodies.size(); ++b)
    if (m.bodies[b].kind == vehicle::BodyKind::CarBody) return static_cast<int>(b);
  return 0;
}

}  // namespace

TrainOde::TrainOde(std::vector<Part> parts, std::vector<Connection> connections,
                   Longitudinal longitudinal)
    : parts_(std::move(parts)),
      connections_(std::move(connections)),
      longitudinal_(std::move(longitudinal)) {
  if (parts_.empty()) throw std::logic_error("TrainOde: a train needs a vehicle");
  for (const auto& p : parts_) {
    offsets_.push_back(size_);
    size_ += p.ode->size();
  }
  const int n = static_cast<int>(parts_.size());
  for (const auto& c : connections_) {
    if (c.front < 0 || c.rear != c.front + 1 || c.rear >= n)
      throw std::logic_error("TrainOde: a connection joins neighbouring vehicles");
    if (vehicle(c.front).layout().freeSlot(static_cast<std::size_t>(c.front_body)) < 0 ||
        vehicle(c.rear).layout().freeSlot(static_cast<std::size_t>(c.rear_body)) < 0)
      throw std::logic_error("TrainOde: a connection acts on car bodies or bogies");
  }
  longitudinal_offset_ = size_;
  if (longitudinal_.spec.on) {
    if (longitudinal_.traction.size() != parts_.size() ||
        longitudinal_.resistance.size() != parts_.size())
      throw std::logic_error("TrainOde: longitudinal motion needs every vehicle's forces");
    size_ += 2 * n;
  }
  motion_.resize(parts_.size());
  const bool at_wheelsets =
      longitudinal_.spec.on && longitudinal_.spec.traction_at == TractionPath::Wheelsets;
  for (int k = 0; k < n; ++k) {
    VehicleMotion& mo = motion_[static_cast<std::size_t>(k)];
    mo.mass =
        longitudinalMass(vehicle(k).model(), !(at_wheelsets && vehicle(k).layout().spinFree()));
    mo.body_mass = longitudinalMass(vehicle(k).model(), false);
  }
  states_.resize(connections_.size());
  kin_.resize(2 * connections_.size());
  loads_.resize(parts_.size());
  moments_.resize(parts_.size());
  drives_.resize(parts_.size());
  for (int k = 0; k < n; ++k) {
    const int body = slopeBody(vehicle(k).model());
    int slot = -1;
    for (std::size_t i = 0; i < connections_.size() && slot < 0; ++i) {
      const Connection& c = connections_[i];
      if (c.front == k && c.front_body == body) slot = static_cast<int>(2 * i);
      if (c.rear == k && c.rear_body == body) slot = static_cast<int>(2 * i + 1);
    }
    slope_body_.push_back(body);
    slope_kin_.push_back(slot);
  }
  if (at_wheelsets)
    for (int k = 0; k < n; ++k) {
      if (!longitudinal_.traction[static_cast<std::size_t>(k)].given()) continue;
      drives_[static_cast<std::size_t>(k)] = drivesOf(vehicle(k).model());
      for (const auto& d : drives_[static_cast<std::size_t>(k)])
        if (d[1] < 0 || !vehicle(k).layout().spinFree())
          throw std::logic_error(
              "TrainOde: traction at the wheelsets needs free wheelset spins and a body every "
              "wheelset hangs from");
    }
}

void TrainOde::initialLongitudinal(Eigen::VectorXd& y) const {
  if (!longitudinal()) return;
  for (int k = 0; k < vehicles(); ++k) {
    y[travelIndex(k)] = 0.0;
    y[speedIndex(k)] = vehicle(k).model().speedAt(0.0);
  }
}

int TrainOde::prepare(double t, const double* y) {
  const int n = vehicles();
  for (int k = 0; k < n; ++k) {
    VehicleMotion& mo = motion_[static_cast<std::size_t>(k)];
    const vehicle::VehicleModel& m = vehicle(k).model();
    if (longitudinal()) {
      mo.travel = y[travelIndex(k)];
      mo.speed = y[speedIndex(k)];
      if (!(mo.speed >= longitudinal_.spec.min_speed)) {
        std::ostringstream os;
        os << "vehicle '" << name(k) << "' slowed to " << mo.speed << " m/s at t = " << t
           << " s, below train.longitudinal.min_speed = " << longitudinal_.spec.min_speed
           << " m/s (the contact creepages are referred to the forward speed: a train is not "
              "simulated to a stand)";
        error_ = os.str();
        return 1;
      }
    } else {
      mo.travel = m.travel(t);
      mo.speed = m.speedAt(t);
      mo.acceleration = m.acceleration;
    }
    mo.connections = 0.0;
    loads_[static_cast<std::size_t>(k)].clear();
  }
  error_.clear();
  // The connections on the car bodies at their current motion.
  for (std::size_t i = 0; i < connections_.size(); ++i) {
    const Connection& c = connections_[i];
    vehicle::BodyKinematics* kin[2] = {&kin_[2 * i], &kin_[2 * i + 1]};
    const int veh[2] = {c.front, c.rear}, body[2] = {c.front_body, c.rear_body};
    for (int e = 0; e < 2; ++e) {
      // A vehicle between two connections on one body: its kinematics once (the rear end of the
      // connection before is this one's front end).
      if (e == 0 && i > 0 && connections_[i - 1].rear == c.front &&
          connections_[i - 1].rear_body == c.front_body) {
        *kin[0] = kin_[2 * i - 1];
        continue;
      }
      const vehicle::VehicleOde& ode = vehicle(veh[e]);
      const vehicle::VehicleModel& m = ode.model();
      const vehicle::VehicleLayout& l = ode.layout();
      const auto b = static_cast<std::size_t>(body[e]);
      const int slot = l.freeSlot(b);
      const double* yk = y + offset(veh[e]);
      vehicle::Vector6d q = vehicle::Vector6d::Zero(), qd = vehicle::Vector6d::Zero();
      q[vehicle::kS] = m.bodySAt(b, motion_[static_cast<std::size_t>(veh[e])].travel);
      qd[vehicle::kS] = motion_[static_cast<std::size_t>(veh[e])].speed;
      for (int cc = 0; cc < vehicle::kFreeBodyDof; ++cc) {
        q[1 + cc] = yk[l.position(slot, cc)];
        qd[1 + cc] = yk[l.rate(slot, cc)];
      }
      vehicle::bodyKinematics(m.geometry, m.bodies[b].rotation, m.bodies[b].height, q, qd, *kin[e]);
    }
    ConnectionState& st = states_[i];
    connectionForces(c.spec, *kin[0], c.front_body,
                     vehicle(c.front).model().bodies[static_cast<std::size_t>(c.front_body)].height,
                     *kin[1], c.rear_body,
                     vehicle(c.rear).model().bodies[static_cast<std::size_t>(c.rear_body)].height,
                     st);
    motion_[static_cast<std::size_t>(c.front)].connections += sForce(*kin[0], st.on_front);
    motion_[static_cast<std::size_t>(c.rear)].connections += sForce(*kin[1], st.on_rear);
    auto& lf = loads_[static_cast<std::size_t>(c.front)];
    auto& lr = loads_[static_cast<std::size_t>(c.rear)];
    lf.insert(lf.end(), st.on_front.begin(), st.on_front.end());
    lr.insert(lr.end(), st.on_rear.begin(), st.on_rear.end());
  }
  for (int k = 0; k < n; ++k) {
    VehicleMotion& mo = motion_[static_cast<std::size_t>(k)];
    if (longitudinal()) {
      const vehicle::VehicleModel& m = vehicle(k).model();
      const double gradient = slopeUnder(k, mo.travel);
      mo.traction =
          tractionForce(longitudinal_.traction[static_cast<std::size_t>(k)], t, mo.travel);
      mo.resistance =
          resistanceForce(longitudinal_.resistance[static_cast<std::size_t>(k)], mo.speed);
      // The slope's share of the weight along the track: gradient = tan(slope), uphill > 0.
      // (the bodies' weight: the rotating-mass allowance is inertia, not weight)
      mo.grade = mo.body_mass * m.gravity * gradient / std::sqrt(1.0 + gradient * gradient);
      // The nominal acceleration; with the traction at the wheelsets the state's is the contact
      // forces' (updateAccelerations), this one the vehicle's inertia terms use.
      mo.acceleration = (mo.traction - mo.resistance - mo.grade + mo.connections) / mo.mass;
      vehicle(k).setForwardMotion({mo.travel, mo.speed, mo.acceleration});
      auto& moments = moments_[static_cast<std::size_t>(k)];
      moments.clear();
      const auto& drives = drives_[static_cast<std::size_t>(k)];
      if (!drives.empty()) {
        const double torque = mo.traction * m.wheel_radius / static_cast<double>(drives.size());
        for (const auto& d : drives) {
          moments.push_back({d[0], d[0], torque});
          moments.push_back({d[1], d[0], -torque});
        }
      }
    }
    if (!connections_.empty() || !moments_[static_cast<std::size_t>(k)].empty())
      vehicle(k).setAppliedLoads(loads_[static_cast<std::size_t>(k)],
                                 moments_[static_cast<std::size_t>(k)]);
  }
  return 0;
}

double TrainOde::slopeUnder(int k, double travel) const {
  const int slot = slope_kin_[static_cast<std::size_t>(k)];
  if (slot >= 0) return kin_[static_cast<std::size_t>(slot)].tf.gradient;
  const vehicle::VehicleModel& m = vehicle(k).model();
  return m.geometry
      .at(m.bodySAt(static_cast<std::size_t>(slope_body_[static_cast<std::size_t>(k)]), travel))
      .gradient;
}

void TrainOde::updateAccelerations() {
  if (!longitudinal() || longitudinal_.spec.traction_at != TractionPath::Wheelsets) return;
  for (int k = 0; k < vehicles(); ++k) {
    VehicleMotion& mo = motion_[static_cast<std::size_t>(k)];
    mo.rail = vehicle(k).railForce();
    // A vehicle without traction has no torques: its effort is zero either way.
    mo.acceleration = (mo.rail - mo.resistance - mo.grade + mo.connections) / mo.mass;
  }
}

int TrainOde::rhs(double t, const double* y, double* ydot) {
  if (prepare(t, y) != 0) {
    failed_ = vehicles();  // the train's own failure
    return 1;
  }
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    const int rc = parts_[k].ode->rhs(t, y + offsets_[k], ydot + offsets_[k]);
    if (rc != 0) {
      failed_ = static_cast<int>(k);
      return rc;
    }
  }
  updateAccelerations();
  if (longitudinal())
    for (int k = 0; k < vehicles(); ++k) {
      ydot[travelIndex(k)] = y[speedIndex(k)];
      ydot[speedIndex(k)] = motion_[static_cast<std::size_t>(k)].acceleration;
    }
  failed_ = -1;
  return 0;
}

void TrainOde::addConnectionPattern(integ::JacobianPattern& out) const {
  for (const Connection& c : connections_) {
    // Columns: both car bodies' positions and rates (and the vehicles' travel and speed);
    // rows: both car bodies' rates, or with a longitudinal motion every row of both vehicles
    // (the connection forces enter their accelerations) and their speeds.
    std::vector<int> cols, rows;
    for (const auto& [k, b] : {std::pair{c.front, c.front_body}, std::pair{c.rear, c.rear_body}}) {
      const vehicle::VehicleLayout& l = vehicle(k).layout();
      const int slot = l.freeSlot(static_cast<std::size_t>(b));
      for (int cc = 0; cc < vehicle::kFreeBodyDof; ++cc) {
        cols.push_back(offset(k) + l.position(slot, cc));
        cols.push_back(offset(k) + l.rate(slot, cc));
        if (!longitudinal()) rows.push_back(offset(k) + l.rate(slot, cc));
      }
      if (longitudinal()) {
        cols.push_back(travelIndex(k));
        cols.push_back(speedIndex(k));
        for (int i = 0; i < vehicle(k).size(); ++i) rows.push_back(offset(k) + i);
        rows.push_back(speedIndex(k));
      }
    }
    for (const int j : cols) {
      auto& r = out.rows[static_cast<std::size_t>(j)];
      std::set<int> all(r.begin(), r.end());
      all.insert(rows.begin(), rows.end());
      r.assign(all.begin(), all.end());
    }
  }
}

void TrainOde::addLongitudinalPattern(integ::JacobianPattern& out) const {
  for (int k = 0; k < vehicles(); ++k) {
    // Every row of the vehicle depends on its travel (where on the track) and speed; its speed
    // row on both (traction by distance, slope, resistance).
    std::vector<int> rows;
    for (int i = 0; i < vehicle(k).size(); ++i) rows.push_back(offset(k) + i);
    rows.push_back(speedIndex(k));
    out.rows[static_cast<std::size_t>(travelIndex(k))] = rows;
    rows.insert(rows.end() - 1, travelIndex(k));  // the travel row is the speed itself
    out.rows[static_cast<std::size_t>(speedIndex(k))] = rows;
    out.copy_of[static_cast<std::size_t>(travelIndex(k))] = speedIndex(k);
    out.copy_of[static_cast<std::size_t>(speedIndex(k))] = -1;
  }
}

integ::JacobianPattern TrainOde::jacobianPattern() const {
  if (parts_.size() == 1 && connections_.empty() && !longitudinal())
    return parts_.front().ode->jacobianPattern();
  integ::JacobianPattern out;
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    const integ::JacobianPattern p = parts_[k].ode->jacobianPattern();
    const int o = offsets_[k];
    const int n = parts_[k].ode->size();
    // A part without structure is a dense block of its own: still no entries across vehicles.
    for (int j = 0; j < n; ++j) {
      std::vector<int> rows;
      if (p.empty()) {
        for (int i = 0; i < n; ++i) rows.push_back(o + i);
      } else {
        for (const int i : p.rows[static_cast<std::size_t>(j)]) rows.push_back(o + i);
      }
      out.rows.push_back(std::move(rows));
    }
    for (int i = 0; i < n; ++i) {
      const int c = p.copy_of.empty() ? -1 : p.copy_of[static_cast<std::size_t>(i)];
      out.copy_of.push_back(c < 0 ? -1 : o + c);
    }
  }
  out.rows.resize(static_cast<std::size_t>(size_));
  out.copy_of.resize(static_cast<std::size_t>(size_), -1);
  if (longitudinal()) addLongitudinalPattern(out);
  addConnectionPattern(out);
  return out;
}

std::vector<int> TrainOde::stiffComponents() const {
  std::vector<int> out;
  for (std::size_t k = 0; k < parts_.size(); ++k)
    for (const int i : parts_[k].ode->stiffComponents()) out.push_back(offsets_[k] + i);
  return out;
}

std::string TrainOde::componentName(int i) const {
  if (i >= longitudinal_offset_) {
    const auto k = static_cast<std::size_t>((i - longitudinal_offset_) / 2);
    const std::string what = (i - longitudinal_offset_) % 2 == 0 ? "travel" : "speed";
    return parts_[k].name.empty() ? what : parts_[k].name + "." + what;
  }
  std::size_t k = parts_.size() - 1;
  while (k > 0 && i < offsets_[k]) --k;
  const auto& p = parts_[k];
  const std::string local = p.ode->componentName(i - offsets_[k]);
  return p.name.empty() ? local : p.name + "." + local;
}

integ::ModelFailure TrainOde::lastFailure() const {
  if (failed_ < 0 || failed_ >= vehicles()) return {};
  const auto& p = parts_[static_cast<std::size_t>(failed_)];
  integ::ModelFailure f = p.ode->lastFailure();
  if (!p.name.empty() && !f.body.empty()) f.body = p.name + "." + f.body;
  return f;
}

std::string TrainOde::lastError() const {
  if (failed_ < 0) return {};
  if (failed_ >= vehicles()) return error_;
  const auto& p = parts_[static_cast<std::size_t>(failed_)];
  const std::string e = p.ode->lastError();
  return p.name.empty() || e.empty() ? e : p.name + ": " + e;
}

}  // namespace rb::train
