#pragma once
// Elastic (multi-point) wheel/rail contact geometry: the online contact search of the "elastic"
// contact method, pure geometry, no dynamics. docs/elastic_contact.md.
//
// One wheel over one rail (architecture.md: "the contact search asks the rails near a wheel"):
// the wheel is the surface of revolution of its profile h_w(s_w) (profile.hpp) about the axle of
// a wheelset with FULL rigid-body freedom (lateral y, vertical z, roll phi, yaw psi; the
// longitudinal position and the pitch (spin) angle do not change a surface of revolution over a
// prismatic rail); the rail is the prism of its profile h_r(s_r) along the track X, placed as the
// KEC/LUT geometry places it (config.hpp: origin at sigma Lr, rotated by sigma beta).
//
// Frames and rotations (SI, track frame X forward, Y LEFT, Z UP as everywhere in railbench):
//   wheelset -> track   R = Rx(phi) Rz(psi)      (exact rotations, no linearisation; the
//                                                 order is ElasticSearchSpec::angles)
//   wheel point (wheelset coordinates, theta the angle from the lowest point, forward > 0)
//                       X(s, theta) = (h sin theta, sigma Lw + s, -h cos theta)
//   outward normal      m(s, theta) = (sin theta, -h'(s), -cos theta)   (unnormalised)
//
// Contact locus (exact for a prismatic rail). The rail normal never has an X component, so at a
// contact the wheel normal must have none either: R m . e_X = 0, i.e. for every wheel circle s
//   R00 sin(theta) - R02 cos(theta) = R01 h'(s),
// whose root near theta = 0 gives the one point of that circle that can touch the rail. These
// points form the contact locus (Wang 1984; the "virtual profile" of Ayasse & Chollet, Handbook
// of Railway Vehicle Dynamics, 2006, ch. 4); with R = Rx(phi) Rz(psi) it reads
//   cos(psi) sin(theta) = -sin(psi) h'(s)
// (the roll drops out). Its projection on the Y-Z plane is a plane curve whose
// normal IS the wheel normal, so the 3-D search reduces EXACTLY to a plane problem between that
// curve and the rail profile. To first order in the angles theta = -psi h', i.e. the contact
// point leads the wheel centre by
//   x_w = h sin(theta) ~ -r tan(gamma_w) psi        (r rolling radius, gamma_w = atan h' the
//                                                    profile slope; Wickens, Fundamentals of Rail
//                                                    Vehicle Dynamics, 2003, the classic "contact
//                                                    point shift" of a yawed wheelset),
// which the search computes exactly (and the Manchester benchmark confirms, docs).
//
// Search. The wheel is sampled (ElasticSearchSpec::sample_step) over its whole profile (tread,
// flange root, flange, flange back); every sample's locus point is measured against the rail
// below it (distance to the rail tangent line there, negative = penetration). Every local minimum
// of that sampled gap below spec.candidate_gap is refined by Newton on (s_w, s_r):
//   (W(s_w) - R(s_r)) . t_r(s_r) = 0   (the wheel point lies on the rail normal through R)
//   n_w(s_w) x n_r(s_r) = 0            (the normals are parallel)
// and each refined minimum with penetration delta_g = -(W - R) . n_r > 0 is a patch. Where that
// Newton fails or leaves the sample interval around its minimum (near-conformal contact: the S1002
// throat is an R13 arc against the R13 gauge corner of 60E1, the normals stay parallel along it
// and the 2x2 system is singular), the minimum is found by a safeguarded 1-D search of the exact
// gap over the two sample intervals around it (refineBracketed).
// Seeds (a previous result, a table) are tried only where the refinement of a scanned minimum
// fails: they never add or move a patch, and the result does not depend on them (tested).
//
// Patch birth and death are continuous. A patch is born with delta = 0. But two penetration
// zones can also merge (the gap ridge between two minima sinks below zero), swap which one is
// deeper, or a shallow minimum can die by merging with the gap maximum beside it (a fold) while it
// still penetrates. The approach given to the normal problem shares the overlap between
// neighbouring minima: with r the lowest ridge (highest sampled gap on the path) to a neighbouring
// minimum j, e_k = r - gap_k and e_j = r - gap_j the depths of the two below it,
//   delta_k = min(delta_g, e_k + max(0, -r) e_k / (e_k + e_j)).
// Zones separated by a gap above zero keep their full delta_g; merged zones split the common part
// max(0, -r) in proportion to their own depths, so nothing jumps when two minima swap depth, and
// a minimum dying at a fold (e_k -> 0) takes its force to zero. (With three or more mutually
// penetrating minima the neighbour with the lowest ridge is used; the share jumps where two
// ridges are equal: not seen on S1002/UIC60.)
//
// Cost (docs/elastic_contact.md, section 7). The scan dominates (~70 % of the instructions of a
// search). With ElasticSearchSpec::prune_scan (default; steps up to 0.3 mm) it evaluates the
// gap exactly every 16 samples and at block middles, and skips a block, or fills it by
// interpolation, only where a rigorous bound proves every sample in it above candidate_gap, or the
// gap strictly monotonic there (so no sample in it can be a candidate minimum, a ridge or min_gap):
// with e = v - h_r(u) the rail-frame vertical gap, its value and slope at both ends and a bound of
// |e''| from the profiles' precomputed range maxima of |h'|, |h''|, |h'''| (wheel) and |h'|, |h''|
// (rail), and a signed bound of e'' from the signed ranges of h'' and h_r'' (the gap's curvature
// is the difference of the two profiles' curvatures, which nearly cancel on a conformal tread).
// The result is bit-identical to the full scan (tested at 3900 poses); only the workspace's gap
// array holds bounds/interpolations at skipped samples.
// Successive poses (the dynamic method keeps one workspace per wheel): blocks of 16 samples proved
// above candidate_gap keep a certificate in the workspace; at a later pose the movement of every
// locus point is bounded from the pose change, hence the change of every sample's gap, and the
// block is skipped without a sample while its bound stays above candidate_gap. The same model at
// the same pose (bit for bit, no seed) returns the workspace's last result. Neither can change a
// result (tested against fresh full scans along a random walk of 10000 poses).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "workbench/contact/config.hpp"
#include "workbench/profiles/profile.hpp"

namespace rb::contact {

// Wheelset pose relative to the track frame at the wheelset's longitudinal position.
struct ElasticPose {
  double y = 0.0;    // [m] lateral, positive to the left
  double z = 0.0;    // [m] axle centre height above the track frame
  double phi = 0.0;  // [rad] roll about X (left wheel up for phi > 0)
  double psi = 0.0;  // [rad] yaw about Z (nose to the left for psi > 0)
  // [-] WheelRailPair::rail_next's share of the rail under the wheel (ignored, taken as 0, when
  // the pair has no rail_next).
  double blend = 0.0;
};

// One wheel over one rail: the geometry set-up of config.hpp for one side.
struct WheelRailPair {
  std::shared_ptr<const profiles::Profile> wheel, rail;
  Side side = Side::Left;
  double wheel_lw = 0.750;   // [m] wheel profile origin at sigma Lw along the axle
  double rail_lr = 0.75303;  // [m] rail profile origin at sigma Lr
  double beta = 1.0 / 40.0;  // [rad] rail inclination (the rail frame is rotated by sigma beta)
  double rail_dy = 0.0;      // [m] rail profile origin offset (irregularity, gauge), track Y
  double rail_dz = 0.0;      // [m] rail profile origin offset, track Z
  // A rail that changes along the track (sliced_rail.hpp): the rail between two profile slices is
  // h_r(u) + b (h_next(u) - h_r(u)) in the same rail frame, b = ElasticPose::blend in [0, 1],
  // over the part of the profile parameter both slices cover. Null: a prismatic rail.
  std::shared_ptr<const profiles::Profile> rail_next;
};
// The two pairs of a ContactGeometryConfig (left, right), the same placement the LUT/KEC use.
std::array<WheelRailPair, 2> wheelRailPairs(const ContactGeometryConfig& config);

// Order of the wheelset angles (they differ at second order, phi psi: the contact point's
// longitudinal shift changes by about r phi psi).
enum class EulerOrder {
  RollYaw,  // R = Rx(phi) Rz(psi): roll about the track X, then yaw about the rolled vertical
            // (CONTACT's roll-yaw-pitch convention, user guide section "wheelset position"; the
            // Manchester benchmark inputs give their roll and yaw in it)
  YawRoll,  // R = Rz(psi) Rx(phi)
};

// The wheelset -> track rotation of a pose's roll and yaw in that order (the spin left out),
// rows of the matrix.
std::array<std::array<double, 3>, 3> wheelsetRotation(double phi, double psi, EulerOrder order);

struct ElasticSearchSpec {
  EulerOrder angles = EulerOrder::RollYaw;
  double sample_step = 0.25e-3;   // [m] wheel sampling of the scan
  double candidate_gap = 0.1e-3;  // [m] sampled minima below this gap are refined
  // [m] half-width over which B_span is measured (the lateral semi-axes of patches are
  // 0.35-5 mm); 0: B_span = B.
  double curvature_span = 1.0e-3;
  double min_approach = 1e-10;  // [m] patches with a smaller (shared-overlap) delta dropped
  double same_point = 1e-6;     // [m] refined minima closer than this on the wheel are one
  double newton_tol = 1e-13;    // [m] residual tolerance of the refinement
  int newton_max_iter = 30;
  // Skip the wheel samples a rigorous bound proves above candidate_gap or monotonic (header
  // comment "Cost"; only for sample_step <= 0.3 mm, coarser scans are faster in full); the
  // result is bit-identical to the full scan (tested). false: every sample.
  bool prune_scan = true;
};

// Geometry of one contact patch (SI, track frame unless said otherwise).
struct ElasticPatchGeometry {
  double s_w = 0.0, s_r = 0.0;       // [m] wheel and rail profile parameters of the contact point
  double x = 0.0, y = 0.0, z = 0.0;  // [m] contact (rail) point, track frame; x relative to the
                                     // wheelset centre
  double x_w = 0.0;                  // [m] longitudinal shift in the wheelset frame, h sin(theta)
  double theta = 0.0;                // [rad] angle of the contact point on its wheel circle
  double n_y = 0.0, n_z = 1.0;       // [-] unit rail normal (out of the rail), track frame
  // [-] its X component: 0 on a prismatic rail; a rail that rises or moves sideways along the
  // track (rail_slope.hpp) tilts its normal by its slope
  double n_x = 0.0;
  double gamma = 0.0;      // [rad] contact angle, positive toward the track centre (geometry.hpp)
  double radius = 0.0;     // [m] rolling radius h_w(s_w)
  double gap_depth = 0.0;  // [m] delta_g = penetration of the undeformed surfaces, > 0
  double approach = 0.0;   // [m] delta used by the normal problem (shared overlap)
  double k_wheel_trans = 0.0;    // [1/m] principal curvatures, convex positive
  double k_wheel_rolling = 0.0;  // [1/m] cos(alpha) / r (Meusnier)
  double k_rail_trans = 0.0;     // [1/m]
  double A = 0.0, B = 0.0;       // [1/m] relative curvatures, rolling and lateral (hertz.hpp)
  // [1/m] lateral relative curvature measured over the span +-w of ElasticSearchSpec::
  // curvature_span: B_span = (sep(w) + sep(-w) - 2 sep(0)) / (2 w^2), sep(t) the normal
  // separation of the two profiles at tangent offset t (equals B as w -> 0; B where a side
  // could not be measured).
  double B_span = 0.0;
  bool refined = true;  // Newton converged (false: the sampled point is used)
  // [m] rise of the rail surface along n per unit of ElasticPose::blend at the contact,
  // (h_next - h_r)(s_r) / sqrt(1 + h_r'^2): the rail surface's normal velocity is
  // V d(blend)/ds times this (0 on a prismatic rail).
  double rail_rise = 0.0;
};

inline constexpr int kMaxElasticPatches = 8;

struct ElasticWheelGeometry {
  std::array<ElasticPatchGeometry, kMaxElasticPatches> patch{};
  int count = 0;           // patches, deepest (largest approach) first
  bool truncated = false;  // more than kMaxElasticPatches penetrating minima (the shallowest
                           // were dropped)
  double min_gap = 0.0;    // [m] smallest sampled gap over the rail (< 0: penetration)
  int newton_iterations = 0;
};

// What the pruned scan proved about one block of wheel samples at a reference pose: every
// sample's gap was at least lb, at most g_abs in magnitude, with its rail parameter in
// [u_lo, u_hi] (ElasticContactSearch::scanPruned).
struct ElasticScanCert {
  std::uint64_t model = 0;   // ElasticContactSearch::id(); 0: none
  std::uint64_t ref_id = 0;  // the search (ElasticSearchWorkspace::searches) that made it
  double blend = 0.0;        // ElasticPose::blend of the reference pose (a certificate holds
                             // for that rail only)
  double lb = 0.0, g_abs = 0.0, u_lo = 0.0, u_hi = 0.0;
  // The reference pose: y, z, rows Y and Z of the rotation, R01 / rho, cos(eps), sin(eps).
  std::array<double, 11> ref{};
};

// Scratch memory of a search (one per thread, or per wheel); sized on first use, then
// allocation-free.
struct ElasticSearchWorkspace {
  std::vector<double> gap;  // sampled gap per wheel sample (+inf when not over the rail; with
                            // ElasticSearchSpec::prune_scan, a lower bound above candidate_gap
                            // where bound[i], an interpolation where the gap is monotonic)
  std::vector<unsigned char> bound;
  std::vector<int> minima;    // sample indices of candidate minima
  std::vector<double> depth;  // refined gap at each candidate
  std::vector<double> sw, sr;
  std::vector<unsigned char> ok;
  // Blocks of samples certified above candidate_gap, kept between searches (scanPruned()).
  std::vector<ElasticScanCert> cert;
  std::uint64_t searches = 0;  // searches made with this workspace
  // The last search made with this workspace: the same search model (ElasticContactSearch::id())
  // at the same pose, bit for bit, without a seed, has the same result, returned without
  // searching (14 % of the calls of the case-2 elastic run repeat their wheel's last pose).
  std::uint64_t last_model = 0;  // 0: none
  ElasticPose last_pose;
  ElasticWheelGeometry last_out;
};

// The search model of one wheel-rail pair (precomputed wheel samples).
class ElasticContactSearch {
 public:
  ElasticContactSearch(WheelRailPair pair, ElasticSearchSpec spec = {});

  const WheelRailPair& pair() const { return pair_; }
  const ElasticSearchSpec& spec() const { return spec_; }
  // Identity of this search model (its pair and spec) for ElasticSearchWorkspace: unique per
  // constructed model, shared by its copies.
  std::uint64_t id() const { return id_; }
  double sigma() const { return sigma_; }
  // The rail profile at u: WheelRailPair::rail, blended with rail_next by `blend` (ignored without
  // rail_next), exactly the rail where the two slices are the same profile.
  profiles::ProfilePoint railAt(double u, double blend) const;
  // The rail profile parameters the search covers: the rail's, or the part that both slices of a
  // blended rail cover.
  double railMin() const { return rail_smin_; }
  double railMax() const { return rail_smax_; }

  // Every penetrating local minimum of the wheel-rail gap at this pose (see header comment).
  // `seed` (optional): patches of an earlier search whose (s_w, s_r) are tried as extra starting
  // points. Allocation-free once the workspace is sized.
  void search(const ElasticPose& pose, ElasticWheelGeometry& out, ElasticSearchWorkspace& ws,
              const ElasticWheelGeometry* seed = nullptr) const;
  ElasticWheelGeometry search(const ElasticPose& pose,
                              const ElasticWheelGeometry* seed = nullptr) const;

  // Locus point of the wheel circle s_w at a pose: track-frame Y-Z position, the wheel normal,
  // theta and the longitudinal position. Exposed for tests and plots.
  struct LocusPoint {
    double x = 0.0, y = 0.0, z = 0.0;    // [m] track frame (x relative to the wheelset centre)
    double n_y = 0.0, n_z = -1.0;        // [-] outward wheel normal (unit), track frame
    double t_y = 0.0, t_z = 0.0;         // d(y, z)/ds_w along the locus
    double dn_y = 0.0, dn_z = 0.0;       // d(unnormalised normal)/ds_w
    double ny_raw = 0.0, nz_raw = -1.0;  // unnormalised normal (y, z)
    double theta = 0.0, x_w = 0.0;
  };
  LocusPoint locus(const ElasticPose& pose, double s_w) const;

  // Geometry of the contact at given (s_w, s_r) (no solve); approach = gap_depth.
  ElasticPatchGeometry describe(const ElasticPose& pose, double s_w, double s_r) const;

  // Newton refinement from (s_w, s_r); returns iterations (< 0: not converged).
  int refine(const ElasticPose& pose, double& s_w, double& s_r) const;
  // Signed distance of the locus point of s_w to the rail (its foot point s_r, updated from the
  // value passed in) and its derivative d gap / d s_w = t_w . n_r (envelope theorem).
  double gapAt(const ElasticPose& pose, double s_w, double& s_r, double* dgap = nullptr) const;
  // Safeguarded 1-D minimisation of gapAt over [lo, hi] (a root of d gap / d s_w bracketed by
  // the ends), for where the 2-D Newton is ill-conditioned (near-conformal contacts, B ~ 0).
  // Returns iterations, < 0 when the ends do not bracket a minimum.
  int refineBracketed(const ElasticPose& pose, double lo, double hi, double& s_w,
                      double& s_r) const;

 private:
  struct PoseTrig;
  // The same as the public functions, with the pose's rotation computed once per search.
  // full = false: only the track-frame position, its tangent and the unnormalised normal with
  // its derivative (what the Newton solves use: no atan2 and no hypot per iteration).
  LocusPoint locus(const PoseTrig& t, double s_w, bool full = true) const;
  double gapAt(const PoseTrig& t, double s_w, double& s_r, double* dgap = nullptr) const;
  int refine(const PoseTrig& t, double& s_w, double& s_r) const;
  int refineBracketed(const PoseTrig& t, double lo, double hi, double& s_w, double& s_r) const;
  ElasticPatchGeometry describe(const PoseTrig& t, double s_w, double s_r) const;
  // The rail profile at u: WheelRailPair::rail, blended with rail_next by the pose's blend.
  profiles::ProfilePoint railAt(const PoseTrig& t, double u) const;
  bool railInside(double u) const { return u >= rail_smin_ && u <= rail_smax_; }
  // Normal separation of wheel and rail at tangent offset t from the rail point (y0, z0) with unit
  // normal (ny, nz) (false when a side cannot be reached).
  bool separation(const PoseTrig& t, double y0, double z0, double ny, double nz, double off,
                  double s_w, double s_r, double& sep) const;
  // Wheel sample i's locus point in the rail frame (u along the rail profile, v normal to it) and
  // the rail point below it; over = false when u is beyond the rail profile.
  struct SampleOnRail {
    double st = 0.0, ct = 1.0, wq = 1.0;  // sin, cos of the locus angle, and its root term
    double h = 0.0;                       // wheel radius at the sample
    double u = 0.0, v = 0.0;
    profiles::ProfilePoint rp;
    bool over = false;
  };
  SampleOnRail sampleOnRail(const PoseTrig& t, std::size_t i) const;
  double sampledGap(const PoseTrig& t, std::size_t i, double& s_r) const;
  // The same gap (bit for bit), with e = v - h_r(u) (rail-frame vertical gap) and de/ds.
  double sampledGap(const PoseTrig& t, std::size_t i, double& s_r, double& e, double& de) const;
  // A sample of the pruned scan: gap, rail parameter, rail-frame vertical gap e and de/ds.
  struct ScanNode {
    std::size_t i;
    double g, u, e, de;
  };
  // What the exact ends of a block of samples prove about the samples inside it (Scan: nothing;
  // Skip: all above candidate_gap, lb a lower bound; Increasing/Decreasing: strictly monotonic).
  enum class ScanBlock { Scan, Skip, Increasing, Decreasing };
  // Skip: lb; Skip and monotonic: the range of the rail parameter in the block, and (Skip) a
  // bound of |gap| there.
  struct BlockInfo {
    double lb = 0.0, u_lo = 0.0, u_hi = 0.0, g_abs = 0.0;
  };
  ScanBlock classifyBlock(const PoseTrig& t, const ScanNode& a, const ScanNode& b,
                          BlockInfo& info) const;
  void poseShift(const PoseTrig& t, const ElasticScanCert& c, double& fixed,
                 double& per_slope) const;
  // What the scan of one block proved about all its samples (for its certificate).
  struct ScanTrack {
    bool ok = true;
    double lb = kScanInf, g_abs = 0.0, u_lo = kScanInf, u_hi = -kScanInf;
    void sample(double g, double u) {
      ok = ok && g < kScanInf;
      lb = std::min(lb, g);
      g_abs = std::max(g_abs, std::abs(g));
      u_lo = std::min(u_lo, u);
      u_hi = std::max(u_hi, u);
    }
  };
  static constexpr double kScanInf = std::numeric_limits<double>::infinity();
  template <class Exact>
  void scanBlock(const PoseTrig& t, const ScanNode& na, const ScanNode& nb, Exact& exact,
                 ScanTrack& track, ElasticWheelGeometry& out, ElasticSearchWorkspace& ws) const;
  void scanPruned(const PoseTrig& t, std::size_t i_lo, std::size_t i_hi, ElasticWheelGeometry& out,
                  ElasticSearchWorkspace& ws) const;
  void searchFull(const ElasticPose& pose, ElasticWheelGeometry& out, ElasticSearchWorkspace& ws,
                  const ElasticWheelGeometry* seed) const;
  void refineCandidates(const PoseTrig& t, ElasticWheelGeometry& out, ElasticSearchWorkspace& ws,
                        const ElasticWheelGeometry* seed) const;
  void collectPatches(const PoseTrig& t, ElasticWheelGeometry& out,
                      ElasticSearchWorkspace& ws) const;

  WheelRailPair pair_;
  ElasticSearchSpec spec_;
  std::uint64_t id_ = 0;
  double sigma_ = 1.0;
  double cb_ = 1.0, sb_ = 0.0;      // cos(beta), sigma sin(beta)
  std::vector<double> s_, h_, dh_;  // wheel samples
  std::vector<double> d2h_;         // h'' at the wheel samples
  // Scan pruning (header comment "Cost"): per wheel sample interval [s_i, s_i+1] and per rail bin
  // of width rail_bin_ (from rail_bin0_) upper bounds of |h'|, |h''| (and |h'''| on the wheel).
  // Range maxima in O(1) (sparse tables: level l holds the maxima over 2^l entries).
  struct RangeMax {
    std::vector<std::vector<double>> level;
    void build(const std::vector<double>& v);
    double operator()(std::size_t a, std::size_t b) const;  // max over [a, b), a < b
  };
  RangeMax wheel_d1_, wheel_d2_, wheel_d3_, rail_d1_, rail_d2_;
  // Signed bounds of h'' (maxima of h'' and of -h''), wheel and rail: the gap's curvature is the
  // DIFFERENCE of the two profiles' curvatures (classifyBlock()).
  RangeMax wheel_d2_hi_, wheel_d2_neg_, rail_d2_hi_, rail_d2_neg_;
  double wheel_xmax_ = 0.0;  // bound of |X| = sqrt(h^2 + L^2) over the wheel
  double wheel_hmax_ = 0.0, rail_bin0_ = 0.0, rail_bin_ = 0.25e-3;
  // [m] the rail's profile parameter range (with rail_next: the part both slices cover)
  double rail_smin_ = 0.0, rail_smax_ = 0.0;
  std::size_t rail_bins_ = 0;
};

}  // namespace rb::contact
