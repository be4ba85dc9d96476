// SPDX-License-Identifier: Apache-2.0
// Builders shared by the detect unit tests: a focal plane with a detector model, flat-field
// settings, and a helper that runs a chain over a flat field and collects its pixels.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "glint/core/units.h"
#include "glint/detect/chain.h"
#include "glint/detect/detector.h"
#include "glint/model/instrument.h"

namespace glint::detect::test {

/// A 10 µm × 10 µm pixel: 1e-10 m², 1e-6 cm².
inline constexpr double kPixelAreaM2 = 1e-10;
inline constexpr double kPixelAreaCm2 = 1e-6;

/// An instrument's properties with an aperture.
inline model::InstrumentProperties properties_with_aperture() {
    model::InstrumentProperties p;
    p.focal_length_m = 0.1;
    p.aperture_diameter_m = 0.02;
    return p;
}

/// A simple 8 × 6 focal plane "Frame" of 10 µm pixels with the given channels, 10 ms
/// integration and a 12-bit detector model over [0, 1e5] electrons.
inline model::FocalPlane focal_plane(std::vector<std::string> channels = {"Pan"}) {
    model::FocalPlane fp;
    fp.name = "Frame";
    for (auto& name : channels) {
        model::Channel c;
        c.name = name;
        fp.capture_method.spectral_response.channels.push_back(c);
    }
    fp.capture_method.temporal_integration.time_s = 0.01;
    model::DetectorModel d;
    d.quantum_efficiency = 0.8;
    d.read_noise_e = 20;
    d.dark_current_density_a_per_m2 = 1e-5;
    d.min_electrons = 0;
    d.max_electrons = 1e5;
    d.bit_depth = 12;
    fp.capture_method.detector_model = d;
    fp.capture_method.image_file.datatype = 12;
    fp.detector_array.x_count = 8;
    fp.detector_array.y_count = 6;
    fp.detector_array.x_size_m = 10e-6;
    fp.detector_array.y_size_m = 10e-6;
    fp.detector_array.x_spacing_m = 10e-6;
    fp.detector_array.y_spacing_m = 10e-6;
    return fp;
}

/// Settings of one channel, 10 µm pixels, QE 1, the given noise and ADC, float64 storage.
inline DetectionSettings settings(double read_noise_e, double dark_electrons, double min_e,
                                  double max_e, int bits, double time_s = 0.01,
                                  std::size_t stages = 1) {
    DetectionSettings s;
    s.focal_plane = "Frame";
    s.channel_names = {"Pan"};
    DetectorModelSettings d;
    d.quantum_efficiency = 1.0;
    d.read_noise_e = read_noise_e;
    d.integration_time_s = time_s;
    d.pixel_area_m2 = kPixelAreaM2;
    // Dark density giving `dark_electrons` per stage.
    d.dark_current_density_a_per_m2 = dark_electrons * kElementaryChargeC / (kPixelAreaM2 * time_s);
    d.min_electrons = min_e;
    d.max_electrons = max_e;
    d.bit_depth = bits;
    s.detector = d;
    s.tdi_stages = stages;
    s.data_type = io::EnviDataType::float64;
    s.seed = 1234;
    return s;
}

/// The fluence (photons/cm²) that makes `electrons` signal electrons at QE 1.
inline double fluence_for(double electrons) { return electrons / kPixelAreaCm2; }

/// Runs `chain` over `lines` lines of a flat single-channel field of `fluence`, as capture
/// `capture`, and returns every output value.
inline std::vector<double> flat_field(const DetectionChain& chain, double fluence,
                                      std::size_t lines, std::uint64_t capture = 0) {
    const std::size_t samples = chain.samples();
    std::vector<double> in(chain.input_values_per_line(), fluence);
    std::vector<double> out(chain.output_values_per_line());
    std::vector<double> all;
    all.reserve(lines * out.size());
    for (std::size_t y = 0; y < lines; ++y) {
        chain.process_line({capture, y}, in, out);
        all.insert(all.end(), out.begin(), out.end());
    }
    (void)samples;
    return all;
}

struct Moments {
    double mean = 0;
    double variance = 0;  ///< unbiased
};

inline Moments moments(const std::vector<double>& v) {
    double sum = 0;
    for (double x : v) sum += x;
    const double mean = sum / static_cast<double>(v.size());
    double ss = 0;
    for (double x : v) ss += (x - mean) * (x - mean);
    return {mean, ss / static_cast<double>(v.size() - 1)};
}

}  // namespace glint::detect::test
