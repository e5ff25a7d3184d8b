// The elastic contact method's evaluations (contact_elastic.hpp), one per creep law of the
// registry, in a translation unit of their own (contact_evaluate.hpp says why).
#include "workbench/dynamics/contact_elastic.hpp"
#include "workbench/dynamics/contact_evaluate.hpp"
#include "workbench/dynamics/creep_laws.hpp"

namespace rb::dynamics {

namespace internal {

double wheelLiftOf(const ContactModel& c, const WheelsetWork& ww, const vehicle::Vector6d& q,
                   int side) {
  return wheelLift(c, q, ww.height, railOffset(ww.irr, side), contact::kSideSign[side]);
}

}  // namespace internal

ContactVehicleOde::EvalFn ContactVehicleOde::elasticEvaluation(CreepModel creep) {
  EvalFn out = nullptr;
  const auto choose = [&]<class... Laws>(LawList<Laws...>) {
    const auto pick = [&]<class Law>() {
      out = &ContactVehicleOde::evaluateT<ContactMethod::Elastic, Law>;
      return true;
    };
    return ((creep == Laws::kModel && pick.template operator()<Laws>()) || ...);
  };
  if (!choose(CreepLaws{})) return nullptr;
  return out;
}

}  // namespace rb::dynamics
