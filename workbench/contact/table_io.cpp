#include "workbench/contact/table_io.hpp"

#include <array>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <utility>
#include <vector>

#include "railbench/version.hpp"
#include "workbench/core/files.hpp"

namespace rb::contact {
namespace {

namespace fs = std::filesystem;

using Magic = std::array<char, 16>;
constexpr Magic makeMagic(const char* s) {
  Magic m{};
  for (std::size_t i = 0; s[i] != '\0' && i < m.size(); ++i) m[i] = s[i];
  return m;
}
constexpr Magic kLutMagic = makeMagic("railbench-lut");
constexpr Magic kKecMagic = makeMagic("railbench-kec");
constexpr std::uint64_t kByteOrderMark = 0x0102030405060708ULL;
// Cache files above this size are not read (a refined S1002 KEC table is about 10 MB).
constexpr std::size_t kMaxTableFileBytes = std::size_t{1} << 30;

// FNV-1a 64 over 8-byte words (then the tail bytes): a cheap corruption check, ~1 ms per 5 MB.
std::uint64_t checksum(const char* p, std::size_t n) {
  std::uint64_t h = 14695981039346656037ULL;
  constexpr std::uint64_t prime = 1099511628211ULL;
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8) {
    std::uint64_t w;
    std::memcpy(&w, p + i, 8);
    h = (h ^ w) * prime;
  }
  for (; i < n; ++i) h = (h ^ static_cast<unsigned char>(p[i])) * prime;
  return h;
}

// ---- Serialisation primitives ---------------------------------------------------------------

class Writer {
 public:
  void raw(const void* p, std::size_t n) {
    if (n > 0) buf_.append(static_cast<const char*>(p), n);
  }
  void u64(std::uint64_t v) { raw(&v, sizeof v); }
  void f64(double v) { raw(&v, sizeof v); }
  void flag(bool b) { u64(b ? 1 : 0); }
  void side(Side s) { u64(s == Side::Left ? 0 : 1); }
  void str(const std::string& s) {
    u64(s.size());
    raw(s.data(), s.size());
  }
  template <class T>
  void vec(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    u64(v.size());
    raw(v.data(), v.size() * sizeof(T));
  }
  void grid(const GridSpec& g) {
    f64(g.min);
    f64(g.max);
    f64(g.step);
  }
  void stats(const TableBuildStats& s) {
    f64(s.build_seconds);
    u64(s.bytes);
    u64(s.nodes);
    u64(static_cast<std::uint64_t>(s.newton_iterations));
    u64(s.restarts);
    u64(s.failures);
    for (const auto* list : {&s.warnings, &s.notes}) {
      u64(list->size());
      for (const std::string& x : *list) str(x);
    }
  }
  std::string& buffer() { return buf_; }

 private:
  std::string buf_;
};

// Bounds-checked reader: any read past the end (or a bad value reported by the caller) sets
// ok() to false and returns zeros; the caller checks ok() at the end.
class Reader {
 public:
  Reader(const char* p, std::size_t n) : p_(p), end_(p + n) {}
  bool ok() const { return ok_; }
  void fail() { ok_ = false; }
  bool atEnd() const { return p_ == end_; }
  std::size_t remaining() const { return static_cast<std::size_t>(end_ - p_); }

  bool raw(void* out, std::size_t n) {
    if (!ok_ || n > remaining()) {
      ok_ = false;
      return false;
    }
    if (n > 0) std::memcpy(out, p_, n);
    p_ += n;
    return true;
  }
  std::uint64_t u64() {
    std::uint64_t v = 0;
    raw(&v, sizeof v);
    return v;
  }
  double f64() {
    double v = 0.0;
    raw(&v, sizeof v);
    return v;
  }
  // A size_t count whose elements of `elem` bytes each still fit in the input.
  std::size_t count(std::size_t elem) {
    const std::uint64_t n = u64();
    if (!ok_ || (elem > 0 && n > remaining() / elem)) {
      ok_ = false;
      return 0;
    }
    return static_cast<std::size_t>(n);
  }
  bool flag() {
    const std::uint64_t v = u64();
    if (v > 1) ok_ = false;
    return v == 1;
  }
  Side side() {
    const std::uint64_t v = u64();
    if (v > 1) ok_ = false;
    return v == 0 ? Side::Left : Side::Right;
  }
  std::string str() {
    const std::size_t n = count(1);
    std::string s(n, '\0');
    raw(s.data(), n);
    return s;
  }
  template <class T>
  std::vector<T> vec() {
    static_assert(std::is_trivially_copyable_v<T>);
    const std::size_t n = count(sizeof(T));
    std::vector<T> v(n);
    raw(v.data(), n * sizeof(T));
    return v;
  }
  GridSpec grid() {
    GridSpec g;
    g.min = f64();
    g.max = f64();
    g.step = f64();
    return g;
  }
  TableBuildStats stats() {
    TableBuildStats s;
    s.build_seconds = f64();
    s.bytes = static_cast<std::size_t>(u64());
    s.nodes = static_cast<std::size_t>(u64());
    s.newton_iterations = static_cast<long>(u64());
    s.restarts = static_cast<std::size_t>(u64());
    s.failures = static_cast<std::size_t>(u64());
    for (auto* list : {&s.warnings, &s.notes}) {
      const std::size_t n = count(sizeof(std::uint64_t));
      for (std::size_t i = 0; i < n && ok_; ++i) list->push_back(str());
    }
    return s;
  }

 private:
  const char* p_;
  const char* end_;
  bool ok_ = true;
};

// Header + key + payload + checksum (the file format of table_io.hpp).
std::string fileBytes(const Magic& magic, const std::string& key, std::string_view payload) {
  Writer file;
  file.raw(magic.data(), magic.size());
  file.u64(kByteOrderMark);
  file.u64(kTableFormatVersion);
  file.u64(kTableAlgorithmVersion);
  file.str(key);
  file.u64(payload.size());
  file.raw(payload.data(), payload.size());
  file.u64(checksum(file.buffer().data(), file.buffer().size()));
  return std::move(file.buffer());
}

// The file bytes written to a unique temporary file renamed over `path`.
void writeFile(const std::string& path, const Magic& magic, const std::string& key,
               const std::string& payload) {
  const std::string bytes = fileBytes(magic, key, payload);

  // Unique per writer (process and call), so racing writers never share a temporary file.
  static std::atomic<std::uint64_t> counter{0};
  std::uint64_t salt =
      static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()) +
      (++counter << 48);
  try {
    std::random_device rd;
    salt ^= (static_cast<std::uint64_t>(rd()) << 32) ^ rd();
  } catch (const std::exception&) {  // no entropy source: clock and counter only
  }
  const std::string tmp = path + ".tmp." + hashHex(salt);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out)
      throw std::runtime_error("saveTable: cannot open '" + tmp + "' to write '" + path + "'");
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
      std::error_code ec;
      fs::remove(tmp, ec);
      throw std::runtime_error("saveTable: cannot write '" + tmp + "' for '" + path + "'");
    }
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw std::runtime_error("saveTable: cannot rename '" + tmp + "' to '" + path +
                             "': " + ec.message());
  }
}

// Where the payload of a file accepted by readFile starts and how long it is.
struct Accepted {
  std::string bytes;
  std::size_t payload_at = 0, payload_size = 0;
};

// The whole content of a valid file for `key`, or nullopt. Never throws.
std::optional<Accepted> readFile(const std::string& path, const Magic& magic,
                                 const std::string& key) noexcept {
  try {
    std::string why;
    std::optional<std::string> bytes = readRegularFile(path, why, kMaxTableFileBytes);
    if (!bytes || bytes->size() < sizeof(Magic) + 6 * sizeof(std::uint64_t)) return std::nullopt;
    const std::size_t body = bytes->size() - sizeof(std::uint64_t);
    std::uint64_t stored = 0;
    std::memcpy(&stored, bytes->data() + body, sizeof stored);
    if (stored != checksum(bytes->data(), body)) return std::nullopt;

    Reader r(bytes->data(), body);
    Magic m{};
    r.raw(m.data(), m.size());
    if (m != magic || r.u64() != kByteOrderMark || r.u64() != kTableFormatVersion ||
        r.u64() != kTableAlgorithmVersion) {
      return std::nullopt;
    }
    // The full key, not a hash of it: a file made for other inputs never matches.
    if (r.str() != key || !r.ok()) return std::nullopt;
    const std::uint64_t payload = r.u64();
    if (!r.ok() || payload != r.remaining()) return std::nullopt;
    Accepted a;
    a.payload_at = body - static_cast<std::size_t>(payload);
    a.payload_size = static_cast<std::size_t>(payload);
    a.bytes = std::move(*bytes);
    return a;
  } catch (...) {
    return std::nullopt;
  }
}

// A reader over the payload of a file accepted by readFile.
Reader payloadOf(const Accepted& file) {
  return Reader(file.bytes.data() + file.payload_at, file.payload_size);
}

std::uint64_t keyHash(const std::string& key) {
  return checksum(key.data(), key.size());
}

}  // namespace

// Access to the private members of LutTable / KecTable (declared friend there).
class TableIo {
 public:
  static std::string payload(const LutTable& t) {
    Writer w;
    w.u64(kLutChannels);
    w.grid(t.y_);
    w.grid(t.g_);
    w.u64(t.ny_);
    w.u64(t.ng_);
    w.f64(t.hy_);
    w.f64(t.hg_);
    w.flag(t.has_flange_[0]);
    w.flag(t.has_flange_[1]);
    w.vec(t.data_);
    w.vec(t.flags_);
    w.vec(t.branch_);
    w.f64(t.jump_threshold_);
    w.u64(t.jumps_.size());
    for (const LutJump& j : t.jumps_) {
      w.f64(j.xi_g);
      w.side(j.side);
      for (double v : {j.y_before, j.y_after, j.s_w_before, j.s_w_after}) w.f64(v);
    }
    w.u64(t.two_point_.size());
    for (const TwoPointContact& p : t.two_point_) {
      w.f64(p.xi_g);
      w.side(p.side);
      w.flag(p.tread_edge);
      for (double v : {p.y, p.z, p.phi, p.s_w_tread, p.s_r_tread, p.gamma_tread, p.s_w_flange,
                       p.s_r_flange, p.gamma_flange}) {
        w.f64(v);
      }
    }
    w.stats(t.stats_);
    return std::move(w.buffer());
  }

  // `interpolation` is the config's: the key the file was accepted for includes it.
  static std::optional<LutTable> lut(const Reader& payload, std::uint64_t hash,
                                     TableInterpolation interpolation) {
    Reader r = payload;
    LutTable t;
    t.interp_ = interpolation;
    if (r.u64() != kLutChannels) return std::nullopt;
    t.y_ = r.grid();
    t.g_ = r.grid();
    t.ny_ = static_cast<std::size_t>(r.u64());
    t.ng_ = static_cast<std::size_t>(r.u64());
    t.hy_ = r.f64();
    t.hg_ = r.f64();
    t.has_flange_[0] = r.flag();
    t.has_flange_[1] = r.flag();
    t.data_ = r.vec<double>();
    t.flags_ = r.vec<std::uint8_t>();
    t.branch_ = r.vec<std::int8_t>();
    t.jump_threshold_ = r.f64();
    const std::size_t nj = r.count(6 * sizeof(std::uint64_t));
    for (std::size_t i = 0; i < nj && r.ok(); ++i) {
      LutJump j;
      j.xi_g = r.f64();
      j.side = r.side();
      j.y_before = r.f64();
      j.y_after = r.f64();
      j.s_w_before = r.f64();
      j.s_w_after = r.f64();
      t.jumps_.push_back(j);
    }
    const std::size_t np = r.count(12 * sizeof(std::uint64_t));
    for (std::size_t i = 0; i < np && r.ok(); ++i) {
      TwoPointContact p;
      p.xi_g = r.f64();
      p.side = r.side();
      p.tread_edge = r.flag();
      for (double* v : {&p.y, &p.z, &p.phi, &p.s_w_tread, &p.s_r_tread, &p.gamma_tread,
                        &p.s_w_flange, &p.s_r_flange, &p.gamma_flange}) {
        *v = r.f64();
      }
      t.two_point_.push_back(p);
    }
    t.stats_ = r.stats();
    if (!r.ok() || !r.atEnd()) return std::nullopt;
    // Consistency of the sizes the evaluation relies on.
    const std::size_t nodes = t.ny_ * t.ng_;
    if (t.ny_ < 2 || t.ng_ < 1 || t.ny_ != t.y_.count() || t.ng_ != t.g_.count() ||
        t.flags_.size() != nodes || t.branch_.size() != 2 * nodes || nodes / t.ng_ != t.ny_ ||
        t.data_.size() / (kLutChannels * 4) != nodes || t.data_.size() % (kLutChannels * 4) != 0 ||
        !(t.hy_ > 0.0) || !(t.hg_ > 0.0)) {
      return std::nullopt;
    }
    t.hash_ = hash;
    return t;
  }

  static std::string payload(const KecTable& t) {
    Writer w;
    w.u64(kKecQuantities);
    w.grid(t.grid_);
    w.u64(t.n_);
    w.f64(t.r0_);
    w.f64(t.lr_);
    for (std::size_t k = 0; k < 2; ++k) {
      w.vec(t.herm_[k]);
      w.f64(t.valid_[k][0]);
      w.f64(t.valid_[k][1]);
      w.u64(t.trans_[k].size());
      for (const KecTransition& x : t.trans_[k]) {
        for (double v : {x.s_jump, x.lo, x.hi}) w.f64(v);
        w.flag(x.own);
        w.flag(x.flange);
        for (double v : {x.s_w_field, x.s_w_flange, x.y}) w.f64(v);
      }
    }
    w.stats(t.stats_);
    return std::move(w.buffer());
  }

  static std::optional<KecTable> kec(const Reader& payload, std::uint64_t hash,
                                     TableInterpolation interpolation) {
    Reader r = payload;
    KecTable t;
    t.interp_ = interpolation;
    if (r.u64() != kKecQuantities) return std::nullopt;
    t.grid_ = r.grid();
    t.n_ = static_cast<std::size_t>(r.u64());
    t.r0_ = r.f64();
    t.lr_ = r.f64();
    for (std::size_t k = 0; k < 2; ++k) {
      t.herm_[k] = r.vec<double>();
      t.valid_[k][0] = r.f64();
      t.valid_[k][1] = r.f64();
      const std::size_t n = r.count(8 * sizeof(std::uint64_t));
      for (std::size_t i = 0; i < n && r.ok(); ++i) {
        KecTransition x;
        x.s_jump = r.f64();
        x.lo = r.f64();
        x.hi = r.f64();
        x.own = r.flag();
        x.flange = r.flag();
        x.s_w_field = r.f64();
        x.s_w_flange = r.f64();
        x.y = r.f64();
        t.trans_[k].push_back(x);
      }
    }
    t.stats_ = r.stats();
    if (!r.ok() || !r.atEnd()) return std::nullopt;
    if (t.n_ < 2 || t.n_ != t.grid_.count() || !(t.grid_.step > 0.0)) return std::nullopt;
    for (std::size_t k = 0; k < 2; ++k) {
      if (t.herm_[k].size() % (kKecQuantities * 2) != 0 ||
          t.herm_[k].size() / (kKecQuantities * 2) != t.n_) {
        return std::nullopt;
      }
    }
    try {
      t.makeFSpline(0);  // throws only for an invalid grid (checked above)
      t.makeFSpline(1);
    } catch (const std::exception&) {
      return std::nullopt;
    }
    t.hash_ = hash;
    return t;
  }
};

std::string hashHex(std::uint64_t hash) {
  char b[17];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(hash));
  return b;
}

std::string tableInputKey(const ContactGeometryConfig& c, TableKind kind) {
  Writer w;
  const std::string head =
      std::string("railbench contact table\nkind=") + (kind == TableKind::Lut ? "lut" : "kec") +
      "\nalgorithm=" + std::to_string(kTableAlgorithmVersion) + "\nworkbench=" + kVersion + "\n";
  w.raw(head.data(), head.size());
  const auto num = [&](double v) { w.f64(v == 0.0 ? 0.0 : v); };  // -0 and +0 are one input
  for (const auto* p :
       {c.left_wheel.get(), c.right_wheel.get(), c.left_rail.get(), c.right_rail.get()}) {
    if (!p) {
      w.u64(0);
      continue;
    }
    w.u64(p->kind() == profiles::ProfileKind::Wheel ? 1 : 2);
    w.flag(p->isMirrored());
    num(p->step());
    w.vec(p->knots());
    w.vec(p->values());
  }
  for (double x : {c.wheel_lw, c.rail_lr, c.beta, c.r0, c.flange_boundary, c.flange_angle}) num(x);
  for (const GridSpec* g : {&c.lut_y, &c.lut_gauge, &c.kec_s}) {
    num(g->min);
    num(g->max);
    num(g->step);
  }
  for (double x :
       {c.kec_dhat, c.kec_dbar, c.kec_min_transition, c.kec_max_curvature, c.kec_max_map_slope,
        c.kec_sample_step, c.jump_threshold, c.search_step, c.newton_tol}) {
    num(x);
  }
  w.u64(static_cast<std::uint64_t>(static_cast<std::int64_t>(c.newton_max_iter)));
  // The table carries its interpolation (the evaluation reads the Hermite node slopes only when
  // cubic), so a linear and a cubic table are different tables. Written after every fixed-size
  // field and only when not cubic: the key stays injective, and a cubic key does not depend on
  // the option.
  if (c.interpolation != TableInterpolation::Cubic) {
    const std::string tail = std::string("\ninterpolation=") + std::string(nameOf(c.interpolation));
    w.raw(tail.data(), tail.size());
  }
  return std::move(w.buffer());
}

std::string tableFileBytes(TableKind kind, const std::string& key, std::string_view payload) {
  return fileBytes(kind == TableKind::Kec ? kKecMagic : kLutMagic, key, payload);
}

void saveTable(const LutTable& table, const ContactGeometryConfig& config,
               const std::string& path) {
  writeFile(path, kLutMagic, tableInputKey(config, TableKind::Lut), TableIo::payload(table));
}

void saveTable(const KecTable& table, const ContactGeometryConfig& config,
               const std::string& path) {
  writeFile(path, kKecMagic, tableInputKey(config, TableKind::Kec), TableIo::payload(table));
}

std::optional<LutTable> loadLut(const std::string& path, const ContactGeometryConfig& config) {
  try {
    const std::optional<Accepted> file =
        readFile(path, kLutMagic, tableInputKey(config, TableKind::Lut));
    if (!file) return std::nullopt;
    return TableIo::lut(payloadOf(*file), configHash(config), config.interpolation);
  } catch (const std::exception&) {  // e.g. bad_alloc on a huge but self-consistent file
    return std::nullopt;
  }
}

std::optional<KecTable> loadKec(const std::string& path, const ContactGeometryConfig& config) {
  try {
    const std::optional<Accepted> file =
        readFile(path, kKecMagic, tableInputKey(config, TableKind::Kec));
    if (!file) return std::nullopt;
    return TableIo::kec(payloadOf(*file), configHash(config), config.interpolation);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// ---- DiskTableCache -------------------------------------------------------------------------

DiskTableCache::DiskTableCache(std::string directory) : dir_(std::move(directory)) {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec || !fs::is_directory(dir_, ec)) {
    throw std::runtime_error("cannot create the folder '" + dir_ + "'" +
                             (ec ? ": " + ec.message() : std::string()));
  }
}

std::string DiskTableCache::lutPath(const ContactGeometryConfig& config) const {
  return (fs::path(dir_) / (hashHex(keyHash(tableInputKey(config, TableKind::Lut))) + ".lut"))
      .string();
}

std::string DiskTableCache::kecPath(const ContactGeometryConfig& config) const {
  return (fs::path(dir_) / (hashHex(keyHash(tableInputKey(config, TableKind::Kec))) + ".kec"))
      .string();
}

namespace {

// Load, else build and save; a failed save keeps the built table (see the header).
template <class Table, class Load, class Build>
std::shared_ptr<const Table> loadOrBuild(const std::string& path,
                                         const ContactGeometryConfig& config, Load load,
                                         Build build, bool* built, std::string* save_error) {
  if (std::optional<Table> t = load(path, config)) {
    if (built) *built = false;
    return std::make_shared<const Table>(std::move(*t));
  }
  auto t = std::make_shared<const Table>(build(config));
  if (built) *built = true;
  try {
    saveTable(*t, config, path);
  } catch (const std::exception& e) {
    if (!save_error) throw;
    *save_error = e.what();
  }
  return t;
}

}  // namespace

std::shared_ptr<const LutTable> DiskTableCache::lut(const ContactGeometryConfig& config,
                                                    bool* built, std::string* save_error) const {
  return loadOrBuild<LutTable>(lutPath(config), config, loadLut, buildLut, built, save_error);
}

std::shared_ptr<const KecTable> DiskTableCache::kec(const ContactGeometryConfig& config,
                                                    bool* built, std::string* save_error) const {
  return loadOrBuild<KecTable>(kecPath(config), config, loadKec, buildKec, built, save_error);
}

}  // namespace rb::contact
