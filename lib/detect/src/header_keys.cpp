// SPDX-License-Identifier: Apache-2.0
// The header description of a detection (header_keys.h).
#include "glint/detect/header_keys.h"

#include "glint/core/text.h"
#include "glint/io/envi.h"

namespace glint::detect {

std::string output_data_units(const DetectionSettings& s, const std::string& input_units) {
    if (!s.detector) return input_units;
    return s.output == DetectOutput::counts ? "DN" : "Electrons";
}

std::vector<std::string> output_band_names(const DetectionSettings& s) {
    if (!s.cfa) return {};
    return {std::string(cfa_pattern_name(s.cfa->pattern)) + " mosaic"};
}

std::vector<std::pair<std::string, std::string>> detection_header_keys(const DetectionSettings& s) {
    std::vector<std::pair<std::string, std::string>> keys;
    auto add = [&](const std::string& key, const std::string& value) {
        keys.emplace_back(key, value);
    };
    add("glint seed", std::to_string(s.seed));
    if (const auto& d = s.detector) {
        add("glint detector quantum efficiency", format_shortest(d->quantum_efficiency));
        add("glint detector read noise e", format_shortest(d->read_noise_e));
        add("glint detector dark current density a per m2",
            format_shortest(d->dark_current_density_a_per_m2));
        add("glint detector integration time s", format_shortest(d->integration_time_s));
        add("glint detector pixel area m2", format_shortest(d->pixel_area_m2));
        add("glint detector dark electrons", format_shortest(d->dark_electrons(s.tdi_stages)));
        add("glint detector min electrons", format_shortest(d->min_electrons));
        add("glint detector max electrons", format_shortest(d->max_electrons));
        add("glint detector bit depth", std::to_string(d->bit_depth));
        add("glint detector gain dn per e", format_shortest(d->gain_dn_per_e()));
        add("glint detector noise", s.noise ? "true" : "false");
        add("glint detector output", s.output == DetectOutput::counts ? "counts" : "electrons");
    }
    add("glint tdi stages", std::to_string(s.tdi_stages));
    if (s.tdi_stages > 1) add("glint tdi mode", tdi_mode_name(s.tdi_mode));
    if (const auto& cfa = s.cfa) {
        add("glint cfa pattern", cfa_pattern_name(cfa->pattern));
        if (cfa->pattern == CfaPattern::bayer) add("glint cfa phase", bayer_phase_name(cfa->phase));
        std::vector<std::string> filters;
        for (CfaFilter f : cfa_filters(cfa->pattern)) {
            const int channel = cfa->channel_of_filter[static_cast<std::size_t>(f)];
            filters.push_back(std::string(cfa_filter_name(f)) + " " +
                              s.channel_names[static_cast<std::size_t>(channel)]);
        }
        add("glint cfa filters", io::envi_brace_list(filters));
    }
    return keys;
}

}  // namespace glint::detect
