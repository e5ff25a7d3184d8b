#pragma once
// Reading CONTACT's rail slices-files (.slcs; E.A.H. Vollebregt, CONTACT user guide, "Rail
// slices-file"): a rail that changes along the track as a list of profile files at positions u.
//
// Format: `%` starts a comment (whole line or trailing); blank lines are skipped. The data lines,
// in order, each with its values first and any description after them:
//   U_OFFSET U_SCALE           u_fc [mm] = U_SCALE * (U_OFFSET + U_SLC)
//   NSLC                       the number of slices, 1 .. kMaxSlices
//   NFEAT NKINK NACCEL         features and kinks of the 3-D surface building
//   U_INTPOL [PERTURB]         1 interpolating spline, 2 approximation; PERTURB 0 (no surface
//                              perturbations; others are refused)
//   NSLC x: U_SLC 'file'       the slices, u strictly increasing by at least 0.001 mm (u_fc)
// and then kink, acceleration and feature lines, which are not read: railbench blends its slices
// linearly at a fixed lateral coordinate (contact/sliced_rail.hpp), whatever the features say.
// The file names are relative to the slices-file's folder; they are returned as written.
//
// Errors: rb::InputError with "file:line: message" at the offending line. The file is read by
// rb::readRegularFile with a bound of 4 MiB.
#include <cstddef>
#include <string>
#include <vector>

namespace rb::profiles {

struct SliceListEntry {
  double u_fc = 0.0;  // [m] position along the track curve, U_SCALE * (U_OFFSET + U_SLC) / 1000
  std::string file;   // as written in the slices-file
  int line = 0;
};

struct SliceList {
  std::string path;
  int features = 0, kinks = 0, accelerations = 0;  // NFEAT, NKINK, NACCEL (not used)
  int interpolation = 1;                           // U_INTPOL (not used: the blend is linear)
  std::vector<SliceListEntry> slices;
};

inline constexpr std::size_t kMaxSlices = 2000;

SliceList readSliceList(const std::string& path);

}  // namespace rb::profiles
