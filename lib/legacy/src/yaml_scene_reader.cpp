// SPDX-License-Identifier: Apache-2.0
// Reader of the glint YAML scene (docs/scene.md): origin, materials (inline or two-column
// file spectra), geometry objects (OBJ or primitive) and their static or dynamic instances.
// yaml-cpp parses the text; every problem is reported with the YAML file line and the key
// path (e.g. "materials[1].reflectance.values[2]") and the reader carries on.
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include "glint/core/text.h"
#include "glint/io/xml.h"
#include "glint/legacy/motion_reader.h"
#include "glint/legacy/scene_reader.h"

namespace glint::legacy {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

/// `text` in lower case (ASCII).
std::string to_lower(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

/// Everything the key readers share.
struct Reader {
    std::string file;  ///< display name of the YAML file
    std::filesystem::path base_dir;
    ReadOptions options;
    Diagnostics& diagnostics;

    ErrorContext where(const YAML::Node& node, const std::string& path) const {
        return {file, node.Mark().line >= 0 ? node.Mark().line + 1 : 0, path};
    }
    void error(const YAML::Node& node, const std::string& path, const std::string& message) {
        diagnostics.error(where(node, path), message);
    }

    /// True when `node` is a mapping; otherwise an error.
    bool expect_map(const YAML::Node& node, const std::string& path) {
        if (node.IsMap()) return true;
        error(node, path, "expected a mapping");
        return false;
    }
    /// Warns about each key of `node` not in `known`.
    void warn_unknown(const YAML::Node& node, const std::string& path,
                      std::initializer_list<std::string_view> known) {
        for (const auto& entry : node) {
            const std::string key = entry.first.Scalar();
            bool found = false;
            for (const std::string_view k : known) found = found || k == key;
            if (!found) {
                diagnostics.warning(where(entry.first, join(path, key)),
                                    "unknown key \"" + key + "\" (ignored)");
            }
        }
    }
    static std::string join(const std::string& path, const std::string& key) {
        return path.empty() ? key : path + "." + key;
    }

    std::optional<double> number(const YAML::Node& node, const std::string& path) {
        if (node.IsScalar()) {
            if (auto value = io::parse_double(node.Scalar())) return value;
            error(node, path, "expected a finite number, got \"" + node.Scalar() + "\"");
        } else {
            error(node, path, "expected a finite number");
        }
        return std::nullopt;
    }
    std::optional<double> number_key(const YAML::Node& parent, const std::string& path,
                                     const std::string& key, bool required) {
        const YAML::Node node = parent[key];
        if (!node) {
            if (required) error(parent, path, "missing required key \"" + key + "\"");
            return std::nullopt;
        }
        return number(node, join(path, key));
    }
    std::optional<long long> integer_key(const YAML::Node& parent, const std::string& path,
                                         const std::string& key) {
        const YAML::Node node = parent[key];
        if (!node) return std::nullopt;
        if (node.IsScalar()) {
            if (auto value = io::parse_int(node.Scalar())) return *value;
        }
        error(node, join(path, key), "expected an integer");
        return std::nullopt;
    }
    std::optional<std::string> text_key(const YAML::Node& parent, const std::string& path,
                                        const std::string& key, bool required) {
        const YAML::Node node = parent[key];
        if (!node) {
            if (required) error(parent, path, "missing required key \"" + key + "\"");
            return std::nullopt;
        }
        if (!node.IsScalar() || node.Scalar().empty()) {
            error(node, join(path, key), "expected non-empty text");
            return std::nullopt;
        }
        return node.Scalar();
    }
    std::vector<double> numbers(const YAML::Node& node, const std::string& path) {
        std::vector<double> out;
        if (!node.IsSequence()) {
            error(node, path, "expected a list of numbers");
            return out;
        }
        for (std::size_t i = 0; i < node.size(); ++i) {
            const auto value = number(node[i], path + "[" + std::to_string(i) + "]");
            out.push_back(value.value_or(std::nan("")));
        }
        return out;
    }
    std::optional<std::array<double, 3>> triple_key(const YAML::Node& parent,
                                                    const std::string& path,
                                                    const std::string& key) {
        const YAML::Node node = parent[key];
        if (!node) return std::nullopt;
        const std::size_t errors = diagnostics.error_count();
        const std::vector<double> values = numbers(node, join(path, key));
        if (diagnostics.error_count() != errors) return std::nullopt;
        if (values.size() != 3) {
            error(node, join(path, key),
                  "expected 3 numbers [x, y, z], got " + std::to_string(values.size()));
            return std::nullopt;
        }
        return std::array<double, 3>{values[0], values[1], values[2]};
    }
};

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
        const auto w = io::parse_double(a);
        const auto v = io::parse_double(b);
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

/// Reads a spectrum key (`reflectance`, `emissivity`): inline lists or a file; checks
/// wavelengths (positive, strictly increasing) and values (in [0, 1]).
model::SpectralTable read_spectrum(Reader& r, const YAML::Node& node, const std::string& path,
                                   const std::string& quantity) {
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

// ---- materials ------------------------------------------------------------------------------

model::Material read_material(Reader& r, const YAML::Node& node, const std::string& path) {
    model::Material m;
    m.where = r.where(node, path);
    if (!r.expect_map(node, path)) return m;
    r.warn_unknown(node, path,
                   {"id", "name", "reflectance", "specular", "emissivity", "temperature"});
    m.id = r.text_key(node, path, "id", true).value_or("");
    m.name = r.text_key(node, path, "name", false).value_or(m.id);
    if (node["reflectance"]) {
        m.reflectance =
            read_spectrum(r, node["reflectance"], Reader::join(path, "reflectance"), "reflectance");
    } else {
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
    if (node["emissivity"]) {
        m.emissivity =
            read_spectrum(r, node["emissivity"], Reader::join(path, "emissivity"), "emissivity");
        m.emissivity_is_default = false;
    } else {
        m.emissivity.wavelengths_um = m.reflectance.wavelengths_um;
        for (const double rho : m.reflectance.values) m.emissivity.values.push_back(1.0 - rho);
        m.emissivity.where = m.reflectance.where;
    }
    if (const auto t = r.number_key(node, path, "temperature", false)) {
        if (*t > 0.0) {
            m.temperature_k = *t;
        } else {
            r.error(node["temperature"], Reader::join(path, "temperature"),
                    "temperature " + format_shortest(*t) + " K is not > 0");
        }
    }
    return m;
}

// ---- objects and instances ------------------------------------------------------------------

std::optional<model::PrimitiveKind> primitive_kind(const std::string& text) {
    using K = model::PrimitiveKind;
    static const std::map<std::string, K> kinds{{"ground_plane", K::ground_plane},
                                                {"box", K::box},
                                                {"sphere", K::sphere},
                                                {"disk", K::disk},
                                                {"cylinder", K::cylinder}};
    const auto it = kinds.find(text);
    return it == kinds.end() ? std::nullopt : std::optional(it->second);
}

/// Reads the motion of a dynamic instance from an inline FlexMotion text block, mapping
/// the XML lines of its diagnostics onto lines of the YAML file.
model::PlatformMotion read_inline_motion(Reader& r, const YAML::Node& node,
                                         const std::string& path) {
    model::PlatformMotion motion;
    motion.file = r.file;
    Diagnostics local;
    // A block scalar ("|") starts on the line after its indicator; a plain one on its own.
    const std::string& text = node.Scalar();
    const int first_line = node.Mark().line + (node.Tag() == "!" ? 2 : 1);
    try {
        const io::XmlDocument document = io::XmlDocument::parse(text, r.file);
        const io::XmlNode root = document.root("motion");
        const MotionReadContext context{r.options, r.base_dir, text};
        motion.flexible = read_flex_motion(root, context, local);
    } catch (const Error& error) {
        local.add(error);
    }
    for (const Diagnostic& d : local.items()) {
        ErrorContext where = d.where;
        if (where.file == r.file) {
            where.line = where.line > 0 ? where.line + first_line - 1 : first_line - 1;
            where.element = path + (where.element.empty() ? "" : " " + where.element);
        }
        if (d.severity == Diagnostic::Severity::error) {
            r.diagnostics.error(where, d.message);
        } else {
            r.diagnostics.warning(where, d.message);
        }
    }
    return motion;
}

model::Instance read_instance(Reader& r, const YAML::Node& node, const std::string& path,
                              std::size_t object_index, const std::string& object_name) {
    model::Instance in;
    in.object_index = object_index;
    in.where = r.where(node, path);
    in.name = object_name;
    if (node.IsNull()) return in;
    if (!r.expect_map(node, path)) return in;
    r.warn_unknown(node, path,
                   {"name", "tags", "translation", "rotation_deg", "rotation_order", "scale",
                    "matrix", "motion", "flex_motion"});
    in.name = r.text_key(node, path, "name", false).value_or(object_name);
    if (const YAML::Node tags = node["tags"]) {
        if (!tags.IsSequence()) {
            r.error(tags, Reader::join(path, "tags"), "expected a list of text");
        } else {
            for (std::size_t i = 0; i < tags.size(); ++i) {
                if (tags[i].IsScalar() && !tags[i].Scalar().empty()) {
                    in.tags.push_back(tags[i].Scalar());
                } else {
                    r.error(tags[i], Reader::join(path, "tags") + "[" + std::to_string(i) + "]",
                            "expected non-empty text");
                }
            }
        }
    }
    const auto starts_important = [](const std::string& s) {
        return s.rfind(model::kImportantLabel, 0) == 0;
    };
    in.important = starts_important(in.name);
    for (const std::string& tag : in.tags) in.important = in.important || starts_important(tag);

    const bool has_static =
        node["translation"] || node["rotation_deg"] || node["rotation_order"] || node["scale"];
    const bool dynamic = node["motion"] || node["flex_motion"];
    if (node["motion"] && node["flex_motion"]) {
        r.error(node, path, "give either motion or flex_motion, not both");
        return in;
    }
    if (dynamic && (has_static || node["matrix"])) {
        r.error(node, path,
                "a dynamic instance (motion, flex_motion) takes no static "
                "transform keys");
        return in;
    }
    if (node["matrix"] && has_static) {
        r.error(node, path,
                "give either matrix or translation, rotation_deg, rotation_order and scale");
        return in;
    }
    auto& t = in.transform;
    if (auto v = r.triple_key(node, path, "translation")) t.translation_m = *v;
    if (auto v = r.triple_key(node, path, "rotation_deg")) {
        for (int k = 0; k < 3; ++k) t.rotation_rad[k] = (*v)[k] * kDegToRad;
    }
    if (const auto order = r.text_key(node, path, "rotation_order", false)) {
        std::string sorted = to_lower(*order);
        std::sort(sorted.begin(), sorted.end());
        if (sorted != "xyz") {
            r.error(node["rotation_order"], Reader::join(path, "rotation_order"),
                    "rotation order \"" + *order + "\" is not a permutation of xyz");
        } else {
            t.rotation_order = to_lower(*order);
        }
    }
    if (const YAML::Node scale = node["scale"]) {
        const std::string sp = Reader::join(path, "scale");
        if (scale.IsScalar()) {
            if (const auto s = r.number(scale, sp)) t.scale = {*s, *s, *s};
        } else if (const auto s = r.triple_key(node, path, "scale")) {
            t.scale = *s;
        }
        for (const double s : t.scale) {
            if (s == 0.0) {
                r.error(scale, sp, "scale must be non-zero");
                break;
            }
        }
    }
    if (const YAML::Node matrix = node["matrix"]) {
        const std::string mp = Reader::join(path, "matrix");
        const std::size_t errors = r.diagnostics.error_count();
        const std::vector<double> values = r.numbers(matrix, mp);
        if (r.diagnostics.error_count() == errors) {
            if (values.size() != 16) {
                r.error(matrix, mp,
                        "matrix has " + std::to_string(values.size()) + " values, expected 16");
            } else if (values[12] != 0.0 || values[13] != 0.0 || values[14] != 0.0 ||
                       values[15] != 1.0) {
                r.error(matrix, mp, "matrix last row must be 0 0 0 1");
            } else {
                std::array<double, 16> m{};
                std::copy(values.begin(), values.end(), m.begin());
                t.matrix = m;
            }
        }
    }
    if (const YAML::Node motion = node["motion"]) {
        if (const auto text = r.text_key(node, path, "motion", true)) {
            in.motion_file = r.options.paths.resolve(
                *text, r.base_dir, r.where(motion, Reader::join(path, "motion")), r.diagnostics);
            if (!in.motion_file.resolved.empty()) {
                in.motion = read_motion(in.motion_file.resolved, r.options, r.diagnostics);
            }
        }
    } else if (const YAML::Node flex = node["flex_motion"]) {
        if (r.text_key(node, path, "flex_motion", true)) {
            in.motion = read_inline_motion(r, flex, Reader::join(path, "flex_motion"));
        }
    }
    return in;
}

/// Reads the primitive parameters of `node` into `p` (kind already set).
void read_primitive(Reader& r, const YAML::Node& node, const std::string& path,
                    model::Primitive& p) {
    using K = model::PrimitiveKind;
    const bool round = p.kind == K::sphere || p.kind == K::disk || p.kind == K::cylinder;
    if (p.kind != K::box) {
        if (auto v = r.triple_key(node, path, "center")) p.center_m = *v;
    }
    if (p.kind == K::ground_plane) {
        if (auto v = r.number_key(node, path, "size", false)) p.size_m = *v;
    }
    if (p.kind == K::box) {
        if (!node["lower"]) r.error(node, path, "missing required key \"lower\"");
        if (!node["upper"]) r.error(node, path, "missing required key \"upper\"");
        if (auto v = r.triple_key(node, path, "lower")) p.lower_m = *v;
        if (auto v = r.triple_key(node, path, "upper")) p.upper_m = *v;
    }
    if (round) {
        if (auto v = r.number_key(node, path, "radius", true)) p.radius_m = *v;
        if (auto v = r.integer_key(node, path, "segments")) p.segments = static_cast<int>(*v);
    }
    if (p.kind == K::sphere) {
        if (auto v = r.integer_key(node, path, "rings")) p.rings = static_cast<int>(*v);
    }
    if (p.kind == K::cylinder) {
        if (auto v = r.number_key(node, path, "height", true)) p.height_m = *v;
        if (const YAML::Node caps = node["caps"]) {
            const auto value = caps.IsScalar() ? io::parse_bool(caps.Scalar()) : std::nullopt;
            if (value) {
                p.caps = *value;
            } else {
                r.error(caps, Reader::join(path, "caps"), "expected true or false");
            }
        }
    }
}

/// Keys an object of each kind takes.
std::vector<std::string_view> object_keys(std::optional<model::PrimitiveKind> kind) {
    using K = model::PrimitiveKind;
    std::vector<std::string_view> keys{"name", "obj", "primitive", "material", "instances"};
    if (!kind) return keys;
    if (*kind != K::box) keys.push_back("center");
    if (*kind == K::ground_plane) keys.push_back("size");
    if (*kind == K::box) keys.insert(keys.end(), {"lower", "upper"});
    if (*kind == K::sphere || *kind == K::disk || *kind == K::cylinder) {
        keys.insert(keys.end(), {"radius", "segments"});
    }
    if (*kind == K::sphere) keys.push_back("rings");
    if (*kind == K::cylinder) keys.insert(keys.end(), {"height", "caps"});
    return keys;
}

void read_object(Reader& r, const YAML::Node& node, const std::string& path, model::Scene& scene) {
    model::GeometryObject object;
    object.where = r.where(node, path);
    object.name = "object" + std::to_string(scene.objects.size());
    if (!r.expect_map(node, path)) return;
    object.name = r.text_key(node, path, "name", false).value_or(object.name);
    const std::size_t errors = r.diagnostics.error_count();

    std::optional<model::PrimitiveKind> kind;
    if (node["primitive"] && node["obj"]) {
        r.error(node, path, "give either obj or primitive, not both");
    } else if (!node["primitive"] && !node["obj"]) {
        r.error(node, path, "missing required key \"obj\" or \"primitive\"");
    } else if (node["primitive"]) {
        if (const auto text = r.text_key(node, path, "primitive", true)) {
            kind = primitive_kind(*text);
            if (!kind) {
                r.error(node["primitive"], Reader::join(path, "primitive"),
                        "unknown primitive \"" + *text +
                            "\", expected ground_plane, box, sphere, disk or cylinder");
            }
        }
    }
    {
        const std::vector<std::string_view> keys = object_keys(kind);
        for (const auto& entry : node) {
            const std::string key = entry.first.Scalar();
            if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
                r.diagnostics.warning(r.where(entry.first, Reader::join(path, key)),
                                      "unknown key \"" + key + "\" (ignored)");
            }
        }
    }

    std::optional<std::uint32_t> material;
    if (const auto id = r.text_key(node, path, "material", kind.has_value())) {
        object.material_id = *id;
        for (std::size_t i = 0; i < scene.materials.size(); ++i) {
            if (scene.materials[i].id == *id) material = static_cast<std::uint32_t>(i);
        }
        if (!material) {
            r.error(node["material"], Reader::join(path, "material"),
                    "unknown material id \"" + *id + "\"");
        }
    }

    if (kind) {
        object.primitive = model::Primitive{};
        object.primitive->kind = *kind;
        read_primitive(r, node, path, *object.primitive);
        if (material && r.diagnostics.error_count() == errors) {
            object.mesh =
                tessellate_primitive(*object.primitive, *material, object.where, r.diagnostics);
            validate_mesh(object.mesh, scene.materials.size(), object.where, r.diagnostics);
        }
    } else if (node["obj"] && r.diagnostics.error_count() == errors) {
        if (const auto text = r.text_key(node, path, "obj", true)) {
            object.obj_file = r.options.paths.resolve(
                *text, r.base_dir, r.where(node["obj"], Reader::join(path, "obj")), r.diagnostics);
            if (!object.obj_file.resolved.empty()) {
                const auto by_name = [&scene](const std::string& name) {
                    std::optional<std::uint32_t> found;
                    for (std::size_t i = 0; i < scene.materials.size() && !found; ++i) {
                        if (scene.materials[i].name == name) {
                            found = static_cast<std::uint32_t>(i);
                        }
                    }
                    return found;
                };
                object.mesh =
                    load_obj_mesh(object.obj_file.resolved, object.obj_file.resolved.string(),
                                  by_name, material, scene.materials.size(), r.diagnostics);
            }
        }
    }

    const std::size_t object_index = scene.objects.size();
    if (const YAML::Node instances = node["instances"]) {
        const std::string ip = Reader::join(path, "instances");
        if (!instances.IsSequence()) {
            r.error(instances, ip, "expected a list of instances");
        } else if (instances.size() == 0) {
            r.diagnostics.warning(r.where(instances, ip),
                                  "object \"" + object.name + "\" has no instances");
        } else {
            for (std::size_t i = 0; i < instances.size(); ++i) {
                scene.instances.push_back(read_instance(r, instances[i],
                                                        ip + "[" + std::to_string(i) + "]",
                                                        object_index, object.name));
            }
        }
    } else {
        model::Instance in;
        in.object_index = object_index;
        in.name = object.name;
        in.important = object.name.rfind(model::kImportantLabel, 0) == 0;
        in.where = object.where;
        scene.instances.push_back(in);
    }
    scene.objects.push_back(std::move(object));
}

void read_origin(Reader& r, const YAML::Node& node, model::Scene& scene) {
    if (!r.expect_map(node, "origin")) return;
    r.warn_unknown(node, "origin", {"latitude", "longitude", "altitude"});
    model::SceneOrigin origin;
    origin.where = r.where(node, "origin");
    const auto lat = r.number_key(node, "origin", "latitude", true);
    const auto lon = r.number_key(node, "origin", "longitude", true);
    const auto alt = r.number_key(node, "origin", "altitude", false);
    if (lat && (*lat < -90.0 || *lat > 90.0)) {
        r.error(node["latitude"], "origin.latitude",
                "latitude " + format_shortest(*lat) + " deg is outside [-90, 90]");
    }
    if (lon && (*lon < -180.0 || *lon > 180.0)) {
        r.error(node["longitude"], "origin.longitude",
                "longitude " + format_shortest(*lon) + " deg is outside [-180, 180]");
    }
    origin.latitude_deg = lat.value_or(0.0);
    origin.longitude_deg = lon.value_or(0.0);
    origin.altitude_m = alt.value_or(0.0);
    scene.origin = origin;
}

void read_document(Reader& r, const YAML::Node& root, model::Scene& scene) {
    if (!root.IsMap()) {
        r.error(root, "", "expected a mapping with keys origin, materials and objects");
        return;
    }
    r.warn_unknown(root, "", {"origin", "materials", "objects"});
    if (const YAML::Node origin = root["origin"]) read_origin(r, origin, scene);

    if (const YAML::Node materials = root["materials"]) {
        if (!materials.IsSequence()) {
            r.error(materials, "materials", "expected a list of materials");
        } else {
            std::set<std::string> ids;
            std::set<std::string> names;
            for (std::size_t i = 0; i < materials.size(); ++i) {
                const std::string path = "materials[" + std::to_string(i) + "]";
                model::Material m = read_material(r, materials[i], path);
                if (!m.id.empty() && !ids.insert(m.id).second) {
                    r.error(materials[i]["id"], path + ".id",
                            "duplicate material id \"" + m.id + "\"");
                }
                if (!m.name.empty() && !names.insert(m.name).second) {
                    r.error(materials[i], path, "duplicate material name \"" + m.name + "\"");
                }
                scene.materials.push_back(std::move(m));
            }
        }
    }

    const YAML::Node objects = root["objects"];
    if (!objects) {
        r.error(root, "", "missing required key \"objects\"");
    } else if (!objects.IsSequence()) {
        r.error(objects, "objects", "expected a list of objects");
    } else {
        for (std::size_t i = 0; i < objects.size(); ++i) {
            read_object(r, objects[i], "objects[" + std::to_string(i) + "]", scene);
        }
    }
}

}  // namespace

model::Scene read_yaml_scene(const std::filesystem::path& file, const ReadOptions& options,
                             Diagnostics& diagnostics) {
    model::Scene scene;
    scene.file = file.string();
    ReadOptions local = options;
    const std::filesystem::path base_dir = std::filesystem::absolute(file).parent_path();
    if (!local.paths.scene_dir) local.paths.scene_dir = base_dir;
    Reader reader{scene.file, base_dir, local, diagnostics};
    try {
        const std::string text = io::read_input_file(file, scene.file);
        YAML::Node root;
        try {
            root = YAML::Load(text);
        } catch (const YAML::Exception& error) {
            diagnostics.error({scene.file, error.mark.line >= 0 ? error.mark.line + 1 : 0, {}},
                              "invalid YAML: " + error.msg);
            return scene;
        }
        read_document(reader, root, scene);
    } catch (const Error& error) {
        diagnostics.add(error);
    } catch (const YAML::Exception& error) {
        diagnostics.error({scene.file, error.mark.line >= 0 ? error.mark.line + 1 : 0, {}},
                          "cannot read YAML: " + error.msg);
    }
    return scene;
}

}  // namespace glint::legacy
