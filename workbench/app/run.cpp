#include "workbench/app/run.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "workbench/dynamics/contact_model.hpp"
#include "workbench/dynamics/names.hpp"
#include "workbench/dynamics/wheel_measures.hpp"
#include "workbench/io/result_file.hpp"
#include "workbench/run/compile.hpp"
#include "workbench/run/run_stats.hpp"
#include "workbench/run/simulate.hpp"
#include "workbench/run/vehicle_run.hpp"

namespace fs = std::filesystem;

namespace rb::app {
namespace {

std::string isoNow() {
  std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

std::string defaultOut(const RunOptions& o) {
  return o.out.empty() ? "out/" + fs::path(o.scenario).stem().string() + ".h5" : o.out;
}

// Contact tables are cached on disk by the hash of their inputs, beside the results, so a study's
// cases share them; RAILBENCH_TABLE_CACHE names another folder.
run::CompileOptions compileOptions(const RunOptions& o) {
  run::CompileOptions c;
  c.scenario = o.scenario;
  c.overrides = o.overrides;
  c.root = o.root;
  const char* env = std::getenv("RAILBENCH_TABLE_CACHE");
  c.table_cache =
      env ? std::string(env) : (fs::path(defaultOut(o)).parent_path() / ".table-cache").string();
  return c;
}

// The result may only replace an earlier result: never the scenario, one of its inputs or any
// other file that is not an HDF5 file.
void checkOutputPath(const std::string& out, const run::Model& m) {
  const SourceLoc cli{"<command line>", 0};
  std::error_code ec;
  const fs::path p(out);
  auto same = [&](const std::string& other) {
    std::error_code e2;
    return fs::exists(other, e2) && fs::exists(p, e2) && fs::equivalent(p, other, e2);
  };
  if (same(m.spec.file))
    throw InputError(cli, "--out: '" + out + "' is the scenario file; refusing to overwrite it");
  for (const auto& [name, text] : m.spec.modules)
    if (same(name))
      throw InputError(cli, "--out: '" + out +
                                "' is a file the scenario reads; refusing to "
                                "overwrite it");
  if (fs::is_directory(p, ec))
    throw InputError(cli, "--out: '" + out + "' is a folder; give a file name (.h5)");
  if (fs::exists(p, ec)) {
    static const char kSignature[8] = {'\x89', 'H', 'D', 'F', '\r', '\n', '\x1a', '\n'};
    char head[8] = {};
    bool hdf5 = false;
    if (fs::is_regular_file(p, ec)) {  // never open a FIFO or device: it would block
      std::ifstream in(out, std::ios::binary);
      hdf5 = in.read(head, 8) && std::equal(head, head + 8, kSignature);
    }
    if (!hdf5)
      throw InputError(
          cli, "--out: '" + out + "' exists and is not an HDF5 result; refusing to replace it");
  }
}

// 1 in how many rhs evaluations are timed: the option, else RAILBENCH_STAGE_SAMPLING (a count,
// 0 = off: the callgrind comparison of docs/run_stats.md), else the default.
unsigned stagePeriod(const RunOptions& o) {
  if (o.stage_period >= 0) return static_cast<unsigned>(o.stage_period);
  const char* env = std::getenv("RAILBENCH_STAGE_SAMPLING");
  if (env == nullptr || *env == '\0') return vehicle::StageClock::kDefaultPeriod;
  char* end = nullptr;
  const long n = std::strtol(env, &end, 10);
  if (*end != '\0' || n < 0 || n > 1000000000L)
    throw InputError(SourceLoc{"<environment>", 0},
                     "RAILBENCH_STAGE_SAMPLING must be a count >= 0 (0: no stage timing), got '" +
                         std::string(env) + "'");
  return static_cast<unsigned>(n);
}

// --track-store must be a folder this process can write (created when missing): a file, a FIFO,
// a read-only place is refused before anything runs (exit 1, nothing written).
void checkTrackStore(const std::string& dir) {
  if (dir.empty()) return;
  const SourceLoc cli{"<command line>", 0};
  std::error_code ec;
  const fs::file_status st = fs::status(dir, ec);
  if (fs::exists(st) && !fs::is_directory(st))
    throw InputError(cli, "--track-store: '" + dir + "' exists and is not a folder");
  if (!fs::exists(st)) {
    fs::create_directories(dir, ec);
    if (ec)
      throw InputError(cli,
                       "--track-store: cannot create the folder '" + dir + "': " + ec.message());
  }
  // access() answers for the permission bits only (root passes it on /proc or a read-only
  // mount): a file made and removed again is the test the track file will meet.
  std::string probe = (fs::path(dir) / ".railbench_probe_XXXXXX").string();
  const int fd = ::mkstemp(probe.data());
  if (fd < 0)
    throw InputError(
        cli, "--track-store: the folder '" + dir + "' is not writable: " + std::strerror(errno));
  ::close(fd);
  ::unlink(probe.c_str());
}

// The notes on the wheels read from files (their EN 15313 flange measures), once per line over
// the vehicles and their wheelsets' own wheels; on stderr with the warnings, so that the run's
// stdout keeps its lines.
void printProfileNotes(const run::Model& m) {
  std::vector<std::string> printed;
  auto print = [&](const dynamics::ContactModel& cm) {
    for (const std::string& n : dynamics::wheelMeasureNotes(cm)) {
      if (std::find(printed.begin(), printed.end(), n) != printed.end()) continue;
      printed.push_back(n);
      std::cerr << n << "\n";
    }
  };
  for (const run::RunVehicle& rv : m.vehicles) {
    if (!rv.contact) continue;
    print(*rv.contact);
    for (const auto& own : rv.contact->own_wheels)
      if (own) print(*own);
  }
}

}  // namespace

void checkScenario(const RunOptions& options) {
  run::Model m = run::compile(compileOptions(options));
  for (const auto& w : m.warnings) std::cerr << w << "\n";
  printProfileNotes(m);
}

std::unique_ptr<io::ResultFile> openResultFile(const std::string& out, bool compact) {
  const SourceLoc cli{"<command line>", 0};
  if (fs::path(out).has_parent_path()) {
    std::error_code ec;
    fs::create_directories(fs::path(out).parent_path(), ec);
    if (ec)
      throw InputError(cli, "--out: cannot create the folder of '" + out + "': " + ec.message());
  }
  try {
    return std::make_unique<io::ResultFile>(
        out, compact ? io::ResultFile::Storage::Compact : io::ResultFile::Storage::Plain);
  } catch (const io::WriteError& e) {
    throw InputError(cli, std::string("--out: ") + e.what());
  }
}

int runScenario(const RunOptions& options) {
  // Everything that can be checked is checked before the result file exists: a run that does
  // not start never touches an earlier result.
  run::Model c = run::compile(compileOptions(options));
  for (const auto& w : c.warnings) std::cerr << w << "\n";
  printProfileNotes(c);
  // Output only: the model, its integration and every written signal are those of a full run.
  if (options.compact) c.spec.run.output_patches = false;
  const unsigned period = stagePeriod(options);
  const std::string out = defaultOut(options);
  checkOutputPath(out, c);
  checkTrackStore(options.track_store);
  const std::unique_ptr<io::ResultFile> opened = openResultFile(out, options.compact);
  io::ResultFile& f = *opened;
  const std::string stored = run::writeProvenance(c, f, isoNow(), options.track_store);
  if (options.compact) f.attr("/", "compact", std::string(kCompactOmits));

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
  msg << " (built in " << c.track_build_s * 1e3 << " ms)";
  if (!stored.empty()) msg << ", " << stored;

  int rc = 0;
  if (c.hasVehicle()) {
    run::VehicleRunOptions vo;
    vo.progress = !options.quiet && isatty(STDERR_FILENO);  // only for a person at a terminal
    vo.stage_period = period;
    run::VehicleRunResult res = run::runVehicle(c, f, vo);
    f.finalize();
    std::cout << run::statsLine(res.result, res.result.t_reached);
    if (!res.warnings.empty())
      std::cout << "; " << res.warnings.size()
                << (res.warnings.size() == 1 ? " warning" : " warnings");
    std::cout << "\n";
    std::cout << "effects: " << run::effectsSummary(res.effects) << "; "
              << run::costSummary(res.costs) << "\n";
    for (const auto& w : res.warnings) std::cout << "warning: " << w << "\n";
    for (const auto& line : res.rails_summary) std::cout << line << "\n";
    for (const auto& line : res.assessment_summary) std::cout << line << "\n";
    if (res.assessment_summary.empty())
      for (const auto& n : res.assessment_notes) std::cout << n << "\n";
    // Every vehicle of the run (a train: each under its name, front to rear).
    for (std::size_t k = 0; k < c.vehicles.size(); ++k) {
      const run::RunVehicle& rv = c.vehicles[k];
      const vehicle::VehicleModel& v = rv.vehicle;
      msg << (k == 0 ? "; vehicle " : ", ")
          << (rv.name.empty() ? v.name : rv.name + " (" + v.name + ")");
      if (rv.contact)
        msg << " with " << nameOf(rv.contact->method) << " contact";
      else
        msg << " (" << v.bodies.size() << " bodies, " << v.elementCount() << " elements)";
    }
    if (!res.result.ok) {
      std::cerr << c.spec.file << ": run failed: " << res.result.message << "\n";
      rc = 2;
    }
  } else {
    // No vehicle in the scene: nothing is integrated. The stats group still says what was done
    // so every result file has the same shape.
    f.attr("/stats", "status", std::string("ok"));
    f.attr("/stats", "message",
           std::string("no vehicle in the scene: track only, nothing integrated"));
    run::writeWarnings(f, {});
    f.finalize();
    msg << "; no vehicle in the scene, nothing integrated";
  }
  std::cout << msg.str() << "\n";
  return rc;
}

}  // namespace rb::app
