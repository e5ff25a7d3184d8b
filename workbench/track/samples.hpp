#pragma once
// Plain arrays describing a compiled track, for the output file (/track) and plots. SI units;
// angles in rad; sign conventions of geometry.hpp (positive curvature and signed cant = left).
#include <limits>
#include <vector>

#include "workbench/track/track.hpp"

namespace rb::track {

struct TrackSamples {
  double length = 0.0;  // [m] of the whole track, also when the samples cover a stretch of it

  // Centreline at the preprocessor knots (spline values, i.e. what the simulation uses).
  std::vector<double> s, x, y, z;                  // [m]
  std::vector<double> heading, slope, cant_angle;  // [rad] psi, theta, phi
  std::vector<double> curvature;                   // [1/m] dpsi/ds, positive left
  std::vector<double> cant;                        // [m] signed cant height, positive banked left

  // Segments as specified.
  std::vector<double> seg_start, seg_length;  // [m]
  std::vector<int> seg_kind;                  // 0 tangent, 1 transition, 2 curve
  std::vector<double> seg_radius;             // [m] (0: straight)
  std::vector<int> seg_side;                  // +1 left, -1 right
  std::vector<double> seg_cant;               // [m] spec cant (unsigned, at the segment end)

  // Irregularities at their knots (empty when the model has none).
  std::vector<double> irr_s;                                    // [m]
  std::vector<double> alignment, vertical, gauge, cross_level;  // [m]
  std::vector<double> left_y, left_z, right_y, right_z;         // [m]
  std::vector<double> delta;                                    // [rad]

  // One-sided target PSD (targetPsd()) on a log grid over the synthesis band (Psd source only).
  std::vector<double> psd_omega;                                                // [rad/m]
  std::vector<double> psd_alignment, psd_vertical, psd_gauge, psd_cross_level;  // [m^2/(rad/m)]
  bool psd_verified = true;  // false for spectra with an UNVERIFIED parameter table
};

inline constexpr int kPsdSamplePoints = 200;

// The whole track, or the stretch [s_from, s_to] of it (a run writes the stretch its vehicle
// covers): the centreline knots and irregularity samples inside it and the nearest one outside
// on either side, so interpolating the written samples covers the stretch. Segments and the
// target PSD are written whole.
TrackSamples sampleTrack(const TrackModel& model,
                         double s_from = -std::numeric_limits<double>::infinity(),
                         double s_to = std::numeric_limits<double>::infinity());

}  // namespace rb::track
