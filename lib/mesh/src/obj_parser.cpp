// SPDX-License-Identifier: Apache-2.0
// Wavefront OBJ parsing (glint/mesh/mesh.h), in one pass over the text, with no allocation
// for a well-formed line. It reads what tinyobjloader 2.0's callback parser read when glint
// used it, value for value (obj_numbers.h), and reports what glint's checks around it
// reported, in the same order: first, in file order, the vertex coordinates that are not
// finite numbers and the face indices that are not integers in range as written (no
// narrowing: "4294967299" is not 3); then, in file order, unknown materials, faces with fewer
// than 3 vertices and faces without a material. Lines end at "\n", "\r\n" or "\r"; a line is
// read up to its first NUL.
#include <array>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "glint/core/text.h"
#include "glint/mesh/mesh.h"
#include "obj_numbers.h"

namespace glint::mesh {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t'; }

std::string_view skip_blanks(std::string_view text) {
    std::size_t at = 0;
    while (at < text.size() && is_blank(text[at])) ++at;
    return text.substr(at);
}

/// One face index as written: a base-10 integer, 1..count or -count..-1 (relative). Sets
/// `value` and returns nullopt when it is one, or returns the problem. An empty texture or
/// normal index means none (`1//3`, `1/2`).
std::optional<std::string> index_problem(std::string_view text, long long count, const char* what,
                                         const char* counted, bool optional, long long& value) {
    value = 0;
    if (text.empty() && optional) return std::nullopt;
    bool integer = false;
    bool overflow = false;
    if (!text.empty() && text.size() <= 18 && detail::is_digit(text.front())) {
        // The hot path: up to 18 digits, no sign, never out of long long's range.
        integer = true;
        for (const char c : text) {
            if (!detail::is_digit(c)) {
                integer = false;
                break;
            }
            value = value * 10 + (c - '0');
        }
    }
    if (!integer) {
        std::string_view digits = text;
        if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
        const auto [end, error] =
            std::from_chars(digits.data(), digits.data() + digits.size(), value);
        integer = !digits.empty() && end == digits.data() + digits.size() &&
                  (error == std::errc{} || error == std::errc::result_out_of_range) &&
                  digits.front() != '+';
        overflow = error == std::errc::result_out_of_range;
    }
    if (!integer) return std::string(what) + " index " + quote(text) + " is not an integer";
    const bool in_range = !overflow && value != 0 && (value > 0 ? value <= count : value >= -count);
    if (!in_range) {
        return std::string(what) + " index " + std::string(text) + " is out of range (" +
               std::to_string(count) + " " + counted + " so far)";
    }
    return std::nullopt;
}

/// Checks the x, y, z of a `v` statement (`rest`: the text after "v "), fields split at any
/// white space. The slow path: lines whose coordinates are not all plain decimals.
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

/// The state of one parse.
class ObjReader {
public:
    ObjReader(const std::string& file, const MaterialLookup& material_index,
              std::optional<std::uint32_t> default_material, Diagnostics& diagnostics)
        : m_file(file),
          m_material_index(material_index),
          m_material(default_material),
          m_diagnostics(diagnostics) {}

    /// One line, up to its end or first NUL.
    void statement(std::string_view row, int line);
    /// Reports the errors kept for after the whole text (see the file comment).
    void report_later_errors();
    model::Mesh& mesh() { return m_mesh; }

private:
    void vertex(std::string_view rest, int line);
    void texcoord(std::string_view rest);
    void face(std::string_view rest, int line);
    void use_material(std::string_view name, int line);
    /// The texture coordinates of the face just added (`count` corners, count − 2 triangles),
    /// when it or an earlier face gave any.
    void add_face_uvs(std::size_t count);
    /// Reads the indices of a face (`rest`: from its first index to the line's end), checking
    /// each as written; fills m_vertex_indices with each vertex index as tinyobjloader read it
    /// (atoi). Returns false when an index was reported.
    bool read_face(std::string_view rest, int line);
    bool index_ok(std::string_view text, long long count, const char* what, const char* counted,
                  bool optional, int line, long long& value);
    void later_error(int line, const char* element, std::string message) {
        m_later.push_back(
            {Diagnostic::Severity::error, {m_file, line, element}, std::move(message)});
    }

    const std::string& m_file;
    const MaterialLookup& m_material_index;
    std::optional<std::uint32_t> m_material;
    bool m_material_known = true;  ///< false after a usemtl naming an unknown material
    bool m_reported_no_material = false;
    Diagnostics& m_diagnostics;
    std::vector<Diagnostic> m_later;
    model::Mesh m_mesh;
    long long m_texcoords = 0;
    long long m_normals = 0;
    std::vector<std::array<float, 2>> m_uv_values;  ///< every `vt`, in order
    std::vector<int> m_vertex_indices;              ///< of the current face, reused
    /// Of the current face: each corner's texture coordinate as written (0: none).
    std::vector<long long> m_texcoord_indices;
};

void ObjReader::statement(std::string_view row, int line) {
    row = skip_blanks(row);
    if (row.size() < 2) return;
    if (row[0] == 'v' && is_blank(row[1])) {
        vertex(row.substr(2), line);
    } else if (row[0] == 'v' && row.size() > 2 && is_blank(row[2]) && row[1] == 't') {
        texcoord(row.substr(3));
    } else if (row[0] == 'v' && row.size() > 2 && is_blank(row[2]) && row[1] == 'n') {
        ++m_normals;
    } else if (row[0] == 'f' && is_blank(row[1])) {
        const std::string_view rest = skip_blanks(row.substr(2));
        if (!rest.empty()) face(rest, line);  // tinyobjloader reported no face
    } else if (row.substr(0, 6) == "usemtl" && row.size() > 6 && is_blank(row[6])) {
        use_material(row.substr(7), line);
    }
}

void ObjReader::texcoord(std::string_view rest) {
    // u and v as tinyobjloader reads them (a missing or unreadable one is 0); w is not used.
    std::array<double, 2> uv{};
    const char* p = rest.data();
    const char* const end = p + rest.size();
    for (double& value : uv) {
        while (p != end && is_blank(*p)) ++p;
        const char* const token = p;
        while (p != end && !is_blank(*p)) ++p;
        if (!detail::plain_real(token, p, value))
            value = detail::legacy_real(token, p).value_or(0.0);
    }
    m_uv_values.push_back({static_cast<float>(uv[0]), static_cast<float>(uv[1])});
    ++m_texcoords;
}

void ObjReader::vertex(std::string_view rest, int line) {
    // tinyobjloader's fields: split at blanks only, a missing or unreadable one is 0.
    std::array<double, 3> xyz{};
    bool plain = true;
    const char* p = rest.data();
    const char* const end = p + rest.size();
    for (double& value : xyz) {
        while (p != end && is_blank(*p)) ++p;
        const char* const token = p;
        while (p != end && !is_blank(*p)) ++p;
        if (plain && detail::plain_real(token, p, value)) continue;
        plain = false;
        value = detail::legacy_real(token, p).value_or(0.0);
    }
    // Three plain decimals are three fields however white space splits them, and valid.
    if (!plain) check_vertex(rest, {m_file, line, "v"}, m_diagnostics);
    // Far from the file's origin (UTM coordinates), vertices are kept relative to the
    // first one's whole metres (model::Mesh::origin_m), so floats keep their millimetres.
    if (m_mesh.vertices_m.empty()) m_mesh.origin_m = model::mesh_origin_for(xyz);
    const std::array<double, 3>& o = m_mesh.origin_m;
    m_mesh.vertices_m.push_back({static_cast<float>(xyz[0] - o[0]),
                                 static_cast<float>(xyz[1] - o[1]),
                                 static_cast<float>(xyz[2] - o[2])});
}

bool ObjReader::index_ok(std::string_view text, long long count, const char* what,
                         const char* counted, bool optional, int line, long long& value) {
    std::optional<std::string> problem = index_problem(text, count, what, counted, optional, value);
    if (!problem) return true;
    m_diagnostics.error({m_file, line, "f"}, std::move(*problem));
    return false;
}

bool ObjReader::read_face(std::string_view rest, int line) {
    // Split as tinyobjloader's parseRawTriple splits: v, v/t, v//n, v/t/n.
    const auto field_end = [&rest](std::size_t at) {
        while (at < rest.size() && rest[at] != '/' && !is_blank(rest[at]) && rest[at] != '\r') {
            ++at;
        }
        return at;
    };
    const auto vertices = static_cast<long long>(m_mesh.vertices_m.size());
    m_vertex_indices.clear();
    m_texcoord_indices.clear();
    std::size_t at = 0;
    long long value = 0;
    while (at < rest.size()) {
        // The hot path: a plain vertex index in range ("123"), then a blank or the end.
        std::size_t digits_end = at;
        value = 0;
        while (digits_end < rest.size() && digits_end - at < 18 &&
               detail::is_digit(rest[digits_end])) {
            value = value * 10 + (rest[digits_end++] - '0');
        }
        if (digits_end > at && (digits_end == rest.size() || is_blank(rest[digits_end])) &&
            value >= 1 && value <= vertices) {
            m_vertex_indices.push_back(static_cast<int>(value));
            m_texcoord_indices.push_back(0);
            at = digits_end;
            while (at < rest.size() && is_blank(rest[at])) ++at;
            continue;
        }
        std::size_t end = field_end(at);
        const std::string_view field = rest.substr(at, end - at);
        if (!index_ok(field, vertices, "vertex", "vertices", false, line, value)) return false;
        // atoi: "+-3" is 0; otherwise the value, in int as tinyobjloader holds it.
        m_vertex_indices.push_back(
            field.size() > 1 && field[0] == '+' && field[1] == '-' ? 0 : static_cast<int>(value));
        m_texcoord_indices.push_back(0);
        at = end;
        if (at < rest.size() && rest[at] == '/') {
            ++at;
            const bool no_texcoord = at < rest.size() && rest[at] == '/';
            if (!no_texcoord) {
                end = field_end(at);
                if (!index_ok(rest.substr(at, end - at), m_texcoords, "texture coordinate",
                              "texture coordinates", true, line, value)) {
                    return false;
                }
                if (end > at) m_texcoord_indices.back() = value;
                at = end;
            }
            if (at < rest.size() && rest[at] == '/') {
                ++at;
                end = field_end(at);
                if (!index_ok(rest.substr(at, end - at), m_normals, "normal", "normals", true, line,
                              value)) {
                    return false;
                }
                at = end;
            }
        }
        while (at < rest.size() && (is_blank(rest[at]) || rest[at] == '\r')) ++at;
    }
    return true;
}

void ObjReader::face(std::string_view rest, int line) {
    if (!read_face(rest, line)) return;
    const std::size_t count = m_vertex_indices.size();
    if (count < 3) {
        later_error(line, "f",
                    "face has " + std::to_string(count) + " vertices, expected at least 3");
        return;
    }
    // read_face checked the indices as written; this guards the values tinyobjloader read
    // ("+-3" is 0).
    const auto n = static_cast<long long>(m_mesh.vertices_m.size());
    for (int& raw : m_vertex_indices) {
        const long long index = raw > 0 ? raw - 1LL : n + raw;
        if (raw == 0 || index < 0 || index >= n) {
            later_error(line, "f",
                        "vertex index " + std::to_string(raw) + " is out of range (" +
                            std::to_string(n) + " vertices so far)");
            return;
        }
        raw = static_cast<int>(index);
    }
    if (!m_material_known) return;  // reported at the usemtl
    if (!m_material) {
        if (!m_reported_no_material) {
            later_error(line, "f",
                        "face has no material: no usemtl before it and no material given for "
                        "the object");
            m_reported_no_material = true;
        }
        return;
    }
    const auto corner = [this](std::size_t k) {
        return static_cast<std::uint32_t>(m_vertex_indices[k]);
    };
    for (std::size_t k = 1; k + 1 < count; ++k) {
        m_mesh.triangles.push_back({corner(0), corner(k), corner(k + 1)});
        m_mesh.triangle_materials.push_back(*m_material);
    }
    add_face_uvs(count);
}

void ObjReader::add_face_uvs(std::size_t count) {
    const auto uv = [this](std::size_t k) -> std::optional<std::array<float, 2>> {
        const long long raw = m_texcoord_indices[k];
        const auto n = static_cast<long long>(m_uv_values.size());
        const long long index = raw > 0 ? raw - 1 : n + raw;
        if (raw == 0 || index < 0 || index >= n) return std::nullopt;
        return m_uv_values[static_cast<std::size_t>(index)];
    };
    bool all = true;
    for (std::size_t k = 0; k < count && all; ++k) all = uv(k).has_value();
    if (!all && m_mesh.triangle_uvs.empty()) return;
    // The first face with texture coordinates gives the faces before it NaN ones.
    constexpr float nan = std::numeric_limits<float>::quiet_NaN();
    m_mesh.triangle_uvs.resize(m_mesh.triangles.size() - (count - 2),
                               {nan, nan, nan, nan, nan, nan});
    for (std::size_t k = 1; k + 1 < count; ++k) {
        std::array<float, 6> corners{nan, nan, nan, nan, nan, nan};
        if (all) {
            std::size_t at = 0;
            for (const std::size_t c : {std::size_t{0}, k, k + 1}) {
                const std::array<float, 2> value = *uv(c);
                corners[at++] = value[0];
                corners[at++] = value[1];
            }
        }
        m_mesh.triangle_uvs.push_back(corners);
    }
}

void ObjReader::use_material(std::string_view name, int line) {
    while (!name.empty() && is_blank(name.back())) name.remove_suffix(1);
    const std::string text(name);
    m_material = m_material_index(text);
    m_material_known = m_material.has_value();
    if (!m_material_known) later_error(line, "usemtl", "unknown material \"" + text + "\"");
}

void ObjReader::report_later_errors() {
    for (Diagnostic& diagnostic : m_later) {
        m_diagnostics.error(std::move(diagnostic.where), std::move(diagnostic.message));
    }
    m_later.clear();
}

/// Where the first '\n', '\r' or NUL of [p, end) is (`end` if none), eight bytes at a time.
const char* first_line_break(const char* p, const char* const end) {
    if constexpr (std::endian::native == std::endian::little) {
        constexpr std::uint64_t ones = 0x0101010101010101u;
        constexpr std::uint64_t highs = 0x8080808080808080u;
        // The lowest byte flagged is the first zero byte (flags above it may be false).
        const auto zero_bytes = [](std::uint64_t w) { return (w - ones) & ~w & highs; };
        for (; end - p >= 8; p += 8) {
            std::uint64_t word = 0;
            std::memcpy(&word, p, 8);
            const std::uint64_t found = zero_bytes(word) | zero_bytes(word ^ (ones * '\n')) |
                                        zero_bytes(word ^ (ones * '\r'));
            if (found != 0) return p + std::countr_zero(found) / 8;
        }
    }
    while (p != end && *p != '\n' && *p != '\r' && *p != '\0') ++p;
    return p;
}

/// The end of the line starting at `at`: the first "\n" or "\r" (or the text's end).
/// `content_end` is set to the end of what is read of it: the line's end or its first NUL.
std::size_t line_end(std::string_view text, std::size_t at, std::size_t& content_end) {
    const char* const begin = text.data();
    const char* const end = begin + text.size();
    const char* p = first_line_break(begin + at, end);
    content_end = static_cast<std::size_t>(p - begin);
    while (p != end && *p != '\n' && *p != '\r') ++p;
    return static_cast<std::size_t>(p - begin);
}

}  // namespace

model::Mesh parse_obj_mesh(std::string_view text, const std::string& display_name,
                           const MaterialLookup& material_index,
                           std::optional<std::uint32_t> default_material,
                           std::size_t material_count, Diagnostics& diagnostics) {
    const std::size_t errors = diagnostics.error_count();
    ObjReader reader(display_name, material_index, default_material, diagnostics);
    std::size_t start = 0;
    int line = 0;
    while (start < text.size()) {
        std::size_t content_end = 0;
        const std::size_t end = line_end(text, start, content_end);
        ++line;
        reader.statement(text.substr(start, content_end - start), line);
        start = end + 1;
        if (end < text.size() && text[end] == '\r' && start < text.size() && text[start] == '\n') {
            ++start;
        }
    }
    reader.report_later_errors();
    if (diagnostics.error_count() != errors) return {};
    model::Mesh& mesh = reader.mesh();
    validate_mesh(mesh, material_count, {display_name, 0, {}}, diagnostics);
    return std::move(mesh);
}

}  // namespace glint::mesh
