#pragma once
// The output stage of one vehicle of a run: the plan of its channels (body coordinates and
// accelerations, suspension elements, wheels and patches), built once before the run from the
// channel rows (channels.hpp), and its values at an output time from one evaluation of the model
// (StateOutputs). The paths of the only vehicle of a run are the file's /bodies, /elements and
// /contact; in a run of several, each vehicle's are under /vehicles/<name>.
#include <array>
#include <span>
#include <string>
#include <vector>

#include "workbench/dynamics/contact_ode.hpp"
#include "workbench/io/result_file.hpp"
#include "workbench/run/band_oscillation.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/run/simulate.hpp"
#include "workbench/run/state_outputs.hpp"
#include "workbench/vehicle/vehicle_ode.hpp"

namespace rb::run {

// Largest creepage of any active patch at the output times, and when.
struct CreepageMaximum {
  double value = 0.0, t = 0.0;
  void update(const dynamics::WheelOutput& w, double t_now);
};

// The answers of a run on several rails per side (profiles.extra_rails), per wheel of such a side:
// where its load first moves from the running rail onto a further rail (the track position s,
// linear between output samples, where the further rail's normal force first exceeds the running
// rail's: stock rail to blade, wing rail to nose) and the largest normal force on each rail, with
// its s (the impact at a nose). Updated at every output time.
struct RailAnswers {
  static constexpr std::size_t kRails = 1 + dynamics::kMaxExtraRails;
  struct Wheel {
    std::size_t wheelset = 0, side = 0;  // index into ContactModel::wheelsets; 0 left, 1 right
    // transfer_s: where the rail first carried more than the running rail (a check rail: where
    // it first touched the wheel).
    std::array<double, kRails> transfer_s{}, peak{}, peak_s{};
    // The running rail's minus this rail's force at the last sample (NaN before the first).
    std::array<double, kRails> last_diff{};
    double last_s = 0.0;
  };
  std::vector<Wheel> wheels;
  // [side][rail]: a check rail (ElasticContactModel::extra_check, the running rail first): its
  // transfer_s is where it first touches the wheel, not where it outcarries the running rail.
  std::array<std::array<bool, kRails>, 2> check{};
  void update(const std::vector<dynamics::WheelOutput>& w, const std::vector<double>& s,
              const std::array<std::size_t, 2>& rails);
};

class VehicleOutputs {
 public:
  // ode: the vehicle's own ODE (its part of the run's), on wheel/rail contact when v has a
  // contact model. All three must outlive this object.
  VehicleOutputs(const Model& m, const RunVehicle& v, vehicle::VehicleOde& ode);

  // Appends the vehicle's channels to `outputs` in the order sample() fills them, and writes the
  // attributes of its groups (body kinds and names, the contact conventions and method).
  void declare(io::ResultFile& f, std::vector<OutputChannel>& outputs) const;
  // The values of every channel at (t, y), y the vehicle's part of the run's state, from `out`;
  // returns the next slot.
  double* sample(double t, const double* y, double* out);

  StateOutputs& state() { return state_; }
  dynamics::ContactVehicleOde* contact() const { return contact_; }
  const CreepageMaximum& creepage() const { return creepage_; }
  // After the run: the rail answers as attributes of each such wheel's rails group
  // (transfer_s_<rail>, peak_normal_force_<rail>, peak_normal_force_s_<rail>; none for a
  // transfer that did not happen) and one summary line per wheel into `lines`.
  void writeRailAnswers(io::ResultFile& f, std::vector<std::string>& lines) const;
  // After the run: a warning per wheel whose band oscillated by itself (band_oscillation.hpp;
  // methods with ContactMethodInfo::band_monitor only).
  void bandOscillationWarnings(std::vector<std::string>& warnings) const;

 private:
  const Model& m_;
  const RunVehicle& v_;
  vehicle::VehicleOde& ode_;
  dynamics::ContactVehicleOde* contact_;  // null: guided
  StateOutputs state_;
  CreepageMaximum creepage_;
  std::vector<vehicle::Vector6d> q_;
  std::vector<Eigen::Vector3d> a_;
  std::vector<vehicle::ElementValue> values_;
  // Rails written per wheel of each side (profiles.extra_rails; 0: the running rail alone).
  std::array<std::size_t, 2> rails_{};
  bool track_ = false;  // the track under the rail: its channels per wheel
  RailAnswers answers_;
  std::vector<double> ws_s_;                  // s of each wheelset at the output time
  std::vector<BandOscillationMonitor> band_;  // per wheel; empty: not watched
};

}  // namespace rb::run
