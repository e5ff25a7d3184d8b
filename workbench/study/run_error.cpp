#include "workbench/study/run_error.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <regex>
#include <sstream>

#include "workbench/core/error.hpp"
#include "workbench/core/strings.hpp"
#include "workbench/io/result_reader.hpp"

namespace fs = std::filesystem;

namespace rb::study {
namespace {

const SourceLoc kCommandLine{"<command line>", 0};

struct Unit {
  double scale;
  const char* unit;
};

// Display unit of a body coordinate (from SI).
std::optional<Unit> bodyUnit(const std::string& c) {
  if (c == "y" || c == "z") return Unit{1e3, "mm"};
  if (c == "roll" || c == "pitch" || c == "yaw") return Unit{1e3, "mrad"};
  return std::nullopt;
}

// The per-wheel quantities: the wheel/rail normal force, the lateral creep force, and the
// EN 14363 running-safety quantities of the contact output (track-lateral wheel force Y, Y/Q).
struct WheelTag {
  const char* tag;
  const char* dataset;
  double scale;
  const char* unit;
};
constexpr WheelTag kWheelTags[] = {{"Q", "normal_force", 1e-3, "kN"},
                                   {"Fy", "creep_force_y", 1e-3, "kN"},
                                   {"Y", "Y", 1e-3, "kN"},
                                   {"YQ", "y_over_q", 1.0, "-"}};

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  for (std::string l; std::getline(ss, l);) {
    l.erase(0, l.find_first_not_of(" \t\r"));
    l.erase(l.find_last_not_of(" \t\r") + 1);
    if (!l.empty()) out.push_back(l);
  }
  return out;
}

// {series name: values in SI} of quantity q of one vehicle whose groups are under `root` ("" for
// a single vehicle, "/vehicles/<name>" in a run of several), the names prefixed by `key`.
void vehicleSeries(const io::ResultReader& f, const Quantity& q, const std::string& root,
                   const std::string& key, std::map<std::string, std::vector<double>>& out) {
  const std::vector<std::string> names = lines(f.text(root + "/bodies", "names").value_or(""));
  auto kind = [&](const std::string& n) {
    return f.text(root + "/bodies/" + n, "kind").value_or("");
  };
  auto put = [&](const std::string& name, const std::string& path) {
    if (auto v = f.dataset(root + path)) out[key + name] = std::move(*v);
  };
  if (q.group == "body") {
    put(q.body, "/bodies/" + q.body + "/" + q.dataset);
  } else if (q.group == "wheels") {
    for (const auto& n : names)
      if (kind(n) == "wheelset")
        for (const char* side : {"left", "right"})
          put(n + " " + side, "/contact/" + n + "/" + side + "/" + q.dataset);
  } else {
    // Guided wheelsets follow the track kinematically (no error of their own): on a vehicle
    // without contact the quantity covers every other body.
    const bool contact = f.has(root + "/contact");
    for (const auto& n : names)
      if ((kind(n) == "wheelset") == contact) put(n, "/bodies/" + n + "/" + q.dataset);
  }
}

// {series name: values in SI} of quantity q in a result file: of its one vehicle, or of every
// vehicle of a run of several ("<vehicle>/<series>").
std::map<std::string, std::vector<double>> series(const io::ResultReader& f, const Quantity& q) {
  std::map<std::string, std::vector<double>> out;
  const std::string head = "/vehicles/";
  for (const auto& g : f.vehicleGroups())
    vehicleSeries(f, q, g, g.empty() ? "" : g.substr(head.size()) + "/", out);
  return out;
}

// Linear interpolation of (t, v) at x, t increasing, x inside [t.front(), t.back()].
double interpolate(const std::vector<double>& t, const std::vector<double>& v, std::size_t n,
                   double x) {
  const auto it = std::lower_bound(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(n), x);
  std::size_t j = static_cast<std::size_t>(it - t.begin());
  if (j >= n) return v[n - 1];
  if (t[j] == x || j == 0) return v[j];
  const double w = (x - t[j - 1]) / (t[j] - t[j - 1]);
  return v[j - 1] + w * (v[j] - v[j - 1]);
}

}  // namespace

std::vector<Quantity> parseQuantities(const std::vector<std::string>& tags,
                                      const std::vector<std::string>& bodies, bool contact) {
  std::vector<Quantity> out;
  static const std::regex kBody(R"(([A-Za-z0-9_\-]+)\.(y|z|roll|pitch|yaw))");
  for (const auto& tag : tags) {
    Quantity q;
    q.tag = tag;
    std::smatch m;
    const auto wheel = std::find_if(std::begin(kWheelTags), std::end(kWheelTags),
                                    [&](const WheelTag& w) { return tag == w.tag; });
    if (tag == "y" || tag == "yaw") {
      const Unit u = *bodyUnit(tag);
      q.group = "wheelsets";
      q.dataset = tag;
      q.scale = u.scale;
      q.unit = u.unit;
    } else if (wheel != std::end(kWheelTags)) {
      if (!contact)
        throw InputError(kCommandLine, "--quantities: '" + tag +
                                           "' is a wheel/rail contact quantity, but the "
                                           "scenario's vehicle has no contact (guided)");
      q.group = "wheels";
      q.dataset = wheel->dataset;
      q.scale = wheel->scale;
      q.unit = wheel->unit;
    } else if (std::regex_match(tag, m, kBody)) {
      q.group = "body";
      q.body = m[1];
      q.dataset = m[2];
      if (std::find(bodies.begin(), bodies.end(), q.body) == bodies.end())
        throw InputError(kCommandLine, "--quantities: '" + tag + "': the vehicle has no body '" +
                                           q.body + "' (bodies: " + join(bodies) + ")");
      const Unit u = *bodyUnit(q.dataset);
      q.scale = u.scale;
      q.unit = u.unit;
    } else {
      throw InputError(kCommandLine, "--quantities: unknown '" + tag +
                                         "' (y, yaw, Q, Fy, Y, YQ or BODY.y|z|roll|pitch|yaw)");
    }
    out.push_back(std::move(q));
  }
  if (out.empty()) throw InputError(kCommandLine, "--quantities: no entry");
  return out;
}

Error runError(const io::ResultReader& run, const io::ResultReader& ref, const Quantity& q) {
  Error e;
  const auto t = run.dataset("/time");
  const auto tr = ref.dataset("/time");
  if (!t || !tr || t->size() < 2 || tr->size() < 2) return e;
  const auto s = series(run, q);
  const auto r = series(ref, q);
  double mx = 0.0, sum = 0.0;
  std::size_t n = 0;
  bool diverged = false;
  for (const auto& [key, rv] : r) {
    const auto it = s.find(key);
    if (it == s.end()) continue;
    const std::vector<double>& v = it->second;
    const std::size_t nv = std::min(t->size(), v.size());
    if (nv < 2) continue;
    const double t0 = (*t)[0] - 1e-12, t1 = (*t)[nv - 1] + 1e-12;
    // A non-finite value of the run inside its range: diverged, whatever the reference says.
    if (!std::all_of(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(nv),
                     [](double x) { return std::isfinite(x); }))
      diverged = true;
    const std::size_t nr = std::min(tr->size(), rv.size());
    for (std::size_t i = 0; i < nr; ++i) {
      const double x = (*tr)[i];
      if (x < t0 || x > t1) continue;
      const double d = (interpolate(*t, v, nv, x) - rv[i]) * q.scale;
      if (!std::isfinite(d)) {
        diverged = true;
        continue;
      }
      mx = std::max(mx, std::abs(d));
      sum += d * d;
      ++n;
    }
  }
  if (n == 0 && !diverged) return e;
  e.have = true;
  e.max = diverged ? kInf : mx;
  e.rms = diverged ? kInf : std::sqrt(sum / static_cast<double>(n));
  return e;
}

Error fileError(const std::string& run, const std::string& ref, const Quantity& q) {
  std::error_code ec;
  if (!fs::exists(run, ec) || !fs::exists(ref, ec)) return {};
  const io::ResultReader a(run);
  const io::ResultReader b(ref);
  if (!a.ok() || !b.ok()) return {};
  return runError(a, b, q);
}

}  // namespace rb::study
