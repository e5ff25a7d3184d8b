#pragma once
// Named parameters before anything runs: a study's --set paths tried on its base scenarios, and
// the listing of a vehicle's named parameters (`workbench help vehicle SCENARIO.lua`).
#include <string>
#include <vector>

#include "workbench/scenario/node.hpp"
#include "workbench/scenario/study.hpp"

namespace rb::scenario {

// Tries every distinct override path of the study's cases on the tree of its base scenario (each
// base scenario's script is run once; one that does not load is left to its runs to report) and
// throws InputError listing each path that names nothing: an unknown block, body, element or
// group, or a group member without the key. Each is reported at the line of the study file where
// the key is written (studyText: that file's text), with the nearest existing name.
void checkStudyOverrides(const StudySpec& study, const std::string& studyText,
                         const std::string& root);

// A --set path as a figure axis reads it: a label in words and the SI unit of the key, from the
// schema (the key's unit; an element's or a group's key by the kind of its members on the tree of
// the base scenario): vehicle.groups.primary_longitudinal.stiffness -> "primary longitudinal
// stiffness", "N/m"; vehicle.speed -> "vehicle speed", "m/s". A path that does not resolve keeps
// its own text as label and an empty unit ("-" for a dimensionless key).
struct ParameterLabel {
  std::string key, label, unit;
};
ParameterLabel parameterLabel(const Node& tree, const std::string& path);

// parameterLabel of every distinct override path of the study's cases, each on the tree of its
// base scenario (run once per base; a base that does not load leaves its paths unresolved).
std::vector<ParameterLabel> studyParameterLabels(const StudySpec& study);

// The named parameters of the vehicle of a scenario: its bodies, its elements with their kind
// and keys, its groups with their members and the keys every member has. Throws InputError
// when the scenario has no vehicle{} block or its vehicle block is invalid.
std::string vehicleParametersText(const std::string& scenarioPath, const std::string& root);

}  // namespace rb::scenario
