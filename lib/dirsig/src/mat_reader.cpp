// SPDX-License-Identifier: Apache-2.0
// Reader of the documented subset of DIRSIG's `.mat` material database: `MATERIAL_ENTRY { }`
// blocks of `KEY = value` lines giving the id, the name, reflectance and emissivity curves
// from two-column text files and a constant temperature. Unsupported solvers and property
// blocks are warnings naming the entry; `.mat.hdf` bundles are errors. docs/scene.md gives
// the exact layout.
#include <algorithm>
#include <cctype>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "glint/core/text.h"
#include "glint/dirsig/scene_reader.h"
#include "mat_curves.h"

namespace glint::dirsig {
namespace {

/// One `KEY = value` line.
struct MatEntry {
    std::string key;
    std::string value;
    int line = 0;
};

/// One `NAME { ... }` block.
struct MatBlock {
    std::string name;
    int line = 0;
    std::vector<MatEntry> entries;
    std::vector<MatBlock> blocks;

    const MatEntry* find(std::string_view key) const {
        for (const MatEntry& e : entries) {
            if (e.key == key) return &e;
        }
        return nullptr;
    }
    const MatBlock* find_block(std::string_view key) const {
        for (const MatBlock& b : blocks) {
            if (b.name == key) return &b;
        }
        return nullptr;
    }
};

std::string trim(std::string_view text) {
    std::size_t begin = 0;
    std::size_t end = text.size();
    while (begin < end && std::isspace(static_cast<unsigned char>(text[begin]))) ++begin;
    while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
    return std::string(text.substr(begin, end - begin));
}

std::string to_upper(std::string text) {
    for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

/// Parses the block structure of a `.mat` text; syntax problems go to `diagnostics`.
MatBlock parse_blocks(const std::string& text, const std::string& file, Diagnostics& diagnostics) {
    MatBlock root;
    std::vector<MatBlock*> stack{&root};
    std::optional<MatEntry> pending;  // a bare name waiting for its "{"
    std::istringstream lines(text);
    std::string raw;
    int number = 0;
    const auto flush_pending = [&] {
        if (pending) {
            diagnostics.error({file, pending->line, pending->key},
                              "expected \"KEY = value\" or \"NAME {\"");
            pending.reset();
        }
    };
    while (std::getline(lines, raw)) {
        ++number;
        // A comment is a line whose first non-blank character is '#'; elsewhere '#' is text
        // ("NAME = Class #2").
        const std::string content = trim(raw).starts_with('#') ? std::string() : raw;
        // One-line blocks ("NAME { KEY = value }") are split into "NAME {", "KEY = value", "}".
        std::vector<std::string> pieces;
        std::string piece;
        for (const char c : content) {
            if (c == '}') {
                pieces.push_back(trim(piece));
                pieces.emplace_back("}");
                piece.clear();
            } else {
                piece += c;
                if (c == '{') {
                    pieces.push_back(trim(piece));
                    piece.clear();
                }
            }
        }
        pieces.push_back(trim(piece));
        for (const std::string& line : pieces) {
            if (line.empty()) continue;
            if (line == "}") {
                flush_pending();
                if (stack.size() == 1) {
                    diagnostics.error({file, number, {}}, "unmatched \"}\"");
                } else {
                    stack.pop_back();
                }
                continue;
            }
            if (line.back() == '{') {
                std::string name = to_upper(trim(line.substr(0, line.size() - 1)));
                int at = number;
                if (name.empty() && pending) {
                    name = pending->key;
                    at = pending->line;
                } else {
                    flush_pending();
                }
                pending.reset();
                if (name.empty()) {
                    diagnostics.error({file, number, {}}, "block \"{\" without a name");
                    name = "?";
                }
                stack.back()->blocks.push_back(MatBlock{name, at, {}, {}});
                stack.push_back(&stack.back()->blocks.back());
                continue;
            }
            flush_pending();
            const std::size_t eq = line.find('=');
            if (eq == std::string::npos) {
                pending = MatEntry{to_upper(line), {}, number};
                continue;
            }
            stack.back()->entries.push_back(
                MatEntry{to_upper(trim(line.substr(0, eq))), trim(line.substr(eq + 1)), number});
        }
    }
    flush_pending();
    if (stack.size() > 1) {
        diagnostics.error({file, stack.back()->line, stack.back()->name},
                          "block is not closed by \"}\"");
    }
    return root;
}

/// Everything the material readers share.
struct MatReader {
    std::string file;  ///< display name of the .mat
    std::filesystem::path base_dir;
    const ReadOptions& options;
    Diagnostics& diagnostics;

    ErrorContext at(int line, const std::string& path) const { return {file, line, path}; }

    /// Where one kind of thing a material names is ignored ("unknown key SPECIFIC_HEAT"): said
    /// once per file (flush_ignored), at the first place, with the count and the next lines.
    struct Ignored {
        ErrorContext first;
        std::vector<int> lines;
    };
    std::map<std::string, Ignored> ignored;
    std::vector<std::string> ignored_order;  ///< as first met

    void ignore(const std::string& what, ErrorContext where) {
        auto [it, added] = ignored.try_emplace(what, Ignored{where, {}});
        if (added) ignored_order.push_back(what);
        it->second.lines.push_back(where.line);
    }

    void warn_unknown(const MatBlock& block, const std::string& path,
                      std::initializer_list<std::string_view> known_entries,
                      std::initializer_list<std::string_view> known_blocks) {
        const auto known = [](std::initializer_list<std::string_view> list, const std::string& k) {
            return std::find(list.begin(), list.end(), k) != list.end();
        };
        for (const MatEntry& e : block.entries) {
            if (!known(known_entries, e.key)) {
                ignore("unknown key " + e.key, at(e.line, path + "/" + e.key));
            }
        }
        for (const MatBlock& b : block.blocks) {
            if (!known(known_blocks, b.name)) {
                ignore("unsupported block " + b.name, at(b.line, path + "/" + b.name));
            }
        }
    }

    /// One warning per ignored key or block: "unknown key SPECIFIC_HEAT ignored", and when it
    /// occurs more than once, "(57 times: also lines 40, 68, 96 and 53 more)".
    void flush_ignored() {
        constexpr std::size_t kLinesShown = 3;
        for (const std::string& what : ignored_order) {
            const Ignored& i = ignored.at(what);
            std::string message = what + " ignored";
            if (i.lines.size() > 1) {
                message += " (" + std::to_string(i.lines.size()) + " times: also line";
                message += i.lines.size() > 2 ? "s " : " ";
                const std::size_t shown = std::min(kLinesShown, i.lines.size() - 1);
                for (std::size_t k = 1; k <= shown; ++k) {
                    if (k > 1)
                        message += k == shown && i.lines.size() - 1 == shown ? " and " : ", ";
                    message += std::to_string(i.lines[k]);
                }
                if (const std::size_t rest = i.lines.size() - 1 - shown; rest > 0) {
                    message += " and " + std::to_string(rest) + " more";
                }
                message += ")";
            }
            diagnostics.warning(i.first, message);
        }
        ignored.clear();
        ignored_order.clear();
    }

    /// Reads a curve file: two columns (wavelength µm, value in [0, max_value]) or a classic
    /// .ems.
    model::SpectralTable read_curve(const MatEntry& entry, const std::string& path,
                                    const std::string& quantity, double max_value = 1.0) {
        model::SpectralTable table;
        table.where = at(entry.line, path);
        table.file = options.paths.resolve(entry.value, base_dir, table.where, diagnostics);
        if (table.file.resolved.empty()) return table;
        const std::string name = table.file.resolved.string();
        std::string text;
        try {
            text = options.read_text(table.file.resolved, name);
        } catch (const Error& error) {
            // Said at the material's key that names the file, with the file's path.
            diagnostics.error(table.where, quantity + " file " + name + ": " + error.message());
            return table;
        }
        detail::parse_curve_text(text, detail::CurveSource{name, path, quantity, max_value}, table,
                                 diagnostics);
        return table;
    }

    /// Reads `<PREFIX>_PROP { TXT_FILENAME | FILENAME }` of SURFACE_PROPERTIES.
    std::optional<model::SpectralTable> read_prop(const MatBlock& surface, const std::string& path,
                                                  const std::string& prefix,
                                                  const std::string& quantity) {
        const MatBlock* prop = surface.find_block(prefix + "_PROP");
        if (!prop) return std::nullopt;
        const std::string pp = path + "/" + prefix + "_PROP";
        warn_unknown(*prop, pp, {"TXT_FILENAME", "FILENAME", "SPECULAR_FRACTION"}, {});
        if (const MatEntry* fraction = prop->find("SPECULAR_FRACTION")) {
            const auto value = parse_double(fraction->value);
            if (!value || *value != 0.0) {
                diagnostics.warning(at(fraction->line, pp + "/SPECULAR_FRACTION"),
                                    "SPECULAR_FRACTION " + fraction->value +
                                        " is read, not applied: the .mat surface is Lambertian "
                                        "(a glint YAML material's specular lobe models it)");
            }
        }
        const MatEntry* entry = prop->find("TXT_FILENAME");
        if (!entry) entry = prop->find("FILENAME");
        if (!entry || entry->value.empty()) {
            diagnostics.error(at(prop->line, pp),
                              "missing TXT_FILENAME or FILENAME (a curve file)");
            return std::nullopt;
        }
        return read_curve(*entry, pp + "/" + entry->key, quantity);
    }

    /// A `RAD_SOLVER_NAME = Null` material: neither reflects nor emits (ρ = 0, ε = 0).
    void read_null(const MatEntry& solver, const std::string& path, model::Material& m) {
        diagnostics.warning(at(solver.line, path + "/RAD_SOLVER_NAME"),
                            "radiometry solver \"" + solver.value + "\" of material \"" + m.name +
                                "\": glint renders it black and non-emitting (reflectance 0, "
                                "emissivity 0); its SURFACE_PROPERTIES are not read");
        for (model::SpectralTable* table : {&m.reflectance, &m.emissivity}) {
            table->wavelengths_um = {0.1, 100.0};
            table->values = {0.0, 0.0};
            table->where = at(solver.line, path + "/RAD_SOLVER_NAME");
        }
        m.emissivity_is_default = false;
    }

    /// An `OPTICAL_DESCRIPTION = SOURCE` material: the spectral radiant intensity of the
    /// `INTENSITY_FILENAME` file (wavelength µm, W/(sr µm)) for the point sources naming it;
    /// black surfaces, since no surface may use it.
    void read_source(const MatBlock& block, const std::string& path, model::Material& m) {
        m.point_source = true;
        for (model::SpectralTable* table : {&m.reflectance, &m.emissivity}) {
            table->wavelengths_um = {0.1, 100.0};
            table->values = {0.0, 0.0};
            table->where = m.where;
        }
        m.emissivity_is_default = false;
        if (const MatBlock* surface = block.find_block("SURFACE_PROPERTIES")) {
            diagnostics.warning(at(surface->line, path + "/SURFACE_PROPERTIES"),
                                "SURFACE_PROPERTIES of point-source material \"" + m.name +
                                    "\" are not read: a source has no surface");
        }
        const MatEntry* intensity = block.find("INTENSITY_FILENAME");
        if (!intensity || intensity->value.empty()) {
            diagnostics.error(m.where, "point-source material \"" + m.name +
                                           "\" (OPTICAL_DESCRIPTION = SOURCE) needs "
                                           "INTENSITY_FILENAME (wavelength um, W/(sr um))");
            return;
        }
        // DIRSIG does not document the file's units; glint reads it as its curve files.
        diagnostics.warning(at(intensity->line, path + "/INTENSITY_FILENAME"),
                            "point-source material \"" + m.name +
                                "\": INTENSITY_FILENAME read as wavelength (um) and spectral "
                                "intensity (W/(sr um)) columns, an isotropic source "
                                "(glint's reading)");
        m.intensity_w_per_sr_um = read_curve(*intensity, path + "/INTENSITY_FILENAME", "intensity",
                                             std::numeric_limits<double>::infinity());
    }

    model::Material read_entry(const MatBlock& block, std::size_t index) {
        model::Material m;
        const MatEntry* id = block.find("ID");
        m.id = id ? id->value : "";
        const std::string path =
            "MATERIAL_ENTRY[" + (m.id.empty() ? std::to_string(index + 1) : m.id) + "]";
        m.where = at(block.line, path);
        if (m.id.empty()) diagnostics.error(m.where, "missing ID");
        const MatEntry* name = block.find("NAME");
        m.name = name && !name->value.empty() ? name->value : m.id;
        warn_unknown(
            block, path,
            {"ID", "NAME", "EDITOR_COLOR", "DOUBLE_SIDED", "RAD_SOLVER_NAME", "TEMP_SOLVER_NAME",
             "TEMPERATURE", "BUNDLE_FILENAME", "OPTICAL_DESCRIPTION", "INTENSITY_FILENAME"},
            {"SURFACE_PROPERTIES", "RAD_SOLVER", "TEMP_SOLVER"});
        if (const MatEntry* bundle = block.find("BUNDLE_FILENAME")) {
            diagnostics.error(at(bundle->line, path + "/BUNDLE_FILENAME"),
                              "material bundles (" + bundle->value +
                                  ") are not supported; give SURFACE_PROPERTIES curve files");
            return m;
        }
        if (const MatEntry* optical = block.find("OPTICAL_DESCRIPTION")) {
            if (to_upper(optical->value) == "SOURCE") {
                read_source(block, path, m);
                return m;
            }
            diagnostics.warning(at(optical->line, path + "/OPTICAL_DESCRIPTION"),
                                "OPTICAL_DESCRIPTION \"" + optical->value + "\" of material \"" +
                                    m.name + "\" is not SOURCE: read as a surface material");
        }
        if (const MatEntry* intensity = block.find("INTENSITY_FILENAME")) {
            diagnostics.warning(at(intensity->line, path + "/INTENSITY_FILENAME"),
                                "INTENSITY_FILENAME is read only with OPTICAL_DESCRIPTION = "
                                "SOURCE; ignored");
        }
        const MatEntry* null_solver = nullptr;
        if (const MatEntry* solver = block.find("RAD_SOLVER_NAME")) {
            const std::string s = to_upper(solver->value);
            if (s == "NULL") {
                null_solver = solver;
            } else if (s != "GENERIC" && s != "LAMBERTIAN") {
                diagnostics.warning(at(solver->line, path + "/RAD_SOLVER_NAME"),
                                    "radiometry solver \"" + solver->value + "\" of material \"" +
                                        m.name + "\" is not supported; treated as Lambertian");
            }
        }
        if (const MatEntry* sides = block.find("DOUBLE_SIDED")) {
            // FALSE: the back face is black (docs/materials.md).
            const std::string value = to_upper(sides->value);
            if (value == "FALSE") {
                m.double_sided = false;
            } else if (value != "TRUE") {
                diagnostics.warning(at(sides->line, path + "/DOUBLE_SIDED"),
                                    "DOUBLE_SIDED \"" + sides->value +
                                        "\" is neither TRUE nor FALSE; the material is "
                                        "two-sided");
            }
        }
        // Temperature: TEMPERATURE in the entry or in its TEMP_SOLVER block.
        const MatEntry* temperature = block.find("TEMPERATURE");
        if (const MatBlock* ts = block.find_block("TEMP_SOLVER")) {
            warn_unknown(*ts, path + "/TEMP_SOLVER", {"TEMPERATURE"}, {});
            const MatEntry* inner = ts->find("TEMPERATURE");
            if (inner && temperature) {
                diagnostics.warning(at(inner->line, path + "/TEMP_SOLVER/TEMPERATURE"),
                                    "TEMP_SOLVER's TEMPERATURE is not used: the entry's "
                                    "TEMPERATURE " +
                                        temperature->value + " is");
            } else if (inner) {
                temperature = inner;
            }
        }
        if (const MatEntry* solver = block.find("TEMP_SOLVER_NAME")) {
            const std::string s = to_upper(solver->value);
            if (s != "DATADRIVEN" && s != "CONSTANT") {
                diagnostics.warning(
                    at(solver->line, path + "/TEMP_SOLVER_NAME"),
                    "temperature solver \"" + solver->value + "\" of material \"" + m.name +
                        "\" is not supported; the constant TEMPERATURE (default " +
                        format_shortest(model::kDefaultTemperature_k) + " K) is used");
            }
        }
        if (temperature) {
            const auto t = parse_double(temperature->value);
            if (t && *t > 0.0) {
                m.temperature_k = *t;
            } else {
                diagnostics.error(
                    at(temperature->line, path + "/TEMPERATURE"),
                    "temperature \"" + temperature->value + "\" K is not a number > 0");
            }
        }
        if (null_solver) {
            read_null(*null_solver, path, m);
            return m;
        }
        const MatBlock* surface = block.find_block("SURFACE_PROPERTIES");
        if (!surface) {
            diagnostics.error(m.where,
                              "missing SURFACE_PROPERTIES (reflectance or emissivity curve)");
            return m;
        }
        const std::string sp = path + "/SURFACE_PROPERTIES";
        warn_unknown(*surface, sp, {"REFLECTANCE_PROP_NAME", "EMISSIVITY_PROP_NAME"},
                     {"REFLECTANCE_PROP", "EMISSIVITY_PROP"});
        const bool has_reflectance = surface->find_block("REFLECTANCE_PROP") != nullptr;
        const bool has_emissivity = surface->find_block("EMISSIVITY_PROP") != nullptr;
        if (!has_reflectance && !has_emissivity) {
            diagnostics.error(at(surface->line, sp),
                              "missing REFLECTANCE_PROP and EMISSIVITY_PROP");
            return m;
        }
        if (auto r = read_prop(*surface, sp, "REFLECTANCE", "reflectance")) {
            m.reflectance = std::move(*r);
        }
        if (auto e = read_prop(*surface, sp, "EMISSIVITY", "emissivity")) {
            m.emissivity = std::move(*e);
            m.emissivity_is_default = false;
        }
        if (!has_reflectance) {
            // DIRSIG's opaque surface: an emissivity alone gives reflectance 1 − ε.
            m.reflectance.wavelengths_um = m.emissivity.wavelengths_um;
            for (const double e : m.emissivity.values) m.reflectance.values.push_back(1.0 - e);
            m.reflectance.where = m.emissivity.where;
        } else if (!has_emissivity) {
            m.emissivity.wavelengths_um = m.reflectance.wavelengths_um;
            for (const double rho : m.reflectance.values) m.emissivity.values.push_back(1.0 - rho);
            m.emissivity.where = m.reflectance.where;
        } else if (!m.reflectance.empty() && !m.emissivity.empty()) {
            detail::limit_reflectance(m, diagnostics);
        }
        return m;
    }
};

/// Reads the .mat `file` (every diagnostic, uncapped).
std::vector<model::Material> read_materials(const std::filesystem::path& file,
                                            const ReadOptions& options, Diagnostics& diagnostics) {
    std::vector<model::Material> materials;
    const std::string name = file.string();
    const std::optional<std::string> read = options.read_text_reported(file, name, diagnostics);
    if (!read) return materials;
    const std::string& text = *read;
    const MatBlock root = parse_blocks(text, name, diagnostics);
    MatReader reader{name, std::filesystem::absolute(file).parent_path(), options, diagnostics, {},
                     {}};
    for (const MatEntry& e : root.entries) {
        diagnostics.warning({name, e.line, e.key}, "key outside MATERIAL_ENTRY ignored");
    }
    std::set<std::string> ids;
    for (const MatBlock& block : root.blocks) {
        if (block.name != "MATERIAL_ENTRY") {
            diagnostics.warning({name, block.line, block.name}, "unknown block ignored");
            continue;
        }
        model::Material m = reader.read_entry(block, materials.size());
        if (!m.id.empty() && !ids.insert(m.id).second) {
            diagnostics.error(m.where, "duplicate material ID \"" + m.id + "\"");
        }
        materials.push_back(std::move(m));
    }
    reader.flush_ignored();
    if (root.blocks.empty()) diagnostics.error({name, 0, {}}, "no MATERIAL_ENTRY blocks");
    return materials;
}

}  // namespace

model::SpectralTable read_curve_file(const std::filesystem::path& file, const std::string& quantity,
                                     const ReadOptions& options, Diagnostics& diagnostics) {
    model::SpectralTable table;
    const std::string name = file.string();
    table.where = ErrorContext{name, 0, {}};
    table.file = model::FileRef{name, file, table.where};
    const std::optional<std::string> read = options.read_text_reported(file, name, diagnostics);
    if (!read) return table;
    const std::string& text = *read;
    const double max_value =
        quantity == "intensity" ? std::numeric_limits<double>::infinity() : 1.0;
    detail::parse_curve_text(text, detail::CurveSource{name, {}, quantity, max_value}, table,
                             diagnostics);
    return table;
}

std::vector<model::Material> read_dirsig_materials(const std::filesystem::path& file,
                                                   const ReadOptions& options,
                                                   Diagnostics& capped) {
    // At most kMaxDiagnosticsPerFile of each file (the .mat, each curve file) are reported.
    Diagnostics diagnostics;
    std::vector<model::Material> materials = read_materials(file, options, diagnostics);
    capped.append_capped(diagnostics);
    return materials;
}

}  // namespace glint::dirsig
