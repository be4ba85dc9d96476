// SPDX-License-Identifier: Apache-2.0
// Internal interface of the spectral half of the capture-method reader: `<spectralresponse>`
// (bandpass, channel list, channel pattern) and the checks that need the whole response,
// plus the small helpers both capture_reader.cpp and spectral_reader.cpp use.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "glint/core/diagnostics.h"
#include "glint/core/text.h"
#include "glint/io/xml.h"
#include "glint/model/capture.h"
#include "glint/model/spectral_response.h"

namespace glint::dirsig::detail::capture_io {

/// The most samples a bandpass may have; checked before anything is sized by it.
inline constexpr std::size_t kMaxBandpassSamples = 100'000;

/// `text` without leading and trailing blanks.
std::string trim(const std::string& text);

/// Text of child `name` that must not be empty when given (an error naming `expected` when it
/// is empty); nullopt when absent or empty.
std::optional<std::string> non_empty_text(const io::XmlNode& node, std::string_view name,
                                          std::string_view expected, Diagnostics& diagnostics);

/// The only child called `name`, if any; a second one is an error (and ignored).
std::optional<io::XmlNode> single_child(const io::XmlNode& node, std::string_view name,
                                        Diagnostics& diagnostics);

/// The attribute `name`; an error "missing required attribute" when absent.
std::optional<std::string> required_attribute(const io::XmlNode& node, std::string_view name,
                                              Diagnostics& diagnostics);

/// Reads `<spectralresponse>`. `needs_channels`: the capture writes channels (simple), so
/// an empty channel list is an error.
model::SpectralResponse read_spectral_response(const io::XmlNode& node, bool needs_channels,
                                               Diagnostics& diagnostics);

/// Checks a spectral response as a whole: unique channel names, channels inside the
/// bandpass, the pattern's filters each mapped once to an existing channel, and no pattern
/// on a raw capture.
void check_spectral_response(const model::SpectralResponse& response, model::CaptureMethodType type,
                             Diagnostics& diagnostics);

}  // namespace glint::dirsig::detail::capture_io
