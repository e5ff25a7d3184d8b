// The result-file harness (entry_points.hpp, resultFiles): forged HDF5 files decoded from the
// fuzzer's bytes by a small grammar, then read by every reader of results. The files are written
// with the HDF5 library itself, so they are well-formed HDF5: what is fuzzed is our readers'
// trust in a file's structure and values, not HDF5's parser.
//
// Grammar (README.md has the table): byte 0 holds flags (check-result's --exit-code and --t-end,
// whether assess runs); then operations, each an opcode byte and its operands, until the input
// ends (missing operand bytes read as 0). Names come from vocabularies of the result layout's
// groups, datasets and attributes (or raw bytes), values from generators (ramp, sine, constant,
// the input's bytes) with one injected special value (NaN, infinity, a denormal).
#include <hdf5.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "entry_points.hpp"
#include "workbench/app/assess.hpp"
#include "workbench/core/error.hpp"
#include "workbench/io/hdf5_init.hpp"
#include "workbench/io/read_stats.hpp"
#include "workbench/io/result_file.hpp"
#include "workbench/io/result_reader.hpp"
#include "workbench/io/root_text.hpp"
#include "workbench/io/track_store.hpp"
#include "workbench/scenario/study.hpp"
#include "workbench/stress/result_checks.hpp"
#include "workbench/study/metrics.hpp"
#include "workbench/study/run_error.hpp"

#ifndef RB_SOURCE_DIR
#error "RB_SOURCE_DIR must name the source tree (scenarios/)"
#endif

namespace rb::fuzz {
namespace {

namespace fs = std::filesystem;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// The input's bytes, read front to back; past the end every read gives 0.
class Bytes {
 public:
  explicit Bytes(std::string_view d) : d_(d) {}
  bool done() const { return at_ >= d_.size(); }
  unsigned u8() { return at_ < d_.size() ? static_cast<unsigned char>(d_[at_++]) : 0U; }
  unsigned u16() {
    const unsigned lo = u8();
    return lo | (u8() << 8U);
  }
  double f64() {
    std::array<char, 8> b{};
    for (char& c : b) c = static_cast<char>(u8());
    double v = 0.0;
    std::memcpy(&v, b.data(), sizeof v);
    return v;
  }
  std::string raw(std::size_t maxLen) {
    const std::size_t n = u8() % (maxLen + 1);
    std::string s;
    for (std::size_t i = 0; i < n; ++i) s += static_cast<char>(u8());
    return s;
  }
  // The next byte of the input as a sample value source (cycled; 0 when empty).
  unsigned peekCycled(std::size_t i) const {
    return d_.empty() ? 0U : static_cast<unsigned char>(d_[i % d_.size()]);
  }

 private:
  std::string_view d_;
  std::size_t at_ = 0;
};

template <std::size_t N>
const char* pick(const std::array<const char*, N>& v, unsigned b) {
  return v[b % N];
}

// Path components: the result layout (docs/architecture.md, "Output layout") and what assess,
// check-result and the study metrics look for.
constexpr std::array<const char*, 64> kParts = {"time",
                                                "bodies",
                                                "ws1",
                                                "ws2",
                                                "ws",
                                                "y",
                                                "s",
                                                "z",
                                                "yaw",
                                                "contact",
                                                "left",
                                                "right",
                                                "Q",
                                                "Y",
                                                "y_track",
                                                "normal_force",
                                                "flange_force",
                                                "normal_flange",
                                                "flange_indentation",
                                                "y_over_q",
                                                "creep_force_y",
                                                "patch0",
                                                "patch1",
                                                "t_gamma",
                                                "power",
                                                "assessment",
                                                "safety",
                                                "stability",
                                                "comfort",
                                                "wear",
                                                "summary",
                                                "distance",
                                                "stats",
                                                "track",
                                                "irregularities",
                                                "left_y",
                                                "right_y",
                                                "alignment",
                                                "centreline",
                                                "segments",
                                                "vehicles",
                                                "a",
                                                "b",
                                                "schema",
                                                "metrics",
                                                "vehicle",
                                                "speed",
                                                "stage_names",
                                                "stage_share",
                                                "sections",
                                                "acceleration",
                                                "bogie1",
                                                "p1",
                                                "a_x",
                                                "a_y",
                                                "a_z",
                                                "carbody",
                                                "sec1",
                                                "x",
                                                "heading",
                                                "assessment",
                                                "time",
                                                "..",
                                                "."};

constexpr std::array<const char*, 56> kAttrNames = {"status",
                                                    "message",
                                                    "failure_kind",
                                                    "failure_reason",
                                                    "failure_body",
                                                    "failure_t",
                                                    "failure_s",
                                                    "t_reached",
                                                    "cpu_time_s",
                                                    "rhs_evals",
                                                    "steps",
                                                    "stored_in",
                                                    "track_hash",
                                                    "names",
                                                    "kind",
                                                    "units",
                                                    "alpha",
                                                    "flange_angle",
                                                    "mu",
                                                    "yq_limit",
                                                    "instability_frequency",
                                                    "comfort_limit",
                                                    "sample_every",
                                                    "q0",
                                                    "s_offset",
                                                    "value",
                                                    "y_over_q",
                                                    "y_over_q_limit",
                                                    "y_over_q_unit",
                                                    "input_hash",
                                                    "compact",
                                                    "definitions_hash",
                                                    "content",
                                                    "q0_source",
                                                    "bogie_mass",
                                                    "x_offset",
                                                    "from",
                                                    "to",
                                                    "radius",
                                                    "cant",
                                                    "zone",
                                                    "y_max",
                                                    "y_max_why",
                                                    "y_max_note",
                                                    "yq",
                                                    "yq_why",
                                                    "method",
                                                    "yq_path",
                                                    "rejected_steps",
                                                    "jacobian_evals",
                                                    "rhs_evals_jac",
                                                    "y_win",
                                                    "q_time",
                                                    "y_ss",
                                                    "y_err",
                                                    "q_fn"};

constexpr std::array<const char*, 32> kTexts = {
    "ok",
    "failed",
    "",
    "none",
    "store.h5",
    "tracks/store.h5",
    "../victim.h5",
    "/dev/zero",
    "fifo.h5",
    "0123456789abcdef",
    "ws1\nws2",
    "ws1",
    "a\nb",
    "wheelset",
    "derailment",
    "wheel_lift",
    "newton",
    "tangent",
    "sec1",
    "y_max\ny_win\nq_time\ny_ss\nyq\nyq_path\ny_err\nq_fn",
    "m",
    "../../../../../etc/passwd",
    "tracks/../fuzz.h5",
    "fuzz.h5",
    ".",
    "tracks",
    "a\n\nb\n",
    "/proc/self/fd/0",
    "curve",
    "ws1\nws2\nws3",
    "step_failure",
    "<metrics hash>"};

constexpr std::array<double, 32> kNumbers = {
    0.0,  1.0,   -1.0,   2.0,    0.5,  2.5e-3, 1e-9,   20.0, 50e3, 801.0, 1e9,
    1e11, 1e308, -1e308, 5e-324, kNaN, kInf,   -kInf,  0.3,  1e-3, 0.8,   4.0,
    14.0, 600.0, 1.5,    -0.0,   3.0,  100.0,  0.2364, 70.0, 5e-3, 1e-300};

// Link targets: files beside the result, the victim outside its folder, devices, the FIFO.
constexpr std::array<const char*, 10> kLinkFiles = {
    "../victim.h5", "ref.h5",     "tracks/store.h5", "fuzz.h5", "/dev/zero",
    "fifo.h5",      "missing.h5", "tracks",          "",        "../victim.h5"};

const scenario::StudySpec& metricStudy(const fs::path& dir);

// The files a forged input may write: the result, the reference of the comparisons, a track
// store the result may name, and a victim outside the result's folder that no reader may change.
enum FileId { kResult = 0, kReference = 1, kStore = 2, kVictim = 3, kFiles = 4 };

// At most this many values are written per input (datasets are generated, not stored).
constexpr std::size_t kValueBudget = std::size_t{1} << 21;

class Forge {
 public:
  Forge(const fs::path& work, const fs::path& victim, std::string metricsHash)
      : work_(work), victim_(victim), metricsHash_(std::move(metricsHash)) {
    lcpl_ = H5Pcreate(H5P_LINK_CREATE);
    H5Pset_create_intermediate_group(lcpl_, 1);
    H5Pset_char_encoding(lcpl_, H5T_CSET_UTF8);
  }
  ~Forge() {
    closeAll();
    H5Pclose(lcpl_);
  }
  Forge(const Forge&) = delete;
  Forge& operator=(const Forge&) = delete;

  std::string path(FileId id) const {
    switch (id) {
      case kResult:
        return (work_ / "fuzz.h5").string();
      case kReference:
        return (work_ / "ref.h5").string();
      case kStore:
        return (work_ / "tracks" / "store.h5").string();
      default:
        return victim_.string();
    }
  }

  void run(Bytes& in) {
    file(kResult);
    file(kVictim);
    victimContent();
    while (!in.done()) {
      switch (in.u8() % 10) {
        case 0:
          base(in);
          break;
        case 1:
          current_ = static_cast<FileId>(in.u8() % kFiles);
          break;
        case 2:
          H5Gclose(
              H5Gcreate2(file(current_), objectPath(in).c_str(), lcpl_, H5P_DEFAULT, H5P_DEFAULT));
          break;
        case 3:
          dataset(in);
          break;
        case 4:
          attribute(in);
          break;
        case 5: {
          const std::string link = objectPath(in), target = objectPath(in);
          H5Lcreate_soft(target.c_str(), file(current_), link.c_str(), lcpl_, H5P_DEFAULT);
          break;
        }
        case 6: {
          const std::string link = objectPath(in);
          const unsigned f = in.u8();
          const std::string target = f == 255 ? in.raw(32) : pick(kLinkFiles, f);
          const std::string object = objectPath(in);
          H5Lcreate_external(target.c_str(), object.c_str(), file(current_), link.c_str(), lcpl_,
                             H5P_DEFAULT);
          break;
        }
        case 7: {
          const std::string link = objectPath(in), existing = objectPath(in);
          H5Lcreate_hard(file(current_), existing.c_str(), file(current_), link.c_str(), lcpl_,
                         H5P_DEFAULT);
          break;
        }
        case 8:
          H5Ldelete(file(current_), objectPath(in).c_str(), H5P_DEFAULT);
          break;
        default:
          assessmentGroup(in);
          break;
      }
    }
    closeAll();
  }

 private:
  hid_t file(FileId id) {
    if (files_[id] < 0) {
      const hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
      H5Pset_libver_bounds(fapl, H5F_LIBVER_V18, H5F_LIBVER_LATEST);
      files_[id] = H5Fcreate(path(id).c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
      H5Pclose(fapl);
      if (files_[id] < 0) throw std::runtime_error("cannot create " + path(id));
    }
    return files_[id];
  }

  void closeAll() {
    for (hid_t& f : files_)
      if (f >= 0) {
        H5Fclose(f);
        f = -1;
      }
  }

  // "/a/b/c" of 1 to 8 components, each from kParts or raw (byte 255), or the root.
  static std::string objectPath(Bytes& in) {
    const unsigned head = in.u8();
    if ((head & 16U) != 0) return "/";  // bit 4: the root group
    const unsigned depth = 1 + (head & 7U);
    std::string p;
    for (unsigned i = 0; i < depth; ++i) {
      const unsigned c = in.u8();
      p += "/";
      p += c == 255 ? in.raw(16) : pick(kParts, c);
    }
    return (head & 8U) != 0 ? p.substr(1) : p;  // bit 3: relative
  }

  // A 1-D series of n values: generator byte (kind, scale), then one injected special value.
  std::vector<double> values(Bytes& in, std::size_t n) {
    const unsigned g = in.u8();
    const double scale = std::pow(10.0, static_cast<int>(in.u8() % 24) - 12);
    const std::size_t salt = in.u8();
    std::vector<double> v(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double x = static_cast<double>(i);
      switch (g & 7U) {
        case 0:
          v[i] = 0.0;
          break;
        case 1:
          v[i] = x * scale;
          break;
        case 2:
          v[i] = scale * std::sin(0.05 * x);
          break;
        case 3:
          v[i] = scale;
          break;
        case 4:
          v[i] = scale * (static_cast<double>(in.peekCycled(i + salt)) - 128.0);
          break;
        case 5:
          v[i] = -x * scale;
          break;
        case 6:
          v[i] = i < n / 2 ? 0.0 : scale;
          break;
        default:
          v[i] = (i % 2 == 0 ? 1.0 : -1.0) * scale;
          break;
      }
    }
    const unsigned special = in.u8();
    const std::size_t at = n == 0 ? 0 : in.u16() % n;
    if (n > 0 && (special & 7U) != 0) {
      constexpr std::array<double, 8> kSpecial = {0.0,    kNaN, kInf,  -kInf,
                                                  5e-324, -0.0, 1e308, kNaN};
      v[at] = kSpecial[special & 7U];
      if ((special & 8U) != 0)
        std::fill(v.begin() + static_cast<std::ptrdiff_t>(at), v.end(), v[at]);
    }
    return v;
  }

  bool spend(std::size_t n) {
    if (n > kValueBudget - spent_) return false;
    spent_ += n;
    return true;
  }

  // Opcode 3: path, type, space and layout, length, values.
  void dataset(Bytes& in) {
    const std::string name = objectPath(in);
    const unsigned t = in.u8();
    const unsigned kind = t & 7U, shape = (t >> 3U) & 3U, layout = t >> 5U;
    const std::size_t n = in.u16() & 0x7FFFU;
    hid_t type = -1;
    switch (kind) {
      case 0:
        type = H5Tcopy(H5T_IEEE_F64LE);
        break;
      case 1:
        type = H5Tcopy(H5T_IEEE_F32LE);
        break;
      case 2:
        type = H5Tcopy(H5T_STD_I32LE);
        break;
      case 3:
        type = H5Tcopy(H5T_STD_U8LE);
        break;
      case 4:
        type = H5Tcopy(H5T_C_S1);
        H5Tset_size(type, 16);
        break;
      case 5:
        type = H5Tcopy(H5T_C_S1);
        H5Tset_size(type, H5T_VARIABLE);
        break;
      case 6:
        type = H5Tcopy(H5T_IEEE_F64BE);
        break;
      default:
        type = H5Tcreate(H5T_COMPOUND, 8);
        H5Tinsert(type, "x", 0, H5T_NATIVE_DOUBLE);
        break;
    }
    hsize_t dims[2] = {n, 1};
    int rank = 1;
    hid_t space = -1;
    bool huge = false;
    if (layout == 4) {
      // Declared but never written: nothing is allocated in the file.
      huge = true;
      dims[0] = static_cast<hsize_t>(std::pow(10.0, static_cast<double>(in.u8() % 13)));
    }
    if (shape == 1) {
      space = H5Screate(H5S_SCALAR);
      rank = 0;
    } else if (shape == 2) {
      space = H5Screate(H5S_NULL);
      rank = -1;
    } else if (shape == 3 && !huge) {
      dims[0] = 2;
      dims[1] = n / 2;
      rank = 2;
      space = H5Screate_simple(2, dims, nullptr);
    } else {
      const hsize_t maxdims[1] = {H5S_UNLIMITED};
      space = H5Screate_simple(1, dims, layout == 1 || layout >= 4 ? maxdims : nullptr);
    }
    const std::size_t points = rank < 0    ? 0
                               : rank == 0 ? 1
                               : rank == 1 ? dims[0]
                                           : dims[0] * dims[1];
    const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    const hsize_t chunk[2] = {std::max<hsize_t>(1, std::min<hsize_t>(dims[0], 1024)),
                              std::max<hsize_t>(1, std::min<hsize_t>(dims[1], 1024))};
    const bool simple = rank >= 1;
    if (simple && (layout == 1 || layout == 2 || layout >= 4)) H5Pset_chunk(dcpl, rank, chunk);
    if (simple && (layout == 2 || layout == 7)) {
      if (layout == 7) H5Pset_shuffle(dcpl);
      H5Pset_deflate(dcpl, 6);
    }
    if (layout == 3 && points * 8 < 32000) H5Pset_layout(dcpl, H5D_COMPACT);
    if (layout == 5 || layout == 6) {
      // Never written: a reader gets the fill value (NaN here).
      if (kind <= 1 || kind == 6) H5Pset_fill_value(dcpl, H5T_NATIVE_DOUBLE, &kNaN);
      if (layout == 6) H5Pset_alloc_time(dcpl, H5D_ALLOC_TIME_EARLY);
    }
    const hid_t d = H5Dcreate2(file(current_), name.c_str(), type, space, lcpl_, dcpl, H5P_DEFAULT);
    const bool write = d >= 0 && !huge && layout != 5 && layout != 6 && points > 0 && spend(points);
    const std::vector<double> v = write ? values(in, points) : std::vector<double>{};
    if (write && kind == 4) {
      std::string packed(points * 16, '\0');
      for (std::size_t i = 0; i < points; ++i) {
        const std::string s = pick(kTexts, static_cast<unsigned>(i) + in.peekCycled(i));
        std::memcpy(&packed[i * 16], s.data(), std::min<std::size_t>(s.size(), 16));
      }
      H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, packed.data());
    } else if (write && kind == 5) {
      std::vector<const char*> p(points);
      for (std::size_t i = 0; i < points; ++i) p[i] = pick(kTexts, static_cast<unsigned>(i));
      H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, p.data());
    } else if (write && kind == 7) {
      H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
    } else if (write) {
      H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
    }
    if (d >= 0) H5Dclose(d);
    H5Pclose(dcpl);
    H5Sclose(space);
    H5Tclose(type);
  }

  // Opcode 4: object, name, then a value of one of eight shapes.
  void attribute(Bytes& in) {
    const std::string object = objectPath(in);
    const unsigned nameByte = in.u8();
    const std::string name = nameByte == 255 ? in.raw(16) : pick(kAttrNames, nameByte);
    const unsigned t = in.u8();
    const unsigned v = in.u8();
    const double number = v == 255 ? in.f64() : kNumbers[v % kNumbers.size()];
    std::string text = v == 255 ? in.raw(64) : pick(kTexts, v);
    // The hash of the metric study's definitions: /metrics is then read back by the summary.
    if (text == "<metrics hash>") text = metricsHash_;
    setAttribute(file(current_), object, name, t & 7U, number, text, in.u8());
  }

  static void setAttribute(hid_t f, const std::string& object, const std::string& name,
                           unsigned shape, double number, const std::string& text, unsigned count) {
    if (object != "/" && H5Lexists(f, object.c_str(), H5P_DEFAULT) <= 0) {
      const hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
      H5Pset_create_intermediate_group(lcpl, 1);
      const hid_t g = H5Gcreate2(f, object.c_str(), lcpl, H5P_DEFAULT, H5P_DEFAULT);
      if (g >= 0) H5Gclose(g);
      H5Pclose(lcpl);
    }
    const hid_t o = H5Oopen(f, object.c_str(), H5P_DEFAULT);
    if (o < 0) return;
    if (H5Aexists(o, name.c_str()) > 0) H5Adelete(o, name.c_str());
    hid_t type = -1, space = -1;
    std::vector<double> numbers;
    const hsize_t n = count + 1;
    switch (shape) {
      case 0:
      case 1:
        type = H5Tcopy(shape == 0 ? H5T_IEEE_F64LE : H5T_STD_I64LE);
        space = H5Screate(H5S_SCALAR);
        numbers = {number};
        break;
      case 2:
      case 3:
        type = H5Tcopy(H5T_C_S1);
        H5Tset_size(type, shape == 2 ? std::max<std::size_t>(1, text.size()) : H5T_VARIABLE);
        space = H5Screate(H5S_SCALAR);
        break;
      case 4:
        type = H5Tcopy(H5T_IEEE_F64LE);
        space = H5Screate_simple(1, &n, nullptr);
        numbers.assign(n, number);
        break;
      case 5:
        type = H5Tcopy(H5T_C_S1);
        H5Tset_size(type, 8);
        space = H5Screate(H5S_NULL);
        break;
      case 6:
        type = H5Tcopy(H5T_IEEE_F32LE);
        space = H5Screate(H5S_SCALAR);
        numbers = {number};
        break;
      default:
        type = H5Tcopy(H5T_C_S1);
        H5Tset_size(type, H5T_VARIABLE);
        space = H5Screate_simple(1, &n, nullptr);
        break;
    }
    const hid_t a = H5Acreate2(o, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
    if (a >= 0) {
      if (!numbers.empty()) {
        H5Awrite(a, H5T_NATIVE_DOUBLE, numbers.data());
      } else if (shape == 2) {
        std::string buf = text.empty() ? std::string(1, '\0') : text;
        H5Awrite(a, type, buf.data());
      } else if (shape == 3) {
        const char* p = text.c_str();
        H5Awrite(a, type, static_cast<const void*>(&p));
      } else if (shape == 7) {
        const std::vector<const char*> p(n, text.c_str());
        H5Awrite(a, type, p.data());
      }
      H5Aclose(a);
    }
    H5Sclose(space);
    H5Tclose(type);
    H5Oclose(o);
  }

  void series(const std::string& p, const std::vector<double>& v) {
    if (!spend(v.size())) return;
    const hsize_t n = v.size();
    const hid_t space = H5Screate_simple(1, &n, nullptr);
    const hid_t d = H5Dcreate2(file(current_), p.c_str(), H5T_IEEE_F64LE, space, lcpl_, H5P_DEFAULT,
                               H5P_DEFAULT);
    if (d >= 0) {
      if (n > 0) H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
      H5Dclose(d);
    }
    H5Sclose(space);
  }

  void text(const std::string& object, const std::string& name, const std::string& value) {
    setAttribute(file(current_), object, name, 2, 0.0, value, 0);
  }
  void number(const std::string& object, const std::string& name, double value) {
    setAttribute(file(current_), object, name, 0, value, "", 0);
  }

  // Opcode 0: a run's outputs as the workbench writes them (tests/hostile/forge_result.py's
  // base): /time, /bodies/<ws>/{s,y}, /contact/<ws>/<side>/{Y,Q,y_track,normal_force}, /stats,
  // optionally under /vehicles/<name>, with irregularities, a stored track or a failure record.
  void base(Bytes& in) {
    const std::size_t n = 1 + in.u8() * 4U;
    const double dt = (in.u8() & 1U) != 0 ? 5e-3 : 2.5e-3;
    const unsigned flags = in.u8();
    const std::string root = (flags & 1U) != 0 ? "/vehicles/a" : "";
    ws_ = (flags & 32U) != 0 ? "ws" : "ws1";
    std::vector<double> t(n), s(n), y(n), q(n), yy(n);
    for (std::size_t i = 0; i < n; ++i) {
      t[i] = dt * static_cast<double>(i);
      s[i] = 20.0 * t[i];
      y[i] = 1e-3 * std::sin(2 * M_PI * 1.5 * t[i]);
      q[i] = 50e3 + 1e3 * std::sin(7.0 * t[i]);
      yy[i] = 2e3 * std::sin(2 * M_PI * 1.5 * t[i]);
    }
    series("/time", t);
    series(root + "/bodies/" + ws_ + "/s", s);
    series(root + "/bodies/" + ws_ + "/y", y);
    text(root + "/bodies", "names", ws_);
    text(root + "/bodies/" + ws_, "kind", "wheelset");
    if (!root.empty()) text("/vehicles", "names", "a");
    for (const char* side : {"left", "right"}) {
      const std::string g = root + "/contact/" + ws_ + "/" + side + "/";
      series(g + "Y", yy);
      series(g + "Q", q);
      series(g + "y_track", yy);
      series(g + "normal_force", q);
      if ((flags & 2U) != 0) {
        series(g + "patch0/t_gamma", y);
        series(g + "patch0/power", y);
        series(g + "patch1/t_gamma", y);
        series(g + "patch1/power", y);
      }
    }
    number("/contact", "mu", 0.3);
    const bool failed = (flags & 4U) != 0;
    text("/stats", "status", failed ? "failed" : "ok");
    text("/stats", "message", failed ? "step failure" : "");
    number("/stats", "t_reached", t.back());
    if (failed) {
      text("/stats", "failure_kind", "step_failure");
      number("/stats", "failure_t", t.back());
      number("/stats", "failure_s", s.back());
    }
    if ((flags & 8U) != 0) {
      series("/track/irregularities/s", s);
      series("/track/irregularities/left_y", y);
      series("/track/irregularities/right_y", y);
    }
    if ((flags & 16U) != 0) {
      text("/track", "stored_in", "tracks/store.h5");
      text("/track", "track_hash", "0123456789abcdef");
      const FileId was = current_;
      current_ = kStore;
      text("/track", "track_hash", "0123456789abcdef");
      series("/track/centreline/s", s);
      series("/track/irregularities/s", s);
      series("/track/irregularities/alignment", y);
      current_ = was;
    }
  }

  // Opcode 9: /assessment as a run's assessment writes it (safety of ws1; with flags, wear,
  // a section and the comfort and stability groups), n samples at sample_every.
  void assessmentGroup(Bytes& in) {
    const std::size_t n = in.u16() % 2048;
    const unsigned flags = in.u8();
    const double dt = (flags & 1U) != 0 ? 5e-3 : 2.5e-3;
    std::vector<double> t(n), d(n), y(n), q(n);
    for (std::size_t i = 0; i < n; ++i) {
      t[i] = dt * static_cast<double>(i);
      d[i] = 20.0 * t[i];
      y[i] = 2e3 * std::sin(2 * M_PI * 1.5 * t[i]);
      q[i] = 50e3 + 1e3 * std::sin(7.0 * t[i]);
    }
    const std::string A = "/assessment";
    number(A, "sample_every", dt);
    series(A + "/time", t);
    series(A + "/distance", d);
    for (const char* side : {"left", "right"}) {
      const std::string g = A + "/safety/" + ws_ + "/" + side;
      number(g, "q0", 50e3);
      number(g, "s_offset", 0.0);
      series(g + "/Y", y);
      series(g + "/Q", q);
      series(g + "/y_track", y);
      if ((flags & 2U) != 0) {
        for (const char* p : {"/patch0", "/patch1"}) {
          series(A + "/wear/" + ws_ + "/" + side + p + "/t_gamma", y);
          series(A + "/wear/" + ws_ + "/" + side + p + "/power", y);
        }
      }
    }
    if ((flags & 4U) != 0) {
      text(A + "/sections", "names", "sec1");
      text(A + "/sections/sec1", "kind", (flags & 8U) != 0 ? "tangent" : "curve");
      number(A + "/sections/sec1", "from", 0.0);
      number(A + "/sections/sec1", "to", d.empty() ? 0.0 : d.back() * 0.5);
      if ((flags & 8U) == 0) number(A + "/sections/sec1", "radius", 300.0);
    }
    if ((flags & 16U) != 0) {
      series(A + "/comfort/p1/a_x", y);
      series(A + "/comfort/p1/a_y", y);
      series(A + "/comfort/p1/a_z", y);
    }
    if ((flags & 32U) != 0) {
      number(A + "/stability/bogie1/" + ws_, "bogie_mass", 2500.0);
      series(A + "/stability/bogie1/" + ws_ + "/acceleration", y);
    }
  }

  void victimContent() {
    const FileId was = current_;
    current_ = kVictim;
    text("/", "owner", "not railbench");
    series("/schema/assessment/path", {1.0, 2.0});
    current_ = was;
  }

  fs::path work_, victim_;
  std::string metricsHash_;
  std::array<hid_t, kFiles> files_ = {-1, -1, -1, -1};
  FileId current_ = kResult;
  hid_t lcpl_ = -1;
  std::size_t spent_ = 0;
  std::string ws_ = "ws1";  // the wheelset's name in base() and assessmentGroup()
};

// RB_FUZZ_VERBOSE=1: what each reader made of the input (to check that a seed reaches its code).
void verbose(const char* what, const std::string& text) {
  static const bool on = std::getenv("RB_FUZZ_VERBOSE") != nullptr;
  if (on) std::fprintf(stderr, "%s: %s\n", what, text.c_str());
}

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Swallows what assess prints (its summary and warnings).
class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return c; }
};

// The study whose metrics are evaluated on the forged result (as a summary does), written once
// beside its base scenario (the single wheelset of case 1).
const scenario::StudySpec& metricStudy(const fs::path& dir) {
  static const scenario::StudySpec st = [&] {
    std::ifstream in(fs::path(RB_SOURCE_DIR) / "scenarios/validation/case1_R300_kec.lua");
    std::ofstream(dir / "base.lua")
        << std::string{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    std::ofstream(dir / "result_study.lua") << R"(study {
  base = "base.lua",
  cases = { { label = "reference", role = "reference" }, { label = "other", ["vehicle.speed"] = 21 } },
  metrics = {
    { name = "y_max", signal = "/bodies/ws/y", stat = "max_abs" },
    { name = "y_win", signal = "/bodies/ws/y", stat = "rms", from = 5, to = 30 },
    { name = "q_time", signal = "/contact/ws/left/normal_force", stat = "mean", along = "time" },
    { name = "y_ss", kind = "steady", signal = "/bodies/ws/y", length = 10 },
    { name = "yq", kind = "assessment", quantity = "y_over_q" },
    { name = "yq_path", kind = "assessment", quantity = "/assessment/safety/ws/left/y_over_q@value" },
    { name = "y_err", kind = "error", signal = "/bodies/ws/y" },
    { name = "q_fn", signals = { l = "/contact/ws/left/normal_force" }, fn = function(s) return #s.l end },
  },
}
)";
    return scenario::loadStudy((dir / "result_study.lua").string(), RB_SOURCE_DIR);
  }();
  return st;
}

// A metric value is finite exactly when it has no reason (the summary's rule).
void checkRecords(const std::vector<io::MetricRecord>& records) {
  for (const auto& r : records) {
    if (r.why.empty() && !std::isfinite(r.value))
      throw std::logic_error("metric " + r.name + ": non-finite value without a reason");
    if (!r.why.empty() && !std::isnan(r.value))
      throw std::logic_error("metric " + r.name + ": a value and a reason");
  }
}

// Every reader that does not write, each on the forged files; BadResult (exit 1) and InputError
// are the expected refusals.
void readOnly(const Forge& forge, unsigned flags, const fs::path& scratch) {
  const std::string result = forge.path(kResult), ref = forge.path(kReference);
  try {
    const double tEnds[] = {0.0, 2.0, 1.0, 10.0};
    const auto c = stress::checkResult(result, (flags & 1U) != 0 ? 2 : 0, stress::Bounds{},
                                       tEnds[(flags >> 1U) & 3U]);
    std::string problems;
    for (const auto& p : c.problems) problems += p + "; ";
    verbose("check-result", problems.empty() ? "passes" : problems);
    volatile std::size_t sink = stress::toJson(c).size();
    (void)sink;
  } catch (const io::BadResult& e) {
    verbose("check-result", e.what());
  } catch (const InputError& e) {
    verbose("check-result", e.what());
  }
  for (const std::string& f : {result, forge.path(kStore)}) {
    try {
      (void)io::readStats(f);
      (void)io::readRootText(f, "input_hash");
      (void)io::readMetrics(f);
      (void)io::isStoredTrack(f, "0123456789abcdef");
    } catch (const io::BadResult&) {
    }
  }
  try {
    for (const auto& q : study::parseQuantities({"y", "yaw", "Q", "YQ", "ws1.y"}, {"ws1"}, true)) {
      const study::Error e = study::fileError(result, ref, q);
      if (e.have) verbose(("error " + q.tag).c_str(), std::to_string(e.max));
      if (e.have && (std::isnan(e.max) || std::isnan(e.rms) || e.max < 0.0 || e.rms < 0.0))
        throw std::logic_error("fileError: a NaN or negative error of " + q.tag);
    }
  } catch (const io::BadResult&) {
  }
  try {
    const scenario::StudySpec& st = metricStudy(scratch);
    study::detail::MetricContext ctx(st);
    const auto records = study::detail::summaryMetrics(ctx, st.cases.front(), result, ref);
    for (const auto& r : records)
      verbose(("metric " + r.name).c_str(), r.why.empty() ? std::to_string(r.value) : r.why);
    checkRecords(records);
  } catch (const io::BadResult& e) {
    verbose("metrics", e.what());
  }
}

// The /assessment a successful assess wrote holds no NaN or infinity.
void checkAssessed(const std::string& result) {
  const io::ResultReader r(result);
  if (!r.ok()) throw std::logic_error("assess succeeded but the result cannot be read");
  for (const auto& p : r.nonFinite(std::numeric_limits<std::size_t>::max()))
    if (p.rfind("/assessment", 0) == 0 || p.rfind("/schema/assessment", 0) == 0)
      throw std::logic_error("assess wrote a non-finite value: " + p);
}

void assess(const Forge& forge) {
  const std::string result = forge.path(kResult), victim = forge.path(kVictim);
  const std::string before = readAll(result), victimBefore = readAll(victim);
  app::AssessOptions o;
  o.file = result;
  o.quiet = true;
  NullBuffer null;
  std::streambuf* const out = std::cout.rdbuf(&null);
  bool ok = false;
  try {
    ok = app::assessFile(o) == 0;
    verbose("assess", ok ? "replaced /assessment" : "exit != 0");
  } catch (const io::BadResult& e) {
    verbose("assess", e.what());
  } catch (const InputError& e) {
    verbose("assess", e.what());
  } catch (...) {
    std::cout.rdbuf(out);
    throw;
  }
  std::cout.rdbuf(out);
  if (readAll(victim) != victimBefore)
    throw std::logic_error("assess changed a file outside the result's folder");
  if (!ok && readAll(result) != before) throw std::logic_error("a failed assess changed the file");
  if (ok) checkAssessed(result);
}

}  // namespace

void resultFiles(std::string_view data) {
  static const fs::path scratch = [] {
    std::string templ = (fs::temp_directory_path() / "railbench_fuzz_result_XXXXXX").string();
    if (::mkdtemp(templ.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    return fs::path(templ);
  }();
  static const bool cleanup = [] {
    std::atexit([] {
      std::error_code ec;
      fs::remove_all(scratch, ec);
    });
    return true;
  }();
  (void)cleanup;
  io::initHdf5();
  const fs::path work = scratch / "work";
  std::error_code ec;
  fs::remove_all(work, ec);
  fs::create_directories(work / "tracks");
  ::mkfifo((work / "fifo.h5").c_str(), 0600);
  Bytes in(data);
  const unsigned flags = in.u8();
  {
    Forge forge(work, scratch / "victim.h5", study::detail::metricsHash(metricStudy(scratch)));
    forge.run(in);
    readOnly(forge, flags, scratch);
    if ((flags & 8U) == 0) assess(forge);
  }
  if (H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL) != 0)
    throw std::logic_error("an HDF5 object was left open by a reader");
}

}  // namespace rb::fuzz
