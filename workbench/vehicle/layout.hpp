#pragma once
// Where the states of a vehicle ODE live: one layout for the guided vehicle (GuidedVehicleOde)
// and the vehicle on wheel/rail contact (dynamics::ContactVehicleOde).
//
// State layout (nf free bodies = car bodies and bogies in body order, nw wheelsets in body order,
// ns series dampers, d = ws_dof independent coordinates per wheelset; size 10 nf + 2 d nw + ns):
//   [5k + c]                  position c (0..4: y, z, phi, theta, psi) of free body k  "car.y"
//   [5 nf + d w + j]          wheelset w: j = 0 y, 1 theta (spin, free only), 2 (or 1) psi
//                                                                         "ws1.y", "ws1.theta"
//   [5 nf + d nw + 5k + c]    rate of free body coordinate                              "car.y_dot"
//   [10 nf + d nw + d w + j]  wheelset rate                                        "ws1.theta_dot"
//   [10 nf + 2 d nw + e]      Maxwell force of series damper e (Appendix A)         "series[3].f"
//   [10 nf + 2 d nw + ns + 4 w + 2 side + c], then the same + 4 nw: rail mass displacement (c = 0
//                             lateral, 1 vertical) under wheel side of wheelset w, and its rate
//                             (contact.elastic.rail_support only)                 "ws1.rail_left.z"
// d = 0: guided wheelsets, which follow the track kinematically (no state); d = 3: wheelsets on
// constraint contact (KEC, LUT: z and roll are dependent) with a free spin (y, theta, psi); d = 2:
// with a prescribed spin (y, psi); d = 5: wheelsets on elastic contact, every coordinate but s a
// state (y, theta, psi, z, phi); d = 4: elastic with a prescribed spin (y, psi, z, phi).
// wsPosition(w, c) / wsRate(w, c) take c = 0 y, 1 theta, 2 psi, 3 z, 4 phi in every case and
// return -1 for a coordinate that is not a state.
#include <string>
#include <vector>

#include "workbench/vehicle/kinematics.hpp"
#include "workbench/vehicle/model.hpp"

namespace rb::vehicle {

// Independent coordinates per wheelset (VehicleLayout::ws_dof).
inline constexpr int kGuidedWheelsetDof = 0;         // guided: no wheelset state
inline constexpr int kPrescribedSpinDof = 2;         // contact, prescribed spin: y, psi
inline constexpr int kFreeSpinDof = 3;               // contact, free spin: y, theta, psi
inline constexpr int kElasticPrescribedSpinDof = 4;  // elastic, prescribed spin: y, psi, z, phi
inline constexpr int kElasticFreeSpinDof = 5;        // elastic, free spin: y, theta, psi, z, phi
inline constexpr int kFreeBodyDof = 5;               // car bodies and bogies: y, z, phi, theta, psi
// Wheelset coordinate c: 0 y, 1 theta, 2 psi, 3 z, 4 phi (z and phi are states on elastic
// contact only).
inline constexpr int kWheelsetCoordinates = 5;
inline constexpr Coord kWheelsetCoord[5] = {kY, kPitch, kYaw, kZ, kRoll};  // c -> body coordinate

struct VehicleLayout {
  std::vector<int> free_bodies;  // car bodies and bogies, body order
  std::vector<int> wheelsets;    // wheelsets, body order
  std::vector<int> slot;         // per body: free-body number, wheelset number, or -1 (frame)
  int n_free = 0, n_ws = 0, n_series = 0, size = 0;
  int ws_dof = kGuidedWheelsetDof;

  bool spinFree() const { return ws_dof == kFreeSpinDof || ws_dof == kElasticFreeSpinDof; }
  // Wheelset height and roll are states (elastic contact), not constraint outputs.
  bool wheelsetVertical() const { return ws_dof >= kElasticPrescribedSpinDof; }
  // Slot of wheelset coordinate c (0 y, 1 theta, 2 psi, 3 z, 4 phi) among the wheelset's states;
  // -1 if c is not a state (the prescribed spin; z and phi on constraint contact; every
  // coordinate of a guided wheelset).
  int wsSlot(int c) const {
    switch (ws_dof) {
      case kElasticFreeSpinDof:
        return c;
      case kElasticPrescribedSpinDof:
        return c == 1 ? -1 : (c == 0 ? 0 : c - 1);
      case kFreeSpinDof:
        return c < 3 ? c : -1;
      case kPrescribedSpinDof:
        return c == 0 ? 0 : (c == 2 ? 1 : -1);
      default:
        return -1;
    }
  }
  int position(int k, int c) const { return 5 * k + c; }  // c = 0..4: y, z, phi, theta, psi
  int wsPosition(int w, int c) const {
    const int j = wsSlot(c);
    return j < 0 ? -1 : 5 * n_free + ws_dof * w + j;
  }
  int rate(int k, int c) const { return 5 * n_free + ws_dof * n_ws + 5 * k + c; }
  int wsRate(int w, int c) const {
    const int j = wsSlot(c);
    return j < 0 ? -1 : 10 * n_free + ws_dof * n_ws + ws_dof * w + j;
  }
  int series(int e) const { return 10 * n_free + 2 * ws_dof * n_ws + e; }
  // The track under the rail (elastic contact with contact.elastic.rail_support): per wheelset w
  // and side (0 left, 1 right) a rail mass's lateral (c = 0) and vertical (c = 1) displacement,
  // after the series forces, then their rates; rail_masses = 0 without it.
  int rail_masses = 0;  // wheelsets with rail masses (0 or n_ws)
  int railPosition(int w, int side, int c) const {
    return 10 * n_free + 2 * ws_dof * n_ws + n_series + 4 * w + 2 * side + c;
  }
  int railRate(int w, int side, int c) const { return railPosition(w, side, c) + 4 * rail_masses; }
  // The rate state of a position state (body, wheelset or rail mass).
  int rateOf(int position_state) const {
    return position_state < positions() ? position_state + positions()
                                        : position_state + 4 * rail_masses;
  }
  // Number of position states (the rates follow them).
  int positions() const { return 5 * n_free + ws_dof * n_ws; }

  // Body index of free body k / wheelset w.
  std::size_t freeBody(int k) const { return static_cast<std::size_t>(free_bodies[at(k)]); }
  std::size_t wheelset(int w) const { return static_cast<std::size_t>(wheelsets[at(w)]); }
  // Free-body number of body b, or -1 if it is not a car body or bogie.
  int freeSlot(std::size_t b) const {
    const int k = slot[b];
    return k >= 0 && k < n_free && freeBody(k) == b ? k : -1;
  }
  // Wheelset number of body b, or -1 if it is not a wheelset.
  int wheelsetSlot(std::size_t b) const {
    const int w = slot[b];
    return w >= 0 && w < n_ws && wheelset(w) == b ? w : -1;
  }

  // State index of coordinate c of body b (or of its rate); -1 if not a state (prescribed or
  // dependent: s of every body, z and phi of wheelsets on contact, all of a guided wheelset or a
  // frame).
  int index(int body, Coord c, bool rate = false) const;
  // "car.y", "ws1.theta_dot", "series[3].f"; "y[i]" outside the state.
  std::string componentName(int i, const VehicleModel& model) const;
  int indexOf(const std::string& component, const VehicleModel& model) const;  // -1 if none

 private:
  static std::size_t at(int i) { return static_cast<std::size_t>(i); }
};

// The layout of a vehicle with ws_dof states per wheelset (kGuidedWheelsetDof, kPrescribedSpinDof
// or kFreeSpinDof).
VehicleLayout vehicleLayout(const VehicleModel& model, int ws_dof);

}  // namespace rb::vehicle
