// SPDX-License-Identifier: Apache-2.0
// Reader of the documented subset of DIRSIG's `.mat` material database: `MATERIAL_ENTRY { }`
// blocks of `KEY = value` lines giving the id, the name, reflectance and emissivity curves
// from two-column text files and a constant temperature. Unsupported solvers and property
// blocks are warnings naming the entry; `.mat.hdf` bundles are errors. docs/scene.md gives
// the exact layout.
#include <algorithm>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "glint/core/text.h"
#include "glint/dirsig/scene_reader.h"
#include "mat_blocks.h"
#include "mat_curves.h"

namespace glint::dirsig {
namespace detail {

/// A `RAD_SOLVER_NAME = Null` material: neither reflects nor emits (ρ = 0, ε = 0).
void MatReader::read_null(const MatEntry& solver, const std::string& path, model::Material& m) {
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
void MatReader::read_source(const MatBlock& block, const std::string& path, model::Material& m) {
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

model::Material MatReader::read_entry(const MatBlock& block, std::size_t index) {
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
    const MatEntry* solver_name = block.find("TEMP_SOLVER_NAME");
    const bool mapped = solver_name && to_upper(solver_name->value) == "MAP";
    if (mapped) {
        if (const MatBlock* ts = block.find_block("TEMP_SOLVER")) {
            read_temperature_map(*ts, path + "/TEMP_SOLVER", m);
        } else {
            diagnostics.error(at(solver_name->line, path + "/TEMP_SOLVER_NAME"),
                              "temperature solver \"Map\" needs a TEMP_SOLVER block (its "
                              "IMAGE_FILENAME and projector)");
        }
    } else if (solver_name && to_upper(solver_name->value) == "THERM") {
        if (const MatBlock* ts = block.find_block("TEMP_SOLVER")) {
            read_therm(*ts, path + "/TEMP_SOLVER", m);
        } else {
            diagnostics.error(at(solver_name->line, path + "/TEMP_SOLVER_NAME"),
                              "temperature solver \"Therm\" needs a TEMP_SOLVER block (its "
                              "SPECIFIC_HEAT, MASS_DENSITY, THERMAL_CONDUCTIVITY, EXPOSED_AREA, "
                              "...)");
        }
    } else if (const MatBlock* ts = block.find_block("TEMP_SOLVER")) {
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
        if (s != "THERM" && s != "DATADRIVEN" && s != "CONSTANT" && s != "MAP") {
            diagnostics.warning(at(solver->line, path + "/TEMP_SOLVER_NAME"),
                                "temperature solver \"" + solver->value + "\" of material \"" +
                                    m.name +
                                    "\" is not supported; the constant TEMPERATURE (default " +
                                    format_shortest(model::kDefaultTemperature_k) + " K) is used");
        }
    }
    if (temperature) {
        const auto t = parse_double(temperature->value);
        if (t && *t > 0.0) {
            m.temperature_k = *t;
        } else {
            diagnostics.error(at(temperature->line, path + "/TEMPERATURE"),
                              "temperature \"" + temperature->value + "\" K is not a number > 0");
        }
    }
    if (null_solver) {
        read_null(*null_solver, path, m);
        return m;
    }
    const MatBlock* surface = block.find_block("SURFACE_PROPERTIES");
    if (!surface) {
        diagnostics.error(m.where, "missing SURFACE_PROPERTIES (reflectance or emissivity curve)");
        return m;
    }
    read_surface(*surface, path + "/SURFACE_PROPERTIES", m);
    return m;
}

}  // namespace detail

namespace {

using detail::MatBlock;
using detail::MatEntry;
using detail::MatReader;
using detail::parse_blocks;

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
