// SPDX-License-Identifier: Apache-2.0
// glint-detect's option values from their command-line spellings (glint/app_detect/
// detect_tool.h), each refused with a usage error that names the option and the choices.
#include <string>

#include "glint/app_detect/detect_tool.h"
#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::app_detect {

io::EnviDataType parse_data_type(const std::string& text) {
    // The real types (no complex ones: digital counts are real).
    if (const auto type = io::envi_type_from_string(text)) {
        for (long code : {1L, 2L, 3L, 4L, 5L, 12L, 13L, 14L, 15L}) {
            if (static_cast<long>(*type) == code) return *type;
        }
    }
    throw usage_error("--data-type: unknown ENVI data type '" + text +
                      "' (uint8, int16, uint16, int32, uint32, int64, uint64, float32, float64 "
                      "or their codes 1, 2, 12, 3, 13, 14, 15, 4, 5)");
}

detect::MosaicChoice parse_mosaic(const std::string& text) {
    const std::string m = to_lower(text);
    if (m == "none") return detect::MosaicChoice::none;
    if (m == "bayer") return detect::MosaicChoice::bayer;
    if (m == "truesense") return detect::MosaicChoice::truesense;
    throw usage_error("--mosaic: expected bayer, truesense or none, got '" + text + "'");
}

detect::BayerPhase parse_bayer_phase(const std::string& text) {
    if (const auto phase = detect::bayer_phase_from_name(text)) return *phase;
    throw usage_error("--bayer-phase: expected rggb, grbg, gbrg or bggr, got '" + text + "'");
}

detect::TdiMode parse_tdi_mode(const std::string& text) {
    const std::string m = to_lower(text);
    if (m == "charge") return detect::TdiMode::charge;
    if (m == "digital") return detect::TdiMode::digital;
    throw usage_error("--tdi-mode: expected charge or digital, got '" + text + "'");
}

}  // namespace glint::app_detect
