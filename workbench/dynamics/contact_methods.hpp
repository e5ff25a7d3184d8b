#pragma once
// The one registry of contact methods (docs/architecture.md, "Contact methods"): per method its
// ContactMethod value, its scenario / HDF5 name and help, the wheelset coordinates it integrates
// (the others it solves from its constraints), whether it builds a contact table and has a
// normal-force coupling, and what its two output patches and its flange contact are. From the list
// ContactMethods below come the name table of dynamics/names.hpp, the state layout
// (contactLayout), the instantiations of ContactVehicleOde::evaluateT (one per method and creep
// law, chosen once per model: no branch on the method in an evaluation), the roles of the output
// patches and the effect labels; non-template code reads the same rows through methodInfo().
//
// Adding a contact method: its value in ContactMethod (spec.hpp), its struct below and its entry
// in ContactMethods, its stages (as contact_elastic.hpp for the elastic method) selected in
// contact_ode.cpp's wheelsetStages and solveConstraints, its Model data in ContactModel and its
// keys in the contact{} schema.
#include <array>
#include <string_view>

#include "workbench/core/names.hpp"
#include "workbench/dynamics/spec.hpp"
#include "workbench/vehicle/layout.hpp"

namespace rb::dynamics {

// Each method: kMethod, kName, kHelp; kWheelsetDof[spin]: states per wheelset with a free (0) and
// a prescribed (1) spin (vehicle/layout.hpp); kTable: it builds a contact table (profiles.
// refined_tables applies); kCoupling: its creep forces are coupled to constraint normal forces
// (contact.normal_forces applies); kFlangeContact: the effect label of its flange contact;
// kPatchRole: what output patch 0 and 1 are; kPatches: the /contact@patches description;
// kBandMonitor: its two-point contact is a regularised band (Eq. 26) whose lateral force can
// oscillate by itself in steady flanging, so a run watches its wheels for that (run/band_
// oscillation.hpp).
struct KecMethod {
  static constexpr ContactMethod kMethod = ContactMethod::Kec;
  static constexpr std::string_view kName = "kec";
  static constexpr std::string_view kHelp = "knife-edge equivalent contact (paper section 2.4)";
  static constexpr std::array<int, 2> kWheelsetDof = {vehicle::kFreeSpinDof,
                                                      vehicle::kPrescribedSpinDof};
  static constexpr bool kTable = true;
  static constexpr bool kCoupling = true;
  static constexpr std::string_view kFlangeContact = "kec_band";
  static constexpr std::array<std::string_view, 2> kPatchRole = {
      "KEC contact point, or point A in the band", "KEC point B (flange-side end of the band)"};
  static constexpr std::string_view kPatches =
      "KEC: patch0 = the contact point, or inside a regularised tread-flange band point A "
      "(field-side end, weight 1 - w); patch1 = point B (flange-side end, weight w), active only "
      "inside the band (Eq. 26)";
  static constexpr bool kBandMonitor = true;
};

struct LutMethod {
  static constexpr ContactMethod kMethod = ContactMethod::Lut;
  static constexpr std::string_view kName = "lut";
  static constexpr std::string_view kHelp =
      "contact lookup table with Hertz flange contact (Eq. 20)";
  static constexpr std::array<int, 2> kWheelsetDof = {vehicle::kFreeSpinDof,
                                                      vehicle::kPrescribedSpinDof};
  static constexpr bool kTable = true;
  static constexpr bool kCoupling = true;
  static constexpr std::string_view kFlangeContact = "hertz";
  static constexpr std::array<std::string_view, 2> kPatchRole = {"LUT tread", "LUT flange (Hertz)"};
  static constexpr std::string_view kPatches =
      "LUT: patch0 = the tread contact (Eq. 17); patch1 = the Hertz flange contact (Eq. 20-21), "
      "active while the flange indentation is positive";
  static constexpr bool kBandMonitor = false;
};

struct ElasticMethod {
  static constexpr ContactMethod kMethod = ContactMethod::Elastic;
  static constexpr std::string_view kName = "elastic";
  static constexpr std::string_view kHelp =
      "elastic multi-point contact: online search on the profiles, Hertz per patch, the wheelset "
      "free to lift and climb (docs/elastic_contact.md)";
  static constexpr std::array<int, 2> kWheelsetDof = {vehicle::kElasticFreeSpinDof,
                                                      vehicle::kElasticPrescribedSpinDof};
  static constexpr bool kTable = false;
  static constexpr bool kCoupling = false;
  static constexpr std::string_view kFlangeContact = "multi_point";
  static constexpr std::array<std::string_view, 2> kPatchRole = {
      "elastic: the tread patch with the largest normal force",
      "elastic: the flange patch with the largest normal force"};
  static constexpr std::string_view kPatches =
      "elastic: every penetrating minimum of the wheel-rail gap is a patch (contact_count per "
      "wheel); patch0 = the tread patch with the largest normal force, patch1 = the flange patch "
      "with the largest normal force; the wheel's totals sum every patch";
  static constexpr bool kBandMonitor = false;
};

template <class... Methods>
struct MethodList {};

// The registry, in the order of the scenario reference.
using ContactMethods = MethodList<KecMethod, LutMethod, ElasticMethod>;

// A method's row as plain data, for code that is not compiled per method.
struct ContactMethodInfo {
  ContactMethod method = ContactMethod::Kec;
  std::string_view name;
  std::array<int, 2> wheelset_dof{};
  bool table = false;
  bool coupling = false;
  std::string_view flange_contact;
  std::array<std::string_view, 2> patch_role{};
  std::string_view patches;
  bool band_monitor = false;
};

template <class... Methods>
constexpr std::array<ContactMethodInfo, sizeof...(Methods)> contactMethodInfos(
    MethodList<Methods...>) {
  return {{{Methods::kMethod, Methods::kName, Methods::kWheelsetDof, Methods::kTable,
            Methods::kCoupling, Methods::kFlangeContact, Methods::kPatchRole, Methods::kPatches,
            Methods::kBandMonitor}...}};
}
inline constexpr auto kContactMethodInfos = contactMethodInfos(ContactMethods{});

// The row of method m (every ContactMethod value has one: checked below).
constexpr const ContactMethodInfo& methodInfo(ContactMethod m) {
  for (const ContactMethodInfo& i : kContactMethodInfos)
    if (i.method == m) return i;
  return kContactMethodInfos.front();
}

// The row of the method named `name` ("kec", "lut", "elastic"); null for an unknown name.
constexpr const ContactMethodInfo* methodInfoNamed(std::string_view name) {
  for (const ContactMethodInfo& i : kContactMethodInfos)
    if (i.name == name) return &i;
  return nullptr;
}

template <class... Methods>
constexpr std::array<NameEntry<ContactMethod>, sizeof...(Methods)> contactMethodNames(
    MethodList<Methods...>) {
  return {{{Methods::kMethod, Methods::kName, Methods::kHelp}...}};
}

template <class... Methods>
constexpr bool distinctContactMethods(MethodList<Methods...>) {
  const std::array<ContactMethod, sizeof...(Methods)> m{Methods::kMethod...};
  for (std::size_t i = 0; i < m.size(); ++i)
    for (std::size_t j = i + 1; j < m.size(); ++j)
      if (m[i] == m[j]) return false;
  return true;
}
static_assert(distinctContactMethods(ContactMethods{}), "two methods share a ContactMethod value");
static_assert(kContactMethodInfos.size() == 3 &&
                  methodInfo(ContactMethod::Elastic).method == ContactMethod::Elastic &&
                  methodInfo(ContactMethod::Lut).method == ContactMethod::Lut,
              "every ContactMethod value needs its registry row");

}  // namespace rb::dynamics
