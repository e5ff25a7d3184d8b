#pragma once
// The EN 15313 flange measures (flange height Sh, flange thickness Sd, qR) of a contact model's
// wheels, and those a MiniProf wheel file's header states, for check and run to print and for
// the result file (/contact/<ws> attributes; docs/profiles.md).
#include <array>
#include <limits>
#include <string>
#include <vector>

#include "workbench/dynamics/contact_model.hpp"

namespace rb::dynamics {

struct WheelMeasures {
  // [m] measured on the wheel's profile (profiles::measureWheel); NaN: no measurable flange
  double sd = std::numeric_limits<double>::quiet_NaN();
  double sh = std::numeric_limits<double>::quiet_NaN();
  double qr = std::numeric_limits<double>::quiet_NaN();
  // [m] the file's header (MiniProf); NaN: the file states none
  double header_sd = std::numeric_limits<double>::quiet_NaN();
  double header_sh = std::numeric_limits<double>::quiet_NaN();
  double header_qr = std::numeric_limits<double>::quiet_NaN();
  int header_line = 0;  // the header line that states them
};

// Left (0) and right (1) wheel of the model's pair.
std::array<WheelMeasures, 2> wheelMeasures(const ContactModel& m);

// One line per wheel file of the model (built-in profiles have none): its name and measures,
// with the header's where the file states them.
std::vector<std::string> wheelMeasureNotes(const ContactModel& m);

}  // namespace rb::dynamics
