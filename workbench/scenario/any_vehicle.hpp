#pragma once
// Whether any vehicle of a scenario has a property of its profiles{} or contact{}: the scenario's
// own blocks, or those a train's vehicle gives itself (scenario.hpp, TrainVehicleSpec).
#include <algorithm>

#include "workbench/scenario/scenario.hpp"

namespace rb::scenario {

template <class Pred>
bool anyProfiles(const ScenarioSpec& s, Pred pred) {
  return pred(s.profiles) || std::any_of(s.train.begin(), s.train.end(), [&](const auto& v) {
           return v.has_profiles && pred(v.profiles);
         });
}

template <class Pred>
bool anyContact(const ScenarioSpec& s, Pred pred) {
  return pred(s.contact) || std::any_of(s.train.begin(), s.train.end(), [&](const auto& v) {
           return v.has_contact && pred(v.contact);
         });
}

}  // namespace rb::scenario
