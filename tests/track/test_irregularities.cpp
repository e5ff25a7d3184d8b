// Track irregularities (paper Fig. 3): PSDs, synthesis statistics, reproducibility, rail relations.
#include <gtest/gtest.h>
#include <algorithm>

#include <cmath>
#include <complex>
#include <cstring>
#include <fstream>
#include <numbers>
#include <vector>

#include "track_test_util.hpp"
#include "workbench/track/irregularities.hpp"
#include "workbench/track/psd.hpp"
#include "workbench/track/samples.hpp"
#include "workbench/track/track.hpp"

namespace {

using namespace rb::track;
constexpr double kPi = std::numbers::pi;

IrregularitySpec psdSpec(const std::string& spectrum, std::uint64_t seed = 42) {
  IrregularitySpec s;
  s.source = IrregularitySource::Psd;
  s.spectrum = spectrum;
  s.seed = seed;
  s.loc = {"t.lua", 20};
  return s;
}

TrackSpec straightWithIrregularities(double length, const IrregularitySpec& irr) {
  TrackSpec t;
  t.segments = {rbtest::tangent(length)};
  t.step = 0.5;
  t.loc = {"t.lua", 1};
  t.irregularities = irr;
  return t;
}

// ---- PSD formulas ---------------------------------------------------------------------------

// GENSYS TRC_IPSD "ORE B176 high level" table [m^2/(1/m)] = 2 pi G(2 pi f) (reference document).
TEST(Psd, OreB176HighMatchesGensysTable) {
  struct Row {
    double f, lat, vert;
  };
  for (const Row r : {Row{0.02, 2.3194e-4, 4.0897e-4}, Row{0.1, 6.1608e-6, 1.0863e-5},
                      Row{0.2, 7.3333e-7, 1.2931e-6}}) {
    const double om = 2.0 * kPi * r.f;
    EXPECT_NEAR(2.0 * kPi * spectrumPsd(Spectrum::OreB176High, Channel::Alignment, om) / r.lat, 1.0,
                2e-4)
        << r.f;
    EXPECT_NEAR(2.0 * kPi * spectrumPsd(Spectrum::OreB176High, Channel::Vertical, om) / r.vert, 1.0,
                3e-4)
        << r.f;
  }
  // Spot values quoted in the brief: f = 0.1 1/m -> 6.16e-6 and 1.0865e-5.
  EXPECT_NEAR(2.0 * kPi * spectrumPsd(Spectrum::OreB176High, Channel::Alignment, 0.2 * kPi),
              6.16e-6, 0.01e-6);
  EXPECT_NEAR(2.0 * kPi * spectrumPsd(Spectrum::OreB176High, Channel::Vertical, 0.2 * kPi),
              1.0865e-5, 0.0002e-5);
}

// Cross level: the reference formula is an angle PSD with A_v / b^2 (b = 0.75 m); the model
// returns the height difference PSD, (2 b)^2 times larger. Gauge: A_g formula.
TEST(Psd, OreCrossLevelIsHeightDifferenceAndGaugeFormula) {
  const double wc = 0.8246, wr = 0.0206, ws = 0.4380, b = 0.75;
  for (const double om : {0.1, 0.5, 1.0, 2.0}) {
    const double o2 = om * om;
    const double den = (o2 + wr * wr) * (o2 + wc * wc) * (o2 + ws * ws);
    const double angle = (4.032e-7 / (b * b)) * wc * wc * o2 / den;
    EXPECT_NEAR(spectrumPsd(Spectrum::OreB176Low, Channel::CrossLevel, om) / (4.0 * b * b * angle),
                1.0, 1e-12);
    const double gauge = 5.32e-8 * wc * wc * o2 / den;
    EXPECT_NEAR(spectrumPsd(Spectrum::OreB176Low, Channel::Gauge, om) / gauge, 1.0, 1e-12);
  }
}

TEST(Psd, VerifiedFlags) {
  EXPECT_TRUE(psdVerified("ore_b176_low"));
  EXPECT_TRUE(psdVerified("ore_b176_high"));
  for (int c = 1; c <= 6; ++c) EXPECT_FALSE(psdVerified("fra_class_" + std::to_string(c)));
  EXPECT_TRUE(psdVerified("user"));
  EXPECT_FALSE(psdVerified("nonsense"));
  const TrackModel fra = compileTrack(straightWithIrregularities(100.0, psdSpec("fra_class_4")));
  EXPECT_FALSE(fra.psdVerified());
  EXPECT_FALSE(sampleTrack(fra).psd_verified);
  const TrackModel ore = compileTrack(straightWithIrregularities(100.0, psdSpec("ore_b176_low")));
  EXPECT_TRUE(ore.psdVerified());
}

// FRA class 5 vertical, with the public STEM-style value A_v = 0.2095 cm^2 rad/m.
TEST(Psd, FraFormulaUnits) {
  const double om = 0.5, wc = 0.8245;
  const double cm2 = 0.25 * 0.2095 * wc * wc / (om * om * (om * om + wc * wc));
  EXPECT_NEAR(spectrumPsd(Spectrum::FraClass5, Channel::Vertical, om) / (cm2 * 1e-4), 1.0, 1e-12);
}

TEST(Psd, UserTableLogLogAndZeroOutside) {
  PsdTable t;
  t.omega = {0.1, 1.0, 10.0};
  t.value = {1e-4, 1e-7, 1e-10};  // G = 1e-7 Omega^-3
  for (const double om : {0.1, 0.2, 0.5, 1.0, 3.0, 10.0}) {
    EXPECT_NEAR(psdTableValue(t, om) / (1e-7 * std::pow(om, -3.0)), 1.0, 1e-12) << om;
  }
  EXPECT_EQ(psdTableValue(t, 0.09), 0.0);
  EXPECT_EQ(psdTableValue(t, 10.01), 0.0);
  EXPECT_EQ(psdTableValue(PsdTable{}, 1.0), 0.0);
  // targetPsd: scale^2, band limits, disabled channels.
  IrregularitySpec s = psdSpec("user");
  s.user[0] = t;
  s.scale = 2.0;
  s.wavelength_min = 3.0;
  s.wavelength_max = 70.0;
  EXPECT_NEAR(targetPsd(s, Channel::Alignment, 1.0), 4e-7, 1e-19);
  EXPECT_EQ(targetPsd(s, Channel::Alignment, 2.0 * kPi / 80.0), 0.0);  // below the band
  EXPECT_EQ(targetPsd(s, Channel::Vertical, 1.0), 0.0);                // empty table
  s.enabled[0] = false;
  EXPECT_EQ(targetPsd(s, Channel::Alignment, 1.0), 0.0);
}

// ---- Reproducibility -------------------------------------------------------------------------

// The random stream is fixed by the C++ standard (mt19937_64), SplitMix64 and the 53-bit
// conversion: these values hold on every platform.
TEST(Synthesis, RandomStreamIsPinned) {
  std::mt19937_64 g(5489u);
  EXPECT_EQ(uniform01(g), static_cast<double>(14514284786278117030ull >> 11) * 0x1.0p-53);
  EXPECT_EQ(channelSeed(42, Channel::Alignment), 0xbdd732262feb6e95ull);
  const CosineSeries a = makeCosineSeries(psdSpec("ore_b176_high"), Channel::Alignment);
  EXPECT_EQ(a.phase[0], 0x1.c152d4f438b52p-1);
  EXPECT_EQ(a.phase[1], 0x1.86239118a81a9p+2);
  EXPECT_EQ(a.omega[2], 0x1.7a6e967c8a651p-4);
  const CosineSeries v = makeCosineSeries(psdSpec("ore_b176_high"), Channel::Vertical);
  EXPECT_EQ(v.phase[0], 0x1.f88ae05f8e0d3p+1);
  EXPECT_EQ(v.omega[1], 0x1.7474a82ee1f2cp-4);
}

TEST(Synthesis, SameSeedBitIdenticalDifferentSeedDiffers) {
  const IrregularitySpec s = psdSpec("ore_b176_low", 7);
  const IrregularityTable a = synthesizeIrregularities(s, 1000.0);
  const IrregularityTable b = synthesizeIrregularities(s, 1000.0);
  for (int c = 0; c < kChannels; ++c) {
    const auto& x = a.channel[static_cast<std::size_t>(c)];
    const auto& y = b.channel[static_cast<std::size_t>(c)];
    ASSERT_EQ(x.size(), y.size());
    EXPECT_EQ(std::memcmp(x.data(), y.data(), x.size() * sizeof(double)), 0) << c;
  }
  // Longer track, same seed: the same irregularity on the common part (knots at j * step).
  const IrregularityTable longer = synthesizeIrregularities(s, 1500.0);
  for (std::size_t j = 0; j < a.s.size(); ++j) {
    ASSERT_EQ(longer.channel[1][j], a.channel[1][j]) << j;
  }
  // Another seed differs everywhere it matters; the channels differ from each other.
  const IrregularityTable c = synthesizeIrregularities(psdSpec("ore_b176_low", 8), 1000.0);
  double diff = 0.0, cross = 0.0;
  for (std::size_t j = 0; j < a.s.size(); ++j) {
    diff = std::max(diff, std::abs(a.channel[0][j] - c.channel[0][j]));
    cross = std::max(cross, std::abs(a.channel[0][j] - a.channel[1][j]));
  }
  EXPECT_GT(diff, 1e-3);
  EXPECT_GT(cross, 1e-3);
}

TEST(Synthesis, BandCentresWithoutRandomisedFrequencies) {
  IrregularitySpec s = psdSpec("ore_b176_low");
  s.randomize_frequencies = false;
  s.components = 100;
  const CosineSeries a = makeCosineSeries(s, Channel::Vertical);
  const double lo = 2.0 * kPi / 70.0, hi = 2.0 * kPi / 3.0, d = (hi - lo) / 100.0;
  for (std::size_t k = 0; k < 100; ++k) {
    EXPECT_NEAR(a.omega[k], lo + (static_cast<double>(k) + 0.5) * d, 1e-14);
    EXPECT_NEAR(
        a.amplitude[k],
        std::sqrt(2.0 * spectrumPsd(Spectrum::OreB176Low, Channel::Vertical, a.omega[k]) * d),
        1e-18);
  }
  // The phases are the same draws as with randomised frequencies only for k = 0.
  s.randomize_frequencies = true;
  EXPECT_EQ(makeCosineSeries(s, Channel::Vertical).phase[0], a.phase[0]);
}

// ---- Statistics of a long realisation --------------------------------------------------------

void fft(std::vector<std::complex<double>>& a) {
  const std::size_t n = a.size();
  for (std::size_t i = 1, j = 0; i < n; ++i) {
    std::size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(a[i], a[j]);
  }
  for (std::size_t len = 2; len <= n; len <<= 1) {
    const double ang = -2.0 * kPi / static_cast<double>(len);
    for (std::size_t i = 0; i < n; i += len) {
      for (std::size_t k = 0; k < len / 2; ++k) {
        const std::complex<double> w = std::polar(1.0, ang * static_cast<double>(k));
        const std::complex<double> u = a[i + k], v = a[i + k + len / 2] * w;
        a[i + k] = u + v;
        a[i + k + len / 2] = u - v;
      }
    }
  }
}

// Welch estimate (Hann window, 50 % overlap) of the one-sided PSD [m^2/(rad/m)] of x sampled
// every ds; returns G at bins k = 0..n/2 (Omega_k = 2 pi k / (n ds)).
std::vector<double> welch(const std::vector<double>& x, double ds, std::size_t n) {
  std::vector<double> acc(n / 2 + 1, 0.0), w(n);
  double w2 = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    w[j] = 0.5 * (1.0 - std::cos(2.0 * kPi * static_cast<double>(j) / static_cast<double>(n)));
    w2 += w[j] * w[j];
  }
  int segments = 0;
  std::vector<std::complex<double>> buf(n);
  for (std::size_t start = 0; start + n <= x.size(); start += n / 2, ++segments) {
    for (std::size_t j = 0; j < n; ++j) buf[j] = w[j] * x[start + j];
    fft(buf);
    for (std::size_t k = 0; k <= n / 2; ++k) acc[k] += std::norm(buf[k]);
  }
  for (double& v : acc) v *= 2.0 * ds / (2.0 * kPi * w2 * segments);  // one-sided, per rad/m
  return acc;
}

double integrateTarget(const IrregularitySpec& s, Channel c, double a, double b) {
  const int n = 4000;  // Simpson
  const double h = (b - a) / n;
  double sum = targetPsd(s, c, a) + targetPsd(s, c, b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * targetPsd(s, c, a + i * h);
  return sum * h / 3.0;
}

class LongRealisation : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    spec_ = new IrregularitySpec(psdSpec("ore_b176_high", 2024));
    model_ = new TrackModel(compileTrack(straightWithIrregularities(20000.0, *spec_)));
  }
  static void TearDownTestSuite() {
    delete model_;
    delete spec_;
  }
  // Channel c evaluated through the spline between the knots (s = (j + 1/2) ds).
  static std::vector<double> signal(Channel c, double ds) {
    std::vector<double> x;
    for (double s = 0.5 * ds; s < 20000.0; s += ds) {
      x.push_back(model_->irregularities()->at(s).xi[static_cast<std::size_t>(c)]);
    }
    return x;
  }
  static IrregularitySpec* spec_;
  static TrackModel* model_;
};
IrregularitySpec* LongRealisation::spec_ = nullptr;
TrackModel* LongRealisation::model_ = nullptr;

// Band power of the realisation per octave equals the integral of the target PSD within 20 %.
TEST_F(LongRealisation, PsdMatchesTargetPerOctave) {
  const double ds = 0.1;
  const std::size_t n = 16384;  // 1638 m segments, bin width 3.8e-3 rad/m
  const double dOm = 2.0 * kPi / (static_cast<double>(n) * ds);
  const double lo = 2.0 * kPi / spec_->wavelength_max, hi = 2.0 * kPi / spec_->wavelength_min;
  for (int c = 0; c < kChannels; ++c) {
    const Channel ch = static_cast<Channel>(c);
    const std::vector<double> G = welch(signal(ch, ds), ds, n);
    int octaves = 0;
    for (double a = lo; a * 2.0 <= hi * 1.0001; a *= 2.0, ++octaves) {
      // Bins whose centres lie in [a, 2a); compare with the target over exactly those bins.
      const auto k0 = static_cast<std::size_t>(std::ceil(a / dOm));
      const auto k1 = static_cast<std::size_t>(std::ceil(2.0 * a / dOm));
      double measured = 0.0;
      for (std::size_t k = k0; k < k1; ++k) measured += G[k] * dOm;
      const double target = integrateTarget(*spec_, ch, (static_cast<double>(k0) - 0.5) * dOm,
                                            (static_cast<double>(k1) - 0.5) * dOm);
      EXPECT_NEAR(measured / target, 1.0, 0.2)
          << channelName(ch) << " octave from " << a << " rad/m";
    }
    EXPECT_EQ(octaves, 4);
  }
}

// RMS equals sqrt(integral of G over the band) within 3 %.
TEST_F(LongRealisation, RmsMatchesIntegralOfTarget) {
  const double lo = 2.0 * kPi / spec_->wavelength_max, hi = 2.0 * kPi / spec_->wavelength_min;
  for (int c = 0; c < kChannels; ++c) {
    const Channel ch = static_cast<Channel>(c);
    const std::vector<double> x = signal(ch, 0.1);
    double sum2 = 0.0;
    for (const double v : x) sum2 += v * v;
    const double rms = std::sqrt(sum2 / static_cast<double>(x.size()));
    const double expect = std::sqrt(integrateTarget(*spec_, ch, lo, hi));
    EXPECT_NEAR(rms / expect, 1.0, 0.03) << channelName(ch) << " rms " << rms;
  }
  // Sanity against the reference's implied values (high, 3-70 m): sigma_v ~ sqrt(1.61^2+2.70^2)
  // = 3.14 mm, sigma_a ~ sqrt(1.21^2+2.04^2) = 2.37 mm.
  EXPECT_NEAR(std::sqrt(integrateTarget(*spec_, Channel::Vertical, lo, hi)), 3.14e-3, 0.05e-3);
  EXPECT_NEAR(std::sqrt(integrateTarget(*spec_, Channel::Alignment, lo, hi)), 2.37e-3, 0.05e-3);
}

// ---- Rails -------------------------------------------------------------------------------------

TEST(Irregularities, LeftRightRelationsAndDelta) {
  TrackSpec t = straightWithIrregularities(300.0, psdSpec("ore_b176_low", 3));
  t.rail_lr = 0.7555;
  const TrackModel m = compileTrack(t);
  ASSERT_TRUE(m.irregularities().has_value());
  const Irregularities& irr = *m.irregularities();
  for (double s = 0.0; s < 300.0; s += 1.37) {
    const IrregularityPoint p = irr.at(s);
    const double a = p.xi[0], v = p.xi[1], g = p.xi[2], c = p.xi[3];
    EXPECT_NEAR(p.y_l - p.y_r, g, 1e-15);
    EXPECT_NEAR(0.5 * (p.y_l + p.y_r), a, 1e-15);
    EXPECT_NEAR(p.z_l - p.z_r, c, 1e-15);
    EXPECT_NEAR(0.5 * (p.z_l + p.z_r), v, 1e-15);
    EXPECT_NEAR(p.delta, (p.z_l - p.z_r) / (2.0 * 0.7555), 1e-15);
    // Derivatives against central differences of the splines.
    const double h = 1e-5;
    if (s > h) {
      const IrregularityPoint pa = irr.at(s + h), pb = irr.at(s - h);
      EXPECT_NEAR(p.y_l_s, (pa.y_l - pb.y_l) / (2 * h), 1e-8);
      EXPECT_NEAR(p.z_r_s, (pa.z_r - pb.z_r) / (2 * h), 1e-8);
      EXPECT_NEAR(p.delta_s, (pa.delta - pb.delta) / (2 * h), 1e-8);
      EXPECT_NEAR(p.xi_ss[1], (pa.xi_s[1] - pb.xi_s[1]) / (2 * h), 1e-6);
    }
  }
  // Zero outside the sampled range.
  const IrregularityPoint out = irr.at(-1.0);
  EXPECT_EQ(out.xi[0], 0.0);
  EXPECT_EQ(out.delta, 0.0);
  EXPECT_GE(irr.sEnd(), 300.0);
}

TEST(Irregularities, NoneBuildsNoIrregularitiesAndDisabledChannelsAreZero) {
  EXPECT_FALSE(compileTrack(rbtest::paperCase1(300.0)).irregularities().has_value());
  IrregularitySpec s = psdSpec("ore_b176_low");
  s.enabled[2] = false;
  s.scale = 0.5;
  const TrackModel m = compileTrack(straightWithIrregularities(200.0, s));
  const IrregularityPoint p = m.irregularities()->at(50.3);
  EXPECT_EQ(p.xi[2], 0.0);
  EXPECT_EQ(p.y_l, p.y_r);
  // scale halves the amplitudes of the same realisation.
  IrregularitySpec full = psdSpec("ore_b176_low");
  const TrackModel mf = compileTrack(straightWithIrregularities(200.0, full));
  EXPECT_NEAR(p.xi[1], 0.5 * mf.irregularities()->at(50.3).xi[1], 1e-15);
}

TEST(Irregularities, CsvMeasuredTable) {
  const std::string path = ::testing::TempDir() + "rb_track_irr.csv";
  {
    std::ofstream f(path);
    f.precision(17);
    f << "# measured irregularities\n";
    f << "s, alignment, vertical, gauge, cross_level\n";
    for (int i = 0; i <= 20; ++i) {
      const double s = 0.5 * i;
      f << s << ", " << 1e-3 * std::sin(s) << ", " << 2e-3 * std::cos(s) << ", " << 1e-4 * s << ", "
        << -5e-4 << "\n";
    }
  }
  TrackSpec t = straightWithIrregularities(20.0, {});
  t.irregularities.source = IrregularitySource::Csv;
  t.irregularities.csv_path = path;
  t.irregularities.beyond = Beyond::Zero;  // the file covers 10 of the 20 m
  const TrackModel m = compileTrack(t);
  ASSERT_EQ(m.warnings().size(), 1u);
  EXPECT_NE(m.warnings()[0].message.find("covers s = 0 .. 10 m of the 20 m track"),
            std::string::npos)
      << m.warnings()[0].message;
  const Irregularities& irr = *m.irregularities();
  EXPECT_EQ(irr.samples().s.size(), 21u);
  EXPECT_NEAR(irr.at(3.0).xi[0], 1e-3 * std::sin(3.0), 1e-15);
  EXPECT_NEAR(irr.at(3.2).xi[1], 2e-3 * std::cos(3.2), 1e-5);
  EXPECT_NEAR(irr.at(7.3).xi[2], 7.3e-4, 1e-15);
  EXPECT_NEAR(irr.at(7.3).z_l - irr.at(7.3).z_r, -5e-4, 1e-15);
  EXPECT_EQ(irr.at(10.5).xi[1], 0.0);  // beyond the table
  const TrackSamples ts = sampleTrack(m);
  EXPECT_EQ(ts.irr_s.size(), 21u);
  EXPECT_TRUE(ts.psd_omega.empty());
}

// ---- Output arrays ------------------------------------------------------------------------------

TEST(Samples, ArraysConsistent) {
  TrackSpec t = rbtest::paperCase2(0.1);
  t.irregularities = psdSpec("ore_b176_low");
  const TrackModel m = compileTrack(t);
  const TrackSamples s = sampleTrack(m);
  EXPECT_EQ(s.s.size(), 1001u);
  for (const auto* v :
       {&s.x, &s.y, &s.z, &s.heading, &s.slope, &s.cant_angle, &s.curvature, &s.cant}) {
    EXPECT_EQ(v->size(), s.s.size());
  }
  EXPECT_EQ(s.seg_kind, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(s.seg_start, (std::vector<double>{0.0, 100.0, 150.0}));
  EXPECT_EQ(s.seg_side, (std::vector<int>{1, 1, 1}));
  EXPECT_EQ(s.seg_radius[2], 500.0);
  EXPECT_NEAR(s.curvature.back(), 1.0 / 500.0, 1e-9);
  EXPECT_NEAR(s.cant.back(), 0.1, 1e-12);
  EXPECT_EQ(s.irr_s.size(), 5001u);
  for (std::size_t j = 0; j < s.irr_s.size(); j += 97) {
    EXPECT_NEAR(s.left_y[j] - s.right_y[j], s.gauge[j], 1e-15);
    EXPECT_NEAR(s.left_z[j] - s.right_z[j], s.cross_level[j], 1e-15);
    EXPECT_NEAR(s.delta[j], s.cross_level[j] / (2.0 * t.rail_lr), 1e-15);
  }
  ASSERT_EQ(s.psd_omega.size(), static_cast<std::size_t>(kPsdSamplePoints));
  EXPECT_DOUBLE_EQ(s.psd_omega.front(), 2.0 * kPi / 70.0);
  EXPECT_DOUBLE_EQ(s.psd_omega.back(), 2.0 * kPi / 3.0);
  EXPECT_GT(s.psd_alignment.front(), 0.0);
  EXPECT_GT(s.psd_cross_level.back(), 0.0);
  EXPECT_NEAR(s.psd_vertical[57],
              spectrumPsd(Spectrum::OreB176Low, Channel::Vertical, s.psd_omega[57]), 1e-20);
}

// A run writes the stretch its vehicle covers: the samples inside it and one beyond on either
// side, the same values as the whole track's; segments and the target PSD whole.
TEST(Samples, StretchIsTheWholeTracksSamplesInside) {
  TrackSpec t = rbtest::paperCase2(0.1);
  t.irregularities = psdSpec("ore_b176_low");
  const TrackModel m = compileTrack(t);
  const TrackSamples all = sampleTrack(m);
  const TrackSamples part = sampleTrack(m, 120.25, 140.0);
  ASSERT_FALSE(part.s.empty());
  EXPECT_LT(part.s.front(), 120.25);
  EXPECT_GE(part.s[1], 120.25);
  EXPECT_GT(part.s.back(), 140.0);
  EXPECT_LE(part.s[part.s.size() - 2], 140.0);
  const auto k0 = static_cast<std::size_t>(std::find(all.s.begin(), all.s.end(), part.s.front()) -
                                           all.s.begin());
  ASSERT_LT(k0 + part.s.size(), all.s.size());
  for (std::size_t k = 0; k < part.s.size(); ++k) {
    EXPECT_EQ(part.s[k], all.s[k0 + k]);
    EXPECT_EQ(part.y[k], all.y[k0 + k]);
    EXPECT_EQ(part.cant[k], all.cant[k0 + k]);
  }
  ASSERT_FALSE(part.irr_s.empty());
  EXPECT_LT(part.irr_s.front(), 120.25);
  EXPECT_GT(part.irr_s.back(), 140.0);
  EXPECT_GE(part.irr_s[1], 120.25);
  EXPECT_LE(part.irr_s[part.irr_s.size() - 2], 140.0);
  const auto i0 = static_cast<std::size_t>(
      std::find(all.irr_s.begin(), all.irr_s.end(), part.irr_s.front()) - all.irr_s.begin());
  for (std::size_t i = 0; i < part.irr_s.size(); ++i) {
    EXPECT_EQ(part.vertical[i], all.vertical[i0 + i]);
    EXPECT_EQ(part.left_y[i], all.left_y[i0 + i]);
  }
  EXPECT_EQ(part.seg_start, all.seg_start);
  EXPECT_EQ(part.psd_omega.size(), all.psd_omega.size());
  // A stretch beyond the track: the last sample only.
  EXPECT_EQ(sampleTrack(m, 600.0, 700.0).s.size(), 1u);
}

}  // namespace
