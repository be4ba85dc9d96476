// SPDX-License-Identifier: Apache-2.0
// DetectionChain: turns one line of a capture's channel values (the photon fluence at the
// focal plane, Photons/cm², one band per channel) into output values (digital counts, or
// electrons), applying QE, shot noise, dark current, read noise, TDI accumulation, the ADC,
// the storage type and the CFA mosaic. Built once per focal plane (glint-detect, and the
// renderer for in-render detection), it streams line by line without allocating.
//
// Random numbers: every pixel's draws depend only on (seed, capture global index, pixel index
// within the capture, channel): the stream RandomStream(seed, {kDetectStreamTag, capture})
// is positioned at word (pixel × channels + channel) × 2^20 before the pixel's draws
// (so each pixel has its own Philox counter range). Results are therefore bit-identical for
// any thread count, line order or sharding, and between glint-detect and in-render detection.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "glint/core/rng.h"
#include "glint/detect/adc.h"
#include "glint/detect/detector.h"
#include "glint/detect/noise.h"

namespace glint::detect {

/// First stream id of every detection stream (separates them from the renderer's streams).
inline constexpr std::uint64_t kDetectStreamTag = 0x64657465637431ull;  // "detect1"
/// log2 of the words reserved for one pixel-channel's draws.
inline constexpr unsigned kWordsPerDrawLog2 = 20;

/// Where a line sits: its capture's global schedule index and its line within the capture
/// (TDI focal planes have one line per capture).
struct LineKey {
    std::uint64_t capture_index = 0;
    std::size_t line_in_capture = 0;
};

/// The detection chain of one focal plane for lines of `samples` pixels.
class DetectionChain {
public:
    /// Throws glint::Error (input) for zero samples.
    DetectionChain(DetectionSettings settings, std::size_t samples);

    const DetectionSettings& settings() const { return m_settings; }
    std::size_t samples() const { return m_samples; }
    /// Values of one input line: samples × channels (BIP).
    std::size_t input_values_per_line() const { return m_samples * m_settings.channels(); }
    /// Values of one output line: samples × output bands (BIP).
    std::size_t output_values_per_line() const { return m_samples * m_settings.output_bands(); }

    /// Converts one line. `in` holds input_values_per_line() values, `out` receives
    /// output_values_per_line() values (exact integers for counts, already truncated to the
    /// storage type). Thread-safe; allocates nothing. Throws glint::Error (input) naming the
    /// sample and band for an input value that is negative, NaN or infinite when a detector
    /// model is applied, and (internal) for spans of the wrong size.
    void process_line(LineKey key, std::span<const double> in, std::span<double> out) const;

private:
    /// One value through the whole chain (the reference the batched path reproduces).
    double detect_value(double value, RandomStream& stream, std::uint64_t pixel,
                        std::size_t channel, std::size_t sample) const;
    /// Mean electrons of an input value; throws for a bad one (naming sample and band).
    double checked_mean(double value, std::size_t channel, std::size_t sample) const {
        const double mean = value * m_electrons_per_fluence + m_dark_electrons;
        if (!(value >= 0.0) || !(mean <= kMaxPoissonMean)) bad_value(value, channel, sample);
        return mean;
    }
    [[noreturn]] static void bad_value(double value, std::size_t channel, std::size_t sample);
    /// The draws of one line with noise on, in batches (chain_noise.cpp).
    void process_noisy(RandomStream& stream, const int* cfa_row, std::uint64_t first_pixel,
                       std::span<const double> in, std::span<double> out) const;
    /// Poisson(mean) + σZ drawn at `slot` (pixel × channels + channel) of `stream`.
    double noisy_electrons(double mean, RandomStream& stream, std::uint64_t slot) const;
    /// Electrons → output value (ADC and storage type, or electrons as they are).
    double finish(double electrons) const;

    DetectionSettings m_settings;
    std::size_t m_samples = 0;
    // Precomputed from the settings.
    double m_electrons_per_fluence = 0.0;  ///< area (cm²) × QE
    double m_dark_electrons = 0.0;         ///< mean over all stages
    double m_read_sigma_e = 0.0;           ///< once (charge) or √N × (digital)
    Adc m_adc{0.0, 1.0, 1};
    /// Input channel of each pixel of the CFA's repeating block (period × period), row-major.
    std::vector<int> m_cfa_channel;
    std::size_t m_cfa_period = 0;
};

}  // namespace glint::detect
