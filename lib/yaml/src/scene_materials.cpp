#include "glint/core/text.h"
// SPDX-License-Identifier: Apache-2.0
#include "glint/core/text.h"
// The glint YAML scene's materials: reflectance and emissivity spectra (inline or from a
#include "glint/core/text.h"
// two-column file in µm or nm), the specular lobe and the temperature.
#include "glint/core/text.h"
#include "scene_parts.h"
namespace glint::yaml::yaml_scene {
#include "glint/core/text.h"
namespace {
#include "glint/core/text.h"
// ---- spectra --------------------------------------------------------------------------------
#include "glint/core/text.h"
/// The scale from `units` ("um" or "nm") to µm; nullopt for anything else.
#include "glint/core/text.h"
std::optional<double> unit_scale(const std::string& units) {
#include "glint/core/text.h"
    const std::string u = to_lower(units);
#include "glint/core/text.h"
    if (u == "um" || u == "micrometers" || u == "microns") return 1.0;
#include "glint/core/text.h"
    if (u == "nm" || u == "nanometers") return 1e-3;
#include "glint/core/text.h"
    return std::nullopt;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
/// Reads a two-column file: wavelength and value per line, blanks or commas between, `#`
#include "glint/core/text.h"
/// comments; a comment `# units: nm` (or `um`) gives the wavelength unit.
#include "glint/core/text.h"
void read_table_file(model::SpectralTable& table, std::optional<double> yaml_scale,
#include "glint/core/text.h"
                     const std::string& key_path, Diagnostics& diagnostics) {
#include "glint/core/text.h"
    const std::string name = table.file.resolved.string();
#include "glint/core/text.h"
    std::string text;
#include "glint/core/text.h"
    try {
#include "glint/core/text.h"
        text = io::read_input_file(table.file.resolved, name);
#include "glint/core/text.h"
    } catch (const Error& error) {
#include "glint/core/text.h"
        diagnostics.add(error.with_file(table.where.file, table.where.line));
#include "glint/core/text.h"
        return;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    std::optional<double> header_scale;
#include "glint/core/text.h"
    std::istringstream lines(text);
#include "glint/core/text.h"
    std::string line;
#include "glint/core/text.h"
    int number = 0;
#include "glint/core/text.h"
    while (std::getline(lines, line)) {
#include "glint/core/text.h"
        ++number;
#include "glint/core/text.h"
        const std::size_t hash = line.find('#');
#include "glint/core/text.h"
        if (hash != std::string::npos) {
#include "glint/core/text.h"
            std::string comment = to_lower(line.substr(hash + 1));
#include "glint/core/text.h"
            for (char& c : comment) {
#include "glint/core/text.h"
                if (c == ':' || c == '=') c = ' ';
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
            std::istringstream words(comment);
#include "glint/core/text.h"
            std::string word;
#include "glint/core/text.h"
            std::string unit;
#include "glint/core/text.h"
            if (words >> word && word == "units" && words >> unit) {
#include "glint/core/text.h"
                header_scale = unit_scale(unit);
#include "glint/core/text.h"
                if (!header_scale) {
#include "glint/core/text.h"
                    diagnostics.error({name, number, key_path}, "unknown wavelength units \"" +
#include "glint/core/text.h"
                                                                    unit + "\", expected um or nm");
#include "glint/core/text.h"
                }
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
            line.resize(hash);
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
        for (char& c : line) {
#include "glint/core/text.h"
            if (c == ',' || c == '\t' || c == ';' || c == '\r') c = ' ';
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
        std::istringstream fields(line);
#include "glint/core/text.h"
        std::string a;
#include "glint/core/text.h"
        std::string b;
#include "glint/core/text.h"
        if (!(fields >> a)) continue;
#include "glint/core/text.h"
        if (!(fields >> b)) {
#include "glint/core/text.h"
            diagnostics.error({name, number, key_path}, "expected two columns (wavelength value)");
#include "glint/core/text.h"
            continue;
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
        const auto w = parse_double(a);
#include "glint/core/text.h"
        const auto v = parse_double(b);
#include "glint/core/text.h"
        if (!w || !v) {
#include "glint/core/text.h"
            diagnostics.error({name, number, key_path},
#include "glint/core/text.h"
                              "expected two numbers, got \"" + a + "\" and \"" + b + "\"");
#include "glint/core/text.h"
            continue;
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
        table.wavelengths_um.push_back(*w);
#include "glint/core/text.h"
        table.values.push_back(*v);
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (yaml_scale && header_scale && *yaml_scale != *header_scale) {
#include "glint/core/text.h"
        diagnostics.warning(table.where,
#include "glint/core/text.h"
                            "units given in the scene differ from the file's "
#include "glint/core/text.h"
                            "header; the scene's are used");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    const double scale = yaml_scale.value_or(header_scale.value_or(1.0));
#include "glint/core/text.h"
    for (double& w : table.wavelengths_um) w *= scale;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
/// Reads a spectrum key (`reflectance`, `emissivity`): inline lists or a file; checks
#include "glint/core/text.h"
/// wavelengths (positive, strictly increasing) and values (in [0, 1]).
#include "glint/core/text.h"
model::SpectralTable read_spectrum(Reader& r, const YAML::Node& node, const std::string& path,
#include "glint/core/text.h"
                                   const std::string& quantity) {
#include "glint/core/text.h"
    model::SpectralTable table;
#include "glint/core/text.h"
    table.where = r.where(node, path);
#include "glint/core/text.h"
    if (!r.expect_map(node, path)) return table;
#include "glint/core/text.h"
    r.warn_unknown(node, path, {"wavelengths", "values", "units", "file"});
#include "glint/core/text.h"
    std::optional<double> scale;
#include "glint/core/text.h"
    if (const auto units = r.text_key(node, path, "units", false)) {
#include "glint/core/text.h"
        scale = unit_scale(*units);
#include "glint/core/text.h"
        if (!scale) {
#include "glint/core/text.h"
            r.error(node["units"], Reader::join(path, "units"),
#include "glint/core/text.h"
                    "unknown wavelength units \"" + *units + "\", expected um or nm");
#include "glint/core/text.h"
            return table;
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    const std::size_t errors = r.diagnostics.error_count();
#include "glint/core/text.h"
    if (node["file"]) {
#include "glint/core/text.h"
        if (node["wavelengths"] || node["values"]) {
#include "glint/core/text.h"
            r.error(node, path, "give either file or wavelengths and values, not both");
#include "glint/core/text.h"
            return table;
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
        const auto text = r.text_key(node, path, "file", true);
#include "glint/core/text.h"
        if (!text) return table;
#include "glint/core/text.h"
        table.file = r.options.paths.resolve(
#include "glint/core/text.h"
            *text, r.base_dir, r.where(node["file"], Reader::join(path, "file")), r.diagnostics);
#include "glint/core/text.h"
        if (table.file.resolved.empty()) return table;
#include "glint/core/text.h"
        read_table_file(table, scale, path, r.diagnostics);
#include "glint/core/text.h"
    } else {
#include "glint/core/text.h"
        if (!node["wavelengths"] || !node["values"]) {
#include "glint/core/text.h"
            r.error(node, path,
#include "glint/core/text.h"
                    std::string("missing required key \"") +
#include "glint/core/text.h"
                        (node["wavelengths"] ? "values" : "wavelengths") + "\" (or give \"file\")");
#include "glint/core/text.h"
            return table;
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
        table.wavelengths_um = r.numbers(node["wavelengths"], Reader::join(path, "wavelengths"));
#include "glint/core/text.h"
        table.values = r.numbers(node["values"], Reader::join(path, "values"));
#include "glint/core/text.h"
        for (double& w : table.wavelengths_um) w *= scale.value_or(1.0);
#include "glint/core/text.h"
        if (table.wavelengths_um.size() != table.values.size()) {
#include "glint/core/text.h"
            r.error(node, path,
#include "glint/core/text.h"
                    std::to_string(table.wavelengths_um.size()) + " wavelengths but " +
#include "glint/core/text.h"
                        std::to_string(table.values.size()) + " values");
#include "glint/core/text.h"
            return table;
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (r.diagnostics.error_count() != errors) return table;
#include "glint/core/text.h"
        // Inline values are reported at their own key; file values at the spectrum key.
#include "glint/core/text.h"
    const bool inline_values = table.file.empty();
#include "glint/core/text.h"
    if (table.empty()) r.error(node, path, "spectrum has no samples");
#include "glint/core/text.h"
    for (std::size_t i = 0; i < table.values.size(); ++i) {
#include "glint/core/text.h"
        const std::string index = "[" + std::to_string(i) + "]";
#include "glint/core/text.h"
        const double w = table.wavelengths_um[i];
#include "glint/core/text.h"
        if (!(w > 0.0) || (i > 0 && !(w > table.wavelengths_um[i - 1]))) {
#include "glint/core/text.h"
            r.diagnostics.error(
#include "glint/core/text.h"
                inline_values
#include "glint/core/text.h"
                    ? r.where(node["wavelengths"][i], Reader::join(path, "wavelengths") + index)
#include "glint/core/text.h"
                    : table.where,
#include "glint/core/text.h"
                "wavelength " + format_shortest(w) + " um is not positive and strictly increasing" +
#include "glint/core/text.h"
                    (inline_values ? "" : " (row " + std::to_string(i + 1) + " of the file)"));
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
        const double v = table.values[i];
#include "glint/core/text.h"
        if (!(v >= 0.0 && v <= 1.0)) {
#include "glint/core/text.h"
            r.diagnostics.error(
#include "glint/core/text.h"
                inline_values ? r.where(node["values"][i], Reader::join(path, "values") + index)
#include "glint/core/text.h"
                              : table.where,
#include "glint/core/text.h"
                quantity + " " + format_shortest(v) + " is outside [0, 1]" +
#include "glint/core/text.h"
                    (inline_values ? "" : " (row " + std::to_string(i + 1) + " of the file)"));
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    return table;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
}  // namespace
#include "glint/core/text.h"
// ---- materials ------------------------------------------------------------------------------
#include "glint/core/text.h"
model::Material read_material(Reader& r, const YAML::Node& node, const std::string& path) {
#include "glint/core/text.h"
    model::Material m;
#include "glint/core/text.h"
    m.where = r.where(node, path);
#include "glint/core/text.h"
    if (!r.expect_map(node, path)) return m;
#include "glint/core/text.h"
    r.warn_unknown(node, path,
#include "glint/core/text.h"
                   {"id", "name", "reflectance", "specular", "emissivity", "temperature"});
#include "glint/core/text.h"
    m.id = r.text_key(node, path, "id", true).value_or("");
#include "glint/core/text.h"
    m.name = r.text_key(node, path, "name", false).value_or(m.id);
#include "glint/core/text.h"
    if (node["reflectance"]) {
#include "glint/core/text.h"
        m.reflectance =
#include "glint/core/text.h"
            read_spectrum(r, node["reflectance"], Reader::join(path, "reflectance"), "reflectance");
#include "glint/core/text.h"
    } else {
#include "glint/core/text.h"
        r.error(node, path, "missing required key \"reflectance\"");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (const YAML::Node specular = node["specular"]) {
#include "glint/core/text.h"
        const std::string sp = Reader::join(path, "specular");
#include "glint/core/text.h"
        if (r.expect_map(specular, sp)) {
#include "glint/core/text.h"
            r.warn_unknown(specular, sp, {"fraction", "roughness"});
#include "glint/core/text.h"
            for (const auto& [key, field] : {std::pair{"fraction", &m.specular.fraction},
#include "glint/core/text.h"
                                             std::pair{"roughness", &m.specular.roughness}}) {
#include "glint/core/text.h"
                if (const auto value = r.number_key(specular, sp, key, false)) {
#include "glint/core/text.h"
                    if (*value < 0.0 || *value > 1.0) {
#include "glint/core/text.h"
                        r.error(specular[key], Reader::join(sp, key),
#include "glint/core/text.h"
                                std::string("specular ") + key + " " + format_shortest(*value) +
#include "glint/core/text.h"
                                    " is outside [0, 1]");
#include "glint/core/text.h"
                    } else {
#include "glint/core/text.h"
                        *field = *value;
#include "glint/core/text.h"
                    }
#include "glint/core/text.h"
                }
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (node["emissivity"]) {
#include "glint/core/text.h"
        m.emissivity =
#include "glint/core/text.h"
            read_spectrum(r, node["emissivity"], Reader::join(path, "emissivity"), "emissivity");
#include "glint/core/text.h"
        m.emissivity_is_default = false;
#include "glint/core/text.h"
    } else {
#include "glint/core/text.h"
        m.emissivity.wavelengths_um = m.reflectance.wavelengths_um;
#include "glint/core/text.h"
        for (const double rho : m.reflectance.values) m.emissivity.values.push_back(1.0 - rho);
#include "glint/core/text.h"
        m.emissivity.where = m.reflectance.where;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (const auto t = r.number_key(node, path, "temperature", false)) {
#include "glint/core/text.h"
        if (*t > 0.0) {
#include "glint/core/text.h"
            m.temperature_k = *t;
#include "glint/core/text.h"
        } else {
#include "glint/core/text.h"
            r.error(node["temperature"], Reader::join(path, "temperature"),
#include "glint/core/text.h"
                    "temperature " + format_shortest(*t) + " K is not > 0");
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    return m;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
}  // namespace glint::yaml::yaml_scene
