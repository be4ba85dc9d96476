// SPDX-License-Identifier: Apache-2.0
// glint-detect's output header (output_header.h).
#include "output_header.h"

#include <string>

#include "glint/core/runner.h"
#include "glint/core/text.h"
#include "glint/detect/header_keys.h"

namespace glint::app_detect::internal {
namespace {

/// Input keys that describe the input's own production and are renamed in the output.
constexpr const char* kRenamed[][2] = {
    {"glint command line", "glint input command line"},
    {"glint version", "glint input version"},
    {"glint tool", "glint input tool"},
};


}  // namespace

io::EnviHeader output_header(const detect::DetectionSettings& s, const HeaderSources& src) {
    const io::EnviHeader& in = *src.input;
    io::EnviHeader h;
    const bool counts = s.detector && s.output == detect::DetectOutput::counts;
    h.description = std::string("glint-detect ") +
                    (s.detector ? (counts ? "digital counts" : "electrons") : "mosaic") + " of " +
                    src.input_path.filename().string() + " (focal plane " + s.focal_plane + ")";
    h.samples = in.samples;
    h.lines = in.lines;
    h.bands = s.output_bands();
    h.data_type = s.data_type;
    if (!s.cfa) {
        h.wavelength_units = in.wavelength_units;
        h.wavelength = in.wavelength;
        h.fwhm = in.fwhm;
        h.band_names = in.band_names;
    } else {
        h.band_names = detect::output_band_names(s);
    }
    h.data_units = detect::output_data_units(s, in.data_units);

    for (const auto& [key, value] : in.extra) {
        std::string name = key;
        for (const auto& renamed : kRenamed) {
            if (key == renamed[0]) name = renamed[1];
        }
        h.set_extra(name, value);
    }
    h.set_extra("glint tool", "glint-detect");
    h.set_extra("glint version", version());
    if (!src.command_line.empty()) h.set_extra("glint command line", src.command_line);
    h.set_extra("glint input", src.input_path.string());
    h.set_extra("glint input data units", in.data_units.empty() ? "none" : in.data_units);
    h.set_extra("glint platform", src.platform_path.string());
    h.set_extra("glint instrument", src.instrument);
    h.set_extra("glint focal plane", s.focal_plane);
    if (src.captures != nullptr) {
        h.set_extra("glint lines per capture", std::to_string(src.captures->lines_per_capture));
        std::vector<std::string> indices;
        for (std::uint64_t i : src.captures->indices) indices.push_back(std::to_string(i));
        h.set_extra("glint capture indices", io::envi_brace_list(indices));
    }
    for (const auto& [key, value] : detect::detection_header_keys(s)) h.set_extra(key, value);
    return h;
}

}  // namespace glint::app_detect::internal
