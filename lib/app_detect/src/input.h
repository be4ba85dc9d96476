// SPDX-License-Identifier: Apache-2.0
// What glint-detect learns before processing: the focal plane (from --platform/--focal-plane
// or the input header's provenance keys), the seed, and how the input's lines map to
// captures (`glint lines per capture`, `glint capture indices`).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "glint/app_detect/detect_tool.h"
#include "glint/core/context.h"
#include "glint/io/envi.h"
#include "glint/model/platform.h"

namespace glint::app_detect::internal {

/// The focal plane chosen, with the platform that owns it.
struct FocalPlaneChoice {
    model::Platform platform;
    std::filesystem::path platform_path;
    std::string instrument_name;
    const model::Instrument* instrument = nullptr;   ///< into `platform`
    const model::FocalPlane* focal_plane = nullptr;  ///< into `platform`
};

/// Reads the platform and finds the focal plane. Throws glint::Error: usage when neither
/// the options nor the header name them, input when the platform has errors or no (or
/// several) focal planes of that name.
/// Not copyable (it points into its own platform), so it is filled in place.
void choose_focal_plane(const Options& options, const io::EnviHeader& header,
                        const std::filesystem::path& header_path, Context& ctx,
                        FocalPlaneChoice& choice);

/// The seed: --seed, else the header's `glint seed`, else kDefaultSeed.
std::uint64_t choose_seed(const Options& options, const io::EnviHeader& header,
                          const std::string& header_file);

/// The header's `glint scale resolution`, else 1.
double scale_resolution(const io::EnviHeader& header, const std::string& header_file);

/// How lines map to captures.
struct CaptureMap {
    std::size_t lines_per_capture = 1;
    std::vector<std::uint64_t> indices;  ///< global index of each capture, in line order
    /// The first line's line in its capture: A of a row part's `glint part rows = {A, B}`
    /// (glint/io/envi_part.h), so a part's lines draw their whole capture's streams.
    std::size_t first_line = 0;
};

/// From `glint lines per capture` and `glint capture indices` when present (they must fit
/// the line count); otherwise one capture per `default_lines_per_capture` lines when that
/// divides the line count, else one capture; captures numbered 0, 1, ... then.
CaptureMap capture_map(const io::EnviHeader& header, const std::string& header_file,
                       std::size_t default_lines_per_capture);

}  // namespace glint::app_detect::internal
