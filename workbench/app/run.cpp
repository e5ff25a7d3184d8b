#include "workbench/app/run.hpp"

#include <chrono>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

#include "railbench/version.hpp"
#include "workbench/integrators/registry.hpp"
#include "workbench/io/result_file.hpp"
#include "workbench/io/track_output.hpp"
#include "workbench/scenario/scenario.hpp"
#include "workbench/track/psd.hpp"
#include "workbench/track/samples.hpp"
#include "workbench/track/track.hpp"

namespace fs = std::filesystem;

namespace rb::app {
namespace {

struct Compiled {
  scenario::ScenarioSpec spec;
  std::optional<track::TrackModel> track;
  double track_build_s = 0.0;
  std::vector<std::string> warnings;
};

// Spec -> Model: every problem of every block is collected before anything runs.
Compiled compile(const RunOptions& o) {
  scenario::LoadOptions lo;
  lo.root = o.root;
  lo.overrides = o.overrides;
  Compiled c{scenario::loadScenario(o.scenario, lo), std::nullopt, 0.0, {}};
  Diagnostics d;
  auto t0 = std::chrono::steady_clock::now();
  try {
    c.track = track::compileTrack(c.spec.track);
  } catch (const InputError& e) {
    d.add(e);
  }
  c.track_build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (c.spec.has_solver) {
    try {
      (void)integ::makeIntegrator(c.spec.solver);
    } catch (const InputError& e) {
      d.add(e);
    }
  }
  d.throwIfAny();
  const auto& irr = c.spec.track.irregularities;
  if (irr.source == track::IrregularitySource::Psd && !track::psdVerified(irr.spectrum))
    c.warnings.push_back(irr.loc.str() + ": warning: the parameters of spectrum '" + irr.spectrum +
                         "' are UNVERIFIED against a primary source (see docs/track.md)");
  return c;
}

std::string isoNow() {
  std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

std::string joinLines(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : "\n") + s;
  return out;
}

}  // namespace

void checkScenario(const RunOptions& options) {
  Compiled c = compile(options);
  for (const auto& w : c.warnings) std::cerr << w << "\n";
}

int runScenario(const RunOptions& options) {
  Compiled c = compile(options);
  for (const auto& w : c.warnings) std::cerr << w << "\n";

  std::string out = options.out;
  if (out.empty()) out = "out/" + fs::path(options.scenario).stem().string() + ".h5";
  if (fs::path(out).has_parent_path()) fs::create_directories(fs::path(out).parent_path());

  io::ResultFile f(out);
  f.attr("/", "version", std::string(kVersion));
  f.attr("/", "created", isoNow());
  f.attr("/", "scenario_file", c.spec.file);
  f.attr("/", "scenario_text", c.spec.text);
  f.attr("/", "overrides", joinLines(c.spec.overrides));
  std::vector<std::string> effects = {"track_geometry"};
  std::string seeds;
  if (c.track->irregularities()) {
    effects.push_back("irregularities");
    if (c.spec.track.irregularities.source == track::IrregularitySource::Psd)
      seeds = "track.irregularities.seed=" + std::to_string(c.spec.track.irregularities.seed);
  }
  f.attr("/", "effects", joinLines(effects));
  f.attr("/", "seeds", seeds);
  io::writeTrack(f, c.spec.track, track::sampleTrack(*c.track));
  f.attr("/track", "build_time_s", c.track_build_s);

  // No vehicle in the scene yet (the vehicle model is issue 5): nothing is integrated. The stats
  // group still says what was done so every result file has the same shape.
  f.attr("/stats", "status", std::string("ok"));
  f.attr("/stats", "message", std::string("no vehicle in the scene: track only, nothing integrated"));
  f.finalize();

  std::ostringstream msg;
  msg << "wrote " << out << ": track " << c.track->geometry().length() << " m, "
      << c.spec.track.segments.size() << " segments";
  if (c.track->irregularities()) {
    const auto& irr = c.spec.track.irregularities;
    if (irr.source == track::IrregularitySource::Psd)
      msg << ", irregularities " << irr.spectrum << " seed " << irr.seed;
    else
      msg << ", measured irregularities";
  }
  msg << " (built in " << c.track_build_s * 1e3 << " ms); no vehicle in the scene, nothing integrated";
  std::cout << msg.str() << "\n";
  return 0;
}

}  // namespace rb::app
