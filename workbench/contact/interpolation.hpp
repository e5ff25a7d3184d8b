#pragma once
// How the contact tables are interpolated between their stored nodes (KEC: one entry, the knife
// position s_k; LUT: two, the wheelset lateral displacement y and the gauge variation xi_g).
// The name table is the scenario keyword of contact.table_interpolation and the text recorded in
// result files (core/names.hpp).
#include <array>

#include "workbench/core/names.hpp"

namespace rb::contact {

// Cubic: cubic Hermite (KEC) / bicubic Hermite (LUT) with node derivatives from splines (C1; the
// KEC equivalent profile f is a C2 not-a-knot spline). Linear: the paper's "linear interpolation
// between the stored data" (Yu et al., section 5.5): straight segments in s_k (KEC), bilinear
// cells in (y, xi_g) (LUT); C0, derivatives are the slopes of the segment or cell, constant
// between nodes and discontinuous at them, second derivatives zero (the bilinear cross term
// d2/dy dxi_g excepted).
enum class TableInterpolation { Cubic, Linear };

inline constexpr std::array<NameEntry<TableInterpolation>, 2> kTableInterpolationNames = {{
    {TableInterpolation::Cubic, "cubic",
     "cubic Hermite (KEC) / bicubic Hermite (LUT) between the stored nodes, C1"},
    {TableInterpolation::Linear, "linear",
     "linear (KEC) / bilinear (LUT) between the stored nodes, the paper's (section 5.5): kinks at "
     "the nodes, derivative channels piecewise constant"},
}};
constexpr const auto& nameTable(TableInterpolation /*tag*/) {
  return kTableInterpolationNames;
}

}  // namespace rb::contact
