#include "workbench/scenario/scenario.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "workbench/core/strings.hpp"
#include "workbench/integrators/registry.hpp"
#include "workbench/scenario/lua_host.hpp"
#include "workbench/scenario/schema.hpp"

namespace rb::scenario {
namespace {

const SourceLoc kCommandLine{"<command line>", 0};

std::string fmt(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

// Typed, validated access to one block's keys, driven by its BlockSpec.
class Reader {
 public:
  Reader(const Node& node, const BlockSpec& spec, std::string path, Diagnostics& d)
      : node_(node), spec_(spec), path_(std::move(path)), d_(d) {
    label_ = path_;
    if (!node.kind.empty() && node.kind != path_) label_ += " (" + node.kind + ")";
    for (const auto& [k, v] : node.fields) {
      if (spec.key(k)) continue;
      std::string msg = "unknown key '" + k + "'";
      std::string hint = closestMatch(k, spec.keyNames());
      if (!hint.empty())
        msg += " (did you mean '" + hint + "'?)";
      else
        msg += " (valid keys: " + join(spec.keyNames(), ", ") + ")";
      error(v, msg);
    }
    if (!node.items.empty())
      error(node, "expects named values (key = value), not a list of " +
                      std::to_string(node.items.size()) + " entries");
  }

  const std::string& path() const { return path_; }
  const SourceLoc& loc() const { return node_.loc; }
  void error(const Node& at, const std::string& msg) { d_.add(at.loc, label_ + ": " + msg); }
  void errorAt(const SourceLoc& loc, const std::string& msg) { d_.add(loc, label_ + ": " + msg); }

  const Node* value(const std::string& name) {
    const KeySpec& k = key(name);
    const Node* v = node_.field(name);
    if (v && v->type == Node::Type::Nil) v = nullptr;
    if (!v && k.required) error(node_, "missing required key '" + name + "'");
    return v;
  }

  double number(const std::string& name) {
    const KeySpec& k = key(name);
    const Node* v = value(name);
    if (!v) return k.num_default;
    if (v->type != Node::Type::Number) {
      error(*v, name + " must be a number" + unitText(k) + ", got " + v->describe());
      return k.num_default;
    }
    checkRange(*v, k, v->number);
    if (k.type == ValueType::Integer && v->number != std::floor(v->number))
      error(*v, name + " must be a whole number, got " + fmt(v->number));
    return v->number;
  }

  std::string choice(const std::string& name) {
    const KeySpec& k = key(name);
    const Node* v = value(name);
    if (!v) return k.def;
    if (v->type != Node::Type::String) {
      error(*v, name + " must be one of " + join(k.choices, ", ") + "; got " + v->describe());
      return k.def;
    }
    for (const auto& c : k.choices)
      if (c == v->string) return c;
    std::string msg = name + ": unknown value '" + v->string + "'";
    std::string hint = closestMatch(v->string, k.choices);
    if (!hint.empty()) msg += " (did you mean '" + hint + "'?)";
    msg += "; valid: " + join(k.choices, ", ");
    error(*v, msg);
    return k.def;
  }

  std::string string(const std::string& name) {
    const Node* v = value(name);
    if (!v) return {};
    if (v->type != Node::Type::String) {
      error(*v, name + " must be a string, got " + v->describe());
      return {};
    }
    return v->string;
  }

  bool pair(const std::string& name, double& a, double& b) {
    const KeySpec& k = key(name);
    const Node* v = value(name);
    if (!v) return false;
    if (v->type != Node::Type::Table || v->items.size() != 2 || !v->fields.empty() ||
        v->items[0].type != Node::Type::Number || v->items[1].type != Node::Type::Number) {
      error(*v, name + " must be a pair of numbers {min, max}" + unitText(k) + ", got " +
                    v->describe());
      return false;
    }
    a = v->items[0].number;
    b = v->items[1].number;
    checkRange(*v, k, a);
    checkRange(*v, k, b);
    if (!(a < b))
      error(*v, name + " must be {min, max} with min < max, got {" + fmt(a) + ", " + fmt(b) + "}");
    return true;
  }

  // A nested constructor block (kinds) or plain table (sub); nullptr if absent or wrong.
  const Node* blockValue(const std::string& name) {
    const KeySpec& k = key(name);
    const Node* v = value(name);
    if (!v) return nullptr;
    if (v->type != Node::Type::Table) {
      error(*v, name + " must be " + expected(k) + ", got " + v->describe());
      return nullptr;
    }
    if (!k.kinds.empty() && !isKind(*v, k)) {
      error(*v, name + " must be " + expected(k) + ", got " + v->describe());
      return nullptr;
    }
    return v;
  }

  std::vector<const Node*> blockList(const std::string& name) {
    const KeySpec& k = key(name);
    const Node* v = value(name);
    std::vector<const Node*> out;
    if (!v) return out;
    if (v->type != Node::Type::Table || !v->fields.empty()) {
      error(*v, name + " must be a list of " + expected(k) + ", got " + v->describe());
      return out;
    }
    if (v->items.empty()) error(*v, name + " must not be empty");
    for (std::size_t i = 0; i < v->items.size(); ++i) {
      const Node& item = v->items[i];
      if (item.type != Node::Type::Table || !isKind(item, k)) {
        error(item, name + "[" + std::to_string(i + 1) + "] must be " + expected(k) + ", got " +
                        item.describe());
        continue;
      }
      out.push_back(&item);
    }
    return out;
  }

  std::vector<std::string> stringList(const std::string& name) {
    const KeySpec& k = key(name);
    const Node* v = value(name);
    std::vector<std::string> out;
    if (!v) return k.choices;
    if (v->type != Node::Type::Table || !v->fields.empty()) {
      error(*v, name + " must be a list of names from: " + join(k.choices, ", "));
      return out;
    }
    for (const auto& item : v->items) {
      bool ok = item.type == Node::Type::String;
      if (ok) {
        ok = false;
        for (const auto& c : k.choices) ok = ok || c == item.string;
      }
      if (!ok) {
        std::string msg = name + ": unknown entry " + item.describe();
        if (item.type == Node::Type::String) {
          std::string hint = closestMatch(item.string, k.choices);
          if (!hint.empty()) msg += " (did you mean '" + hint + "'?)";
        }
        error(item, msg + "; valid: " + join(k.choices, ", "));
        continue;
      }
      out.push_back(item.string);
    }
    return out;
  }

  bool boolean(const std::string& name) {
    const KeySpec& k = key(name);
    const Node* v = value(name);
    if (!v) return k.num_default != 0.0;
    if (v->type != Node::Type::Bool) {
      error(*v, name + " must be true or false, got " + v->describe());
      return k.num_default != 0.0;
    }
    return v->boolean;
  }

  // {x, y, z}: true when present and well-formed (out stays zero otherwise).
  bool vec3(const std::string& name, Eigen::Vector3d& out) {
    const KeySpec& k = key(name);
    const Node* v = value(name);
    out.setZero();
    if (!v) return false;
    bool ok = v->type == Node::Type::Table && v->fields.empty() && v->items.size() == 3;
    for (std::size_t i = 0; ok && i < 3; ++i) ok = v->items[i].type == Node::Type::Number;
    if (!ok) {
      error(*v, name + " must be {x, y, z} of numbers" + unitText(k) + ", got " + v->describe());
      return false;
    }
    for (int i = 0; i < 3; ++i) out[i] = v->items[static_cast<std::size_t>(i)].number;
    if (!out.allFinite()) {
      error(*v, name + " must be finite");
      return false;
    }
    return true;
  }

  // {{a, b}, ...}: fills a and b; false if absent or malformed.
  bool pairList(const std::string& name, std::vector<double>& a, std::vector<double>& b) {
    const Node* v = value(name);
    if (!v) return false;
    if (v->type != Node::Type::Table || !v->fields.empty() || v->items.empty()) {
      error(*v, name + " must be a list of pairs {{a, b}, ...}, got " + v->describe());
      return false;
    }
    for (std::size_t i = 0; i < v->items.size(); ++i) {
      const Node& p = v->items[i];
      if (p.type != Node::Type::Table || p.items.size() != 2 || !p.fields.empty() ||
          p.items[0].type != Node::Type::Number || p.items[1].type != Node::Type::Number) {
        error(*v, name + "[" + std::to_string(i + 1) + "] must be a pair of numbers {a, b}");
        return false;
      }
      a.push_back(p.items[0].number);
      b.push_back(p.items[1].number);
    }
    return true;
  }

  // A list of free-form names {"a", "b"} (checked later against the model).
  std::vector<std::string> names(const std::string& name) {
    const Node* v = value(name);
    std::vector<std::string> out;
    if (!v) return out;
    if (v->type != Node::Type::Table || !v->fields.empty()) {
      error(*v, name + " must be a list of names {\"a\", \"b\"}, got " + v->describe());
      return out;
    }
    for (const auto& item : v->items) {
      if (item.type != Node::Type::String) {
        error(item, name + ": entries must be strings, got " + item.describe());
        continue;
      }
      out.push_back(item.string);
    }
    return out;
  }

  bool has(const std::string& name) const {
    const Node* v = node_.field(name);
    return v && v->type != Node::Type::Nil;
  }

 private:
  const KeySpec& key(const std::string& name) const {
    const KeySpec* k = spec_.key(name);
    RB_CHECK(k != nullptr, "schema of '" + spec_.name + "' has no key '" + name + "'");
    return *k;
  }
  static std::string unitText(const KeySpec& k) {
    return (k.unit.empty() || k.unit == "-") ? std::string() : " [" + k.unit + "]";
  }
  static bool isKind(const Node& n, const KeySpec& k) {
    for (const auto& kind : k.kinds)
      if (n.kind == kind) return true;
    return false;
  }
  static std::string expected(const KeySpec& k) {
    if (k.kinds.empty()) return "a table { ... }";
    std::string s;
    for (std::size_t i = 0; i < k.kinds.size(); ++i)
      s += (i ? (i + 1 == k.kinds.size() ? " or " : ", ") : "") + k.kinds[i] + "{...}";
    return s;
  }
  void checkRange(const Node& at, const KeySpec& k, double x) {
    std::string u = (k.unit.empty() || k.unit == "-") ? "" : " " + k.unit;
    if (!std::isfinite(x)) {
      error(at, k.name + " must be finite, got " + fmt(x));
    } else if (k.min_exclusive ? !(x > k.min) : !(x >= k.min)) {
      error(at, k.name + " must be " + (k.min_exclusive ? "> " : ">= ") + fmt(k.min) + u +
                    ", got " + fmt(x));
    } else if (k.max_exclusive ? !(x < k.max) : !(x <= k.max)) {
      error(at, k.name + " must be " + (k.max_exclusive ? "< " : "<= ") + fmt(k.max) + u +
                    ", got " + fmt(x));
    }
  }

  const Node& node_;
  const BlockSpec& spec_;
  std::string path_;
  std::string label_;
  Diagnostics& d_;
};

// ---------------------------------------------------------------------------------------------
// --set overrides

Node parseOverrideValue(const std::string& text) {
  Node n;
  n.loc = kCommandLine;
  char* end = nullptr;
  double v = std::strtod(text.c_str(), &end);
  if (!text.empty() && end && *end == '\0') {
    n.type = Node::Type::Number;
    n.number = v;
  } else if (text == "true" || text == "false") {
    n.type = Node::Type::Bool;
    n.boolean = text == "true";
  } else {
    n.type = Node::Type::String;
    n.string = text;
    if (n.string.size() >= 2 && (n.string.front() == '"' || n.string.front() == '\'') &&
        n.string.back() == n.string.front())
      n.string = n.string.substr(1, n.string.size() - 2);
  }
  return n;
}

void applyOverride(Node& root, const std::string& assignment, Diagnostics& d) {
  auto fail = [&](const std::string& msg) {
    d.add(kCommandLine, "--set " + assignment + ": " + msg);
  };
  auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) return fail("expected key=value, e.g. solver.step=5e-4");
  std::string path = assignment.substr(0, eq);
  std::string value = assignment.substr(eq + 1);
  // Tokens: names and 1-based list positions, "a.b[2].c" or "a.b.2.c".
  std::vector<std::string> tokens;
  std::string cur;
  for (char c : path) {
    if (c == '.' || c == '[' || c == ']') {
      if (!cur.empty()) tokens.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) tokens.push_back(cur);
  if (tokens.size() < 2) return fail("the key must name a block and a key, e.g. solver.step");
  for (const auto& t : tokens) {
    const bool index = t.find_first_not_of("0123456789") == std::string::npos;
    const bool name = !std::isdigit(static_cast<unsigned char>(t[0])) &&
                      t.find_first_not_of(
                          "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ_"
                          "0123456789") == std::string::npos;
    if (!index && !name)
      return fail("'" + t + "' is neither a key name nor a list position (1, 2, ...)");
  }
  const auto& tops = topLevelBlocks();
  Node* node = root.field(tokens[0]);
  if (!node) {
    bool known = false;
    for (const auto& t : tops) known = known || t == tokens[0];
    if (!known) {
      std::string hint = closestMatch(tokens[0], tops);
      return fail("unknown block '" + tokens[0] + "'" +
                  (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
    }
    Node b;
    b.type = Node::Type::Table;
    b.kind = tokens[0];
    b.loc = kCommandLine;
    node = &root.setField(tokens[0], std::move(b));
  }
  for (std::size_t i = 1; i < tokens.size(); ++i) {
    const std::string& t = tokens[i];
    bool last = i + 1 == tokens.size();
    bool isIndex = !t.empty() && t.find_first_not_of("0123456789") == std::string::npos;
    if (node->type != Node::Type::Table)
      return fail("'" + tokens[i - 1] + "' is not a table, cannot set '" + t + "' in it");
    if (isIndex) {
      // More digits than any list can have: out of range, without overflowing the conversion.
      const std::size_t idx = t.size() > 9 ? 0 : std::stoul(t);
      if (idx < 1 || idx > node->items.size())
        return fail("list position " + t + " out of range 1.." +
                    std::to_string(node->items.size()));
      if (last) {
        node->items[idx - 1] = parseOverrideValue(value);
        return;
      }
      node = &node->items[idx - 1];
    } else if (last) {
      Node v = parseOverrideValue(value);
      node->setField(t, std::move(v));
      return;
    } else {
      Node* next = node->field(t);
      if (!next) {
        Node tbl;
        tbl.type = Node::Type::Table;
        tbl.loc = kCommandLine;
        next = &node->setField(t, std::move(tbl));
      }
      node = next;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Blocks -> Specs

track::PsdTable readPsdInput(const Node& v, const std::string& path, Reader& r, double omegaMin,
                             double omegaMax) {
  track::PsdTable t;
  if (v.type == Node::Type::Function) {
    // Tabulate the user's function log-spaced over a band a little wider than the synthesis band.
    const int n = 400;
    double a = std::log(omegaMin / 2), b = std::log(omegaMax * 2);
    for (int i = 0; i < n; ++i) {
      double om = std::exp(a + (b - a) * i / (n - 1));
      double g = 0;
      try {
        g = (*v.function)(om);
      } catch (const InputError& e) {
        // Where the function raised the error, not where the psd{} block starts.
        for (const auto& diag : e.diagnostics())
          r.errorAt(diag.loc.line > 0 ? diag.loc : v.loc, path + ": " + diag.message);
        return {};
      }
      if (!std::isfinite(g) || g < 0) {
        r.error(v, path + ": PSD function returned " + fmt(g) + " at omega = " + fmt(om) +
                       " rad/m; it must be finite and >= 0");
        return {};
      }
      t.omega.push_back(om);
      t.value.push_back(g);
    }
    return t;
  }
  if (v.type == Node::Type::Table && v.fields.empty()) {
    for (std::size_t i = 0; i < v.items.size(); ++i) {
      const Node& p = v.items[i];
      if (p.type != Node::Type::Table || p.items.size() != 2 ||
          p.items[0].type != Node::Type::Number || p.items[1].type != Node::Type::Number) {
        r.error(v, path + "[" + std::to_string(i + 1) + "] must be a pair {omega, G}");
        return {};
      }
      t.omega.push_back(p.items[0].number);
      t.value.push_back(p.items[1].number);
    }
    return t;
  }
  r.error(
      v, path + " must be a function of omega or a table of {omega, G} pairs, got " + v.describe());
  return {};
}

void buildIrregularities(const Node& n, const std::string& path, LuaHost& host,
                         track::IrregularitySpec& out, Diagnostics& d) {
  out.loc = n.loc;
  if (n.kind == "measured") {
    Reader r(n, block("measured"), path, d);
    out.source = track::IrregularitySource::Csv;
    std::string file = r.string("file");
    out.csv_unit = r.choice("unit") == "mm" ? track::CsvUnit::Millimetre : track::CsvUnit::Metre;
    out.beyond = r.choice("beyond") == "zero" ? track::Beyond::Zero : track::Beyond::Error;
    if (!file.empty()) {
      try {
        out.csv_path = host.resolveDataFile(file, n.loc);
      } catch (const InputError& e) {
        r.error(n, "file: " + e.diagnostics().front().message);
      }
    }
    return;
  }
  Reader r(n, block("psd"), path, d);
  out.source = track::IrregularitySource::Psd;
  out.spectrum = r.choice("spectrum");
  out.seed = static_cast<std::uint64_t>(r.number("seed"));
  out.components = static_cast<int>(r.number("components"));
  out.step = r.number("step");
  out.scale = r.number("scale");
  out.randomize_frequencies = r.boolean("randomize_frequencies");
  r.pair("wavelengths", out.wavelength_min, out.wavelength_max);
  std::vector<std::string> channels = r.stringList("channels");
  static const char* names[track::kChannels] = {"alignment", "vertical", "gauge", "cross_level"};
  for (int c = 0; c < track::kChannels; ++c) {
    out.enabled[c] = false;
    for (const auto& s : channels) out.enabled[c] = out.enabled[c] || s == names[c];
  }
  bool user = out.spectrum == "user";
  bool anyUser = false;
  for (int c = 0; c < track::kChannels; ++c) {
    const Node* v = r.value(names[c]);
    if (!v) continue;
    anyUser = true;
    if (!user) {
      const Node* given = n.field("spectrum");
      std::string named = given && given->type == Node::Type::String ? given->string : out.spectrum;
      r.error(*v, std::string(names[c]) + " gives a user PSD but spectrum is '" + named +
                      "'; set spectrum = \"user\" or remove it");
      continue;
    }
    if (out.wavelength_min > 0 && out.wavelength_max > out.wavelength_min)
      out.user[c] = readPsdInput(*v, std::string(names[c]), r, 2 * M_PI / out.wavelength_max,
                                 2 * M_PI / out.wavelength_min);
  }
  if (user && !anyUser)
    r.error(n, "spectrum = \"user\" needs at least one of alignment, vertical, gauge, cross_level");
}

void buildTrack(const Node& n, LuaHost& host, track::TrackSpec& t, bool& railsGiven,
                Diagnostics& d) {
  Reader r(n, block("track"), "track", d);
  railsGiven = r.has("rail_lr") || r.has("rail_inclination");
  t.loc = n.loc;
  t.step = r.number("step");
  t.cant_base = r.number("cant_base");
  t.gauge = r.number("gauge");
  t.rail_lr = r.number("rail_lr");
  t.rail_inclination = r.number("rail_inclination");
  t.max_points = r.number("max_points");
  auto segs = r.blockList("segments");
  for (std::size_t i = 0; i < segs.size(); ++i) {
    const Node& s = *segs[i];
    std::string path = "track.segments[" + std::to_string(i + 1) + "]";
    Reader sr(s, block(s.kind), path, d);
    track::SegmentSpec seg;
    seg.loc = s.loc;
    seg.kind = s.kind == "tangent"      ? track::SegmentKind::Tangent
               : s.kind == "transition" ? track::SegmentKind::Transition
                                        : track::SegmentKind::Curve;
    seg.length = sr.number("length");
    seg.gradient = sr.number("gradient");
    if (seg.kind != track::SegmentKind::Tangent) {
      seg.radius = sr.number("radius");
      seg.side = sr.choice("side") == "right" ? track::Side::Right : track::Side::Left;
      seg.cant = sr.number("cant");
    }
    t.segments.push_back(seg);
  }
  if (const Node* irr = r.blockValue("irregularities"))
    buildIrregularities(*irr, "track.irregularities", host, t.irregularities, d);
}

void buildVehicle(const Node& n, vehicle::VehicleSpec& v, Diagnostics& d) {
  Reader r(n, block("vehicle"), "vehicle", d);
  v.loc = n.loc;
  v.name = r.string("name");
  v.speed = r.number("speed");
  v.acceleration = r.number("acceleration");
  v.wheel_radius = r.number("wheel_radius");
  v.start = r.number("start");
  auto bodies = r.blockList("bodies");
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const Node& b = *bodies[i];
    Reader br(b, block("body"), "vehicle.bodies[" + std::to_string(i + 1) + "]", d);
    vehicle::BodySpec body;
    body.loc = b.loc;
    body.name = br.string("name");
    std::string kind = br.choice("kind");
    body.kind = kind == "bogie"      ? vehicle::BodyKind::Bogie
                : kind == "wheelset" ? vehicle::BodyKind::Wheelset
                : kind == "frame"    ? vehicle::BodyKind::Frame
                                     : vehicle::BodyKind::CarBody;
    body.mass = br.number("mass");
    if (br.vec3("inertia", body.inertia) && !(body.inertia.minCoeff() > 0))
      br.error(b, "inertia must be > 0 kg m^2 in every axis");
    body.x = br.number("x");
    body.height = br.number("height");
    v.bodies.push_back(body);
  }
  if (r.has("elements")) {
    auto elements = r.blockList("elements");
    for (std::size_t i = 0; i < elements.size(); ++i) {
      const Node& e = *elements[i];
      Reader er(e, block(e.kind), "vehicle.elements[" + std::to_string(i + 1) + "]", d);
      vehicle::ElementSpec el;
      el.loc = e.loc;
      el.kind = e.kind == "series_damper"    ? vehicle::ElementKind::SeriesSpringDamper
                : e.kind == "shear_spring"   ? vehicle::ElementKind::ShearSpring
                : e.kind == "bending_spring" ? vehicle::ElementKind::BendingSpring
                : e.kind == "bumpstop"       ? vehicle::ElementKind::Bumpstop
                                             : vehicle::ElementKind::SpringDamper;
      el.name = er.string("name");
      el.body1 = er.string("from");
      el.body2 = er.string("to");
      er.vec3("at_from", el.point1);
      er.vec3("at_to", el.point2);
      std::string dir = er.choice("direction");
      el.direction = dir == "x"   ? vehicle::Direction::X
                     : dir == "y" ? vehicle::Direction::Y
                     : dir == "z" ? vehicle::Direction::Z
                                  : vehicle::Direction::Axial;
      const BlockSpec& bs = block(e.kind);
      if (bs.key("stiffness")) el.stiffness = er.number("stiffness");
      if (bs.key("damping")) el.damping = er.number("damping");
      if (bs.key("series_stiffness")) el.series_stiffness = er.number("series_stiffness");
      if (bs.key("length0")) el.length0 = er.number("length0");
      if (bs.key("preload")) el.preload = er.number("preload");
      if (bs.key("table")) er.pairList("table", el.table_d, el.table_f);
      v.elements.push_back(std::move(el));
    }
  }
}

std::string profileSource(Reader& r, const Node& n, const std::string& key,
                          const std::string& builtin, LuaHost& host) {
  std::string v = r.string(key);
  if (v.empty() || v == builtin) return builtin;
  try {
    return host.resolveDataFile(v, n.loc);
  } catch (const InputError& e) {
    r.error(n, key + ": " + e.diagnostics().front().message);
    return builtin;
  }
}

void buildProfiles(const Node& n, LuaHost& host, dynamics::ProfilesSpec& p, Diagnostics& d) {
  Reader r(n, block("profiles"), "profiles", d);
  p.loc = n.loc;
  p.wheel = profileSource(r, n, "wheel", "s1002", host);
  p.rail = profileSource(r, n, "rail", "60e1", host);
  p.back_to_back = r.number("back_to_back");
  p.gauge = r.number("gauge");
  p.r0 = r.number("r0");
  p.inclination = r.number("inclination");
  p.lw = r.number("lw");
  p.lr = r.number("lr");
  p.refined_tables = r.boolean("refined_tables");
  if (r.has("lw") && r.has("back_to_back"))
    r.error(n, "give either lw or back_to_back, not both (lw overrides the positioning)");
  if (r.has("lr") && r.has("gauge"))
    r.error(n, "give either lr or gauge, not both (lr overrides the positioning)");
}

void buildContact(const Node& n, dynamics::ContactSpec& c, Diagnostics& d) {
  Reader r(n, block("contact"), "contact", d);
  c.loc = n.loc;
  c.method =
      r.choice("method") == "lut" ? dynamics::ContactMethod::Lut : dynamics::ContactMethod::Kec;
  c.kec_dhat = r.number("dhat");
  c.kec_dbar = r.number("dbar");
  c.flange_stiffness = r.number("flange_stiffness");
  c.flange_damping = r.number("flange_damping");
  std::string creep = r.choice("creep");
  c.creep = creep == "kalker" ? dynamics::CreepModel::Kalker
            : creep == "none" ? dynamics::CreepModel::None
                              : dynamics::CreepModel::Polach;
  c.mu = r.number("mu");
  c.youngs_modulus = r.number("youngs_modulus");
  c.poisson = r.number("poisson");
  c.normal_forces = r.choice("normal_forces") == "consistent"
                        ? dynamics::NormalForceCoupling::Consistent
                        : dynamics::NormalForceCoupling::Lagged;
  c.wheelset_spin = r.choice("wheelset_spin") == "prescribed" ? dynamics::WheelsetSpin::Prescribed
                                                              : dynamics::WheelsetSpin::Free;
  c.min_normal_force = r.number("min_normal_force");
  // Options that belong to the other method are conflicts, not silently ignored.
  bool kec = c.method == dynamics::ContactMethod::Kec;
  for (const char* k : {"flange_stiffness", "flange_damping"})
    if (kec && r.has(k))
      r.error(
          *n.field(k),
          std::string(k) + " applies to method 'lut' only (KEC treats the flange as a constraint)");
  for (const char* k : {"dhat", "dbar"})
    if (!kec && r.has(k)) r.error(*n.field(k), std::string(k) + " applies to method 'kec' only");
}

void buildSolver(const Node& n, integ::SolverSpec& s, Diagnostics& d) {
  Reader r(n, block("solver"), "solver", d);
  s.loc = n.loc;
  s.method = r.choice("method");
  s.step = r.number("step");
  // Adaptive methods estimate their own initial step unless the scenario gives one.
  if (!r.has("step") && s.method != "rk4" && s.method != "abm") s.step = 0.0;
  s.rtol = r.number("rtol");
  s.atol = r.number("atol");
  s.max_step = r.number("max_step");
  s.max_order = static_cast<int>(r.number("max_order"));
  s.max_steps = static_cast<long>(r.number("max_steps"));
  s.jacobian = r.choice("jacobian");
  // Options that the chosen method does not use are conflicts, not silently ignored.
  for (const auto& m : integ::methods()) {
    if (m.name != s.method) continue;
    for (const auto& [k, v] : n.fields) {
      if (k == "method" || !block("solver").key(k)) continue;
      bool used = false;
      for (const auto& o : m.options) used = used || o.key == k;
      if (!used) {
        std::vector<std::string> valid;
        for (const auto& o : m.options) valid.push_back(o.key);
        r.error(v, k + " has no effect with method '" + s.method +
                       "' (its options: " + join(valid, ", ") + ")");
      }
    }
  }
}

void buildRun(const Node& n, RunSpec& run, Diagnostics& d) {
  Reader r(n, block("run"), "run", d);
  run.loc = n.loc;
  run.distance = r.number("distance");
  run.duration = r.number("duration");
  if (r.has("distance") && r.has("duration"))
    r.error(n, "give either distance or duration, not both");
  if (const Node* out = r.blockValue("output")) {
    Reader o(*out, block("run.output"), "run.output", d);
    run.output_every = o.number("every");
    if (o.has("elements")) run.output_elements = o.names("elements");
    run.body_accelerations = o.boolean("body_accelerations");
    run.max_output_samples = o.number("max_samples");
  }
}

}  // namespace

ScenarioSpec loadScenario(const std::string& path, const LoadOptions& options) {
  ScenarioSpec spec;
  spec.file = path;
  spec.overrides = options.overrides;
  HostOptions ho;
  ho.root = options.root;
  ho.instruction_limit = options.instruction_limit;
  LuaHost host(ho);
  Node root = host.runFile(path);
  spec.text = host.text();  // the bytes that ran, read once (never reopened: it may have changed)
  spec.modules = host.modules();
  Diagnostics d;
  for (const auto& o : options.overrides) applyOverride(root, o, d);

  if (const Node* t = root.field("track"))
    buildTrack(*t, host, spec.track, spec.track_rails_given, d);
  else
    d.add({path, 0}, "scenario has no track { ... } block");
  if (const Node* p = root.field("profiles")) {
    spec.has_profiles = true;
    buildProfiles(*p, host, spec.profiles, d);
    if (spec.track_rails_given)
      d.add(p->loc,
            "profiles: rail position and inclination come from profiles{}; remove "
            "track.rail_lr / track.rail_inclination");
  }
  if (const Node* c = root.field("contact")) {
    spec.has_contact = true;
    buildContact(*c, spec.contact, d);
  }
  if (const Node* v = root.field("vehicle")) {
    spec.has_vehicle = true;
    buildVehicle(*v, spec.vehicle, d);
  }
  if (const Node* s = root.field("solver")) {
    spec.has_solver = true;
    buildSolver(*s, spec.solver, d);
  }
  if (const Node* r = root.field("run")) buildRun(*r, spec.run, d);
  // Blocks that a scenario would otherwise silently ignore.
  if (const Node* st = root.field("study"))
    d.add(st->loc,
          "study{} belongs in a study file of its own, run with `workbench study FILE`; a "
          "scenario cannot hold one");
  if (const Node* s = root.field("solver"); s && !spec.has_vehicle)
    d.add(s->loc, "solver{} has no effect without a vehicle{} block (nothing is integrated)");
  d.throwIfAny();
  return spec;
}

}  // namespace rb::scenario
