// SPDX-License-Identifier: Apache-2.0
// The detection settings of a focal plane: the detector model (QE, noise, ADC), TDI and the
// colour-filter-array pattern, resolved from the `.platform` model plus overrides and checked
// once, before any pixel is touched. DetectionChain (chain.h) applies them.
//
// What is read from the model (docs/detector.md has the formulas):
// clang-format off
// | element | type | unit | used as |
// |---|---|---|---|
// | capturemethod@type | simple (required with a detector model) | - | |
// | imagefile/datatype | ENVI code | - | stored type of the counts (default 5, float64) |
// | temporalintegration/time | number > 0 (required with a detector model or TDI) | s | integration time of one stage |
// | temporalintegration@tdi | bool | - | TDI on: yelementcount stages |
// | detectormodel/quantumefficiency | number in [0, 1] | - | electrons per photon |
// | detectormodel/readnoise | number >= 0 | e⁻ | σ of the Gaussian read noise |
// | detectormodel/darkcurrentdensity | number >= 0 | A/m² | dark current per active area |
// | detectormodel/minelectrons, maxelectrons | numbers, min < max | e⁻ | ADC input range |
// | detectormodel/bitdepth | integer 1–32 | bits | ADC output range [0, 2^bits − 1] |
// | properties/aperturediameter | number > 0 (required with a detector model) | m | (used by the render) |
// | detectorarray/xelementsize, yelementsize | numbers > 0 | m | active pixel area |
// | detectorarray/xelementcount, yelementcount | integers | - | TDI stages = yelementcount |
// | spectralresponse/channellist, channelpattern | channels; bayer or truesense mapping | - | input bands; mosaic |
// clang-format on
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "glint/detect/cfa.h"
#include "glint/io/envi.h"
#include "glint/model/instrument.h"

namespace glint::detect {

/// How TDI stages are summed: charge-domain (read once) or digital (each stage read).
enum class TdiMode : std::uint8_t { charge, digital };
/// "charge", "digital".
const char* tdi_mode_name(TdiMode mode);

/// Where the chain stops: digital counts (after the ADC) or electrons (before it).
enum class DetectOutput : std::uint8_t { counts, electrons };

/// What the mosaic option asks for: the focal plane's `<channelpattern>`, none, or a pattern.
enum class MosaicChoice : std::uint8_t { from_focal_plane, none, bayer, truesense };

/// Command-line overrides of the focal plane's settings (unset = the `.platform`'s value).
struct DetectorOverrides {
    std::optional<double> quantum_efficiency;              ///< --qe
    std::optional<double> read_noise_e;                    ///< --read-noise
    std::optional<double> dark_current_density_a_per_m2;   ///< --dark-current-density
    std::optional<double> min_electrons;                   ///< --min-electrons
    std::optional<double> max_electrons;                   ///< --max-electrons
    std::optional<int> bit_depth;                          ///< --bit-depth
    std::optional<double> integration_time_s;              ///< --integration-time
    std::optional<io::EnviDataType> data_type;             ///< --data-type
    std::optional<TdiMode> tdi_mode;                       ///< --tdi-mode (default charge)
    MosaicChoice mosaic = MosaicChoice::from_focal_plane;  ///< --mosaic
    std::optional<BayerPhase> bayer_phase;                 ///< --bayer-phase (default rggb)
    bool no_noise = false;                                 ///< --no-noise: the mean, no draws
    bool electrons = false;                                ///< --electrons: stop before the ADC
    /// The render's --scale_resolution: the array's extent is divided into the scaled
    /// element counts, so each element's size is divided by count / scaled count (not the
    /// stages of a TDI array, which are never scaled).
    double scale_resolution = 1.0;
};

/// The detector model as applied (all values checked).
struct DetectorModelSettings {
    double quantum_efficiency = 1.0;
    double read_noise_e = 0.0;
    double dark_current_density_a_per_m2 = 0.0;
    double min_electrons = 0.0;
    double max_electrons = 1.0;
    int bit_depth = 12;
    double integration_time_s = 0.0;  ///< of one stage
    double pixel_area_m2 = 0.0;       ///< active element area (after scale_resolution)

    /// Mean dark electrons of one pixel: J A t N / e (N = stages).
    double dark_electrons(std::size_t stages) const;
    /// ADC gain K = (2^bits − 1) / (max − min) in DN per electron.
    double gain_dn_per_e() const;
    /// Largest count, 2^bits − 1.
    double max_count() const;
};

/// The CFA pattern as applied: the pattern, its phase and the input band of each filter.
struct CfaSettings {
    CfaPattern pattern = CfaPattern::bayer;
    BayerPhase phase = BayerPhase::rggb;
    /// Input band (channel index) of each filter, indexed by CfaFilter; -1 where unused.
    std::array<int, 4> channel_of_filter{-1, -1, -1, -1};
};

/// Everything the detection chain of one focal plane needs.
struct DetectionSettings {
    std::string focal_plane;                        ///< name, for messages
    std::vector<std::string> channel_names;         ///< input bands, in order
    std::optional<DetectorModelSettings> detector;  ///< none: values pass through
    std::size_t tdi_stages = 1;                     ///< 1 without TDI
    TdiMode tdi_mode = TdiMode::charge;
    std::optional<CfaSettings> cfa;  ///< none: every channel at every pixel
    bool noise = true;
    DetectOutput output = DetectOutput::counts;
    io::EnviDataType data_type = io::EnviDataType::float64;  ///< stored output type
    std::uint64_t seed = 1;

    std::size_t channels() const { return channel_names.size(); }
    /// Bands of the output: 1 with a CFA, else the channel count.
    std::size_t output_bands() const { return cfa ? 1 : channels(); }
    /// True when the chain changes anything (detector model, TDI or CFA).
    bool active() const { return detector.has_value() || cfa.has_value() || tdi_stages > 1; }
};

/// The stored type of an `<imagefile>`'s `<datatype>` code. Throws glint::Error (input, at
/// the element) for a code that is not a real ENVI data type (complex types included).
io::EnviDataType image_data_type(const model::ImageFile& image);

/// Resolves and checks the settings of `focal_plane` of an instrument with `properties`.
/// Throws glint::Error (input) at the element's file:line for a requirement the DIRSIG5
/// BasicPlatform manual lists (simple capture, aperture, non-zero integration time with a
/// detector model), a value out of range (from the model or an override, which the message
/// names), a CFA filter mapped to no channel, or a focal plane with nothing to detect (no
/// detector model, TDI or pattern, and no overrides that make a detector model).
DetectionSettings resolve_detection(const model::FocalPlane& focal_plane,
                                    const model::InstrumentProperties& properties,
                                    const DetectorOverrides& overrides, std::uint64_t seed);

}  // namespace glint::detect
