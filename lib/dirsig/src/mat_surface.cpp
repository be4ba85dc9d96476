// SPDX-License-Identifier: Apache-2.0
// The SURFACE_PROPERTIES of a `.mat` MATERIAL_ENTRY (mat_blocks.h): the reflectance models
// SimpleReflectance and WardBRDF, ClassicEmissivity with its SPECULAR_FRACTION (a mirror
// share), SimpleTransmittance (a thin sheet); DIRSIG's other models are refused by name.
// docs/materials.md gives the syntax and glint's reading of each key.
#include <cctype>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/text.h"
#include "mat_blocks.h"
#include "mat_curves.h"

namespace glint::dirsig::detail {
namespace {

/// DIRSIG models glint does not read, with what it offers instead.
struct Refused {
    std::string_view name;  ///< upper case, as compared
    std::string_view why;
};

constexpr Refused kRefusedModels[] = {
    {"ROSSLIBRDF",
     "its .mat parameter keys are not documented publicly; glint's YAML scene format has the "
     "Ross-Li model (ross_li: {volumetric, geometric})"},
    {"PRIESTGERMERBRDF", "its parameter files (.brdf) are not documented publicly"},
    {"SHELLTARGETBRDF", "its fit files (NEF Beard-Maxwell parameters) are not read"},
    {"SHELLBACKGROUNDBRDF", "its fit files (NEF Beard-Maxwell parameters) are not read"},
    {"SPHERICALBRDF", "its measured tables' format is not documented publicly"},
    {"SPHERICALDATABRDF", "its measured tables' format is not documented publicly"},
    {"SPHERICALBTDF", "its measured tables' format is not documented publicly"},
    {"SPHERICALDATABTDF", "its measured tables' format is not documented publicly"},
    {"DELTAREFLECTANCE",
     "its keys are not documented publicly; SPECULAR_FRACTION = 1 in EMISSIVITY_PROP gives a "
     "mirror"},
    {"DELTATRANSMITTANCE",
     "its keys are not documented publicly; glint's YAML scene format has straight-through "
     "transmission (transmission: straight)"},
    {"RGBMAP", "reflectance maps are not read"},
    {"REFLECTANCEMAP", "reflectance maps are not read"},
    {"CURVEMAP", "reflectance maps are not read"},
    {"CLASSICEXTINCTION", "extinction (.ext) slabs are not modelled; give a SimpleTransmittance"},
};

/// The numbers of a list value: "0.7, 0.5" or "0.7 0.5".
std::vector<double> numbers(const std::string& text) {
    std::vector<double> out;
    std::string token;
    const auto flush = [&] {
        if (token.empty()) return;
        const auto v = parse_double(token);
        out.push_back(v ? *v : std::numeric_limits<double>::quiet_NaN());
        token.clear();
    };
    for (const char c : text) {
        if (c == ',' || std::isspace(static_cast<unsigned char>(c))) {
            flush();
        } else {
            token += c;
        }
    }
    flush();
    return out;
}

}  // namespace

void MatReader::read_specular_fraction(const MatEntry& fraction, const std::string& path) {
    const auto value = parse_double(fraction.value);
    if (!value || !(*value >= 0.0 && *value <= 1.0)) {
        diagnostics.error(at(fraction.line, path),
                          "SPECULAR_FRACTION \"" + fraction.value + "\" is not a number in [0, 1]");
        return;
    }
    specular_fraction = *value;
    if (*value > 0.0 && !said_specular_fraction) {
        said_specular_fraction = true;
        diagnostics.warning(at(fraction.line, path),
                            "SPECULAR_FRACTION read as the share of the reflectance in a mirror "
                            "lobe, the rest Lambertian (glint's reading of DIRSIG's specularity; "
                            "docs/materials.md); said once per file");
    }
}

std::optional<model::SpectralTable> MatReader::read_prop(const MatBlock& surface,
                                                         const std::string& path,
                                                         const std::string& prefix,
                                                         const std::string& quantity) {
    const MatBlock* prop = surface.find_block(prefix + "_PROP");
    if (!prop) return std::nullopt;
    const std::string pp = path + "/" + prefix + "_PROP";
    // SPECULAR_FRACTION is a share of the reflectance: not a transmittance's key.
    if (prefix == "TRANSMITTANCE") {
        warn_unknown(*prop, pp, {"TXT_FILENAME", "FILENAME"}, {});
    } else {
        warn_unknown(*prop, pp, {"TXT_FILENAME", "FILENAME", "SPECULAR_FRACTION"}, {});
    }
    if (const MatEntry* fraction = prop->find("SPECULAR_FRACTION");
        fraction && prefix != "TRANSMITTANCE") {
        read_specular_fraction(*fraction, pp + "/SPECULAR_FRACTION");
    }
    const MatEntry* entry = prop->find("TXT_FILENAME");
    if (!entry) entry = prop->find("FILENAME");
    if (!entry || entry->value.empty()) {
        diagnostics.error(at(prop->line, pp), "missing TXT_FILENAME or FILENAME (a curve file)");
        return std::nullopt;
    }
    return read_curve(*entry, pp + "/" + entry->key, quantity);
}

/// Reads `NAME_PROP_NAME`: empty when absent; an error (and false) for a model glint refuses.
bool MatReader::model_name(const MatBlock& surface, const std::string& path,
                           const std::string& slot, std::string& name) {
    const MatEntry* entry = surface.find(slot + "_PROP_NAME");
    name = entry ? to_upper(entry->value) : std::string();
    if (!entry) return true;
    for (const Refused& r : kRefusedModels) {
        if (name == r.name) {
            diagnostics.error(
                at(entry->line, path + "/" + entry->key),
                "surface model \"" + entry->value + "\" is not supported: " + std::string(r.why));
            return false;
        }
    }
    return true;
}

void MatReader::read_ward(const MatBlock& surface, const std::string& path, model::Material& m) {
    const MatBlock* prop = surface.find_block("REFLECTANCE_PROP");
    const std::string pp = path + "/REFLECTANCE_PROP";
    if (!prop) {
        diagnostics.error(at(surface.line, path), "WardBRDF needs a REFLECTANCE_PROP block");
        return;
    }
    warn_unknown(*prop, pp, {"DS_WEIGHTS", "XY_SIGMAS"}, {});
    const MatEntry* weights = prop->find("DS_WEIGHTS");
    const MatEntry* sigmas = prop->find("XY_SIGMAS");
    if (!weights || !sigmas) {
        diagnostics.error(at(prop->line, pp),
                          "WardBRDF needs DS_WEIGHTS (diffuse, specular) and XY_SIGMAS (x, y)");
        return;
    }
    const std::vector<double> ds = numbers(weights->value);
    const std::vector<double> xy = numbers(sigmas->value);
    if (ds.size() != 2 || xy.size() != 2) {
        diagnostics.error(at(ds.size() != 2 ? weights->line : sigmas->line, pp),
                          "DS_WEIGHTS and XY_SIGMAS take two numbers each");
        return;
    }
    if (!said_ward_keys) {
        said_ward_keys = true;
        diagnostics.warning(at(weights->line, pp + "/DS_WEIGHTS"),
                            "WardBRDF read as DS_WEIGHTS = diffuse, specular and XY_SIGMAS = "
                            "sigma_x, sigma_y of Ward's 1992 model (glint's reading of DIRSIG's "
                            "keys; docs/materials.md); said once per file");
    }
    m.model = model::ReflectionModel::ward;
    m.ward = {ds[0], ds[1], xy[0], xy[1]};
    m.reflectance.wavelengths_um = {0.01, 1000.0};
    m.reflectance.values = {ds[0] + ds[1], ds[0] + ds[1]};
    m.reflectance.where = at(weights->line, pp + "/DS_WEIGHTS");
}

void MatReader::read_surface(const MatBlock& surface, const std::string& sp, model::Material& m) {
    warn_unknown(surface, sp,
                 {"REFLECTANCE_PROP_NAME", "EMISSIVITY_PROP_NAME", "TRANSMITTANCE_PROP_NAME",
                  "EXTINCTION_PROP_NAME"},
                 {"REFLECTANCE_PROP", "EMISSIVITY_PROP", "TRANSMITTANCE_PROP", "EXTINCTION_PROP"});
    std::string reflectance_model;
    std::string emissivity_model;
    std::string transmittance_model;
    std::string extinction_model;
    if (!model_name(surface, sp, "REFLECTANCE", reflectance_model) ||
        !model_name(surface, sp, "EMISSIVITY", emissivity_model) ||
        !model_name(surface, sp, "TRANSMITTANCE", transmittance_model) ||
        !model_name(surface, sp, "EXTINCTION", extinction_model)) {
        return;
    }
    if (const MatBlock* extinction = surface.find_block("EXTINCTION_PROP")) {
        diagnostics.error(at(extinction->line, sp + "/EXTINCTION_PROP"),
                          "EXTINCTION_PROP is not supported: extinction (.ext) slabs are not "
                          "modelled; give a SimpleTransmittance");
        return;
    }
    if (const MatEntry* extinction = surface.find("EXTINCTION_PROP_NAME")) {
        diagnostics.error(at(extinction->line, sp + "/EXTINCTION_PROP_NAME"),
                          "extinction model \"" + extinction->value +
                              "\" is not supported: extinction slabs are not modelled; give a "
                              "SimpleTransmittance");
        return;
    }
    // A simple model named without its block describes nothing: said once, at the name
    // (WardBRDF and unknown names without a block are errors below).
    for (const auto& [slot, simple] : {std::pair{"REFLECTANCE", "SIMPLEREFLECTANCE"},
                                       std::pair{"EMISSIVITY", "CLASSICEMISSIVITY"},
                                       std::pair{"TRANSMITTANCE", "SIMPLETRANSMITTANCE"}}) {
        const MatEntry* entry = surface.find(std::string(slot) + "_PROP_NAME");
        if (entry && to_upper(entry->value) == simple &&
            !surface.find_block(std::string(slot) + "_PROP")) {
            diagnostics.warning(
                at(entry->line, sp + "/" + entry->key),
                entry->key + " \"" + entry->value + "\" has no " + slot + "_PROP block: ignored");
        }
    }
    // A model name glint does not know: its curve file read as the simple model's, with a
    // warning; without a curve file, an error.
    for (const auto& [slot, name, expected] :
         {std::tuple{"REFLECTANCE", reflectance_model, "SIMPLEREFLECTANCE"},
          std::tuple{"EMISSIVITY", emissivity_model, "CLASSICEMISSIVITY"},
          std::tuple{"TRANSMITTANCE", transmittance_model, "SIMPLETRANSMITTANCE"}}) {
        if (name.empty() || name == expected ||
            (name == "WARDBRDF" && slot == std::string("REFLECTANCE"))) {
            continue;
        }
        const MatEntry* entry = surface.find(std::string(slot) + "_PROP_NAME");
        const MatBlock* prop = surface.find_block(std::string(slot) + "_PROP");
        const bool has_curve = prop && (prop->find("TXT_FILENAME") || prop->find("FILENAME"));
        const std::string simple = slot == std::string("REFLECTANCE")  ? "SimpleReflectance"
                                   : slot == std::string("EMISSIVITY") ? "ClassicEmissivity"
                                                                       : "SimpleTransmittance";
        if (!has_curve) {
            diagnostics.error(at(entry->line, sp + "/" + entry->key),
                              "unknown " + std::string(slot) + " model \"" + entry->value +
                                  "\" (and no curve file to read as " + simple + ")");
            return;
        }
        diagnostics.warning(at(entry->line, sp + "/" + entry->key),
                            "unknown " + std::string(slot) + " model \"" + entry->value +
                                "\": its curve file is read as " + simple + "'s");
    }
    const bool ward = reflectance_model == "WARDBRDF";
    const bool has_reflectance = surface.find_block("REFLECTANCE_PROP") != nullptr;
    const bool has_emissivity = surface.find_block("EMISSIVITY_PROP") != nullptr;
    if (!has_reflectance && !has_emissivity) {
        diagnostics.error(at(surface.line, sp), "missing REFLECTANCE_PROP and EMISSIVITY_PROP");
        return;
    }
    specular_fraction = 0.0;
    if (ward) {
        read_ward(surface, sp, m);
    } else if (auto r = read_prop(surface, sp, "REFLECTANCE", "reflectance")) {
        m.reflectance = std::move(*r);
        if (!last_classes.empty()) {
            m.texture_curves = std::move(last_classes);
            m.texture_curves_are_emissivity = false;
        }
    }
    if (auto e = read_prop(surface, sp, "EMISSIVITY", "emissivity")) {
        m.emissivity = std::move(*e);
        m.emissivity_is_default = false;
        if (!last_classes.empty() && m.texture_curves.empty()) {
            m.texture_curves = std::move(last_classes);
            m.texture_curves_are_emissivity = true;
        }
    }
    if (specular_fraction > 0.0) {
        if (ward) {
            diagnostics.error(m.where, "material \"" + m.name +
                                           "\": SPECULAR_FRACTION with a WardBRDF (whose "
                                           "DS_WEIGHTS give its specular part)");
        }
        m.specular = {specular_fraction, 0.0};
    }
    if (const MatBlock* t = surface.find_block("TRANSMITTANCE_PROP")) {
        if (!said_transmittance_keys) {
            said_transmittance_keys = true;
            diagnostics.warning(at(t->line, sp + "/TRANSMITTANCE_PROP"),
                                "TRANSMITTANCE_PROP read as SimpleTransmittance: a diffuse "
                                "transmittance curve (TXT_FILENAME) of a thin two-sided sheet "
                                "(glint's reading; docs/materials.md); said once per file");
        }
        if (auto tau = read_prop(surface, sp, "TRANSMITTANCE", "transmittance")) {
            m.transmittance = std::move(*tau);
        }
    }
    if (!has_reflectance && !ward) {
        // DIRSIG's opaque surface: an emissivity alone gives reflectance 1 − ε (− τ).
        m.reflectance.wavelengths_um = m.emissivity.wavelengths_um;
        for (const double e : m.emissivity.values) {
            const double w = m.reflectance.wavelengths_um[m.reflectance.values.size()];
            const double tau =
                m.transmittance.empty() ? 0.0 : model::sample_held(m.transmittance, w);
            m.reflectance.values.push_back(std::max(0.0, 1.0 - e - tau));
        }
        m.reflectance.where = m.emissivity.where;
        m.reflectance_from_emissivity = true;
    } else if (!has_emissivity) {
        m.emissivity = model::kirchhoff_emissivity(m);
    } else if (!m.reflectance.empty() && !m.emissivity.empty()) {
        limit_reflectance(m, diagnostics);
    }
}

}  // namespace glint::dirsig::detail
