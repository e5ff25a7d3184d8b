#include "workbench/study/reference_errors.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>

#include "workbench/core/strings.hpp"
#include "workbench/io/result_reader.hpp"
#include "workbench/study/run_error.hpp"

namespace rb::study {

namespace {

bool numerical(const std::string& key) {
  return key.rfind("solver.", 0) == 0 || key.rfind("run.output.", 0) == 0 ||
         key == "profiles.refined_tables" || key == "contact.normal_forces";
}

std::string errorField(double v) {
  return std::isinf(v) ? std::string("inf") : formatNumberExact(v);
}

const CaseResult* firstOfRole(const std::vector<CaseResult>& cases, const std::string& role,
                              const std::string& key) {
  for (const auto& r : cases)
    if (r.c->role == role && !r.file.empty() && (key.empty() || physicalKey(*r.c) == key))
      return &r;
  return nullptr;
}

}  // namespace

std::string physicalKey(const scenario::StudyCase& c) {
  std::vector<std::string> keep;
  for (const auto& o : c.overrides)
    if (!numerical(o.substr(0, o.find('=')))) keep.push_back(o);
  std::sort(keep.begin(), keep.end());
  return c.base + "\n" + join(keep, "\n");
}

std::string referenceErrorsCsv(const std::vector<CaseResult>& cases) {
  struct Pair {
    const CaseResult* run;
    const CaseResult* ref;
    std::string against;
  };
  std::vector<Pair> pairs;
  const CaseResult* baseline = firstOfRole(cases, "baseline", "");
  for (const auto& r : cases) {
    if (r.file.empty()) continue;
    const std::string key = physicalKey(*r.c);
    if (r.c->role.rfind("reference", 0) != 0) {
      for (const char* role : {"reference", "reference_same_tables"})
        if (const CaseResult* ref = firstOfRole(cases, role, key)) pairs.push_back({&r, ref, role});
    } else if (r.c->role == "reference" && firstOfRole(cases, "reference", key) == &r) {
      for (const char* role : {"reference_check", "reference_same_tables"})
        if (const CaseResult* other = firstOfRole(cases, role, key))
          pairs.push_back({other, &r, "reference"});
    }
    if (baseline != nullptr) pairs.push_back({&r, baseline, "baseline"});
  }
  std::ostringstream s;
  s << "case,against,reference,quantity,unit,max,rms\n";
  if (pairs.empty()) return s.str();
  const std::vector<Quantity> quantities = parseQuantities({"y", "yaw", "Q", "Fy"}, {}, true);
  // Each file is opened once, however many pairs it is in.
  std::map<std::string, std::unique_ptr<io::ResultReader>> open;
  const auto reader = [&](const std::string& f) -> const io::ResultReader& {
    auto& p = open[f];
    if (!p) p = std::make_unique<io::ResultReader>(f);
    return *p;
  };
  for (const auto& p : pairs) {
    const io::ResultReader& a = reader(p.run->file);
    const io::ResultReader& b = reader(p.ref->file);
    for (const auto& q : quantities) {
      const Error e = a.ok() && b.ok() ? runError(a, b, q) : Error{};
      s << p.run->c->id << "," << p.against << "," << p.ref->c->id << "," << q.tag << "," << q.unit
        << "," << (e.have ? errorField(e.max) : "") << "," << (e.have ? errorField(e.rms) : "")
        << "\n";
    }
  }
  return s.str();
}

}  // namespace rb::study
