// SPDX-License-Identifier: Apache-2.0
// The readers that tell two formats of one kind of file apart: scenes (DIRSIG `.scene` or
// glint YAML) and atmospheres (DIRSIG `.atm` or glint YAML).
#include <cctype>
#include <string_view>

#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/dirsig/atm_reader.h"
#include "glint/dirsig/scene_reader.h"
#include "glint/inputs/scene_atmosphere.h"
#include "glint/yaml/atmosphere_reader.h"
#include "glint/yaml/scene_reader.h"

namespace glint::inputs {
namespace {

/// True when the text, after a BOM and blanks, starts with '<'.
bool looks_like_xml(std::string_view text) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    for (char c : text) {
        if (std::isspace(static_cast<unsigned char>(c))) continue;
        return c == '<';
    }
    return false;
}

}  // namespace

model::Scene read_scene(const std::filesystem::path& file, const ReadOptions& options,
                        Diagnostics& diagnostics) {
    const std::string ext = to_lower(file.extension().string());
    bool dirsig = ext == ".scene";
    if (!dirsig && ext != ".yaml" && ext != ".yml") {
        // The reader chosen reads the same text again from options.files (no second open).
        try {
            dirsig = looks_like_xml(options.read_text(file, file.string()));
        } catch (const Error&) {
            dirsig = false;  // the YAML reader reports why the file cannot be read
        }
    }
    model::Scene scene = dirsig ? dirsig::read_dirsig_scene(file, options, diagnostics)
                                : yaml::read_yaml_scene(file, options, diagnostics);
    // The physical checks the renderer would make, here, so that every tool (and --check)
    // refuses the same scenes with the material's file:line.
    for (const model::Material& material : scene.materials) {
        model::check_material(material, diagnostics);
    }
    return scene;
}

model::Atmosphere read_atmosphere(const std::filesystem::path& path, const ReadOptions& options,
                                  Diagnostics& diagnostics, const std::string& display_name) {
    const std::string file = display_name.empty() ? path.string() : display_name;
    const std::string text = options.read_text(path, file);
    model::Atmosphere atmosphere;
    if (looks_like_xml(text)) {
        try {
            atmosphere = dirsig::parse_atm(text, file, diagnostics);
        } catch (const Error& e) {
            diagnostics.add(e);
            atmosphere.where = ErrorContext{file, 0, {}};
        }
    } else {
        atmosphere = yaml::parse_yaml_atmosphere(text, path, file, options, diagnostics);
    }
    atmosphere.source = path.string();
    return atmosphere;
}

}  // namespace glint::inputs
