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
// d = 0: guided wheelsets, which follow the track kinematically (no state); d = 3: wheelsets on
// wheel/rail contact with a free spin (y, theta, psi); d = 2: with a prescribed spin (y, psi).
// wsPosition(w, c) / wsRate(w, c) take c = 0 y, 1 theta, 2 psi in every case and return -1 for a
// coordinate that is not a state.
#include <string>
#include <vector>

#include "workbench/vehicle/kinematics.hpp"
#include "workbench/vehicle/model.hpp"

namespace rb::vehicle {

// Independent coordinates per wheelset (VehicleLayout::ws_dof).
inline constexpr int kGuidedWheelsetDof = 0;    // guided: no wheelset state
inline constexpr int kPrescribedSpinDof = 2;    // contact, prescribed spin: y, psi
inline constexpr int kFreeSpinDof = 3;          // contact, free spin: y, theta, psi
inline constexpr int kFreeBodyDof = 5;          // car bodies and bogies: y, z, phi, theta, psi
inline constexpr int kWheelsetCoordinates = 3;  // wheelset coordinate c: 0 y, 1 theta, 2 psi
inline constexpr Coord kWheelsetCoord[3] = {kY, kPitch, kYaw};  // wheelset c -> body coordinate

struct VehicleLayout {
  std::vector<int> free_bodies;  // car bodies and bogies, body order
  std::vector<int> wheelsets;    // wheelsets, body order
  std::vector<int> slot;         // per body: free-body number, wheelset number, or -1 (frame)
  int n_free = 0, n_ws = 0, n_series = 0, size = 0;
  int ws_dof = kGuidedWheelsetDof;

  bool spinFree() const { return ws_dof == kFreeSpinDof; }
  // Slot of wheelset coordinate c (0 y, 1 theta, 2 psi) among the wheelset's states; -1 if c is
  // not a state (the prescribed spin; every coordinate of a guided wheelset).
  int wsSlot(int c) const {
    if (ws_dof == kFreeSpinDof) return c;
    if (ws_dof == kPrescribedSpinDof) return c == 0 ? 0 : (c == 2 ? 1 : -1);
    return -1;
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
