// SPDX-License-Identifier: Apache-2.0
// ENVI header formatting (standard keys in a fixed order, then extras; brace lists wrapped at
// 200 characters; numbers in shortest round-trip form; sanitized band names) and the naming
// rules that pair `<name>.img` with `<name>.img.hdr` or `<name>.hdr`.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <system_error>

#include "envi_text.h"
#include "glint/core/text.h"
#include "glint/io/envi.h"

namespace glint::io {
namespace {

using detail::is_space;
using detail::normalize_key;
using detail::split_list;
using detail::trim;

constexpr std::size_t kMaxLineChars = 200;
constexpr std::string_view kIndent = "  ";

std::string format_number(double value) { return format_shortest(value); }

/// No line breaks inside a one-line value.
std::string one_line(std::string_view text) {
    std::string out(trim(text));
    std::replace_if(
        out.begin(), out.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    return out;
}

/// Appends `key = {p1 p2 ...}` where each piece carries its own trailing `,` (the last one
/// carries `}`), breaking lines between pieces so that none exceeds kMaxLineChars. A piece
/// longer than a line stands alone on its line.
void append_wrapped(std::string& out, std::string_view key,
                    const std::vector<std::string>& pieces) {
    std::string line = std::string(key) + " = {";
    if (pieces.empty()) {
        out += line + "}\n";
        return;
    }
    std::size_t separator = 0;  // no space right after `{` or the indent
    for (const std::string& piece : pieces) {
        if (line.size() + separator + piece.size() > kMaxLineChars && line != kIndent) {
            out += line;
            out += '\n';
            line = kIndent;
            separator = 0;
        }
        line.append(separator, ' ');
        line += piece;
        separator = 1;
    }
    out += line;
    out += '\n';
}

void append_list(std::string& out, std::string_view key, const std::vector<std::string>& items) {
    std::vector<std::string> pieces;
    pieces.reserve(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) {
        pieces.push_back(items[i] + (i + 1 < items.size() ? "," : "}"));
    }
    append_wrapped(out, key, pieces);
}

void append_text(std::string& out, std::string_view key, std::string_view text) {
    // Braces would end the value early; line breaks are only layout in ENVI.
    std::vector<std::string> words;
    std::string word;
    for (char c : text) {
        if (is_space(c)) {
            if (!word.empty()) words.push_back(std::move(word));
            word.clear();
            continue;
        }
        word += c == '{' ? '(' : c == '}' ? ')' : c;
    }
    if (!word.empty()) words.push_back(std::move(word));
    if (!words.empty()) words.back() += '}';
    append_wrapped(out, key, words);
}

}  // namespace

std::string format_envi_header(const EnviHeader& header) {
    std::string out = "ENVI\n";
    append_text(out, "description", header.description);
    out += "samples = " + std::to_string(header.samples) + "\n";
    out += "lines = " + std::to_string(header.lines) + "\n";
    out += "bands = " + std::to_string(header.bands) + "\n";
    out += "header offset = " + std::to_string(header.header_offset) + "\n";
    const std::string file_type = one_line(header.file_type);
    out += "file type = " + (file_type.empty() ? std::string("ENVI Standard") : file_type) + "\n";
    out += "data type = " + std::to_string(static_cast<int>(header.data_type)) + "\n";
    out += std::string("interleave = ") + interleave_name(header.interleave) + "\n";
    out += "byte order = " + std::to_string(static_cast<int>(header.byte_order)) + "\n";
    if (!trim(header.wavelength_units).empty()) {
        out += "wavelength units = " + one_line(header.wavelength_units) + "\n";
    }
    const auto append_numbers = [&](std::string_view key, const std::vector<double>& values) {
        if (values.empty()) return;
        std::vector<std::string> items;
        items.reserve(values.size());
        for (double value : values) items.push_back(format_number(value));
        append_list(out, key, items);
    };
    append_numbers("wavelength", header.wavelength);
    append_numbers("fwhm", header.fwhm);
    if (!header.band_names.empty()) {
        std::vector<std::string> names;
        names.reserve(header.band_names.size());
        for (const std::string& name : header.band_names) names.push_back(sanitize_band_name(name));
        append_list(out, "band names", names);
    }
    if (!trim(header.data_units).empty()) {
        out += "data units = " + one_line(header.data_units) + "\n";
    }
    for (const auto& [key, value] : header.extra) {
        const std::string name = normalize_key(key);
        const std::string text = one_line(value);
        const std::string line = name + " = " + text;
        if (line.size() > kMaxLineChars && text.size() >= 2 && text.front() == '{' &&
            text.back() == '}') {
            append_list(out, name, split_list(text));
        } else {
            out += line + "\n";
        }
    }
    return out;
}

std::string envi_brace_list(const std::vector<std::string>& items) {
    std::string out = "{";
    for (std::size_t i = 0; i < items.size(); ++i) {
        out += (i > 0 ? ", " : "") + sanitize_band_name(items[i]);
    }
    return out + "}";
}

std::vector<std::string> envi_list_items(std::string_view value) {
    return detail::split_list(value);
}

std::string sanitize_band_name(std::string_view name) {
    std::string out(name);
    for (char& c : out) {
        switch (c) {
            case ',':
                c = ';';
                break;
            case '{':
                c = '(';
                break;
            case '}':
                c = ')';
                break;
            case '\n':
            case '\r':
                c = ' ';
                break;
            default:
                break;
        }
    }
    return std::string(trim(out));
}

std::filesystem::path envi_header_path_for(const std::filesystem::path& data_path) {
    std::filesystem::path appended = data_path;
    appended += ".hdr";
    std::filesystem::path replaced = data_path;
    replaced.replace_extension(".hdr");
    std::error_code ec;
    if (replaced != appended && std::filesystem::is_regular_file(replaced, ec) &&
        !std::filesystem::exists(appended, ec)) {
        return replaced;
    }
    return appended;
}

std::filesystem::path envi_data_path_for(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".hdr") return path;
    std::filesystem::path stem = path;
    stem.replace_extension();
    std::error_code ec;
    for (const char* suffix : {"", ".img", ".dat", ".raw", ".bin"}) {
        std::filesystem::path candidate = stem;
        candidate += suffix;
        if (std::filesystem::is_regular_file(candidate, ec)) return candidate;
    }
    return stem;
}

}  // namespace glint::io
