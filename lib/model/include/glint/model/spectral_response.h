// SPDX-License-Identifier: Apache-2.0
// SpectralResponse of a capture method: the bandpass (the spectral grid of the radiometry),
// the channels (relative spectral responses) and an optional colour-filter-array pattern.
//
// clang-format off
// | element / attribute | type | unit | default |
// |---|---|---|---|
// | bandpass@spectralunits | microns, nanometers (also um, nm) | - | microns |
// | bandpass/minimum, maximum, delta | numbers > 0; min < max; delta divides max − min (to 1e-6 of a step); at most 100,000 samples | spectralunits | required |
// | channellist/channel | at least one for a simple capture | | |
// | channellist/channel@name | text (unique within the focal plane) | - | required |
// | channel@shape | gaussian, tabulated, tophat, triangle | - | gaussian |
// | channel@normalize | bool | - | false |
// | channel@gain, @bias | number | - | 1, 0 |
// | channel/center | number inside the bandpass (gaussian, tophat, triangle); just outside but with response reaching in: warning | spectralunits | required |
// | channel/width | number > 0: FWHM (gaussian), full width (tophat, triangle) | spectralunits | required |
// | channel/entry/spectralpoint, value | tabulated response: points > 0 strictly increasing, overlapping the bandpass; value >= 0 | spectralunits, - | ≥ 2 entries |
// | channel/polarizer@type, dataoutput@type | text (kept; only none/total are modelled) | - | none, total |
// | channelpattern@name | bayer (red, green, blue), truesense (pan, red, green, blue); simple captures only | - | - |
// | channelpattern/mapping@filtername, @channelname | filter of the pattern → existing channel name | - | every filter exactly once |
// clang-format on
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "glint/model/common.h"

namespace glint::model {

/// The spectral sampling grid of a focal plane, in µm.
struct Bandpass {
    double min_um = 0.0;
    double max_um = 0.0;
    double delta_um = 0.0;
    std::size_t count = 0;  ///< (max − min) / delta + 1
    /// As written, lower case: microns, micrometers, um, nanometers or nm.
    std::string spectral_units;
    ErrorContext where;
};

enum class ChannelShape { gaussian, tabulated, tophat, triangle };

/// One channel's relative spectral response.
struct Channel {
    std::string name;
    ChannelShape shape = ChannelShape::gaussian;
    bool normalize = false;
    double gain = 1.0;
    double bias = 0.0;
    double center_um = 0.0;                   ///< gaussian, tophat, triangle
    double width_um = 0.0;                    ///< FWHM (gaussian) or full width
    std::vector<double> table_wavelength_um;  ///< tabulated: increasing
    std::vector<double> table_value;          ///< tabulated: response at each point
    std::string polarizer = "none";
    std::string data_output = "total";
    ErrorContext where;
};

enum class ChannelPatternKind { bayer, truesense };

/// A colour-filter-array pattern: which channel each filter of the pattern passes.
struct ChannelPattern {
    ChannelPatternKind kind = ChannelPatternKind::bayer;
    /// (filter name, channel name) pairs: bayer red/green/blue, truesense pan/red/green/blue.
    std::vector<std::pair<std::string, std::string>> mappings;
    ErrorContext where;

    /// Channel name mapped to `filter`, if any.
    std::optional<std::string> channel_for(const std::string& filter) const;
};

/// `<spectralresponse>`.
struct SpectralResponse {
    Bandpass bandpass;
    std::vector<Channel> channels;
    std::optional<ChannelPattern> pattern;
};

}  // namespace glint::model
