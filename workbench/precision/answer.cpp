#include "workbench/precision/answer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/io/read_stats.hpp"
#include "workbench/io/result_file.hpp"
#include "workbench/io/result_reader.hpp"

namespace fs = std::filesystem;

namespace rb::precision {
namespace {

std::string fmt(double v) {
  if (std::isinf(v)) return "inf";
  if (!std::isfinite(v)) return "";
  return formatNumber(v, 4);
}

struct RunFile {
  bool exists = false;
  bool ok = false;
  std::string status;
  std::string message;  // of the first repeat that did not end ok
  double rhs = 0.0;
  std::vector<double> cpu;  // [s] of every repeat that wrote it
  int runs_ok = 0;
};

// Every repeat of a case ended ok (status of /stats), its rhs evaluations from the first.
RunFile runFile(const fs::path& dir, const std::string& id, int repeats) {
  RunFile r;
  r.ok = true;
  for (int k = 0; k < repeats; ++k) {
    const auto st = io::readStats((dir / (id + "_r" + std::to_string(k) + ".h5")).string());
    if (!st) {
      r.ok = false;
      continue;
    }
    const std::string s = st->text.count("status") ? st->text.at("status") : "";
    if (!r.exists) {
      r.status = s;
      if (st->number.count("rhs_evals")) r.rhs = st->number.at("rhs_evals");
    }
    if (s != "ok" && r.message.empty() && st->text.count("message"))
      r.message = st->text.at("message");
    if (s != "ok") r.status = s.empty() ? "failed" : s;
    if (st->number.count("cpu_time_s")) r.cpu.push_back(st->number.at("cpu_time_s"));
    r.exists = true;
    r.ok = r.ok && s == "ok";
    r.runs_ok += s == "ok" ? 1 : 0;
  }
  if (!r.exists) {
    r.ok = false;
    r.status = "missing";
  }
  return r;
}

std::string baseModel(const std::string& model) {
  const auto sp = model.find(" refined");
  return sp == std::string::npos ? model : model.substr(0, sp);
}

}  // namespace

Recommendation recommend(const std::string& model, double level,
                         const std::vector<CaseAnswer>& cases, const ReferenceAnswer* ref,
                         bool refined_tables, const std::string& unit) {
  Recommendation r;
  r.model = model;
  r.level = level;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const CaseAnswer& c = cases[i];
    if (c.model != model || !c.ok || !c.integration.have || !(c.integration.max <= level)) continue;
    const CaseAnswer* b = r.best < 0 ? nullptr : &cases[static_cast<std::size_t>(r.best)];
    if (b == nullptr || c.cpu < b->cpu || (c.cpu == b->cpu && c.rhs < b->rhs))
      r.best = static_cast<int>(i);
  }
  r.reached = r.best >= 0;
  std::vector<std::string> notes;
  if (!r.reached) notes.push_back("none reaches it");
  const std::string lv = formatNumber(level) + " " + unit;
  if (ref == nullptr) {
    notes.push_back("no reference: cannot be verified");
  } else {
    if (!ref->verified)
      notes.push_back("reference UNVERIFIED (" + ref->why + "): cannot be verified");
    const Error& b = ref->bound.front();
    if (!b.have || b.max > level)
      notes.push_back("below the reference bound (" + (b.have ? fmt(b.max) : std::string("?")) +
                      " " + unit + "): not resolvable, cannot be verified");
    const Error& t = ref->table.front();
    if (!refined_tables && t.have && t.max > level) {
      r.table_limited = true;
      notes.push_back("cannot be reached with these tables: the table error " + fmt(t.max) + " " +
                      unit + " exceeds " + lv +
                      ", so the total error stays above it whatever the setting (the integration "
                      "error alone is answered; refined tables: --refine)");
    }
    r.verified = ref->verified && b.have && b.max <= level;
  }
  r.note = join(notes, "; ");
  return r;
}

namespace {

// The run id of a model's reference run of `role` ("" when the plan has none).
std::string referenceId(const Plan& p, const std::string& model, const std::string& role) {
  for (const auto& r : p.references)
    if (r.model == model && r.role == role) return r.c.id;
  return "";
}

fs::path runH5(const fs::path& dir, const std::string& id) {
  return dir / (id + "_r0.h5");
}

// Whether a model's references agree within the limit on every quantity, and why not.
ReferenceAnswer referenceAnswer(const Plan& p, const std::string& model,
                                const std::vector<Quantity>& quantities, double limit,
                                const fs::path& refDir) {
  ReferenceAnswer ra;
  ra.model = model;
  const std::string ref = referenceId(p, model, kRoleReference);
  const std::string check = referenceId(p, model, kRoleCheck);
  // The elastic method has no tables: its own reference is its same-tables reference.
  std::string same = referenceId(p, model, kRoleSameTables);
  if (same.empty()) same = ref;
  const RunFile fr = runFile(refDir, ref, 1);
  const RunFile fc = runFile(refDir, check, 1);
  for (const char* role : {kRoleReference, kRoleCheck, kRoleSameTables}) {
    ReferenceAnswer::Run run{role, "", "missing", 0.0, 0.0};
    const std::string id = referenceId(p, model, role);
    for (const auto& r : p.references)
      if (r.model == model && r.role == role) run.label = r.c.label;
    if (!id.empty()) {
      const RunFile f = runFile(refDir, id, 1);
      run.status = f.status;
      run.cpu = f.cpu.empty() ? 0.0 : f.cpu.front();
      run.rhs = f.rhs;
    }
    ra.runs.push_back(std::move(run));
  }
  const bool both_ok = !ref.empty() && !check.empty() && fr.ok && fc.ok;
  for (const auto& q : quantities) {
    ra.bound.push_back(study::fileError(runH5(refDir, check), runH5(refDir, ref), q));
    ra.table.push_back(study::fileError(runH5(refDir, same), runH5(refDir, ref), q));
  }
  ra.verified = both_ok;
  if (!both_ok) {
    // Which one and why (e.g. a wheel lift on the refined tables): the reader must see what
    // stands between the answer and its verification.
    std::vector<std::string> why;
    for (const auto& [role, f] : {std::pair{kRoleReference, &fr}, std::pair{kRoleCheck, &fc}})
      if (!f->ok)
        why.push_back(std::string(role) + " " + f->status +
                      (f->message.empty() ? "" : ": " + f->message.substr(0, 200)));
    ra.why = "a reference run failed (" + join(why, "; ") + ")";
  }
  for (std::size_t k = 0; k < quantities.size() && ra.verified; ++k) {
    const Quantity& q = quantities[k];
    if (!ra.bound[k].have) {
      ra.verified = false;
      ra.why = "no " + q.tag + " in the references";
    } else if (!(ra.bound[k].max <= limit)) {
      ra.verified = false;
      ra.why = "the references differ by " + fmt(ra.bound[k].max) + " " + q.unit + " in " + q.tag +
               " (limit " + formatNumber(limit) + ")";
    }
  }
  return ra;
}

// Every rung of every ladder with its errors against the references of its model.
std::vector<CaseAnswer> caseAnswers(const Plan& p, const std::vector<Quantity>& qs,
                                    const fs::path& refDir, const fs::path& caseDir, int repeats) {
  std::vector<CaseAnswer> out;
  for (const auto& l : p.ladders) {
    const std::string base = baseModel(l.model);
    const bool refined = base != l.model;
    std::string method;
    for (const auto& m : p.models)
      if (m.name == l.model) method = m.method;
    const std::string ref = referenceId(p, base, kRoleReference);
    std::string same = refined ? ref : referenceId(p, base, kRoleSameTables);
    if (same.empty()) same = ref;  // no tables (elastic)
    for (const auto& rung : l.rungs) {
      CaseAnswer c;
      c.model = l.model;
      c.integrator = l.integrator;
      c.label = rung.c.label;
      c.id = rung.c.id;
      c.fixed = l.fixed;
      c.value = rung.value;
      c.cpu = rung.cpu;
      c.status = rung.status;
      c.method = method;
      c.tables = tablesOf(method, l.model);
      c.kind = l.fixed ? "step" : "tol";
      c.note = rung.note;
      if (rung.status == "run") {
        const RunFile f = runFile(caseDir, c.id, repeats);
        c.status = f.status;
        c.ok = f.ok;
        c.rhs = f.rhs;
        c.runs_ok = f.runs_ok;
        if (!f.cpu.empty()) {
          c.cpu_min = *std::min_element(f.cpu.begin(), f.cpu.end());
          c.cpu_max = *std::max_element(f.cpu.begin(), f.cpu.end());
        }
        if (f.exists && !f.ok)
          c.note = "failed: error over the part it ran; " + f.message.substr(0, 160);
        if (f.exists)
          for (const auto& q : qs) {
            c.integration_all.push_back(
                study::fileError(runH5(caseDir, c.id), runH5(refDir, same), q));
            c.total_all.push_back(study::fileError(runH5(caseDir, c.id), runH5(refDir, ref), q));
          }
        if (!c.integration_all.empty()) {
          c.integration = c.integration_all.front();
          c.total = c.total_all.front();
        }
      }
      out.push_back(std::move(c));
    }
  }
  return out;
}

}  // namespace

Answer computeAnswer(const Plan& p, const std::string& out, int repeats) {
  Answer a;
  a.quantities = parseQuantities(p.quantities, p.bodies, p.contact);
  a.levels = p.levels;
  a.limit = p.limit;
  const fs::path refDir = fs::path(out) / "reference";
  const fs::path caseDir = fs::path(out) / "cases";
  for (const auto& m : p.models)
    if (!m.refined)
      a.references.push_back(referenceAnswer(p, m.name, a.quantities, a.limit, refDir));
  // Model error: each model's reference against the model reference's (both on their finest
  // tables, both at the reference tolerance), so integration and table errors are not in it.
  a.model_reference = p.model_reference;
  if (!p.model_reference.empty()) {
    const std::string against = referenceId(p, p.model_reference, kRoleReference);
    for (auto& r : a.references) {
      if (r.model == p.model_reference) continue;
      const std::string own = referenceId(p, r.model, kRoleReference);
      for (const auto& q : a.quantities)
        r.model_error.push_back(study::fileError(runH5(refDir, own), runH5(refDir, against), q));
    }
  }
  const Quantity& q0 = a.quantities.front();
  a.cases = caseAnswers(p, a.quantities, refDir, caseDir, repeats);
  for (const auto& m : p.models) {
    const std::string base = baseModel(m.name);
    const ReferenceAnswer* ref = nullptr;
    for (const auto& r : a.references)
      if (r.model == base) ref = &r;
    for (double level : a.levels)
      a.recommendations.push_back(recommend(m.name, level, a.cases, ref, m.refined, q0.unit));
  }
  return a;
}

std::string recommendationCsv(const Answer& a) {
  std::ostringstream s;
  s << "model,level,unit,quantity,setting,integrator,value,cpu_median_s,rhs_evals,error_max,"
       "total_error_max,case,reached,verified,table_limited,note\n";
  const Quantity& q = a.quantities.front();
  for (const auto& r : a.recommendations) {
    s << csvField(r.model) << "," << formatNumber(r.level) << "," << q.unit << "," << q.tag << ",";
    if (r.best >= 0) {
      const CaseAnswer& c = a.cases[static_cast<std::size_t>(r.best)];
      s << csvField(c.label) << "," << c.integrator << "," << formatNumberExact(c.value) << ","
        << fmt(c.cpu) << "," << formatNumber(c.rhs, 12) << "," << fmt(c.integration.max) << ","
        << (c.total.have ? fmt(c.total.max) : "") << "," << c.id << ",";
    } else {
      s << "none reaches it,,,,,,,,";
    }
    s << (r.reached ? 1 : 0) << "," << (r.verified ? 1 : 0) << "," << (r.table_limited ? 1 : 0)
      << "," << csvField(r.note) << "\n";
  }
  return s.str();
}

namespace {

// A number of the tables to the last bit (the printed answer rounds; a table is read back),
// "inf" for a diverged run, empty when it is not known.
std::string cell(bool have, double v) {
  if (!have || std::isnan(v)) return {};
  return std::isinf(v) ? std::string("inf") : formatNumberExact(v);
}

// The columns of precision.csv and their values per case, one definition for the CSV and the
// /cases datasets of precision.h5.
struct Table {
  std::vector<std::string> names;
  std::vector<std::vector<std::string>> rows;
};

Table casesTable(const Answer& a) {
  Table t;
  t.names = {"model", "method", "tables",       "integrator", "kind",      "value",   "label",
             "case",  "status", "cpu_median_s", "cpu_min_s",  "cpu_max_s", "runs_ok", "rhs_evals"};
  for (const auto& q : a.quantities)
    for (const char* what : {"integration", "total"})
      for (const char* stat : {"max", "rms"})
        t.names.push_back(q.tag + "_" + what + "_" + stat + "_" + q.unit);
  t.names.emplace_back("note");
  for (const auto& c : a.cases) {
    const bool ran = c.status != "planned" && c.status != "skipped";
    std::vector<std::string> r = {c.model,
                                  c.method,
                                  c.tables,
                                  c.integrator,
                                  c.kind,
                                  formatNumberExact(c.value),
                                  c.label,
                                  c.id,
                                  c.status,
                                  cell(ran && c.cpu > 0.0, c.cpu),
                                  cell(ran && c.cpu_max > 0.0, c.cpu_min),
                                  cell(ran && c.cpu_max > 0.0, c.cpu_max),
                                  ran ? std::to_string(c.runs_ok) : std::string(),
                                  ran ? formatNumber(c.rhs, 12) : std::string()};
    for (std::size_t k = 0; k < a.quantities.size(); ++k) {
      const Error none;
      const Error& i = k < c.integration_all.size() ? c.integration_all[k] : none;
      const Error& o = k < c.total_all.size() ? c.total_all[k] : none;
      for (const Error* e : {&i, &o}) {
        r.push_back(cell(e->have, e->max));
        r.push_back(cell(e->have, e->rms));
      }
    }
    r.push_back(c.note);
    t.rows.push_back(std::move(r));
  }
  return t;
}

Table referencesTable(const Answer& a) {
  Table t;
  t.names = {"model", "role", "label", "status", "cpu_median_s", "rhs_evals", "limit"};
  for (const auto& q : a.quantities)
    for (const char* stat : {"max", "rms"}) t.names.push_back(q.tag + "_" + stat + "_" + q.unit);
  const std::size_t nq = a.quantities.size();
  for (const auto& ref : a.references) {
    for (const auto& run : ref.runs) {
      std::vector<std::string> r = {ref.model,
                                    run.role,
                                    run.label,
                                    run.status,
                                    cell(run.status != "missing" && run.cpu > 0.0, run.cpu),
                                    run.status != "missing" ? formatNumber(run.rhs, 12) : "",
                                    ""};
      r.resize(t.names.size());
      t.rows.push_back(std::move(r));
    }
    const std::pair<const char*, const std::vector<Error>*> errors[] = {
        {"bound (reference_check vs reference)", &ref.bound},
        {"table error (same-tables reference vs reference)", &ref.table}};
    for (const auto& [role, errs] : errors) {
      const bool bound = errs == &ref.bound;
      std::vector<std::string> r = {
          ref.model,
          role,
          "",
          bound ? (ref.verified ? std::string("verified") : "UNVERIFIED: " + ref.why) : "",
          "",
          "",
          bound ? formatNumber(a.limit) : ""};
      for (std::size_t k = 0; k < nq; ++k) {
        const Error& e = (*errs)[k];
        r.push_back(cell(e.have, e.max));
        r.push_back(cell(e.have, e.rms));
      }
      t.rows.push_back(std::move(r));
    }
  }
  return t;
}

std::string csvOf(const Table& t) {
  std::ostringstream s;
  for (std::size_t i = 0; i < t.names.size(); ++i) s << (i ? "," : "") << csvField(t.names[i]);
  s << "\n";
  for (const auto& r : t.rows) {
    for (std::size_t i = 0; i < r.size(); ++i) s << (i ? "," : "") << csvField(r[i]);
    s << "\n";
  }
  return s.str();
}

// A table as one dataset per column under g: numbers where every cell of the column is a number
// or empty (empty: NaN), text otherwise.
void writeTable(io::ResultFile& f, const std::string& g, const Table& t) {
  if (t.rows.empty()) return;
  for (std::size_t c = 0; c < t.names.size(); ++c) {
    std::vector<double> numbers;
    std::vector<std::string> text;
    bool numeric = false, all = true;
    for (const auto& r : t.rows) {
      const std::string& v = r[c];
      text.push_back(v);
      if (v.empty()) {
        numbers.push_back(std::numeric_limits<double>::quiet_NaN());
        continue;
      }
      char* end = nullptr;
      const double x = std::strtod(v.c_str(), &end);
      if (end == v.c_str() || *end != '\0') {
        all = false;
        continue;
      }
      numbers.push_back(x);
      numeric = true;
    }
    if (numeric && all)
      f.dataset(g + "/" + t.names[c], numbers, "-");
    else
      f.stringDataset(g + "/" + t.names[c], text);
  }
}

}  // namespace

std::string casesCsv(const Answer& a) {
  return csvOf(casesTable(a));
}

std::string referencesCsv(const Answer& a) {
  return csvOf(referencesTable(a));
}

namespace {

// /reference_bound/<model>: whether the references agree, and their errors per quantity.
void writeReferenceBounds(io::ResultFile& f, const Answer& a) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const auto& r : a.references) {
    const std::string g = "/reference_bound/" + r.model;
    f.attr(g, "verified", std::int64_t{r.verified ? 1 : 0});
    f.attr(g, "why", r.why);
    for (std::size_t k = 0; k < a.quantities.size(); ++k) {
      const Quantity& q = a.quantities[k];
      const std::string u = "_" + q.unit;
      f.attr(g, q.tag + "_max" + u, r.bound[k].have ? r.bound[k].max : nan);
      f.attr(g, q.tag + "_rms" + u, r.bound[k].have ? r.bound[k].rms : nan);
      f.attr(g, q.tag + "_table_error_max" + u, r.table[k].have ? r.table[k].max : nan);
      f.attr(g, q.tag + "_table_error_rms" + u, r.table[k].have ? r.table[k].rms : nan);
      if (k < r.model_error.size()) {
        f.attr(g, q.tag + "_model_error_max" + u,
               r.model_error[k].have ? r.model_error[k].max : nan);
        f.attr(g, q.tag + "_model_error_rms" + u,
               r.model_error[k].have ? r.model_error[k].rms : nan);
      }
    }
    if (!r.model_error.empty()) f.attr(g, "model_reference", a.model_reference);
  }
}

// /recommendation: one row per model and level.
void writeRecommendations(io::ResultFile& f, const Answer& a) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::string> model, unit, quantity, setting, integrator, id, note;
  std::vector<double> level, value, cpu, rhs, error, total, reached, verified, limited;
  for (const auto& r : a.recommendations) {
    const CaseAnswer* c = r.best >= 0 ? &a.cases[static_cast<std::size_t>(r.best)] : nullptr;
    model.push_back(r.model);
    level.push_back(r.level);
    unit.push_back(a.quantities.front().unit);
    quantity.push_back(a.quantities.front().tag);
    setting.push_back(c ? c->label : "none reaches it");
    integrator.push_back(c ? c->integrator : "");
    value.push_back(c ? c->value : nan);
    cpu.push_back(c ? c->cpu : nan);
    rhs.push_back(c ? c->rhs : nan);
    error.push_back(c ? c->integration.max : nan);
    total.push_back(c && c->total.have ? c->total.max : nan);
    id.push_back(c ? c->id : "");
    reached.push_back(r.reached ? 1.0 : 0.0);
    verified.push_back(r.verified ? 1.0 : 0.0);
    limited.push_back(r.table_limited ? 1.0 : 0.0);
    note.push_back(r.note);
  }
  if (!model.empty()) {
    const std::string g = "/recommendation/";
    f.stringDataset(g + "model", model);
    f.dataset(g + "level", level, a.quantities.front().unit);
    f.stringDataset(g + "unit", unit);
    f.stringDataset(g + "quantity", quantity);
    f.stringDataset(g + "setting", setting);
    f.stringDataset(g + "integrator", integrator);
    f.dataset(g + "value", value, "s or -");
    f.dataset(g + "cpu_median_s", cpu, "s");
    f.dataset(g + "rhs_evals", rhs, "-");
    f.dataset(g + "error_max", error, a.quantities.front().unit);
    f.dataset(g + "total_error_max", total, a.quantities.front().unit);
    f.stringDataset(g + "case", id);
    f.dataset(g + "reached", reached, "-");
    f.dataset(g + "verified", verified, "-");
    f.dataset(g + "table_limited", limited, "-");
    f.stringDataset(g + "note", note);
  }
}

}  // namespace

void writeAnswerH5(const Answer& a, const std::string& path) {
  io::ResultFile f(path);
  std::vector<std::string> tags, units;
  for (const auto& q : a.quantities) {
    tags.push_back(q.tag);
    units.push_back(q.unit);
  }
  f.attr("/", "quantities", join(tags, ","));
  f.attr("/", "units", join(units, ","));
  f.attr("/", "reference_limit", a.limit);
  f.dataset("/levels", a.levels, a.quantities.front().unit);
  writeReferenceBounds(f, a);
  writeRecommendations(f, a);
  writeTable(f, "/cases", casesTable(a));
  writeTable(f, "/references", referencesTable(a));
  f.finalize();
}

namespace {

// One model's reference line of the printed answer: its state, bound, table error and, with a
// model reference, its model error in every quantity.
void printReference(const Answer& a, const ReferenceAnswer& r, std::ostream& out) {
  const Quantity& q = a.quantities.front();
  out << "  " << r.model << ": reference "
      << (r.verified ? std::string("verified") : "UNVERIFIED (" + r.why + ")") << "; bound "
      << (r.bound.front().have ? fmt(r.bound.front().max) : "?") << " " << q.unit
      << "; table error "
      << (r.model == "elastic"
              ? std::string("none (no tables)")
              : (r.table.front().have ? fmt(r.table.front().max) : "?") + " " + q.unit);
  if (!r.model_error.empty()) {
    // Every quantity: the model error is the answer's point, not only the first quantity.
    out << "; model error against " << a.model_reference << ":";
    for (std::size_t k = 0; k < a.quantities.size() && k < r.model_error.size(); ++k)
      out << " " << a.quantities[k].tag << " "
          << (r.model_error[k].have ? fmt(r.model_error[k].max) : "?") << " "
          << a.quantities[k].unit << " max, "
          << (r.model_error[k].have ? fmt(r.model_error[k].rms) : "?") << " rms"
          << (k + 1 < a.quantities.size() ? ";" : "");
  }
  out << "\n";
}

}  // namespace

void printAnswer(const Answer& a, std::ostream& out) {
  const Quantity& q = a.quantities.front();
  out << "\nRecommendation (computed by the engine): the cheapest setting whose integration error "
         "(max |"
      << q.tag << "| against the reference on the same tables) reaches each level\n";
  for (const auto& r : a.references) printReference(a, r, out);
  std::size_t w = 10;
  for (const auto& r : a.recommendations)
    if (r.best >= 0) w = std::max(w, a.cases[static_cast<std::size_t>(r.best)].label.size());
  out << "  " << std::left << std::setw(14) << "model" << std::right << std::setw(10) << "level"
      << "  " << std::left << std::setw(static_cast<int>(w)) << "setting" << std::right
      << std::setw(10) << "CPU [s]" << std::setw(11) << "rhs evals" << std::setw(10) << "error"
      << "  note\n";
  for (const auto& r : a.recommendations) {
    const CaseAnswer* c = r.best >= 0 ? &a.cases[static_cast<std::size_t>(r.best)] : nullptr;
    out << "  " << std::left << std::setw(14) << r.model << std::right << std::setw(10)
        << (formatNumber(r.level) + " " + q.unit) << "  " << std::left
        << std::setw(static_cast<int>(w)) << (c ? c->label : std::string("none reaches it"))
        << std::right << std::setw(10) << (c ? fmt(c->cpu) : "") << std::setw(11)
        << (c ? formatNumber(c->rhs, 12) : "") << std::setw(10)
        << (c ? fmt(c->integration.max) : "") << "  " << r.note << "\n";
  }
}

}  // namespace rb::precision
