#pragma once
// /track in the result file (architecture.md, "Output layout"): centreline, segments and, when the
// scene has them, irregularities and their target PSD.
#include "workbench/io/result_file.hpp"
#include "workbench/track/samples.hpp"
#include "workbench/track/spec.hpp"

namespace rb::io {

void writeTrack(ResultFile& f, const track::TrackSpec& spec, const track::TrackSamples& t);

}  // namespace rb::io
