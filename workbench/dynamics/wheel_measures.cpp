#include "workbench/dynamics/wheel_measures.hpp"

#include <cmath>
#include <filesystem>

#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/profiles/dimensions.hpp"
#include "workbench/profiles/positioning.hpp"
#include "workbench/profiles/profile_io.hpp"

namespace rb::dynamics {
namespace {

bool builtin(const std::string& source) {
  return source.empty() || source == "s1002";
}

}  // namespace

std::array<WheelMeasures, 2> wheelMeasures(const ContactModel& m) {
  std::array<WheelMeasures, 2> out;
  const profiles::Profile* wheels[2] = {m.geometry.left_wheel.get(), m.geometry.right_wheel.get()};
  for (std::size_t side = 0; side < 2; ++side) {
    WheelMeasures& w = out[side];
    // Sd from the flange back 70 mm from the tape circle: the frame every wheel is drawn in
    // (S1002, and the wheel files as read: profile_io.hpp).
    if (wheels[side] != nullptr) {
      if (const auto d =
              profiles::measureWheel(*wheels[side], profiles::kS1002FlangeBackDistance)) {
        w.sd = d->flangeThickness;
        w.sh = d->flangeHeight;
        w.qr = d->qR;
      }
    }
    const std::string& source = m.wheel_sources[side];
    if (builtin(source) || profiles::profileFormat(source) != profiles::ProfileFormat::Miniprof)
      continue;
    // The header is read again (a few lines; the profile was read from the same file without
    // error when the model was compiled).
    profiles::ProfileFileInfo info;
    try {
      (void)profiles::readMiniprofPoints(source, profiles::ProfileKind::Wheel, &info);
    } catch (const InputError&) {
      continue;  // changed since: the note then has no header values
    }
    if (info.hasHeaderDimensions) {
      w.header_sd = info.headerSd;
      w.header_sh = info.headerSh;
      w.header_qr = info.headerQr;
      w.header_line = info.headerDimensionsLine;
    }
  }
  return out;
}

std::vector<std::string> wheelMeasureNotes(const ContactModel& m) {
  std::vector<std::string> notes;
  const std::array<WheelMeasures, 2> ms = wheelMeasures(m);
  const auto mm = [](double v) {
    return std::isnan(v) ? std::string("-") : formatNumber(v * 1e3, 4);
  };
  for (std::size_t side = 0; side < 2; ++side) {
    const std::string& source = m.wheel_sources[side];
    if (builtin(source) || (side == 1 && source == m.wheel_sources[0])) continue;
    const WheelMeasures& w = ms[side];
    std::string note = "profiles: wheel '" + std::filesystem::path(source).filename().string() +
                       "': EN 15313 Sd " + mm(w.sd) + " mm, Sh " + mm(w.sh) + " mm, qR " +
                       mm(w.qr) + " mm";
    if (!std::isnan(w.header_sd))
      note += " (its header, line " + std::to_string(w.header_line) + ": Sd " + mm(w.header_sd) +
              ", Sh " + mm(w.header_sh) + ", qR " + mm(w.header_qr) + " mm)";
    notes.push_back(std::move(note));
  }
  return notes;
}

}  // namespace rb::dynamics
