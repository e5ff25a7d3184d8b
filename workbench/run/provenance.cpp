// Root provenance attributes and the /track group of a result file (vehicle_run.hpp).
#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "railbench/version.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/dynamics/contact_model.hpp"
#include "workbench/io/track_output.hpp"
#include "workbench/io/track_store.hpp"
#include "workbench/run/vehicle_run.hpp"
#include "workbench/track/samples.hpp"

namespace rb::run {

std::string writeProvenance(const Model& c, io::ResultFile& f, const std::string& created,
                            const std::string& track_store) {
  f.attr("/", "version", std::string(kVersion));
  f.attr("/", "created", created);
  f.attr("/", "scenario_file", c.spec.file);
  f.attr("/", "scenario_text", c.spec.text);
  // The files the scenario required (tracks, vehicles, shared set-ups), so the result alone says
  // exactly what was run.
  std::string modules;
  for (const auto& [name, text] : c.spec.modules)
    modules += "-- file: " + name + "\n" + text + "\n";
  f.attr("/", "scenario_modules", modules);
  f.attr("/", "overrides", join(c.spec.overrides, "\n"));
  std::vector<std::string> effects = {"track_geometry"};
  std::string seeds;
  if (c.track->irregularities()) {
    effects.push_back("irregularities");
    if (c.spec.track.irregularities.source == track::IrregularitySource::Psd)
      seeds = "track.irregularities.seed=" + std::to_string(c.spec.track.irregularities.seed);
  }
  // The suspension kinds, contact methods and creep laws of the run's vehicles, each once (a
  // train's vehicles may differ; one vehicle's list is its own).
  const auto add = [&](const std::string& e) {
    if (std::find(effects.begin(), effects.end(), e) == effects.end()) effects.push_back(e);
  };
  for (const auto& rv : c.vehicles)
    for (const auto& k : rv.vehicle.element_kinds) add("suspension:" + k);
  for (const auto& rv : c.vehicles) {
    if (!rv.contact) continue;
    add(std::string("contact:") + dynamics::ContactModel::methodName(rv.contact->method));
    add(std::string("creep:") + dynamics::ContactModel::creepName(rv.contact->creep));
  }
  f.attr("/", "effects", join(effects, "\n"));
  f.attr("/", "seeds", seeds);
  // A result file holds the stretch the vehicle covers, from its rearmost body at the start to
  // its leading body at the end; a track store holds the whole track, which the cases of a study
  // share whatever stretch each covers (and a model without a vehicle writes it whole too).
  double s_from = -std::numeric_limits<double>::infinity();
  double s_to = std::numeric_limits<double>::infinity();
  if (track_store.empty() && c.hasVehicle() && c.t_end > 0.0) {
    const Model::Stretch covered = c.coveredStretch();
    s_from = covered.s_from;
    s_to = covered.s_to;
  }
  const io::TrackContent track =
      io::trackContent(c.spec.track, track::sampleTrack(*c.track, s_from, s_to));
  // With a track store the rows describe the /track datasets of the store file.
  io::writeSchema(f, "track", io::trackSchema(track), io::trackEnums());
  std::string note;
  if (track_store.empty()) {
    io::writeTrackContent(f, track);
  } else {
    const io::StoredTrack stored = io::storeTrack(track, track_store);
    io::writeTrackReference(f, track, stored);
    note = "track " + std::string(stored.written ? "stored in " : "found in ") + stored.file;
  }
  f.attr("/track", "build_time_s", c.track_build_s);
  return note;
}

}  // namespace rb::run
