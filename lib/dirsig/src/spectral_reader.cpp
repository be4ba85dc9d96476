// SPDX-License-Identifier: Apache-2.0
// The spectral half of the `.platform` capture-method reader: `<spectralresponse>` with its
// bandpass (converted to µm, its sample count checked before anything is sized by it),
// channels (gaussian, tabulated, tophat, triangle) and colour-filter-array pattern, and the
// checks that need the whole response. Every problem goes to Diagnostics with its location.
#include "spectral_reader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "glint/core/spectral.h"
#include "glint/core/text.h"
#include "glint/model/names.h"

namespace glint::dirsig::detail::capture_io {
namespace {

using model::Bandpass;
using model::Channel;
using model::ChannelPattern;
using model::ChannelPatternKind;
using model::ChannelShape;

constexpr std::array<std::string_view, 3> kBayerFilters = {"red", "green", "blue"};
constexpr std::array<std::string_view, 4> kTrueSenseFilters = {"pan", "red", "green", "blue"};

std::span<const std::string_view> filters_of(ChannelPatternKind kind) {
    if (kind == ChannelPatternKind::bayer) return kBayerFilters;
    return kTrueSenseFilters;
}

/// The conversion factor of the bandpass's spectral units (1 when unknown).
double unit_factor(const Bandpass& bandpass) {
    if (bandpass.spectral_units.empty()) return 1.0;
    try {
        return wavelength_unit_to_um(bandpass.spectral_units);
    } catch (const Error&) {
        return 1.0;
    }
}

/// "0.4–0.7 microns", in the units the bandpass was written in.
std::string range_text(const Bandpass& bandpass) {
    const double factor = unit_factor(bandpass);
    return format_ten_digits(bandpass.min_um / factor) + "–" +
           format_ten_digits(bandpass.max_um / factor) + " " + bandpass.spectral_units;
}

Bandpass read_bandpass(const io::XmlNode& node, Diagnostics& diagnostics) {
    Bandpass bandpass;
    bandpass.where = node.where();
    node.warn_unknown_children({"minimum", "maximum", "delta"}, diagnostics);
    const auto units = node.attribute_enum(
        "spectralunits", {"microns", "micrometers", "um", "nanometers", "nm"}, diagnostics);
    const bool units_ok = units.has_value() || !node.attribute("spectralunits").has_value();
    bandpass.spectral_units = units.value_or("microns");
    const double factor = wavelength_unit_to_um(bandpass.spectral_units);

    const auto minimum = node.required_double("minimum", diagnostics, io::NumberRule::positive());
    const auto maximum = node.required_double("maximum", diagnostics, io::NumberRule::positive());
    const auto delta = node.required_double("delta", diagnostics, io::NumberRule::positive());
    if (!minimum || !maximum || !delta || !units_ok) return bandpass;

    const std::string unit = " " + bandpass.spectral_units;
    if (!(*maximum > *minimum)) {
        diagnostics.error(node.child("maximum")->where(), "maximum " + format_ten_digits(*maximum) +
                                                              unit + " is not above minimum " +
                                                              format_ten_digits(*minimum) + unit +
                                                              ", expected minimum < maximum");
        return bandpass;
    }
    // The sample count is checked on the step count before anything is sized by it.
    const std::string range =
        format_ten_digits(*minimum) + "–" + format_ten_digits(*maximum) + unit;
    const double steps = (*maximum - *minimum) / *delta;
    if (!(steps + 1.0 <= static_cast<double>(kMaxBandpassSamples) + 1e-6)) {
        char count[64] = "more than 10^18";
        if (steps < 1e18)
            std::snprintf(count, sizeof count, "%.0f", std::floor(steps + 1e-6) + 1.0);
        diagnostics.error(node.child("delta")->where(), "bandpass " + range + " at delta " +
                                                            format_ten_digits(*delta) + " has " +
                                                            count + " samples, expected at most " +
                                                            std::to_string(kMaxBandpassSamples));
        return bandpass;
    }
    const double nearest = std::max(1.0, std::round(steps));
    if (std::fabs(steps - nearest) > 1e-6) {
        diagnostics.error(node.child("delta")->where(),
                          "bandpass delta " + format_ten_digits(*delta) +
                              " does not divide the range " + range + " (" +
                              format_ten_digits(nearest) + " steps would need delta " +
                              format_ten_digits((*maximum - *minimum) / nearest) +
                              "), expected a delta that divides maximum − minimum");
        return bandpass;
    }
    bandpass.min_um = *minimum * factor;
    bandpass.max_um = *maximum * factor;
    bandpass.delta_um = *delta * factor;
    bandpass.count = static_cast<std::size_t>(nearest) + 1;
    return bandpass;
}

/// The `type` attribute of `<polarizer>`/`<dataoutput>`, warning when it is not `modelled`.
std::string read_polarization(const io::XmlNode& channel, std::string_view element,
                              std::string_view modelled, Diagnostics& diagnostics) {
    const auto node = single_child(channel, element, diagnostics);
    if (!node) return std::string(modelled);
    node->warn_unknown_children({}, diagnostics);
    const std::string type = trim(node->attribute("type").value_or(std::string(modelled)));
    if (to_lower(type) != modelled) {
        diagnostics.warning(node->where_attribute("type"),
                            "type '" + type + "': polarization is not modelled, glint writes " +
                                "the total (unpolarized) signal as for type " +
                                std::string(modelled));
    }
    return type;
}

void read_table(const io::XmlNode& node, double factor, Channel& channel,
                Diagnostics& diagnostics) {
    const auto entries = node.children("entry");
    bool complete = true;
    std::optional<double> previous;
    for (const auto& entry : entries) {
        entry.warn_unknown_children({"spectralpoint", "value"}, diagnostics);
        const auto point =
            entry.required_double("spectralpoint", diagnostics, io::NumberRule::positive());
        const auto value =
            entry.required_double("value", diagnostics, io::NumberRule::non_negative());
        if (!point || !value) {
            complete = false;
            continue;
        }
        if (previous && !(*point > *previous)) {
            diagnostics.error(entry.child("spectralpoint")->where(),
                              "spectralpoint " + format_ten_digits(*point) +
                                  " does not increase (previous " + format_ten_digits(*previous) +
                                  "), expected strictly increasing points");
            complete = false;
            continue;
        }
        previous = point;
        channel.table_wavelength_um.push_back(*point * factor);
        channel.table_value.push_back(*value);
    }
    if (entries.size() < 2) {
        diagnostics.error(node.where(), "tabulated channel has " + std::to_string(entries.size()) +
                                            " <entry>, expected at least 2");
        return;
    }
    const bool all_zero = std::all_of(channel.table_value.begin(), channel.table_value.end(),
                                      [](double v) { return v == 0.0; });
    if (complete && all_zero && channel.normalize) {
        diagnostics.error(node.where(),
                          "tabulated response is zero everywhere and cannot be normalized, "
                          "expected some value > 0");
    }
}

Channel read_channel(const io::XmlNode& node, double factor, Diagnostics& diagnostics) {
    Channel channel;
    channel.where = node.where();
    if (const auto name = required_attribute(node, "name", diagnostics)) {
        channel.name = trim(*name);
        if (channel.name.empty()) {
            diagnostics.error(node.where_attribute("name"),
                              "channel name is empty, expected a name");
        }
    }
    const auto shape = node.attribute_enum(
        "shape", {"gaussian", "tabulated", "tophat", "rectangular", "triangle"}, diagnostics);
    const bool shape_ok = shape.has_value() || !node.attribute("shape").has_value();
    const std::string shape_text = shape.value_or("gaussian");
    if (shape_text == "tabulated") channel.shape = ChannelShape::tabulated;
    // "rectangular" (in DIRSIG's own notebooks) is the tophat under another name.
    if (shape_text == "tophat" || shape_text == "rectangular") channel.shape = ChannelShape::tophat;
    if (shape_text == "triangle") channel.shape = ChannelShape::triangle;
    channel.normalize = node.attribute_bool("normalize", diagnostics).value_or(false);
    channel.gain = node.attribute_double("gain", diagnostics).value_or(1.0);
    channel.bias = node.attribute_double("bias", diagnostics).value_or(0.0);
    channel.polarizer = read_polarization(node, "polarizer", "none", diagnostics);
    channel.data_output = read_polarization(node, "dataoutput", "total", diagnostics);

    if (!shape_ok) {
        node.warn_unknown_children({"center", "width", "entry", "polarizer", "dataoutput"},
                                   diagnostics);
        return channel;
    }
    if (channel.shape == ChannelShape::tabulated) {
        node.warn_unknown_children({"entry", "polarizer", "dataoutput"}, diagnostics);
        read_table(node, factor, channel, diagnostics);
        return channel;
    }
    node.warn_unknown_children({"center", "width", "polarizer", "dataoutput"}, diagnostics);
    if (const auto center = node.required_double("center", diagnostics)) {
        channel.center_um = *center * factor;
    }
    if (const auto width = node.required_double("width", diagnostics, io::NumberRule::positive())) {
        channel.width_um = *width * factor;
    }
    return channel;
}

std::optional<ChannelPattern> read_pattern(const io::XmlNode& node, Diagnostics& diagnostics) {
    node.warn_unknown_children({"mapping"}, diagnostics);
    if (!required_attribute(node, "name", diagnostics)) return std::nullopt;
    const auto name = node.attribute_enum("name", {"bayer", "truesense"}, diagnostics);
    if (!name) return std::nullopt;
    ChannelPattern pattern;
    pattern.where = node.where();
    pattern.kind = *name == "bayer" ? ChannelPatternKind::bayer : ChannelPatternKind::truesense;
    const auto filters = filters_of(pattern.kind);
    for (const auto& mapping : node.children("mapping")) {
        mapping.warn_unknown_children({}, diagnostics);
        const auto filter = required_attribute(mapping, "filtername", diagnostics);
        const auto channel = required_attribute(mapping, "channelname", diagnostics);
        if (!filter || !channel) continue;
        const std::string filter_name = to_lower(trim(*filter));
        if (std::find(filters.begin(), filters.end(), filter_name) == filters.end()) {
            diagnostics.error(mapping.where_attribute("filtername"),
                              "filter '" + trim(*filter) + "' is not a filter of the " +
                                  model::name_of(pattern.kind) + " pattern, expected " +
                                  join(filters, ", ", " or "));
            continue;
        }
        pattern.mappings.emplace_back(filter_name, trim(*channel));
    }
    return pattern;
}

void check_channel_in_bandpass(const Channel& channel, const Bandpass& bandpass,
                               Diagnostics& diagnostics) {
    const double factor = unit_factor(bandpass);
    const std::string unit = " " + bandpass.spectral_units;
    if (channel.shape == ChannelShape::tabulated) {
        if (channel.table_wavelength_um.empty()) return;
        const double first = channel.table_wavelength_um.front();
        const double last = channel.table_wavelength_um.back();
        if (last < bandpass.min_um || first > bandpass.max_um) {
            diagnostics.error(channel.where,
                              "tabulated response " + format_ten_digits(first / factor) + "–" +
                                  format_ten_digits(last / factor) + unit +
                                  " lies outside the bandpass " + range_text(bandpass) +
                                  ", expected a response inside the bandpass");
        }
        return;
    }
    if (!(channel.width_um > 0.0)) return;  // already reported
    const double outside =
        std::max({bandpass.min_um - channel.center_um, channel.center_um - bandpass.max_um, 0.0});
    if (outside <= 0.0) return;
    // How far from the centre the response still matters: a Gaussian is down to 1/16 at one
    // FWHM; a tophat or triangle is zero beyond half its full width.
    const double reach =
        channel.shape == ChannelShape::gaussian ? channel.width_um : channel.width_um / 2.0;
    const std::string center = "center " + format_ten_digits(channel.center_um / factor) + unit +
                               " lies outside the bandpass " + range_text(bandpass);
    if (outside >= reach) {
        diagnostics.error(channel.where, center +
                                             " and its response does not reach into it, expected a "
                                             "center inside the bandpass");
    } else {
        diagnostics.warning(channel.where,
                            center +
                                "; only the part of its response inside the bandpass "
                                "is used");
    }
}

void check_pattern(const ChannelPattern& pattern, const std::vector<Channel>& channels,
                   Diagnostics& diagnostics) {
    const auto filters = filters_of(pattern.kind);
    const std::string kind = model::name_of(pattern.kind);
    for (const auto filter : filters) {
        const auto count = std::count_if(pattern.mappings.begin(), pattern.mappings.end(),
                                         [&](const auto& m) { return m.first == filter; });
        if (count == 0) {
            diagnostics.error(pattern.where, "filter '" + std::string(filter) + "' of the " + kind +
                                                 " pattern is not mapped, expected a " +
                                                 "<mapping filtername=\"" + std::string(filter) +
                                                 "\" channelname=\"...\"/>");
        } else if (count > 1) {
            diagnostics.error(pattern.where, "filter '" + std::string(filter) + "' is mapped " +
                                                 std::to_string(count) +
                                                 " times, expected exactly once");
        }
    }
    for (const auto& [filter, channel_name] : pattern.mappings) {
        if (std::find(filters.begin(), filters.end(), filter) == filters.end()) {
            diagnostics.error(pattern.where, "filter '" + filter + "' is not a filter of the " +
                                                 kind + " pattern, expected " +
                                                 join(filters, ", ", " or "));
            continue;
        }
        // Captured by name: clang before 16 cannot capture a structured binding.
        const bool found =
            std::any_of(channels.begin(), channels.end(),
                        [&name = channel_name](const Channel& c) { return c.name == name; });
        if (!found) {
            diagnostics.error(pattern.where, "filter '" + filter + "' is mapped to channel '" +
                                                 channel_name +
                                                 "', which is not in the channel list, expected "
                                                 "the name of a <channel>");
        }
    }
}

}  // namespace

std::optional<std::string> non_empty_text(const io::XmlNode& node, std::string_view name,
                                          std::string_view expected, Diagnostics& diagnostics) {
    const auto child = node.child(name);
    if (!child) return std::nullopt;
    std::string text = child->text();
    if (text.empty()) {
        diagnostics.error(child->where(),
                          std::string(name) + " is empty, expected " + std::string(expected));
        return std::nullopt;
    }
    return text;
}

std::string trim(const std::string& text) {
    const auto first = text.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return {};
    const auto last = text.find_last_not_of(" \t\r\n");
    return text.substr(first, last - first + 1);
}

std::optional<io::XmlNode> single_child(const io::XmlNode& node, std::string_view name,
                                        Diagnostics& diagnostics) {
    auto all = node.children(name);
    if (all.empty()) return std::nullopt;
    for (std::size_t i = 1; i < all.size(); ++i) {
        diagnostics.error(all[i].where(), "<" + std::string(name) +
                                              "> given again (first at line " +
                                              std::to_string(all[0].line()) +
                                              "), expected at most one; this one is ignored");
    }
    return all.front();
}

std::optional<std::string> required_attribute(const io::XmlNode& node, std::string_view name,
                                              Diagnostics& diagnostics) {
    auto value = node.attribute(name);
    if (!value) {
        diagnostics.error(node.where(), "missing required attribute " + std::string(name));
    }
    return value;
}

model::SpectralResponse read_spectral_response(const io::XmlNode& node, bool needs_channels,
                                               Diagnostics& diagnostics) {
    model::SpectralResponse response;
    node.warn_unknown_children({"bandpass", "channellist", "channelpattern"}, diagnostics);
    const auto bandpass = single_child(node, "bandpass", diagnostics);
    if (!bandpass) {
        diagnostics.error(node.where(), "missing required element <bandpass>");
        return response;
    }
    response.bandpass = read_bandpass(*bandpass, diagnostics);
    const double factor = unit_factor(response.bandpass);

    if (const auto list = single_child(node, "channellist", diagnostics)) {
        list->warn_unknown_children({"channel"}, diagnostics);
        for (const auto& channel : list->children("channel")) {
            response.channels.push_back(read_channel(channel, factor, diagnostics));
        }
    }
    if (needs_channels && response.channels.empty()) {
        diagnostics.error(node.where(),
                          "no channel, expected at least one <channel> in "
                          "<channellist>");
    }
    if (const auto pattern = single_child(node, "channelpattern", diagnostics)) {
        response.pattern = read_pattern(*pattern, diagnostics);
    }
    return response;
}

void check_spectral_response(const model::SpectralResponse& response, model::CaptureMethodType type,
                             Diagnostics& diagnostics) {
    std::map<std::string, const Channel*> seen;
    for (const auto& channel : response.channels) {
        if (channel.name.empty()) continue;
        const auto [it, inserted] = seen.emplace(channel.name, &channel);
        if (!inserted) {
            diagnostics.error(channel.where, "duplicate channel name '" + channel.name +
                                                 "' (first at line " +
                                                 std::to_string(it->second->where.line) +
                                                 "), expected unique names");
        }
    }
    if (response.bandpass.count > 0) {
        for (const auto& channel : response.channels) {
            check_channel_in_bandpass(channel, response.bandpass, diagnostics);
        }
    }
    if (response.pattern) {
        if (type != model::CaptureMethodType::simple) {
            diagnostics.error(
                response.pattern->where,
                "a channel pattern needs capturemethod type simple, expected no "
                "<channelpattern> in a " +
                    std::string(type == model::CaptureMethodType::raw ? "raw" : "lidar") +
                    " capture");
        }
        check_pattern(*response.pattern, response.channels, diagnostics);
    }
}

}  // namespace glint::dirsig::detail::capture_io
