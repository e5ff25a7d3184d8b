// The `workbench` command line: run, check, check-result, assess, tables, study, precision, stress,
// effects, modes, critical-speed, help scenario, --version. Never prompts; every problem is
// reported as file:line: message with a non-zero exit code.
//   exit 0: ok; 1: bad input (scenario, options; nothing was run); 2: the run failed (partial
//   results kept), or its result could not be written (an earlier result is unchanged);
//   3: internal error (a bug); 4: only the figures of a study, precision, stress or effects
//   failed (their results are complete); 5: a stress outcome differs from its --expect file.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "railbench/commit.hpp"
#include "railbench/version.hpp"
#include "workbench/app/assess.hpp"
#include "workbench/app/run.hpp"
#include "workbench/app/scenario_command.hpp"
#include "workbench/app/tables.hpp"
#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/effects/effects.hpp"
#include "workbench/io/result_file.hpp"
#include "workbench/io/result_reader.hpp"
#include "workbench/precision/precision.hpp"
#include "workbench/scenario/override_check.hpp"
#include "workbench/scenario/schema.hpp"
#include "workbench/stress/result_checks.hpp"
#include "workbench/stress/stress.hpp"
#include "workbench/study/runner.hpp"

namespace fs = std::filesystem;

namespace {

// The data directory holding scenarios/, profiles/ and plots/: RAILBENCH_ROOT when set; else,
// for an installed program (<prefix>/bin/railbench), <prefix>/share/railbench found from the
// program's own path, so a user's scene in any folder needs no set-up; else the checkout the
// program was built from (a build tree has no share/railbench beside its program).
std::string defaultRoot() {
  if (const char* env = std::getenv("RAILBENCH_ROOT")) return env;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path data = exe.parent_path().parent_path() / "share" / "railbench";
    if (fs::is_directory(data / "scenarios", ec)) return data.string();
  }
  return RB_SOURCE_DIR;
}

void printInputError(const rb::InputError& e) {
  for (const auto& d : e.diagnostics()) std::cerr << d.str() << "\n";
  std::cerr << e.diagnostics().size() << (e.diagnostics().size() == 1 ? " problem" : " problems")
            << " found; nothing was run.\n";
}

int workbench(int argc, char** argv) {
  CLI::App app{"railbench workbench: scripted railway vehicle dynamics"};
  app.set_version_flag("--version",
                       std::string("railbench ") + rb::kVersion + " (commit " + rb::kCommit + ")");
  app.require_subcommand(1);
  std::string root = defaultRoot();
  app.add_option("--root", root, "project root holding scenarios/ and profiles/")
      ->capture_default_str();

  rb::app::RunOptions ro;
  auto* run = app.add_subcommand("run", "run a scenario and write its HDF5 result");
  run->add_option("scenario", ro.scenario, "scenario file (.lua)")->required();
  run->add_option("--set", ro.overrides, "override a scenario value: block.key=value")
      ->allow_extra_args(false);
  run->add_option("--out", ro.out, "result file (default out/<scenario>.h5)");
  run->add_flag("--quiet", ro.quiet, "no progress line");
  run->add_option("--track-store", ro.track_store,
                  "write the track once per distinct track into DIR/<track hash>.h5 and only a "
                  "reference into the result");
  run->add_flag("--compact", ro.compact,
                "leave out the per-patch contact datasets (the result's root attribute "
                "'compact' says so)");

  rb::app::RunOptions co;
  auto* check = app.add_subcommand("check", "validate a scenario without running it");
  check->add_option("scenario", co.scenario, "scenario file (.lua)")->required();
  check->add_option("--set", co.overrides, "override a scenario value: block.key=value")
      ->allow_extra_args(false);

  rb::app::RunOptions to;
  auto* tables = app.add_subcommand("tables", "build and store the contact tables of a scenario");
  tables->add_option("scenario", to.scenario, "scenario file (.lua)")->required();
  tables->add_option("--set", to.overrides, "override a scenario value: block.key=value")
      ->allow_extra_args(false);
  tables->add_option("--out", to.out, "result file (default out/<scenario>_tables.h5)");

  rb::study::StudyOptions so;
  auto* study = app.add_subcommand("study", "run a study: a matrix of cases over a base scenario");
  study->add_option("file", so.file, "study file (.lua)")->required();
  study->add_option("--out", so.out, "output folder (default out/<study>)");
  study
      ->add_option("--jobs", so.jobs,
                   "cases at once, 1..4 x cores (default: the study's jobs, else cores)")
      ->each([&so](const std::string&) { so.jobs_given = true; });
  study->add_option("--run-timeout", so.run_timeout_s,
                    "kill a run after this many seconds of wall time and report it (0: no limit)");
  auto* shard = study->add_option("--shard", so.shard,
                                  "run only shard K of N (K/N, 1 <= K <= N) and write no summary");
  auto* summarize =
      study->add_flag("--summarize", so.summarize,
                      "run nothing: write the summaries and figures of what is on disk");
  auto* mpi = study->add_flag("--mpi", so.mpi, "run as an MPI task farm (mpirun -np N ... --mpi)");
  shard->excludes(summarize)->excludes(mpi);
  summarize->excludes(mpi);

  // The users' three asks on any scenario (docs/three_asks.md).
  rb::precision::PrecisionOptions po;
  auto* precision = rb::app::addPrecisionCommand(app, po);
  rb::stress::StressOptions sto;
  auto* stress = rb::app::addStressCommand(app, sto);
  rb::effects::EffectsOptions eo;
  auto* effects = rb::app::addEffectsCommand(app, eo);

  // Stability (docs/stability.md).
  rb::modes::ModesOptions mo;
  auto* modes = rb::app::addModesCommand(app, mo);
  rb::critical_speed::CriticalSpeedOptions cso;
  auto* critical = rb::app::addCriticalSpeedCommand(app, cso);

  rb::app::AssessOptions ao;
  auto* assess = app.add_subcommand(
      "assess", "recompute /assessment of a result file from its datasets and replace it");
  assess->add_option("file", ao.file, "result file (.h5)")->required();
  assess->add_option("--set", ao.overrides, "change an assessment key: run.assessment.KEY=VALUE")
      ->allow_extra_args(false);

  std::string checkFile;
  int checkExit = 0;
  double checkEnd = 0.0;
  std::vector<std::string> checkBounds;
  auto* checkResult = app.add_subcommand(
      "check-result",
      "check a run's result file as stress and the hard-case suite do (consistent with the "
      "run's exit code, no NaN/Inf, plausible); prints the findings as JSON; exit 0 when it "
      "passes, 2 when it does not");
  checkResult->add_option("file", checkFile, "result file (.h5)")->required();
  checkResult->add_option("--exit-code", checkExit, "the run's exit code: 0 (ok) or 2 (failed)")
      ->check(CLI::IsMember({0, 2}));
  // Checked after parsing (finite and >= 0): CLI11's NonNegativeNumber lets NaN through.
  checkResult->add_option("--t-end", checkEnd, "the run's end time [s] (0: unknown)");
  checkResult
      ->add_option("--bound", checkBounds,
                   "change a plausibility bound: NAME=VALUE, NAME (default) one of " +
                       rb::stress::boundsHelp())
      ->allow_extra_args(false);

  std::string topic;
  std::string helpScenario;
  auto* help = app.add_subcommand("help", "reference documentation");
  help->add_option("topic", topic,
                   "topic: scenario (every block and key), vehicle SCENARIO.lua (the named "
                   "parameters of the scenario's vehicle: bodies, elements, groups)")
      ->required()
      ->check(CLI::IsMember({"scenario", "vehicle"}));
  help->add_option("scenario", helpScenario, "scenario file (topic vehicle)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 1;
  }

  try {
    if (*help) {
      if (topic == "vehicle") {
        if (helpScenario.empty())
          throw rb::InputError({"<command line>", 0},
                               "help vehicle needs a scenario file, e.g. workbench help "
                               "vehicle scenarios/studies/case3_base.lua");
        std::cout << rb::scenario::vehicleParametersText(helpScenario, root);
        return 0;
      }
      std::cout << rb::scenario::referenceText()
                << "\nNamed parameters of a vehicle (its bodies, elements with their keys, and "
                   "groups): workbench help vehicle SCENARIO.lua\n";
      return 0;
    }
    if (*check) {
      co.root = root;
      if (rb::scenario::isStudyFile(co.scenario, root)) {
        if (!co.overrides.empty())
          throw rb::InputError({"<command line>", 0},
                               "--set applies to scenarios; " + co.scenario +
                                   " is a study file, whose cases set their own values");
        rb::study::StudyOptions sco;
        sco.file = co.scenario;
        sco.root = root;
        const std::size_t n = rb::study::checkStudy(sco);
        std::cout << co.scenario << ": ok (a study of " << n << (n == 1 ? " case" : " cases")
                  << "; every case's scenario loads)\n";
        return 0;
      }
      rb::app::checkScenario(co);
      std::cout << co.scenario << ": ok\n";
      return 0;
    }
    if (*assess) return rb::app::assessFile(ao);
    if (*checkResult) {
      if (!std::isfinite(checkEnd) || checkEnd < 0.0)
        throw rb::InputError({"<command line>", 0},
                             "--t-end " + rb::formatNumber(checkEnd) +
                                 ": the end time must be a finite number >= 0 [s]");
      std::error_code ec;
      if (!fs::is_regular_file(checkFile, ec))
        throw rb::InputError({checkFile, 0}, "no such result file");
      rb::stress::Bounds bounds;
      for (const auto& b : checkBounds) rb::stress::setBound(bounds, b, "--bound");
      const auto c = rb::stress::checkResult(checkFile, checkExit, bounds, checkEnd);
      std::cout << rb::stress::toJson(c);
      return c.problems.empty() ? 0 : 2;
    }
    if (*tables) {
      to.root = root;
      return rb::app::buildTables(to);
    }
    if (*study) {
      so.root = root;
      so.program = fs::read_symlink("/proc/self/exe").string();
      return rb::study::runStudy(so);
    }
    const std::string program = fs::read_symlink("/proc/self/exe").string();
    if (*precision) {
      po.root = root;
      po.program = program;
      return rb::precision::runPrecision(po);
    }
    if (*stress) {
      sto.root = root;
      sto.program = program;
      return rb::stress::runStress(sto);
    }
    if (*effects) {
      eo.root = root;
      eo.program = program;
      return rb::effects::runEffects(eo);
    }
    if (*modes) {
      mo.root = root;
      mo.program = program;
      return rb::modes::runModes(mo);
    }
    if (*critical) {
      cso.root = root;
      cso.program = program;
      return rb::critical_speed::runCriticalSpeed(cso);
    }
    ro.root = root;
    return rb::app::runScenario(ro);
  } catch (const rb::InputError& e) {
    printInputError(e);
    return 1;
  } catch (const rb::io::BadResult& e) {
    // A forged or damaged result file (or a track store it names) refused by its reader: bad
    // input, and nothing was written.
    std::cerr << "error: " << e.what() << "\n1 problem found; nothing was run.\n";
    return 1;
  } catch (const rb::io::WriteError& e) {
    // An environment problem (disk full, no permission): the run's result could not be written,
    // and an earlier result under that name is unchanged.
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 3;
  }
}

}  // namespace

// Exit 3 is for our bugs only: anything that escapes the command (also while setting up the
// command line) is reported as an internal error, never as a crash.
int main(int argc, char** argv) {
  try {
    return workbench(argc, argv);
  } catch (const std::exception& e) {
    std::fputs("internal error: ", stderr);
    std::fputs(e.what(), stderr);
    std::fputs("\n", stderr);
  } catch (...) {
    std::fputs("internal error: unknown exception\n", stderr);
  }
  return 3;
}
