#pragma once
// Names of the track's enums (scenario keywords of track{}, psd{} and measured{}, HDF5
// attributes), one table per enum of track/spec.hpp and track/psd.hpp (core/names.hpp).
#include <array>

#include "workbench/core/names.hpp"
#include "workbench/track/psd.hpp"
#include "workbench/track/spec.hpp"

namespace rb::track {

// Segment constructors (paper section 5.2); the schema holds each one's keys.
inline constexpr std::array<NameEntry<SegmentKind>, 3> kSegmentKindNames = {{
    {SegmentKind::Tangent, "tangent", "straight segment"},
    {SegmentKind::Transition, "transition", "clothoid"},
    {SegmentKind::Curve, "curve", "circular curve"},
}};
constexpr const auto& nameTable(SegmentKind /*tag*/) {
  return kSegmentKindNames;
}

inline constexpr std::array<NameEntry<Side>, 2> kSideNames = {{
    {Side::Left, "left", "curvature centre on the +Y side"},
    {Side::Right, "right", "curvature centre on the -Y side"},
}};
constexpr const auto& nameTable(Side /*tag*/) {
  return kSideNames;
}

inline constexpr std::array<NameEntry<CsvUnit>, 2> kCsvUnitNames = {{
    {CsvUnit::Metre, "m", ""},
    {CsvUnit::Millimetre, "mm", ""},
}};
constexpr const auto& nameTable(CsvUnit /*tag*/) {
  return kCsvUnitNames;
}

inline constexpr std::array<NameEntry<Beyond>, 2> kBeyondNames = {{
    {Beyond::Error, "error", "check fails"},
    {Beyond::Zero, "zero", "perfect track there, with a warning"},
}};
constexpr const auto& nameTable(Beyond /*tag*/) {
  return kBeyondNames;
}

// The four irregularity channels of paper Fig. 3, in Channel order.
inline constexpr std::array<NameEntry<Channel>, 4> kChannelNames = {{
    {Channel::Alignment, "alignment", "lateral displacement of the centreline"},
    {Channel::Vertical, "vertical", "vertical displacement of the centreline"},
    {Channel::Gauge, "gauge", "deviation of the gauge from its nominal value"},
    {Channel::CrossLevel, "cross_level", "height difference z_l - z_r of the two rails"},
}};
constexpr const auto& nameTable(Channel /*tag*/) {
  return kChannelNames;
}

inline constexpr std::array<NameEntry<Spectrum>, 9> kSpectrumNames = {{
    {Spectrum::OreB176Low, "ore_b176_low", ""},
    {Spectrum::OreB176High, "ore_b176_high", ""},
    {Spectrum::FraClass1, "fra_class_1", ""},
    {Spectrum::FraClass2, "fra_class_2", ""},
    {Spectrum::FraClass3, "fra_class_3", ""},
    {Spectrum::FraClass4, "fra_class_4", ""},
    {Spectrum::FraClass5, "fra_class_5", ""},
    {Spectrum::FraClass6, "fra_class_6", ""},
    {Spectrum::User, "user", ""},
}};
constexpr const auto& nameTable(Spectrum /*tag*/) {
  return kSpectrumNames;
}

}  // namespace rb::track
