#pragma once
// Track irregularity power spectral densities (reference:
// shared/reference/track_irregularity_psd.md).
//
// Convention: every PSD here is ONE-SIDED, G(Omega) over Omega > 0, Omega = 2 pi / lambda [rad/m],
// in m^2/(rad/m), so that the variance is integral_0^inf G dOmega. For every channel, including
// cross level, the quantity is a length in metres: cross level is the height difference
// xi_c = z_l - z_r (paper, before Eq. 4). A PSD per cycle/m follows as G_f(f) = 2 pi G(2 pi f).
#include <optional>
#include <string>
#include <string_view>

#include "workbench/track/spec.hpp"

namespace rb::track {

enum class Spectrum {
  OreB176Low,
  OreB176High,
  FraClass1,
  FraClass2,
  FraClass3,
  FraClass4,
  FraClass5,
  FraClass6,
  User
};

// "ore_b176_low", "ore_b176_high", "fra_class_1".."fra_class_6", "user"; nullopt if unknown.
std::optional<Spectrum> parseSpectrum(std::string_view name);
std::string spectrumName(Spectrum s);
// All valid names, comma separated (for error messages).
std::string spectrumNames();

// Whether the parameter table of a named spectrum was verified against independent sources.
// ORE B176: verified. FRA classes 1-6: UNVERIFIED (parameter table from recollection of the
// literature; the app should print a warning). "user": true (the data is the user's). Unknown
// names: false.
bool psdVerified(Spectrum s);
bool psdVerified(const std::string& spectrum);

// One-sided G(Omega) [m^2/(rad/m)] of a named spectrum (not User) for one channel, Omega > 0.
double spectrumPsd(Spectrum s, Channel c, double omega);

// Tabulated PSD, log-log interpolation between points (linear in log Omega where an end value is
// zero), zero outside [omega.front(), omega.back()] and for an empty table.
double psdTableValue(const PsdTable& t, double omega);

// The one-sided target the synthesis of `spec` realises: scale^2 G(Omega) inside the band
// [2 pi / wavelength_max, 2 pi / wavelength_min] for enabled channels, 0 elsewhere and for sources
// other than Psd. The spectrum name must be valid (internal check).
double targetPsd(const IrregularitySpec& spec, Channel c, double omega);

}  // namespace rb::track
