#pragma once
// The one registry of creep laws (tangential force laws of a contact patch, paper section 2.5):
// per law its CreepModel value, its scenario / HDF5 name, its one-line help and the function of one
// patch it evaluates. From the list CreepLaws below come the name table of dynamics/names.hpp (the
// schema's choices and help, the reader, the writers) and the instantiations of
// ContactVehicleOde::evaluateT for every contact method (contact_ode.cpp): the law is chosen once
// per model, and each evaluation runs its law's code with no branch on the law (creep "none"
// compiles the creep code out).
//
// Adding a creep law (docs/creep.md "Adding a creep law") touches four files: its pure function in
// workbench/creep/ (a header, a source and their CMake entry) and this one (its value in
// CreepModel, its struct and its entry in CreepLaws). Parameters it needs beyond CreepParams go
// into ContactSpec / ContactModel and the contact{} schema, next to `fastsim`.
#include <array>
#include <string_view>

#include "workbench/core/names.hpp"
#include "workbench/creep/fastsim.hpp"
#include "workbench/creep/polach.hpp"
#include "workbench/creep/shen_hedrick_elkins.hpp"

namespace rb::dynamics {

// The laws of the registry below (ContactSpec::creep); one value per law.
enum class CreepModel { Polach, Kalker, Fastsim, ShenHedrickElkins, None };

// Each law: kModel, kName, kHelp, kCreep (false: no tangential forces, the creep stages are not
// compiled), kSaturates (its resultant reaches mu N on a sliding patch as Kalker's exact theory's
// does, tread to flank and with spin: tests/creep/test_creep_exact.cpp; false: check and run warn)
// and apply(model, patch, creepages, fx, fy, mz), forces and spin moment on the wheel
// (creep/creepages.hpp conventions). `model` is the ContactModel (its creep_params, fastsim).
struct PolachLaw {
  static constexpr CreepModel kModel = CreepModel::Polach;
  static constexpr std::string_view kName = "polach";
  static constexpr std::string_view kHelp = "Polach's creep force law (the paper, section 2.5)";
  static constexpr bool kCreep = true;
  static constexpr bool kSaturates = true;
  template <class Model>
  static void apply(const Model& m, const creep::ContactPatch& p, const creep::Creepages& c,
                    double& fx, double& fy, double& mz) {
    const creep::CreepForce f = creep::polachForce(m.creep_params, p, c);
    fx = f.fx;
    fy = f.fy;
    mz = 0.0;
  }
};

struct KalkerLaw {
  static constexpr CreepModel kModel = CreepModel::Kalker;
  static constexpr std::string_view kName = "kalker";
  static constexpr std::string_view kHelp =
      "Kalker's linear theory (unbounded: exceeds mu N past the saturation creepage)";
  static constexpr bool kCreep = true;
  static constexpr bool kSaturates = false;  // linear: unbounded
  template <class Model>
  static void apply(const Model& m, const creep::ContactPatch& p, const creep::Creepages& c,
                    double& fx, double& fy, double& mz) {
    const creep::LinearCreepForce f = creep::kalkerLinearForce(m.creep_params.G, p, c);
    fx = f.fx;
    fy = f.fy;
    mz = f.mz;
  }
};

struct FastsimLaw {
  static constexpr CreepModel kModel = CreepModel::Fastsim;
  static constexpr std::string_view kName = "fastsim";
  static constexpr std::string_view kHelp =
      "Kalker's FASTSIM (simplified theory, with spin moment; grid in contact.fastsim)";
  static constexpr bool kCreep = true;
  static constexpr bool kSaturates = true;
  template <class Model>
  static void apply(const Model& m, const creep::ContactPatch& p, const creep::Creepages& c,
                    double& fx, double& fy, double& mz) {
    const creep::FastsimForce f = creep::fastsimForce(m.creep_params, p, c, m.fastsim);
    fx = f.fx;
    fy = f.fy;
    mz = f.mz;
  }
};

struct ShenHedrickElkinsLaw {
  static constexpr CreepModel kModel = CreepModel::ShenHedrickElkins;
  static constexpr std::string_view kName = "shen_hedrick_elkins";
  static constexpr std::string_view kHelp =
      "Shen, Hedrick and Elkins (1983): Kalker's linear forces saturated by Johnson and "
      "Vermeulen's cubic";
  static constexpr bool kCreep = true;
  static constexpr bool kSaturates = true;
  template <class Model>
  static void apply(const Model& m, const creep::ContactPatch& p, const creep::Creepages& c,
                    double& fx, double& fy, double& mz) {
    const creep::SaturatedCreepForce f = creep::shenHedrickElkinsForce(m.creep_params, p, c);
    fx = f.fx;
    fy = f.fy;
    mz = f.mz;
  }
};

struct NoCreep {
  static constexpr CreepModel kModel = CreepModel::None;
  static constexpr std::string_view kName = "none";
  static constexpr std::string_view kHelp = "no tangential forces";
  static constexpr bool kCreep = false;
  static constexpr bool kSaturates = true;
  template <class Model>
  static void apply(const Model& /*m*/, const creep::ContactPatch& /*p*/,
                    const creep::Creepages& /*c*/, double& fx, double& fy, double& mz) {
    fx = fy = mz = 0.0;
  }
};

template <class... Laws>
struct LawList {};

// The registry, in the order of the scenario reference.
using CreepLaws = LawList<PolachLaw, KalkerLaw, FastsimLaw, ShenHedrickElkinsLaw, NoCreep>;

template <class... Laws>
constexpr std::array<NameEntry<CreepModel>, sizeof...(Laws)> creepLawNames(LawList<Laws...>) {
  return {{{Laws::kModel, Laws::kName, Laws::kHelp}...}};
}

template <class... Laws>
constexpr bool distinctCreepModels(LawList<Laws...>) {
  const std::array<CreepModel, sizeof...(Laws)> m{Laws::kModel...};
  for (std::size_t i = 0; i < m.size(); ++i)
    for (std::size_t j = i + 1; j < m.size(); ++j)
      if (m[i] == m[j]) return false;
  return true;
}
static_assert(distinctCreepModels(CreepLaws{}), "two creep laws share a CreepModel value");

template <class... Laws>
constexpr bool creepLawSaturates(CreepModel model, LawList<Laws...>) {
  return ((Laws::kModel == model && Laws::kSaturates) || ...);
}

// Whether the law's resultant saturates at mu N (kSaturates above).
constexpr bool creepLawSaturates(CreepModel model) {
  return creepLawSaturates(model, CreepLaws{});
}

}  // namespace rb::dynamics
