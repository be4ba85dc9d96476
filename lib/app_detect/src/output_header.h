// SPDX-License-Identifier: Apache-2.0
// The header of glint-detect's output: the input's band metadata (or one mosaic band), the
// output units, the input's provenance keys, and one `glint ...` key per parameter used.
#pragma once

#include <filesystem>
#include <string>

#include "glint/detect/detector.h"
#include "glint/io/envi.h"
#include "input.h"

namespace glint::app_detect::internal {

/// What the header records besides the settings.
struct HeaderSources {
    const io::EnviHeader* input = nullptr;
    std::filesystem::path input_path;
    std::filesystem::path platform_path;
    std::string instrument;
    std::string command_line;
    const CaptureMap* captures = nullptr;
};

/// The output header for `settings` (see docs/tools/glint-detect.md for the keys).
io::EnviHeader output_header(const detect::DetectionSettings& settings,
                             const HeaderSources& sources);

}  // namespace glint::app_detect::internal
