#pragma once
// The error of a run against a reference run, one rule for every analysis that compares runs
// (`workbench precision`, `workbench stress`, the work-precision table of a study):
//
// quantity q of a run against a reference is max and RMS of |run - reference| in q's display unit
// over the reference's output times inside the run's time range (a failed run: the part it ran),
// the run's series interpolated linearly onto them, over every series q covers. A non-finite
// value of either series inside that range (a diverged run) makes the error infinite: such a run
// is not accurate at any level.
#include <limits>
#include <string>
#include <vector>

namespace rb::io {
class ResultReader;
}

namespace rb::study {

// An error quantity: y, yaw of every wheelset (a guided vehicle: every other body), Q, Fy, Y, YQ of
// every wheel, BODY.y|z|roll|pitch|yaw of one body.
struct Quantity {
  std::string tag;      // as the user wrote it
  std::string group;    // "wheelsets", "wheels" or "body"
  std::string dataset;  // body coordinate, or the contact dataset of a wheel
  double scale = 1.0;   // SI -> display unit
  std::string unit;     // display unit
  std::string body;     // group "body": its name
};

// Parses quantity tags (precision's --quantities); InputError naming --quantities for an unknown
// one, a body the vehicle does not have (`bodies`), or a wheel quantity on a vehicle without
// wheel/rail contact.
std::vector<Quantity> parseQuantities(const std::vector<std::string>& tags,
                                      const std::vector<std::string>& bodies, bool contact);

inline constexpr double kInf = std::numeric_limits<double>::infinity();

struct Error {
  bool have = false;  // the quantity is in both files and their times overlap
  double max = kInf;  // [display unit]
  double rms = kInf;
};

// The error rule above. have = false when either file lacks the quantity or the times.
Error runError(const io::ResultReader& run, const io::ResultReader& ref, const Quantity& q);

// The same for two result files; have = false when either is missing or unreadable.
Error fileError(const std::string& run, const std::string& ref, const Quantity& q);

}  // namespace rb::study
