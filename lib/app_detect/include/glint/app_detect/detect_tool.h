// SPDX-License-Identifier: Apache-2.0
// glint-detect's entry point: applies a focal plane's detection (detector model, TDI, CFA
// mosaic; lib/detect) to a radiometric ENVI product, streaming line by line, and writes the
// digital counts (or electrons) atomically with a header that records every parameter used.
// docs/tools/glint-detect.md documents the options; docs/detector.md the physics.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>

#include "glint/core/context.h"
#include "glint/detect/cfa.h"
#include "glint/detect/detector.h"
#include "glint/io/envi.h"

namespace glint::app_detect {

/// Options of glint-detect.
struct Options {
    std::filesystem::path input;     ///< the radiometric product (data file or its header)
    std::filesystem::path output;    ///< -o: the ENVI data file to write (header beside it)
    std::filesystem::path platform;  ///< --platform; empty: the input header's `glint platform`
    std::string instrument;   ///< --instrument; empty: the header's `glint instrument`, if any
    std::string focal_plane;  ///< --focal-plane; empty: the header's `glint focal plane`
    detect::DetectorOverrides overrides;  ///< --qe, --read-noise, ..., --mosaic, --tdi-mode
    std::optional<std::uint64_t> seed;    ///< --seed; else the header's `glint seed`, else 1
};

/// --data-type: an ENVI data type by name ("uint16") or code ("12"). Throws glint::Error
/// (usage) naming the choices.
io::EnviDataType parse_data_type(const std::string& text);
/// --mosaic: bayer, truesense or none (any case). Throws glint::Error (usage).
detect::MosaicChoice parse_mosaic(const std::string& text);
/// --bayer-phase: rggb, grbg, gbrg or bggr. Throws glint::Error (usage).
detect::BayerPhase parse_bayer_phase(const std::string& text);
/// --tdi-mode: charge or digital (any case). Throws glint::Error (usage).
detect::TdiMode parse_tdi_mode(const std::string& text);

/// What a run did.
struct Result {
    detect::DetectionSettings settings;
    std::size_t samples = 0;
    std::size_t lines = 0;
    std::size_t captures = 0;
    std::size_t lines_per_capture = 0;
};

/// Runs glint-detect. Throws glint::Error: usage for missing or contradictory options or an
/// output that would overwrite the input; input for a platform, focal plane or input cube
/// that does not fit (units other than Photons/cm2 or Electrons/cm2 with a detector model, a
/// band count other than the channel count, capture keys that do not match the lines, a
/// value the detector cannot take); io when a file cannot be read or written. Nothing is
/// left under the output name unless the run succeeded.
Result detect_file(const Options& options, Context& ctx);

/// glint-detect: detect_file; returns the exit status (0; failures are thrown). `out`
/// (stdout) gets nothing: the tool writes its output file.
int run(const Options& options, Context& ctx, std::ostream& out);

}  // namespace glint::app_detect
