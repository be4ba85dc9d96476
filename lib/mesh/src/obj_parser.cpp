// SPDX-License-Identifier: Apache-2.0
// Wavefront OBJ parsing (glint/mesh/mesh.h). tinyobjloader's callback parser reads vertices,
// faces and `usemtl` names; a light scan of the same text beforehand finds the file line of
// every `v`, `f` and `usemtl` statement (tinyobjloader gives none) and checks that vertex
// coordinates are finite numbers (tinyobjloader silently reads "nan" as 0).
#include <tiny_obj_loader.h>

#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "glint/core/text.h"
#include "glint/mesh/mesh.h"

namespace glint::mesh {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t'; }

/// The file lines of the statements tinyobjloader reports through its callbacks, in order.
struct StatementLines {
    std::vector<int> vertices;
    std::vector<int> faces;
    std::vector<int> materials;
};

/// Scans `text` as tinyobjloader does (statement = first token of a line after blanks) and
/// reports `v` lines whose x, y, z are not finite numbers.
StatementLines scan(std::string_view text, const std::string& file, Diagnostics& diagnostics) {
    StatementLines lines;
    std::size_t start = 0;
    int line = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        ++line;
        std::string_view row(text.data() + start, end - start);
        start = end + 1;
        while (!row.empty() && (is_blank(row.front()))) row.remove_prefix(1);
        while (!row.empty() && (row.back() == '\r' || is_blank(row.back()))) row.remove_suffix(1);
        if (row.size() < 2) continue;
        if (row[0] == 'v' && is_blank(row[1])) {
            lines.vertices.push_back(line);
            std::istringstream fields{std::string(row.substr(2))};
            std::string field;
            for (int axis = 0; axis < 3; ++axis) {
                if (!(fields >> field)) {
                    diagnostics.error({file, line, "v"}, "vertex has fewer than 3 coordinates");
                    break;
                }
                if (!parse_double(field)) {
                    diagnostics.error({file, line, "v"}, std::string("vertex ") + "xyz"[axis] +
                                                             " \"" + field +
                                                             "\" is not a finite number");
                }
            }
        } else if (row[0] == 'f' && is_blank(row[1])) {
            lines.faces.push_back(line);
        } else if (row.substr(0, 6) == "usemtl" && row.size() > 6 && is_blank(row[6])) {
            lines.materials.push_back(line);
        }
    }
    return lines;
}

/// State of one load, shared with the tinyobjloader callbacks.
struct Loader {
    std::string file;
    const StatementLines* lines = nullptr;
    const std::function<std::optional<std::uint32_t>(const std::string&)>* material_index = nullptr;
    std::optional<std::uint32_t> current_material;
    bool material_known = true;  ///< false after a usemtl naming an unknown material
    Diagnostics* diagnostics = nullptr;
    model::Mesh mesh;
    std::size_t faces_seen = 0;
    std::size_t materials_seen = 0;
    bool reported_no_material = false;

    int line_of(const std::vector<int>& lines_of_kind, std::size_t index) const {
        return index < lines_of_kind.size() ? lines_of_kind[index] : 0;
    }
};

void on_vertex(void* user, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z,
               tinyobj::real_t /*w*/) {
    auto& loader = *static_cast<Loader*>(user);
    loader.mesh.vertices_m.push_back(
        {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)});
}

void on_usemtl(void* user, const char* name, int /*material_id*/) {
    auto& loader = *static_cast<Loader*>(user);
    const int line = loader.line_of(loader.lines->materials, loader.materials_seen++);
    std::string text(name);
    while (!text.empty() && is_blank(text.back())) text.pop_back();
    loader.current_material = (*loader.material_index)(text);
    loader.material_known = loader.current_material.has_value();
    if (!loader.material_known) {
        loader.diagnostics->error({loader.file, line, "usemtl"},
                                  "unknown material \"" + text + "\"");
    }
}

void on_face(void* user, tinyobj::index_t* indices, int count) {
    auto& loader = *static_cast<Loader*>(user);
    const int line = loader.line_of(loader.lines->faces, loader.faces_seen++);
    const ErrorContext where{loader.file, line, "f"};
    if (count < 3) {
        loader.diagnostics->error(
            where, "face has " + std::to_string(count) + " vertices, expected at least 3");
        return;
    }
    const auto n = static_cast<long long>(loader.mesh.vertices_m.size());
    std::vector<std::uint32_t> resolved;
    for (int k = 0; k < count; ++k) {
        const long long raw = indices[k].vertex_index;
        const long long index = raw > 0 ? raw - 1 : n + raw;
        if (raw == 0 || index < 0 || index >= n) {
            loader.diagnostics->error(where, "vertex index " + std::to_string(raw) +
                                                 " is out of range (" + std::to_string(n) +
                                                 " vertices so far)");
            return;
        }
        resolved.push_back(static_cast<std::uint32_t>(index));
    }
    if (!loader.material_known) return;  // reported at the usemtl
    if (!loader.current_material) {
        if (!loader.reported_no_material) {
            loader.diagnostics->error(where,
                                      "face has no material: no usemtl before it and no "
                                      "material given for the object");
            loader.reported_no_material = true;
        }
        return;
    }
    for (int k = 1; k + 1 < count; ++k) {
        loader.mesh.triangles.push_back({resolved[0], resolved[k], resolved[k + 1]});
        loader.mesh.triangle_materials.push_back(*loader.current_material);
    }
}

}  // namespace

model::Mesh parse_obj_mesh(std::string_view text, const std::string& display_name,
                           const MaterialLookup& material_index,
                           std::optional<std::uint32_t> default_material,
                           std::size_t material_count, Diagnostics& diagnostics) {
    const std::string& name = display_name;
    const std::size_t errors = diagnostics.error_count();
    const StatementLines lines = scan(text, name, diagnostics);

    Loader loader;
    loader.file = name;
    loader.lines = &lines;
    loader.material_index = &material_index;
    loader.current_material = default_material;
    loader.diagnostics = &diagnostics;

    tinyobj::callback_t callbacks;
    callbacks.vertex_cb = on_vertex;
    callbacks.usemtl_cb = on_usemtl;
    callbacks.index_cb = on_face;
    std::istringstream stream{std::string(text)};
    std::string warning;
    std::string error;
    if (!tinyobj::LoadObjWithCallback(stream, callbacks, &loader, nullptr, &warning, &error) ||
        !error.empty()) {
        while (!error.empty() && (error.back() == '\n' || error.back() == '.')) error.pop_back();
        diagnostics.error({name, 0, {}}, "cannot parse OBJ: " + error);
    }
    if (diagnostics.error_count() != errors) return {};
    validate_mesh(loader.mesh, material_count, {name, 0, {}}, diagnostics);
    return std::move(loader.mesh);
}

}  // namespace glint::mesh
