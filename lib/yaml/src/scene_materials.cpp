// SPDX-License-Identifier: Apache-2.0
// The glint YAML scene's materials: reflectance, transmittance and emissivity spectra (inline or
// from a two-column file in µm or nm), the specular lobe, the temperature and THERM's slab.
#include <algorithm>
#include <limits>
#include <optional>

#include "glint/core/text.h"
#include "scene_parts.h"

namespace glint::yaml::yaml_scene {
namespace {

// ---- spectra --------------------------------------------------------------------------------

/// The scale from `units` ("um" or "nm") to µm; nullopt for anything else.
std::optional<double> unit_scale(const std::string& units) {
    const std::string u = to_lower(units);
    if (u == "um" || u == "micrometers" || u == "microns") return 1.0;
    if (u == "nm" || u == "nanometers") return 1e-3;
    return std::nullopt;
}

/// Reads a two-column file: wavelength and value per line, blanks or commas between, `#`
/// comments; a comment `# units: nm` (or `um`) gives the wavelength unit.
void read_table_file(model::SpectralTable& table, std::optional<double> yaml_scale,
                     const std::string& key_path, Diagnostics& diagnostics) {
    const std::string name = table.file.resolved.string();
    std::string text;
    try {
        text = io::read_input_file(table.file.resolved, name);
    } catch (const Error& error) {
        diagnostics.add(error.with_file(table.where.file, table.where.line));
        return;
    }
    std::optional<double> header_scale;
    std::istringstream lines(text);
    std::string line;
    int number = 0;
    while (std::getline(lines, line)) {
        ++number;
        const std::size_t hash = line.find('#');
        if (hash != std::string::npos) {
            std::string comment = to_lower(line.substr(hash + 1));
            for (char& c : comment) {
                if (c == ':' || c == '=') c = ' ';
            }
            std::istringstream words(comment);
            std::string word;
            std::string unit;
            if (words >> word && word == "units" && words >> unit) {
                header_scale = unit_scale(unit);
                if (!header_scale) {
                    diagnostics.error({name, number, key_path}, "unknown wavelength units \"" +
                                                                    unit + "\", expected um or nm");
                }
            }
            line.resize(hash);
        }
        for (char& c : line) {
            if (c == ',' || c == '\t' || c == ';' || c == '\r') c = ' ';
        }
        std::istringstream fields(line);
        std::string a;
        std::string b;
        if (!(fields >> a)) continue;
        if (!(fields >> b)) {
            diagnostics.error({name, number, key_path}, "expected two columns (wavelength value)");
            continue;
        }
        const auto w = parse_double(a);
        const auto v = parse_double(b);
        if (!w || !v) {
            diagnostics.error({name, number, key_path},
                              "expected two numbers, got \"" + a + "\" and \"" + b + "\"");
            continue;
        }
        table.wavelengths_um.push_back(*w);
        table.values.push_back(*v);
    }
    if (yaml_scale && header_scale && *yaml_scale != *header_scale) {
        diagnostics.warning(table.where,
                            "units given in the scene differ from the file's "
                            "header; the scene's are used");
    }
    const double scale = yaml_scale.value_or(header_scale.value_or(1.0));
    for (double& w : table.wavelengths_um) w *= scale;
}

/// The samples of a spectrum key, checked; may be left partial (even with unequal lengths)
/// when an error was reported.
model::SpectralTable read_spectrum_samples(Reader& r, const YAML::Node& node,
                                           const std::string& path, const std::string& quantity) {
    model::SpectralTable table;
    table.where = r.where(node, path);
    if (!r.expect_map(node, path)) return table;
    r.warn_unknown(node, path, {"wavelengths", "values", "units", "file"});
    std::optional<double> scale;
    if (const auto units = r.text_key(node, path, "units", false)) {
        scale = unit_scale(*units);
        if (!scale) {
            r.error(node["units"], Reader::join(path, "units"),
                    "unknown wavelength units \"" + *units + "\", expected um or nm");
            return table;
        }
    }
    const std::size_t errors = r.diagnostics.error_count();
    if (node["file"]) {
        if (node["wavelengths"] || node["values"]) {
            r.error(node, path, "give either file or wavelengths and values, not both");
            return table;
        }
        const auto text = r.text_key(node, path, "file", true);
        if (!text) return table;
        table.file = r.options.paths.resolve(
            *text, r.base_dir, r.where(node["file"], Reader::join(path, "file")), r.diagnostics);
        if (table.file.resolved.empty()) return table;
        read_table_file(table, scale, path, r.diagnostics);
    } else {
        if (!node["wavelengths"] || !node["values"]) {
            r.error(node, path,
                    std::string("missing required key \"") +
                        (node["wavelengths"] ? "values" : "wavelengths") + "\" (or give \"file\")");
            return table;
        }
        table.wavelengths_um = r.numbers(node["wavelengths"], Reader::join(path, "wavelengths"));
        table.values = r.numbers(node["values"], Reader::join(path, "values"));
        for (double& w : table.wavelengths_um) w *= scale.value_or(1.0);
        if (table.wavelengths_um.size() != table.values.size()) {
            r.error(node, path,
                    std::to_string(table.wavelengths_um.size()) + " wavelengths but " +
                        std::to_string(table.values.size()) + " values");
            return table;
        }
    }
    if (r.diagnostics.error_count() != errors) return table;
    // Inline values are reported at their own key; file values at the spectrum key.
    const bool inline_values = table.file.empty();
    if (table.empty()) r.error(node, path, "spectrum has no samples");
    for (std::size_t i = 0; i < table.values.size(); ++i) {
        const std::string index = "[" + std::to_string(i) + "]";
        const double w = table.wavelengths_um[i];
        if (!(w > 0.0) || (i > 0 && !(w > table.wavelengths_um[i - 1]))) {
            r.diagnostics.error(
                inline_values
                    ? r.where(node["wavelengths"][i], Reader::join(path, "wavelengths") + index)
                    : table.where,
                "wavelength " + format_shortest(w) + " um is not positive and strictly increasing" +
                    (inline_values ? "" : " (row " + std::to_string(i + 1) + " of the file)"));
        }
        const double v = table.values[i];
        if (!(v >= 0.0 && v <= 1.0)) {
            r.diagnostics.error(
                inline_values ? r.where(node["values"][i], Reader::join(path, "values") + index)
                              : table.where,
                quantity + " " + format_shortest(v) + " is outside [0, 1]" +
                    (inline_values ? "" : " (row " + std::to_string(i + 1) + " of the file)"));
        }
    }
    return table;
}

/// Reads a spectrum key (`reflectance`, `transmittance`, `emissivity`): inline lists or a file;
/// checks wavelengths (positive, strictly increasing) and values (in [0, 1]). A spectrum with
/// an error comes back without samples, so that nothing downstream (Kirchhoff's default
/// emissivity) reads a half-read table.
model::SpectralTable read_spectrum(Reader& r, const YAML::Node& node, const std::string& path,
                                   const std::string& quantity) {
    const std::size_t errors = r.diagnostics.error_count();
    model::SpectralTable table = read_spectrum_samples(r, node, path, quantity);
    if (r.diagnostics.error_count() != errors) {
        table.wavelengths_um.clear();
        table.values.clear();
    }
    return table;
}

}  // namespace

// ---- materials ------------------------------------------------------------------------------

namespace {

/// `ward: {diffuse, specular, alpha_x, alpha_y}` or `ross_li: {volumetric, geometric}`
/// (docs/materials.md); Ward's reflectance becomes the constant diffuse + specular.
void read_reflection_model(Reader& r, const YAML::Node& node, const std::string& path,
                           model::Material& m) {
    const YAML::Node ward = node["ward"];
    const YAML::Node ross_li = node["ross_li"];
    if (ward && ross_li) {
        r.error(ross_li, Reader::join(path, "ross_li"),
                "a material has one reflection model: \"ward\" or \"ross_li\", not both");
        return;
    }
    for (const char* other : {"ward", "ross_li"}) {
        if (node[other] && node["specular"]) {
            r.error(node["specular"], Reader::join(path, "specular"),
                    std::string("\"specular\" is the Lambertian model's lobe; a \"") + other +
                        "\" material has its own");
        }
    }
    if (ward) {
        const std::string wp = Reader::join(path, "ward");
        if (!r.expect_map(ward, wp)) return;
        r.warn_unknown(ward, wp, {"diffuse", "specular", "alpha_x", "alpha_y"});
        m.model = model::ReflectionModel::ward;
        m.ward.diffuse = r.number_key(ward, wp, "diffuse", true).value_or(0.0);
        m.ward.specular = r.number_key(ward, wp, "specular", true).value_or(0.0);
        m.ward.alpha_x = r.number_key(ward, wp, "alpha_x", true).value_or(0.0);
        m.ward.alpha_y = r.number_key(ward, wp, "alpha_y", false).value_or(m.ward.alpha_x);
        m.reflectance.wavelengths_um = {0.01, 1000.0};
        m.reflectance.values = {m.ward.diffuse + m.ward.specular, m.ward.diffuse + m.ward.specular};
        m.reflectance.where = r.where(ward, wp);
    }
    if (ross_li) {
        const std::string rp = Reader::join(path, "ross_li");
        if (!r.expect_map(ross_li, rp)) return;
        r.warn_unknown(ross_li, rp, {"volumetric", "geometric"});
        m.model = model::ReflectionModel::ross_li;
        m.ross_li.volumetric = r.number_key(ross_li, rp, "volumetric", true).value_or(0.0);
        m.ross_li.geometric = r.number_key(ross_li, rp, "geometric", true).value_or(0.0);
    }
}

/// `therm: {...}`: THERM's slab and surface in SI units (docs/thermal.md), the YAML form of a
/// DIRSIG `.mat`'s TEMP_SOLVER_NAME = Therm block.
std::optional<model::ThermProperties> read_therm(Reader& r, const YAML::Node& node,
                                                 const std::string& path) {
    if (!r.expect_map(node, path)) return std::nullopt;
    r.warn_unknown(node, path,
                   {"specific_heat_j_per_kg_k", "density_kg_per_m3", "conductivity_w_per_m_k",
                    "thickness_m", "exposed_area", "solar_absorptance", "thermal_emissivity"});
    model::ThermProperties t;
    t.where = r.where(node, path);
    bool ok = true;
    // Each key: required or not, its lower bound (strict or not) and its upper bound.
    struct Key {
        const char* name;
        bool required;
        bool positive;  // > 0; otherwise >= 0
        double upper;
    };
    const auto read = [&](const Key& key) -> std::optional<double> {
        const auto value = r.number_key(node, path, key.name, key.required);
        if (!value) {
            ok = ok && !(key.required || node[key.name]);
            return std::nullopt;
        }
        const bool low = key.positive ? *value <= 0.0 : *value < 0.0;
        if (low || *value > key.upper) {
            const bool unit = key.upper == 1.0;
            r.error(node[key.name], Reader::join(path, key.name),
                    std::string(key.name) + " " + format_shortest(*value) + " is " +
                        (unit           ? "outside [0, 1]"
                         : key.positive ? "not > 0"
                                        : "negative"));
            ok = false;
            return std::nullopt;
        }
        return value;
    };
    constexpr double kAny = std::numeric_limits<double>::infinity();
    t.specific_heat_j_per_kg_k = read({"specific_heat_j_per_kg_k", true, true, kAny}).value_or(0.0);
    t.density_kg_per_m3 = read({"density_kg_per_m3", true, true, kAny}).value_or(0.0);
    t.conductivity_w_per_m_k = read({"conductivity_w_per_m_k", true, false, kAny}).value_or(0.0);
    t.thickness_m = read({"thickness_m", true, false, kAny}).value_or(0.0);
    t.exposed_area = read({"exposed_area", false, false, 1.0}).value_or(1.0);
    t.solar_absorptance = read({"solar_absorptance", false, false, 1.0});
    t.thermal_emissivity = read({"thermal_emissivity", false, false, 1.0});
    if (!ok) return std::nullopt;
    return t;
}

}  // namespace

model::Material read_material(Reader& r, const YAML::Node& node, const std::string& path) {
    model::Material m;
    m.where = r.where(node, path);
    if (!r.expect_map(node, path)) return m;
    r.warn_unknown(node, path,
                   {"id", "name", "reflectance", "transmittance", "transmission", "specular",
                    "ward", "ross_li", "emissivity", "temperature", "double_sided", "therm"});
    m.id = r.text_key(node, path, "id", true).value_or("");
    m.name = r.text_key(node, path, "name", false).value_or(m.id);
    read_reflection_model(r, node, path, m);
    if (node["reflectance"]) {
        if (m.model == model::ReflectionModel::ward) {
            r.error(node["reflectance"], Reader::join(path, "reflectance"),
                    "a Ward material's reflectance is its diffuse + specular weights; remove "
                    "\"reflectance\"");
        } else {
            m.reflectance = read_spectrum(r, node["reflectance"], Reader::join(path, "reflectance"),
                                          "reflectance");
        }
    } else if (m.model != model::ReflectionModel::ward) {
        r.error(node, path, "missing required key \"reflectance\"");
    }
    if (const YAML::Node specular = node["specular"]) {
        const std::string sp = Reader::join(path, "specular");
        if (r.expect_map(specular, sp)) {
            r.warn_unknown(specular, sp, {"fraction", "roughness"});
            for (const auto& [key, field] : {std::pair{"fraction", &m.specular.fraction},
                                             std::pair{"roughness", &m.specular.roughness}}) {
                if (const auto value = r.number_key(specular, sp, key, false)) {
                    if (*value < 0.0 || *value > 1.0) {
                        r.error(specular[key], Reader::join(sp, key),
                                std::string("specular ") + key + " " + format_shortest(*value) +
                                    " is outside [0, 1]");
                    } else {
                        *field = *value;
                    }
                }
            }
        }
    }
    if (node["transmittance"]) {
        // A thin two-sided sheet (a leaf): diffuse transmittance, the same from either side.
        m.transmittance = read_spectrum(r, node["transmittance"],
                                        Reader::join(path, "transmittance"), "transmittance");
    }
    if (const auto kind = r.text_key(node, path, "transmission", false)) {
        // `diffuse` (a leaf, the default) or `straight` (a clear pane).
        if (*kind == "straight") {
            m.straight_transmission = true;
        } else if (*kind != "diffuse") {
            r.error(node["transmission"], Reader::join(path, "transmission"),
                    "transmission \"" + *kind + "\" is neither diffuse nor straight");
        }
        if (m.transmittance.empty()) {
            r.error(node["transmission"], Reader::join(path, "transmission"),
                    "\"transmission\" needs a \"transmittance\"");
        }
    }
    if (node["emissivity"]) {
        m.emissivity =
            read_spectrum(r, node["emissivity"], Reader::join(path, "emissivity"), "emissivity");
        m.emissivity_is_default = false;
    } else if (!m.reflectance.empty()) {
        // Kirchhoff: ε = 1 − ρ (− τ for a sheet) at every wavelength of the curves.
        m.emissivity = model::kirchhoff_emissivity(m);
    }
    if (const auto sides = r.bool_key(node, path, "double_sided")) m.double_sided = *sides;
    if (const auto t = r.number_key(node, path, "temperature", false)) {
        if (*t > 0.0) {
            m.temperature_k = *t;
        } else {
            r.error(node["temperature"], Reader::join(path, "temperature"),
                    "temperature " + format_shortest(*t) + " K is not > 0");
        }
    }
    if (const YAML::Node therm = node["therm"]) {
        m.therm = read_therm(r, therm, Reader::join(path, "therm"));
    }
    return m;
}

}  // namespace glint::yaml::yaml_scene
