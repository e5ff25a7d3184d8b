#include "workbench/app/tables.hpp"

#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "railbench/version.hpp"
#include "workbench/contact/derived.hpp"
#include "workbench/contact/kec.hpp"
#include "workbench/contact/lut.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/dynamics/contact_model.hpp"
#include "workbench/io/result_file.hpp"
#include "workbench/profiles/conicity.hpp"
#include "workbench/scenario/scenario.hpp"

namespace fs = std::filesystem;

namespace rb::app {
namespace {

std::vector<double> gridValues(const contact::GridSpec& g) {
  std::vector<double> v;
  for (std::size_t i = 0; i < g.count(); ++i) v.push_back(g.at(i));
  return v;
}

// Units of a LUT channel by its name ("left_k_w_trans", "right_flange_n_y", ...).
std::string lutUnits(const std::string& name) {
  auto has = [&](const char* part) { return name.find(part) != std::string::npos; };
  if (has("k_w_") || has("k_r_")) return "1/m";
  if (name.ends_with("_n_y") || name.ends_with("_n_z")) return "-";
  if (name == "phi" || has("gamma")) return "rad";
  return "m";  // z, s_w, s_r, radius, delta, d delta / d phi
}

void writeStats(io::ResultFile& f, const std::string& group, const contact::TableBuildStats& s) {
  f.attr(group, "build_time_s", s.build_seconds);
  f.attr(group, "bytes", static_cast<std::int64_t>(s.bytes));
  f.attr(group, "nodes", static_cast<std::int64_t>(s.nodes));
  f.attr(group, "newton_iterations", static_cast<std::int64_t>(s.newton_iterations));
  f.attr(group, "failures", static_cast<std::int64_t>(s.failures));
  f.attr(group, "warnings", join(s.warnings, "\n"));
  f.attr(group, "notes", join(s.notes, "\n"));
}

void writeProfile(io::ResultFile& f, const std::string& group, const profiles::Profile& p) {
  f.dataset(group + "/s", p.knots(), "m");
  f.dataset(group + "/h", p.values(), "m");
  f.attr(group, "name", p.name());
}

// Derived: rolling radius difference (EN 15302 convention r_l - r_r), its jumps and the
// conicity. The delta_r jumps (contact-point jumps, located on Eq. 12 between the nodes) enter the
// conicity as exact discontinuities: interpolating across one would bias tan(gamma_e) at
// amplitudes just beyond it.
void writeDerived(io::ResultFile& f, const contact::RollingRadiusTable& rr,
                  const profiles::RollingRadiusDifference& drf) {
  const std::string D = "/tables/derived";
  f.dataset(D + "/y", rr.y, "m");
  f.dataset(D + "/z", rr.z, "m");
  f.dataset(D + "/phi", rr.phi, "rad");
  f.dataset(D + "/r_left", rr.r_left, "m");
  f.dataset(D + "/r_right", rr.r_right, "m");
  f.dataset(D + "/delta_r", rr.delta_r, "m");
  f.dataset(D + "/delta_gamma", rr.delta_gamma, "rad");
  std::vector<double> jy, jl, jr, jside;
  for (const auto& j : rr.jumps) {
    jy.push_back(j.y);
    jl.push_back(j.delta_r_left);
    jr.push_back(j.delta_r_right);
    jside.push_back(j.side == contact::Side::Left ? 1.0 : -1.0);
  }
  f.dataset(D + "/jump_y", jy, "m");
  f.dataset(D + "/jump_delta_r_left", jl, "m");
  f.dataset(D + "/jump_delta_r_right", jr, "m");
  f.dataset(D + "/jump_side", jside, "-");
  std::vector<double> amp, tg;
  for (double a = 0.5e-3; a <= 10e-3 + 1e-12; a += 0.25e-3) {
    double t = drf.tanGammaE(a);
    if (!std::isfinite(t)) continue;
    amp.push_back(a);
    tg.push_back(t);
  }
  f.dataset(D + "/conicity_amplitude", amp, "m");
  f.dataset(D + "/tan_gamma_e", tg, "-");
}

}  // namespace

int buildTables(const RunOptions& o) {
  scenario::LoadOptions lo;
  lo.root = o.root;
  lo.overrides = o.overrides;
  scenario::ScenarioSpec spec = scenario::loadScenario(o.scenario, lo);
  // Without profiles{} / contact{} blocks the defaults apply (S1002 on 60E1 at 1:40).
  contact::ContactGeometryConfig cfg = dynamics::contactGeometryConfig(spec.profiles, spec.contact);

  std::string out =
      o.out.empty() ? "out/" + fs::path(o.scenario).stem().string() + "_tables.h5" : o.out;
  // The place to write is checked before the tables are built: nothing is computed for a result
  // that cannot be written.
  const std::unique_ptr<io::ResultFile> opened = openResultFile(out);
  io::ResultFile& f = *opened;

  contact::LutTable lut = contact::buildLut(cfg);
  contact::KecTable kec = contact::buildKec(cfg);
  f.attr("/", "version", std::string(kVersion));
  f.attr("/", "scenario_file", spec.file);
  f.attr("/", "scenario_text", spec.text);
  f.attr("/", "overrides", join(spec.overrides, "\n"));
  char hash[32];
  std::snprintf(hash, sizeof hash, "%016" PRIx64, contact::configHash(cfg));
  f.attr("/tables", "config_hash", std::string(hash));
  f.attr("/tables", "lw", cfg.wheel_lw);
  f.attr("/tables", "lr", cfg.rail_lr);
  f.attr("/tables", "beta", cfg.beta);
  f.attr("/tables", "r0", cfg.r0);

  writeProfile(f, "/profiles/wheel_left", *cfg.left_wheel);
  writeProfile(f, "/profiles/rail_left", *cfg.left_rail);

  // LUT: every channel on the (gauge, y) grid, row = gauge variation.
  const std::string L = "/tables/lut";
  f.dataset(L + "/y", gridValues(lut.yGrid()), "m");
  f.dataset(L + "/xi_g", gridValues(lut.gaugeGrid()), "m");
  for (std::size_t c = 0; c < contact::kLutChannels; ++c) {
    std::vector<double> v(lut.ng() * lut.ny());
    for (std::size_t ig = 0; ig < lut.ng(); ++ig)
      for (std::size_t iy = 0; iy < lut.ny(); ++iy) v[ig * lut.ny() + iy] = lut.node(c, iy, ig);
    std::string name = contact::lutChannelName(c);
    for (char& ch : name)
      if (ch == '.') ch = '_';
    f.dataset2d(L + "/" + name, lut.ng(), lut.ny(), v, lutUnits(name));
  }
  std::vector<double> tpY, tpXi, tpSide;
  for (const auto& t : lut.twoPointContacts()) {
    tpY.push_back(t.y);
    tpXi.push_back(t.xi_g);
    tpSide.push_back(t.side == contact::Side::Left ? 1.0 : -1.0);
  }
  f.dataset(L + "/two_point/y", tpY, "m");
  f.dataset(L + "/two_point/xi_g", tpXi, "m");
  f.dataset(L + "/two_point/side", tpSide, "-");
  writeStats(f, L, lut.stats());

  // KEC: equivalent profiles and the maps of Eq. 23 on the s_k grid.
  const std::string K = "/tables/kec";
  std::vector<double> sk = gridValues(kec.grid());
  f.dataset(K + "/s_k", sk, "m");
  for (auto side : {contact::Side::Left, contact::Side::Right}) {
    std::string p = K + (side == contact::Side::Left ? "/left_" : "/right_");
    std::vector<double> fk, sw, sr, w;
    contact::KecPoint pt;
    for (double s : sk) {
      kec.eval(side, s, pt);
      fk.push_back(pt.value[static_cast<std::size_t>(contact::KecQuantity::F)]);
      sw.push_back(pt.value[static_cast<std::size_t>(contact::KecQuantity::Sw)]);
      sr.push_back(pt.value[static_cast<std::size_t>(contact::KecQuantity::Sr)]);
      w.push_back(pt.value[static_cast<std::size_t>(contact::KecQuantity::Weight)]);
    }
    f.dataset(p + "f", fk, "m");
    f.dataset(p + "s_w", sw, "m");
    f.dataset(p + "s_r", sr, "m");
    f.dataset(p + "weight", w, "-");
    std::vector<double> sj, lo2, hi;
    for (const auto& t : kec.transitions(side)) {
      sj.push_back(t.s_jump);
      lo2.push_back(t.lo);
      hi.push_back(t.hi);
    }
    f.dataset(p + "transition_s", sj, "m");
    f.dataset(p + "transition_lo", lo2, "m");
    f.dataset(p + "transition_hi", hi, "m");
  }
  f.attr(K, "dhat", cfg.kec_dhat);
  f.attr(K, "dbar", cfg.kec_dbar);
  writeStats(f, K, kec.stats());

  const contact::ContactSolver solver(cfg);
  const contact::RollingRadiusTable rr = contact::rollingRadiusDifference(lut, solver, 0.0);
  const profiles::RollingRadiusDifference drf = contact::conicityInput(rr);
  writeDerived(f, rr, drf);
  f.finalize();

  std::cout << "wrote " << out << ": LUT " << lut.ny() << " x " << lut.ng() << " in "
            << lut.stats().build_seconds << " s (" << lut.stats().bytes / 1024 << " KiB), KEC "
            << sk.size() << " points in " << kec.stats().build_seconds << " s ("
            << kec.stats().bytes / 1024 << " KiB), config hash " << hash << "\n";
  for (double a : {2e-3, 3e-3, 4e-3}) {
    double t = drf.tanGammaE(a);
    if (std::isfinite(t))
      std::cout << "  equivalent conicity tan(gamma_e) at " << a * 1e3 << " mm: " << t << "\n";
  }
  for (const auto& j : rr.jumps)
    std::cout << "  delta_r jump (" << (j.side == contact::Side::Left ? "left" : "right")
              << " wheel) at y = " << j.y * 1e3 << " mm: " << j.delta_r_left * 1e3 << " -> "
              << j.delta_r_right * 1e3 << " mm\n";
  for (const auto& t : lut.twoPointContacts())
    if (std::abs(t.xi_g) < 1e-12)
      std::cout << "  two-point contact (" << (t.side == contact::Side::Left ? "left" : "right")
                << " wheel) at y = " << t.y * 1e3 << " mm\n";
  for (const auto& w : lut.stats().warnings) std::cerr << "warning: LUT: " << w << "\n";
  for (const auto& w : kec.stats().warnings) std::cerr << "warning: KEC: " << w << "\n";
  return 0;
}

}  // namespace rb::app
