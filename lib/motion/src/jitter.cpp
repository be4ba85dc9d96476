// SPDX-License-Identifier: Apache-2.0
// Jitter synthesis (glint/motion/jitter.h): PSD interpolation and integration, the choice of
// sample rate and length, random-phase spectral synthesis through the in-house inverse real
// FFT, time-keyed normal deviates, and the platform and mount samplers built on them.
#include "glint/motion/jitter.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <string>
#include <system_error>

#include "glint/core/diagnostics.h"
#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/motion/fft.h"

namespace glint::motion {
namespace {

std::string num(double value) { return format_shortest(value); }

/// Index i of the segment [f_i, f_i+1] holding f (f within the table's range).
std::size_t segment_of(const std::vector<double>& frequency_hz, double f) {
    const auto upper = std::upper_bound(frequency_hz.begin(), frequency_hz.end(), f);
    const std::size_t i = static_cast<std::size_t>(upper - frequency_hz.begin());
    return std::min(i == 0 ? 0 : i - 1, frequency_hz.size() - 2);
}

/// True when segment i is interpolated log-log (both ends positive in f and S).
bool log_log(const model::PsdTable& table, std::size_t i) {
    return table.frequency_hz[i] > 0.0 && table.psd[i] > 0.0 && table.psd[i + 1] > 0.0;
}

/// ∫ S df over [a, b] within segment i.
double segment_integral(const model::PsdTable& table, std::size_t i, double a, double b) {
    if (!(b > a)) return 0.0;
    const double f0 = table.frequency_hz[i];
    const double f1 = table.frequency_hz[i + 1];
    const double s0 = table.psd[i];
    const double s1 = table.psd[i + 1];
    if (log_log(table, i)) {
        // S = s0 (f/f0)^α; ∫ = s0 f0 / (α+1) [(b/f0)^(α+1) − (a/f0)^(α+1)], or s0 f0 ln(b/a).
        const double alpha = std::log(s1 / s0) / std::log(f1 / f0);
        const double p = alpha + 1.0;
        if (std::abs(p) < 1e-12) return s0 * f0 * std::log(b / a);
        return s0 * f0 / p * (std::pow(b / f0, p) - std::pow(a / f0, p));
    }
    const double slope = (s1 - s0) / (f1 - f0);
    const double sa = s0 + slope * (a - f0);
    const double sb = s0 + slope * (b - f0);
    return 0.5 * (sa + sb) * (b - a);
}

void check_options(const JitterSynthesisOptions& o) {
    if (!(o.min_oversampling >= 2.0) || !(o.oversampling >= o.min_oversampling) ||
        !std::isfinite(o.oversampling)) {
        throw input_error("jitter oversampling " + num(o.oversampling) + " (minimum " +
                          num(o.min_oversampling) +
                          ") is invalid, expected 2 <= minimum <= " + "oversampling");
    }
    if (!is_power_of_two(o.min_samples) || !is_power_of_two(o.max_samples) || o.min_samples < 2 ||
        o.min_samples > o.max_samples) {
        throw input_error("jitter sample counts " + std::to_string(o.min_samples) + " … " +
                          std::to_string(o.max_samples) +
                          " are invalid, expected powers of two with 2 <= min <= max");
    }
}

/// Sample count N and rate fs (Hz) for a PSD over a span: see "Sampling" in
/// docs/motion.md ("Jitter").
struct Grid {
    std::size_t count = 0;
    double rate_hz = 0.0;
};

Grid choose_grid(const model::PsdTable& table, double span_s, const JitterSynthesisOptions& o) {
    const double f_max = table.frequency_hz.back();
    double f_low = f_max;
    for (const double f : table.frequency_hz) {
        if (f > 0.0) {
            f_low = f;
            break;
        }
    }
    const double max_samples = static_cast<double>(o.max_samples);
    double rate_hz = o.oversampling * f_max;
    const double for_span = span_s * rate_hz;
    if (for_span > max_samples) {
        rate_hz = max_samples / span_s;
        if (rate_hz < o.min_oversampling * f_max) {
            throw input_error(
                "jitter PSD up to " + num(f_max) + " Hz over " + num(span_s) + " s needs " +
                    num(std::ceil(span_s * o.min_oversampling * f_max)) + " samples at " +
                    num(o.min_oversampling) + " samples per period of the highest frequency, " +
                    "more than the " + std::to_string(o.max_samples) +
                    " allowed; shorten the span or lower the highest PSD frequency",
                table.where);
        }
        return {o.max_samples, rate_hz};
    }
    const double wanted = std::max({static_cast<double>(o.min_samples), for_span, rate_hz / f_low});
    if (wanted >= max_samples) return {o.max_samples, rate_hz};
    return {next_power_of_two(static_cast<std::size_t>(std::ceil(wanted))), rate_hz};
}

}  // namespace

double psd_at(const model::PsdTable& table, double frequency_hz) noexcept {
    const auto& f = table.frequency_hz;
    if (f.size() < 2 || table.psd.size() != f.size()) return 0.0;
    if (!(frequency_hz >= f.front() && frequency_hz <= f.back())) return 0.0;
    const std::size_t i = segment_of(f, frequency_hz);
    const double s0 = table.psd[i];
    const double s1 = table.psd[i + 1];
    if (log_log(table, i)) {
        const double alpha = std::log(s1 / s0) / std::log(f[i + 1] / f[i]);
        return s0 * std::pow(frequency_hz / f[i], alpha);
    }
    const double w = (frequency_hz - f[i]) / (f[i + 1] - f[i]);
    return s0 + w * (s1 - s0);
}

double psd_phase_at(const model::PsdTable& table, double frequency_hz) noexcept {
    const auto& f = table.frequency_hz;
    const auto& p = table.phase_rad;
    if (p.empty() || p.size() != f.size()) return 0.0;
    if (f.size() == 1 || !(frequency_hz > f.front())) return p.front();
    if (frequency_hz >= f.back()) return p.back();
    const std::size_t i = segment_of(f, frequency_hz);
    const double w = (frequency_hz - f[i]) / (f[i + 1] - f[i]);
    return p[i] + w * (p[i + 1] - p[i]);
}

double psd_integral(const model::PsdTable& table, double f0_hz, double f1_hz) noexcept {
    const auto& f = table.frequency_hz;
    if (f.size() < 2 || table.psd.size() != f.size()) return 0.0;
    const double a = std::max(f0_hz, f.front());
    const double b = std::min(f1_hz, f.back());
    double total = 0.0;
    for (std::size_t i = 0; i + 1 < f.size(); ++i) {
        const double lo = std::max(a, f[i]);
        const double hi = std::min(b, f[i + 1]);
        total += segment_integral(table, i, lo, hi);
    }
    return total;
}

JitterSeries::JitterSeries(const JitterModel& model, std::uint64_t seed,
                           const std::vector<std::uint64_t>& stream_ids, double t0_s, double t1_s,
                           const JitterSynthesisOptions& options)
    : m_kind(model.kind), m_mean(model.mean), m_stream(seed, stream_ids), m_t0_s(t0_s) {
    if (m_kind == Kind::none) {
        m_mean = 0.0;
        return;
    }
    if (!std::isfinite(model.mean)) {
        throw input_error("jitter mean " + num(model.mean) + " is not a finite number",
                          model.where);
    }
    if (m_kind == Kind::normal) {
        if (!std::isfinite(model.stddev) || model.stddev < 0.0) {
            throw input_error("jitter standard deviation " + num(model.stddev) +
                                  " is invalid, expected a finite value >= 0",
                              model.where);
        }
        m_stddev = model.stddev;
        return;
    }

    // psd
    if (model.psd == nullptr) throw input_error("psd jitter has no PSD table", model.where);
    const model::PsdTable& table = *model.psd;
    Diagnostics diagnostics;
    model::validate_psd_table(table, diagnostics);
    diagnostics.throw_if_errors();
    if (!std::isfinite(t0_s) || !std::isfinite(t1_s) || t1_s < t0_s) {
        throw input_error("jitter time span [" + num(t0_s) + ", " + num(t1_s) +
                              "] s is invalid, expected finite t0 <= t1",
                          model.where);
    }
    check_options(options);

    const Grid grid = choose_grid(table, t1_s - t0_s, options);
    const std::size_t n = grid.count;
    const std::size_t half = n / 2;
    m_sample_rate_hz = grid.rate_hz;
    const double df_hz = grid.rate_hz / static_cast<double>(n);  // 1 / period

    // Bin k (1 ≤ k < N/2) carries a cosine of amplitude A_k = √(2 S(f_k) Δf) and phase φ_k:
    // x_n = Σ A_k cos(2π k n / N + φ_k), whose mean square over the period is Σ A_k² / 2 =
    // Σ S(f_k) Δf. With x = IDFT(X) (1/N convention), X_k = (N/2) A_k e^(iφ_k) and the
    // Hermitian extension. DC (the mean is given separately) and Nyquist stay 0.
    std::vector<std::complex<double>> spectrum(half + 1);
    const bool table_phases = !table.phase_rad.empty();
    RandomStream phases(seed, stream_ids);
    double variance = 0.0;
    for (std::size_t k = 1; k < half; ++k) {
        const double f_hz = static_cast<double>(k) * df_hz;
        const double random_phase = 2.0 * std::numbers::pi * phases.uniform();
        const double phase = table_phases ? psd_phase_at(table, f_hz) : random_phase;
        const double power = psd_at(table, f_hz) * df_hz;  // S(f_k) Δf = A_k² / 2
        if (power <= 0.0) continue;
        variance += power;
        const double amplitude = std::sqrt(2.0 * power);
        spectrum[k] = std::polar(0.5 * static_cast<double>(n) * amplitude, phase);
    }
    m_samples = inverse_fft_real(spectrum, n);
    for (double& x : m_samples) x += m_mean;
    m_synthesized_variance = variance;
    m_psd_variance = psd_integral(table, table.frequency_hz.front(), table.frequency_hz.back());
}

double JitterSeries::value_at(double t_s) const noexcept {
    switch (m_kind) {
        case Kind::none:
            return 0.0;
        case Kind::normal: {
            // Block q = round(t / 1 ns), within ±2^61 (±73 years).
            const double ticks = std::nearbyint(t_s / kJitterTimeQuantumS);
            constexpr double kLimit = 2305843009213693952.0;  // 2^61
            if (!(std::abs(ticks) < kLimit)) return std::numeric_limits<double>::quiet_NaN();
            const auto q = static_cast<std::uint64_t>(static_cast<std::int64_t>(ticks));
            RandomStream stream = m_stream;
            stream.skip_to(q * 4u);
            return m_mean + m_stddev * stream.normal();
        }
        case Kind::psd: {
            if (!std::isfinite(t_s)) return std::numeric_limits<double>::quiet_NaN();
            const std::size_t n = m_samples.size();
            const double count = static_cast<double>(n);
            double u = (t_s - m_t0_s) * m_sample_rate_hz;  // in samples
            u -= count * std::floor(u / count);
            if (!(u >= 0.0)) u = 0.0;
            if (u >= count) u -= count;
            std::size_t i = static_cast<std::size_t>(u);
            if (i >= n) i = n - 1;
            const double w = u - static_cast<double>(i);
            const std::size_t j = i + 1 == n ? 0 : i + 1;
            return m_samples[i] + w * (m_samples[j] - m_samples[i]);
        }
    }
    return 0.0;
}

double JitterSeries::stddev() const noexcept {
    return m_kind == Kind::psd ? std::sqrt(m_synthesized_variance) : m_stddev;
}

double JitterSeries::period_s() const noexcept {
    return m_kind == Kind::psd ? static_cast<double>(m_samples.size()) / m_sample_rate_hz : 0.0;
}

// ---- model adapters and samplers ------------------------------------------------------------

namespace {

/// The PSD table of a psd jitter axis: its `psd`, which the input loader fills from the file
/// the axis names. Throws glint::Error (input) when there is none.
const model::PsdTable& psd_table(const std::optional<model::PsdTable>& psd,
                                 const model::FileRef& file, const ErrorContext& where) {
    if (psd) return *psd;
    if (file.empty()) throw input_error("psd jitter names no PSD file", where);
    throw input_error("psd jitter: the PSD file " + file.text +
                          " was not read (inputs::load reads the PSD files a platform or motion "
                          "names)",
                      where);
}

}  // namespace

JitterModel jitter_model(const model::JitterSpec& spec) {
    JitterModel m;
    m.mean = spec.mean;
    m.stddev = spec.stddev;
    m.where = spec.where;
    switch (spec.kind) {
        case model::JitterSpec::Kind::none:
            m.kind = JitterModel::Kind::none;
            break;
        case model::JitterSpec::Kind::normal:
            m.kind = JitterModel::Kind::normal;
            break;
        case model::JitterSpec::Kind::psd:
            m.kind = JitterModel::Kind::psd;
            m.psd = &psd_table(spec.psd, spec.psd_file,
                               spec.psd_file.where.file.empty() ? spec.where : spec.psd_file.where);
            break;
    }
    return m;
}

namespace {

std::vector<std::uint64_t> with_ids(std::vector<std::uint64_t> ids, std::uint64_t domain,
                                    std::uint64_t axis) {
    ids.push_back(domain);
    ids.push_back(axis);
    return ids;
}

}  // namespace

PlatformJitterSampler::PlatformJitterSampler(const model::PlatformJitter& jitter,
                                             std::uint64_t seed,
                                             const std::vector<std::uint64_t>& stream_ids,
                                             double t0_s, double t1_s,
                                             const JitterSynthesisOptions& options) {
    for (std::size_t i = 0; i < 3; ++i) {
        m_location[i] = JitterSeries(jitter_model(jitter.location_m[i]), seed,
                                     with_ids(stream_ids, kJitterDomainPlatformLocation, i), t0_s,
                                     t1_s, options);
        m_orientation[i] = JitterSeries(jitter_model(jitter.orientation_rad[i]), seed,
                                        with_ids(stream_ids, kJitterDomainPlatformOrientation, i),
                                        t0_s, t1_s, options);
    }
}

PlatformJitterSampler::Sample PlatformJitterSampler::at(double t_s) const noexcept {
    Sample s;
    for (std::size_t i = 0; i < 3; ++i) {
        s.location_m[i] = m_location[i].value_at(t_s);
        s.orientation_rad[i] = m_orientation[i].value_at(t_s);
    }
    return s;
}

bool PlatformJitterSampler::any() const noexcept {
    for (std::size_t i = 0; i < 3; ++i) {
        if (m_location[i].kind() != JitterSeries::Kind::none) return true;
        if (m_orientation[i].kind() != JitterSeries::Kind::none) return true;
    }
    return false;
}

MountJitterSampler::MountJitterSampler(const model::RotationDeviates& deviates, std::uint64_t seed,
                                       const std::vector<std::uint64_t>& stream_ids, double t0_s,
                                       double t1_s, const JitterSynthesisOptions& options) {
    for (std::size_t i = 0; i < 3; ++i) {
        m_axes[i] = JitterSeries(jitter_model(deviates.axes[i]), seed,
                                 with_ids(stream_ids, kJitterDomainMount, i), t0_s, t1_s, options);
    }
}

Vec3 MountJitterSampler::at(double t_s) const noexcept {
    return {m_axes[0].value_at(t_s), m_axes[1].value_at(t_s), m_axes[2].value_at(t_s)};
}

bool MountJitterSampler::any() const noexcept {
    for (const JitterSeries& a : m_axes) {
        if (a.kind() != JitterSeries::Kind::none) return true;
    }
    return false;
}

}  // namespace glint::motion
