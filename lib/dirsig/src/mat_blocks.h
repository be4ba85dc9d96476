// SPDX-License-Identifier: Apache-2.0
// Internal interface of the `.mat` reader: the parsed block structure of a `.mat` text
// (`NAME { ... }` blocks of `KEY = value` lines) and MatReader, the state the material entry
// reader (mat_reader.cpp) and its SURFACE_PROPERTIES reader (mat_surface.cpp) share.
#pragma once

#include <algorithm>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "glint/core/diagnostics.h"
#include "glint/dirsig/scene_reader.h"
#include "glint/model/scene.h"
#include "mat_curves.h"

namespace glint::dirsig::detail {

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

/// `text` without leading and trailing white space.
std::string trim(std::string_view text);
/// `text` in upper case (ASCII).
std::string to_upper(std::string text);
/// Parses the block structure of a `.mat` text; syntax problems go to `diagnostics`.
MatBlock parse_blocks(const std::string& text, const std::string& file, Diagnostics& diagnostics);

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
        std::string suffix = " ignored";  ///< what the warning says after `what`
    };
    std::map<std::string, Ignored> ignored;
    std::vector<std::string> ignored_order;  ///< as first met

    void ignore(const std::string& what, ErrorContext where, std::string suffix = " ignored") {
        auto [it, added] = ignored.try_emplace(what, Ignored{where, {}, std::move(suffix)});
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
            std::string message = what + i.suffix;
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
        last_classes.clear();
        parse_curve_text(text, CurveSource{name, path, quantity, max_value}, table, diagnostics,
                         &last_classes);
        return table;
    }
    /// The texture classes of the curve file read_curve read last (empty: one curve).
    std::vector<model::SpectralTable> last_classes{};

    /// Reads `<PREFIX>_PROP { TXT_FILENAME | FILENAME }` of SURFACE_PROPERTIES (mat_surface.cpp).
    std::optional<model::SpectralTable> read_prop(const MatBlock& surface, const std::string& path,
                                                  const std::string& prefix,
                                                  const std::string& quantity);
    /// The SPECULAR_FRACTION of the property being read (mat_surface.cpp), and whether the
    /// once-per-file notes on glint's readings have been said.
    double specular_fraction = 0.0;
    bool said_specular_fraction = false;
    bool said_ward_keys = false;
    bool said_transmittance_keys = false;
    /// Reads a SPECULAR_FRACTION key into specular_fraction.
    void read_specular_fraction(const MatEntry& fraction, const std::string& path);
    /// `<SLOT>_PROP_NAME` upper-cased into `name` (empty when absent); false, with an error
    /// naming it, for a DIRSIG model glint refuses.
    bool model_name(const MatBlock& surface, const std::string& path, const std::string& slot,
                    std::string& name);
    /// A WardBRDF REFLECTANCE_PROP (DS_WEIGHTS, XY_SIGMAS) into `m`.
    void read_ward(const MatBlock& surface, const std::string& path, model::Material& m);
    /// Reads an entry's SURFACE_PROPERTIES into `m` (mat_surface.cpp).
    void read_surface(const MatBlock& surface, const std::string& path, model::Material& m);
    /// A `RAD_SOLVER_NAME = Null` material: neither reflects nor emits (ρ = 0, ε = 0).
    void read_null(const MatEntry& solver, const std::string& path, model::Material& m);
    /// `TEMP_SOLVER_NAME = Map`'s TEMP_SOLVER block: the image and its projector
    /// (mat_temperature.cpp); the map goes to m.temperature_map.
    void read_temperature_map(const MatBlock& solver, const std::string& path, model::Material& m);
    /// THERM's TEMP_SOLVER block (`TEMP_SOLVER_NAME = Therm`) into m.therm, its units
    /// converted to SI (mat_therm.cpp); glint's readings of DIRSIG's units said once per file.
    void read_therm(const MatBlock& solver, const std::string& path, model::Material& m);
    bool said_therm_units = false;
    bool said_therm_exposed_sign = false;
    bool said_therm_no_storage = false;
    /// Whether the once-per-file note on the temperature map's GAIN/BIAS reading was said.
    bool said_temperature_gain = false;
    /// An `OPTICAL_DESCRIPTION = SOURCE` material (mat_reader.cpp).
    void read_source(const MatBlock& block, const std::string& path, model::Material& m);
    /// One MATERIAL_ENTRY block (mat_reader.cpp).
    model::Material read_entry(const MatBlock& block, std::size_t index);
};

}  // namespace glint::dirsig::detail
