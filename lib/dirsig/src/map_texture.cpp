// SPDX-License-Identifier: Apache-2.0
// A `<texturemap>` (map_parts.h; docs/maps.md): DIRSIG's statistical texture. Each band's
// image gives, per texel, the scene's relative brightness in a spectral window; a texel's
// z-score (its value less the image's mean, over the image's standard deviation) is matched
// against each texture class's z-score (the class's mean reflectance in the window, less the
// classes' mean, over their standard deviation), and the class nearest over all bands (least
// squares; the first on a tie) is the surface there. A texture class is a curve of the
// material's multi-curve `.ems`: class 0 is the material itself, each further curve a variant
// material appended to the scene (its truth reported as the material's).
#include <cmath>
#include <string>
#include <utility>

#include "glint/core/text.h"
#include "map_parts.h"

namespace glint::dirsig::detail {
namespace {

/// Samples of a band's window in its mean reflectance (midpoints).
constexpr int kWindowSamples = 200;

/// The variant of `parent` whose curve is `curve` (of its texture_curves).
model::Material texture_variant(const model::Material& parent, std::size_t k) {
    model::Material m = parent;
    m.id = parent.id + "#" + std::to_string(k);
    m.name = parent.name + " (texture class " + std::to_string(k) + ")";
    m.texture_curves.clear();
    const model::SpectralTable& curve = parent.texture_curves[k];
    if (parent.texture_curves_are_emissivity) {
        // The class's emissivity; an opaque surface's reflectance follows it (1 − ε − τ).
        m.emissivity = curve;
        m.emissivity_is_default = false;
        m.reflectance.wavelengths_um = curve.wavelengths_um;
        m.reflectance.values.clear();
        for (std::size_t i = 0; i < curve.values.size(); ++i) {
            const double tau = m.transmittance.empty()
                                   ? 0.0
                                   : model::sample_held(m.transmittance, curve.wavelengths_um[i]);
            m.reflectance.values.push_back(std::max(0.0, 1.0 - curve.values[i] - tau));
        }
        m.reflectance.where = curve.where;
    } else {
        m.reflectance = curve;
        if (m.emissivity_is_default) m.emissivity = model::kirchhoff_emissivity(m);
    }
    return m;
}

double window_mean(const model::SpectralTable& reflectance, double min_um, double max_um) {
    double sum = 0.0;
    for (int i = 0; i < kWindowSamples; ++i) {
        const double w = min_um + (max_um - min_um) * (i + 0.5) / kWindowSamples;
        sum += model::sample_held(reflectance, w);
    }
    return sum / kWindowSamples;
}

/// Standardises `values` in place (mean 0, standard deviation 1; all 0 when they are equal).
void standardise(std::vector<double>& values) {
    double mean = 0.0;
    for (const double v : values) mean += v;
    mean /= static_cast<double>(values.size());
    double variance = 0.0;
    for (const double v : values) variance += (v - mean) * (v - mean);
    const double sd = std::sqrt(variance / static_cast<double>(values.size()));
    for (double& v : values) v = sd > 0.0 ? (v - mean) / sd : 0.0;
}

}  // namespace

bool read_texture_bands(const io::XmlNode& map_node, const std::filesystem::path& map_dir,
                        const ReadOptions& options, model::PropertyMap& map,
                        Diagnostics& diagnostics) {
    const auto list = map_node.child("bandlist");
    if (!list) {
        diagnostics.error(map_node.where(), "missing required element <bandlist>");
        return false;
    }
    list->warn_unknown_children({"band"}, diagnostics);
    bool ok = true;
    for (const io::XmlNode& band : list->children("band")) {
        band.warn_unknown_children({"bandpass", "image"}, diagnostics);
        model::TextureBand out;
        const auto pass = band.child("bandpass");
        if (!pass) {
            diagnostics.error(band.where(), "missing required element <bandpass>");
            ok = false;
            continue;
        }
        pass->warn_unknown_children({"min", "max"}, diagnostics);
        const auto lo = pass->required_double("min", diagnostics, io::NumberRule::positive());
        const auto hi = pass->required_double("max", diagnostics, io::NumberRule::positive());
        if (lo && hi && !(*hi > *lo)) {
            diagnostics.error(pass->where(), "<bandpass> max " + format_shortest(*hi) +
                                                 " um is not above min " + format_shortest(*lo) +
                                                 " um");
        }
        const bool image = read_image_element(band, map_dir, options, map, out.image, diagnostics);
        if (!lo || !hi || !(*hi > *lo) || !image) {
            ok = false;
            continue;
        }
        out.min_um = *lo;
        out.max_um = *hi;
        map.bands.push_back(std::move(out));
    }
    if (ok && map.bands.empty()) {
        diagnostics.error(list->where(), "<bandlist> has no <band>");
        return false;
    }
    return ok;
}

bool make_texture(model::PropertyMap& map, model::Scene& scene, Diagnostics& diagnostics) {
    const std::size_t bands = map.bands.size();
    // The texels' z-scores, band by band, into one raster.
    auto raster = std::make_shared<model::MapRaster>();
    raster->bands = bands;
    for (std::size_t b = 0; b < bands; ++b) {
        const model::TextureBand& band = map.bands[b];
        std::optional<MapBrightness> image = read_brightness(map, band.image, diagnostics);
        if (!image) return false;
        if (b == 0) {
            raster->width = image->width;
            raster->height = image->height;
            raster->weights.resize(raster->width * raster->height * bands);
        } else if (image->width != raster->width || image->height != raster->height) {
            diagnostics.error(map.where, map_label_text(map) + ": band image " +
                                             quote(band.image.text) + " is " +
                                             std::to_string(image->width) + " x " +
                                             std::to_string(image->height) + ", the first band's " +
                                             std::to_string(raster->width) + " x " +
                                             std::to_string(raster->height));
            return false;
        }
        double mean = 0.0;
        for (const float v : image->values) mean += v;
        mean /= static_cast<double>(image->values.size());
        double variance = 0.0;
        for (const float v : image->values) variance += (v - mean) * (v - mean);
        const double sd = std::sqrt(variance / static_cast<double>(image->values.size()));
        for (std::size_t t = 0; t < image->values.size(); ++t) {
            raster->weights[t * bands + b] =
                sd > 0.0 ? static_cast<float>((image->values[t] - mean) / sd) : 0.0f;
        }
    }
    map.raster = raster;
    // Each covered material's classes: itself and its variants (made once per material).
    for (const std::uint32_t m : map.applies_to) {
        model::TextureClasses classes;
        classes.materials.push_back(m);
        const std::size_t curves = scene.materials[m].texture_curves.size();
        if (curves < 2) {
            diagnostics.warning(map.where, map_label_text(map) + ": material " +
                                               quote(scene.materials[m].id) +
                                               " has one curve (no texture classes: a classic "
                                               ".ems with several curves); the map leaves it as "
                                               "it is");
        }
        for (std::size_t k = 1; k < curves; ++k) {
            const std::string id = scene.materials[m].id + "#" + std::to_string(k);
            std::uint32_t found = 0;
            while (found < scene.materials.size() && scene.materials[found].id != id) ++found;
            if (found == scene.materials.size()) {
                model::Material variant = texture_variant(scene.materials[m], k);
                variant.texture_parent = m;
                scene.materials.push_back(std::move(variant));
            }
            classes.materials.push_back(found);
        }
        // Each class's mean reflectance per band, standardised over the classes.
        classes.z.assign(classes.materials.size() * bands, 0.0f);
        for (std::size_t b = 0; b < bands; ++b) {
            std::vector<double> means;
            for (const std::uint32_t c : classes.materials) {
                means.push_back(window_mean(scene.materials[c].reflectance, map.bands[b].min_um,
                                            map.bands[b].max_um));
            }
            standardise(means);
            for (std::size_t k = 0; k < means.size(); ++k) {
                classes.z[k * bands + b] = static_cast<float>(means[k]);
            }
        }
        map.texture_classes.push_back(std::move(classes));
    }
    return true;
}

}  // namespace glint::dirsig::detail
