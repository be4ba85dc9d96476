// SPDX-License-Identifier: Apache-2.0
// Wavefront OBJ parsing (glint/mesh/mesh.h). tinyobjloader's callback parser reads vertices,
// faces and `usemtl` names; a scan of the same text beforehand, splitting lines and spotting
// statements exactly as tinyobjloader does, finds the file line of every `v`, `f` and `usemtl`
// statement (tinyobjloader gives none), checks that vertex coordinates are finite numbers
// (tinyobjloader silently reads "nan" as 0) and range-checks every face index as written
// (tinyobjloader narrows them with atoi, so "4294967299" would wrap to 3).
#include <tiny_obj_loader.h>

#include <charconv>
#include <cstring>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "glint/core/text.h"
#include "glint/mesh/mesh.h"

namespace glint::mesh {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t'; }

/// The file lines of the statements tinyobjloader reports through its callbacks, in order,
/// and which faces the scan already reported as bad.
struct StatementLines {
    std::vector<int> vertices;
    std::vector<int> faces;
    std::vector<bool> bad_faces;  ///< one per face: an index was already reported
    std::vector<int> materials;
};

/// Counts of what a face index may refer to, so far in the file.
struct ElementCounts {
    long long vertices = 0;
    long long texcoords = 0;
    long long normals = 0;
};

/// Checks one index of a face as written: a base-10 integer, 1..count or -count..-1
/// (relative). Reports the problem at `where` and returns false otherwise. An empty texture
/// or normal index means none (`1//3`, `1/2`).
bool check_index(std::string_view text, long long count, const char* what, const char* counted,
                 bool optional, const ErrorContext& where, Diagnostics& diagnostics) {
    if (text.empty() && optional) return true;
    std::string_view digits = text;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    long long value = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    const bool integer = !digits.empty() && end == digits.data() + digits.size() &&
                         (error == std::errc{} || error == std::errc::result_out_of_range) &&
                         digits.front() != '+';
    if (!integer) {
        diagnostics.error(where,
                          std::string(what) + " index " + quote(text) + " is not an integer");
        return false;
    }
    const bool in_range =
        error == std::errc{} && value != 0 && (value > 0 ? value <= count : value >= -count);
    if (!in_range) {
        diagnostics.error(where, std::string(what) + " index " + std::string(text) +
                                     " is out of range (" + std::to_string(count) + " " + counted +
                                     " so far)");
        return false;
    }
    return true;
}

/// Checks the indices of one face statement (`rest`: the text after "f" and its blanks,
/// ending at the line's end), splitting them exactly as tinyobjloader's parseRawTriple does.
/// Returns false when an index was reported.
bool check_face(std::string_view rest, const ElementCounts& counts, const ErrorContext& where,
                Diagnostics& diagnostics) {
    const auto field_end = [&rest](std::size_t at) {
        const std::size_t end = rest.find_first_of("/ \t\r", at);
        return end == std::string_view::npos ? rest.size() : end;
    };
    std::size_t at = 0;
    while (at < rest.size()) {
        std::size_t end = field_end(at);
        if (!check_index(rest.substr(at, end - at), counts.vertices, "vertex", "vertices", false,
                         where, diagnostics)) {
            return false;
        }
        at = end;
        if (at < rest.size() && rest[at] == '/') {
            ++at;
            const bool no_texcoord = at < rest.size() && rest[at] == '/';
            if (!no_texcoord) {
                end = field_end(at);
                if (!check_index(rest.substr(at, end - at), counts.texcoords, "texture coordinate",
                                 "texture coordinates", true, where, diagnostics)) {
                    return false;
                }
                at = end;
            }
            if (at < rest.size() && rest[at] == '/') {
                ++at;
                end = field_end(at);
                if (!check_index(rest.substr(at, end - at), counts.normals, "normal", "normals",
                                 true, where, diagnostics)) {
                    return false;
                }
                at = end;
            }
        }
        while (at < rest.size() && (is_blank(rest[at]) || rest[at] == '\r')) ++at;
    }
    return true;
}

/// Checks the x, y, z of a `v` statement (`rest`: the text after "v ").
void check_vertex(std::string_view rest, const ErrorContext& where, Diagnostics& diagnostics) {
    std::istringstream fields{std::string(rest)};
    std::string field;
    for (int axis = 0; axis < 3; ++axis) {
        if (!(fields >> field)) {
            diagnostics.error(where, "vertex has fewer than 3 coordinates");
            return;
        }
        if (!parse_double(field)) {
            diagnostics.error(where, std::string("vertex ") + "xyz"[axis] + " \"" + field +
                                         "\" is not a finite number");
        }
    }
}

/// Scans `text` as tinyobjloader reads it: lines end at "\n", "\r\n" or "\r"; a line is read
/// up to its first NUL; the statement is the first token after blanks. Reports bad vertices
/// and face indices.
StatementLines scan(std::string_view text, const std::string& file, Diagnostics& diagnostics) {
    StatementLines lines;
    ElementCounts counts;
    std::size_t start = 0;
    int line = 0;
    while (start < text.size()) {
        std::size_t end = text.find_first_of("\r\n", start);
        if (end == std::string_view::npos) end = text.size();
        ++line;
        std::string_view row(text.data() + start, end - start);
        start = end + 1;
        if (end < text.size() && text[end] == '\r' && start < text.size() && text[start] == '\n') {
            ++start;
        }
        if (const std::size_t nul = row.find('\0'); nul != std::string_view::npos) {
            row = row.substr(0, nul);
        }
        while (!row.empty() && is_blank(row.front())) row.remove_prefix(1);
        if (row.size() < 2) continue;
        if (row[0] == 'v' && is_blank(row[1])) {
            lines.vertices.push_back(line);
            ++counts.vertices;
            check_vertex(row.substr(2), {file, line, "v"}, diagnostics);
        } else if (row[0] == 'v' && row.size() > 2 && is_blank(row[2]) &&
                   (row[1] == 't' || row[1] == 'n')) {
            ++(row[1] == 't' ? counts.texcoords : counts.normals);
        } else if (row[0] == 'f' && is_blank(row[1])) {
            std::string_view rest = row.substr(2);
            while (!rest.empty() && is_blank(rest.front())) rest.remove_prefix(1);
            if (rest.empty()) continue;  // tinyobjloader reports no face
            lines.faces.push_back(line);
            lines.bad_faces.push_back(!check_face(rest, counts, {file, line, "f"}, diagnostics));
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
    const std::size_t face = loader.faces_seen++;
    if (face < loader.lines->bad_faces.size() && loader.lines->bad_faces[face]) return;
    const int line = loader.line_of(loader.lines->faces, face);
    const ErrorContext where{loader.file, line, "f"};
    if (count < 3) {
        loader.diagnostics->error(
            where, "face has " + std::to_string(count) + " vertices, expected at least 3");
        return;
    }
    // The scan checked the indices as written; this guards the narrowed values anyway.
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
