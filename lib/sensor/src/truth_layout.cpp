// SPDX-License-Identifier: Apache-2.0
// Truth bands and headers (glint/sensor/truth.h).
#include <algorithm>
#include <string>

#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/sensor/truth.h"

namespace glint::sensor {
namespace {

using Q = model::TruthQuantity;

/// The most names a header lists for an index band (an instance per tree of a forest would
/// make a header of megabytes).
constexpr std::size_t kMaxHeaderNames = 100'000;

/// The index of the band equal to `band` in `layout`, appended when new.
std::size_t band_index(TruthLayout& layout, TruthBand band) {
    for (std::size_t i = 0; i < layout.bands.size(); ++i) {
        const TruthBand& b = layout.bands[i];
        if (b.quantity == band.quantity && b.index == band.index) return i;
    }
    layout.bands.push_back(std::move(band));
    return layout.bands.size() - 1;
}

/// The index of an abundance target equal to `target` in `layout`, appended when new.
std::size_t target_index(TruthLayout& layout, model::AbundanceTarget target) {
    for (std::size_t i = 0; i < layout.targets.size(); ++i) {
        const model::AbundanceTarget& t = layout.targets[i];
        if (t.is_tag == target.is_tag && t.key == target.key) return i;
    }
    layout.targets.push_back(std::move(target));
    return layout.targets.size() - 1;
}

std::string channel_units(const OutputUnits& units, std::size_t channel) {
    const auto& per_channel = units.description().per_channel_units;
    return per_channel.empty() ? units.description().data_units : per_channel[channel];
}

/// The bands collector `collector` asks for, appended to `layout` (new ones) and returned.
std::vector<std::size_t> collector_bands(const model::TruthCollector& collector,
                                         const model::Scene& scene, const OutputUnits& units,
                                         const Log& log, TruthLayout& layout) {
    const auto quantities = model::expand_truth_collector(collector.name);
    if (!quantities) {
        throw input_error("unknown truth collector " + quote(collector.name) + " (" +
                              model::known_truth_collectors() + ")",
                          collector.where);
    }
    std::vector<std::size_t> bands;
    for (const Q q : *quantities) {
        const model::TruthQuantityInfo& info = model::truth_quantity_info(q);
        if (q == Q::abundance) {
            std::vector<std::string> warnings;
            for (model::AbundanceTarget& target :
                 model::resolve_abundance(collector, scene, warnings)) {
                const std::string name = std::string(target.is_tag ? "Tag" : "Material") +
                                         " Abundance '" + target.key + "'";
                const std::size_t t = target_index(layout, std::move(target));
                bands.push_back(band_index(layout, {q, t, name, std::string(info.units)}));
            }
            for (const std::string& warning : warnings) {
                log.warning(format_located(collector.where, warning));
            }
        } else if (q == Q::standard_error) {
            for (std::size_t c = 0; c < units.channels(); ++c) {
                const std::string name = "Standard Error '" + units.band_names()[c] + "'";
                bands.push_back(band_index(layout, {q, c, name, channel_units(units, c)}));
            }
        } else {
            bands.push_back(
                band_index(layout, {q, 0, std::string(info.label), std::string(info.units)}));
        }
    }
    return bands;
}

}  // namespace

TruthLayout make_truth_layout(const model::FocalPlane& fp, const model::Scene& scene,
                              const OutputUnits& units, const Log& log) {
    TruthLayout layout;
    for (std::size_t c = 0; c < fp.truth_collections.size(); ++c) {
        const model::TruthCollection& truth = fp.truth_collections[c];
        if (!model::writes_truth(truth)) continue;
        TruthFileLayout file{c, {}};
        for (const model::TruthCollector& collector : truth.collectors) {
            bool added = false;
            for (const std::size_t band : collector_bands(collector, scene, units, log, layout)) {
                if (std::find(file.bands.begin(), file.bands.end(), band) != file.bands.end()) {
                    continue;
                }
                file.bands.push_back(band);
                added = true;
            }
            if (!added) {
                log.warning(
                    format_located(collector.where, "truth collector " + quote(collector.name) +
                                                        " adds no band: its bands are already in "
                                                        "collection " +
                                                        quote(truth.name)));
            }
        }
        layout.files.push_back(std::move(file));
    }
    for (const TruthBand& band : layout.bands) {
        if (band.quantity != Q::sample_count && band.quantity != Q::standard_error) {
            layout.needs_first_hit = true;
        }
    }
    return layout;
}

io::EnviHeader truth_header(const io::EnviHeader& base, const model::FocalPlane& fp,
                            const TruthLayout& layout, const TruthFileLayout& file,
                            const model::Scene& scene) {
    const model::TruthCollection& truth = fp.truth_collections[file.collection];
    io::EnviHeader h;
    h.description = "glint-render truth collection " + quote(truth.name) + " of " +
                    base.find_extra("glint instrument").value_or("") + " -> " + fp.name;
    h.samples = base.samples;
    h.bands = file.bands.size();
    h.data_type =
        truth.image_file.datatype == 4 ? io::EnviDataType::float32 : io::EnviDataType::float64;
    std::vector<std::string> units;
    bool has[3] = {false, false, false};  // material, instance, object index bands
    for (const std::size_t b : file.bands) {
        const TruthBand& band = layout.bands[b];
        h.band_names.push_back(io::sanitize_band_name(band.name));
        units.push_back(band.units.empty() ? "unitless" : band.units);
        if (band.quantity == Q::material_index) has[0] = true;
        if (band.quantity == Q::instance_index) has[1] = true;
        if (band.quantity == Q::object_index) has[2] = true;
    }
    // Provenance: the radiometric header's glint keys but those about its pixels' values.
    for (const auto& [key, value] : base.extra) {
        if (key.rfind("glint ", 0) != 0) continue;
        if (key == "glint channel units" || key.rfind("glint detector", 0) == 0) continue;
        h.set_extra(key, value);
    }
    h.set_extra("data ignore value", "NaN");
    h.set_extra("glint truth collection", io::sanitize_band_name(truth.name));
    h.set_extra("glint band units", io::envi_brace_list(units));
    if (has[0]) {
        std::vector<std::string> ids;
        std::vector<std::string> names;
        for (const model::Material& m : scene.materials) {
            ids.push_back(m.id);
            names.push_back(m.name);
        }
        h.set_extra("glint material ids", io::envi_brace_list(ids));
        h.set_extra("glint material names", io::envi_brace_list(names));
    }
    if (has[1] && scene.instances.size() <= kMaxHeaderNames) {
        std::vector<std::string> names;
        for (const model::Instance& i : scene.instances) names.push_back(i.name);
        h.set_extra("glint instance names", io::envi_brace_list(names));
    }
    if (has[2] && scene.objects.size() <= kMaxHeaderNames) {
        std::vector<std::string> names;
        for (const model::GeometryObject& o : scene.objects) names.push_back(o.name);
        h.set_extra("glint object names", io::envi_brace_list(names));
    }
    return h;
}

std::vector<double> truth_file_values(const TruthLayout& layout, const TruthFileLayout& file,
                                      std::span<const double> values) {
    const std::size_t all = layout.bands.size();
    const std::size_t pixels = all == 0 ? 0 : values.size() / all;
    std::vector<double> out(pixels * file.bands.size());
    for (std::size_t p = 0; p < pixels; ++p) {
        for (std::size_t b = 0; b < file.bands.size(); ++b) {
            out[p * file.bands.size() + b] = values[p * all + file.bands[b]];
        }
    }
    return out;
}

}  // namespace glint::sensor
