// SPDX-License-Identifier: Apache-2.0
// ENVI header model and parser: `key = value` parsing (keys case-insensitive, brace values
// over several lines, `;` comments, unknown keys kept) and the validation that names file,
// line and key before anything data-sized is allocated. The data types are envi_types.cpp's.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <map>
#include <system_error>
#include <unordered_map>

#include "envi_text.h"
#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/io/envi.h"

namespace glint::io {
namespace detail {

/// Keys glint models; they are never written from `extra`.
constexpr std::string_view kStandardKeys[] = {
    "description", "samples",   "lines",      "bands",      "header offset",
    "file type",   "data type", "interleave", "byte order", "wavelength units",
    "wavelength",  "fwhm",      "band names", "data units",
};

bool is_standard_key(std::string_view key) {
    return std::find(std::begin(kStandardKeys), std::end(kStandardKeys), key) !=
           std::end(kStandardKeys);
}

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

std::string_view trim(std::string_view text) {
    while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
    while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
    return text;
}

std::string normalize_key(std::string_view key) {
    std::string out;
    bool pending_space = false;
    for (char c : trim(key)) {
        if (is_space(c)) {
            pending_space = true;
            continue;
        }
        if (pending_space) out += ' ';
        pending_space = false;
        out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return out;
}

std::string_view brace_content(std::string_view value) {
    if (value.size() >= 2 && value.front() == '{' && value.back() == '}') {
        return trim(value.substr(1, value.size() - 2));
    }
    return trim(value);
}

std::vector<std::string> split_list(std::string_view value) {
    const std::string_view content = brace_content(value);
    std::vector<std::string> items;
    if (content.empty()) return items;
    for (std::size_t start = 0;;) {
        const std::size_t comma = content.find(',', start);
        items.emplace_back(trim(content.substr(start, comma - start)));
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    // Tolerate one trailing comma ("{1, 2, }").
    if (items.size() > 1 && items.back().empty()) items.pop_back();
    return items;
}

}  // namespace detail

namespace {

using detail::brace_content;
using detail::is_standard_key;
using detail::normalize_key;
using detail::split_list;
using detail::trim;

/// One `key = value` of the header; `value` has its line breaks turned into single spaces.
struct Entry {
    std::string key;
    std::string value;
    int line = 0;
};

std::vector<Entry> split_entries(std::string_view text, const std::string& file) {
    std::vector<std::string_view> lines;
    for (std::size_t start = 0; start <= text.size();) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    constexpr std::string_view kBom = "\xEF\xBB\xBF";
    std::string_view first = lines.front();
    if (first.substr(0, kBom.size()) == kBom) first.remove_prefix(kBom.size());
    if (trim(first) != "ENVI") {
        throw input_error(
            "missing ENVI magic: the first line is " + quote(trim(first)) + ", expected \"ENVI\"",
            ErrorContext{file, 1, {}});
    }
    std::vector<Entry> entries;
    for (std::size_t i = 1; i < lines.size(); ++i) {
        const std::string_view line = trim(lines[i]);
        const int line_number = static_cast<int>(i + 1);
        if (line.empty() || line.front() == ';') continue;
        const std::size_t equals = line.find('=');
        if (equals == std::string_view::npos || trim(line.substr(0, equals)).empty()) {
            throw input_error("expected \"key = value\", got " + quote(line),
                              ErrorContext{file, line_number, {}});
        }
        Entry entry{normalize_key(line.substr(0, equals)),
                    std::string(trim(line.substr(equals + 1))), line_number};
        if (!entry.value.empty() && entry.value.front() == '{') {
            // A brace value runs to the first closing brace, possibly lines later.
            while (entry.value.find('}') == std::string::npos) {
                if (++i >= lines.size()) {
                    throw input_error("unterminated brace value (no closing \"}\")",
                                      ErrorContext{file, line_number, entry.key});
                }
                const std::string_view more = trim(lines[i]);
                if (more.empty()) continue;
                if (entry.value.size() > 1) entry.value += ' ';
                entry.value += more;
            }
            entry.value.resize(entry.value.find('}') + 1);
        }
        entries.push_back(std::move(entry));
    }
    return entries;
}

std::uint64_t parse_unsigned(const Entry& entry, const std::string& file, bool positive) {
    const std::string_view text = trim(entry.value);
    const ErrorContext context{file, entry.line, entry.key};
    const char* what = positive ? "expected a positive integer" : "expected an integer >= 0";
    std::uint64_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || end != text.data() + text.size()) {
        throw input_error(std::string(what) + ", got " + quote(text), context);
    }
    if (ec == std::errc::result_out_of_range) {
        throw input_error(std::string(what) + " below 2^64, got " + quote(text), context);
    }
    if (positive && value == 0) throw input_error("must be at least 1, got 0", context);
    return value;
}

double parse_number(std::string_view item, const Entry& entry, const std::string& file,
                    std::size_t index) {
    std::string_view text = trim(item);
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    double value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || end != text.data() + text.size() || ec != std::errc()) {
        throw input_error("value " + std::to_string(index + 1) + " is not a number: " + quote(item),
                          ErrorContext{file, entry.line, entry.key});
    }
    return value;
}

std::vector<double> parse_numbers(const Entry& entry, const std::string& file) {
    const std::vector<std::string> items = split_list(entry.value);
    std::vector<double> values;
    values.reserve(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) {
        values.push_back(parse_number(items[i], entry, file, i));
    }
    return values;
}

void check_list_length(std::size_t count, std::size_t bands, const char* what,
                       const ErrorContext& context) {
    if (count != bands) {
        throw input_error("has " + std::to_string(count) + " " + what + ", expected " +
                              std::to_string(bands) + " (one per band)",
                          context);
    }
}

}  // namespace

std::optional<std::string> EnviHeader::find_extra(std::string_view key) const {
    for (const auto& [name, value] : extra) {
        if (name == key) return value;
    }
    return std::nullopt;
}

void EnviHeader::set_extra(const std::string& key, const std::string& value) {
    for (auto& [name, old_value] : extra) {
        if (name == key) {
            old_value = value;
            return;
        }
    }
    extra.emplace_back(key, value);
}

std::uint64_t EnviHeader::data_bytes() const {
    std::uint64_t total = 0;
    if (__builtin_mul_overflow(static_cast<std::uint64_t>(samples),
                               static_cast<std::uint64_t>(lines), &total) ||
        __builtin_mul_overflow(total, static_cast<std::uint64_t>(bands), &total) ||
        __builtin_mul_overflow(total, static_cast<std::uint64_t>(value_bytes()), &total)) {
        throw input_error("image size overflows 64 bits: " + std::to_string(samples) +
                          " samples x " + std::to_string(lines) + " lines x " +
                          std::to_string(bands) + " bands x " + std::to_string(value_bytes()) +
                          " bytes");
    }
    return total;
}

void validate_envi_header(const EnviHeader& header, const std::string& file) {
    const auto check_size = [&](std::size_t value, const char* key) {
        if (value == 0) throw input_error("must be at least 1, got 0", ErrorContext{file, 0, key});
    };
    check_size(header.samples, "samples");
    check_size(header.lines, "lines");
    check_size(header.bands, "bands");
    if (!envi_type_from_code(static_cast<long>(header.data_type))) {
        throw input_error(
            "invalid data type code " + std::to_string(static_cast<int>(header.data_type)),
            ErrorContext{file, 0, "data type"});
    }
    try {
        std::uint64_t total = header.data_bytes();
        if (__builtin_add_overflow(total, header.header_offset, &total)) {
            throw input_error("header offset + image size overflows 64 bits");
        }
    } catch (const Error& error) {
        throw error.with_file(file);
    }
    if (!header.wavelength.empty()) {
        check_list_length(header.wavelength.size(), header.bands, "values",
                          ErrorContext{file, 0, "wavelength"});
    }
    if (!header.fwhm.empty()) {
        check_list_length(header.fwhm.size(), header.bands, "values",
                          ErrorContext{file, 0, "fwhm"});
    }
    if (!header.band_names.empty()) {
        check_list_length(header.band_names.size(), header.bands, "names",
                          ErrorContext{file, 0, "band names"});
    }
    for (const auto& [key, value] : header.extra) {
        const std::string normalized = normalize_key(key);
        if (normalized.empty() || key.find_first_of("=\n\r{}") != std::string::npos) {
            throw input_error("invalid header key " + quote(key), ErrorContext{file, 0, {}});
        }
        if (is_standard_key(normalized)) {
            throw input_error("is a standard key and cannot be an extra key",
                              ErrorContext{file, 0, key});
        }
    }
}

EnviHeader parse_envi_header(std::string_view text, const std::string& file) {
    const std::vector<Entry> entries = split_entries(text, file);
    std::map<std::string, const Entry*> standard;  // last occurrence wins, as in ENVI
    std::unordered_map<std::string_view, std::size_t> extra_index;  // key → slot in extra
    EnviHeader header;
    header.file_type.clear();
    for (const Entry& entry : entries) {
        if (is_standard_key(entry.key)) {
            standard[entry.key] = &entry;
            continue;
        }
        // A repeated extra key keeps its first place and its last value (set_extra's rule),
        // found by hash so 10⁵ keys stay linear.
        const auto [slot, added] = extra_index.emplace(entry.key, header.extra.size());
        if (added) {
            header.extra.emplace_back(entry.key, entry.value);
        } else {
            header.extra[slot->second].second = entry.value;
        }
    }
    const auto find = [&](const char* key) -> const Entry* {
        const auto it = standard.find(key);
        return it == standard.end() ? nullptr : it->second;
    };
    for (const char* key : {"samples", "lines", "bands", "data type"}) {
        if (!find(key)) {
            throw input_error(std::string("missing required key \"") + key + "\"",
                              ErrorContext{file, 0, {}});
        }
    }
    header.samples = parse_unsigned(*find("samples"), file, true);
    header.lines = parse_unsigned(*find("lines"), file, true);
    header.bands = parse_unsigned(*find("bands"), file, true);

    const Entry& type_entry = *find("data type");
    long code = 0;
    const std::string_view code_text = trim(type_entry.value);
    const auto [end, ec] =
        std::from_chars(code_text.data(), code_text.data() + code_text.size(), code);
    if (code_text.empty() || ec != std::errc() || end != code_text.data() + code_text.size()) {
        throw input_error("expected an ENVI data type code, got " + quote(code_text),
                          ErrorContext{file, type_entry.line, type_entry.key});
    }
    const std::optional<EnviDataType> type = envi_type_from_code(code);
    if (!type) {
        throw input_error("unknown ENVI data type code " + std::to_string(code) +
                              " (expected 1, 2, 3, 4, 5, 6, 9, 12, 13, 14 or 15)",
                          ErrorContext{file, type_entry.line, type_entry.key});
    }
    header.data_type = *type;

    if (const Entry* entry = find("header offset")) {
        header.header_offset = parse_unsigned(*entry, file, false);
    }
    if (const Entry* entry = find("interleave")) {
        const std::string value = normalize_key(entry->value);
        if (value == "bsq") {
            header.interleave = Interleave::bsq;
        } else if (value == "bil") {
            header.interleave = Interleave::bil;
        } else if (value == "bip") {
            header.interleave = Interleave::bip;
        } else {
            throw input_error("expected bsq, bil or bip, got " + quote(entry->value),
                              ErrorContext{file, entry->line, entry->key});
        }
    } else {
        header.interleave = Interleave::bsq;
    }
    if (const Entry* entry = find("byte order")) {
        const std::string_view value = trim(entry->value);
        if (value == "0") {
            header.byte_order = ByteOrder::little;
        } else if (value == "1") {
            header.byte_order = ByteOrder::big;
        } else {
            throw input_error("expected 0 (little-endian) or 1 (big-endian), got " + quote(value),
                              ErrorContext{file, entry->line, entry->key});
        }
    }
    if (const Entry* entry = find("description")) header.description = brace_content(entry->value);
    if (const Entry* entry = find("file type")) header.file_type = entry->value;
    if (const Entry* entry = find("wavelength units")) header.wavelength_units = entry->value;
    if (const Entry* entry = find("data units")) header.data_units = entry->value;
    if (const Entry* entry = find("wavelength")) {
        header.wavelength = parse_numbers(*entry, file);
        check_list_length(header.wavelength.size(), header.bands, "values",
                          ErrorContext{file, entry->line, entry->key});
    }
    if (const Entry* entry = find("fwhm")) {
        header.fwhm = parse_numbers(*entry, file);
        check_list_length(header.fwhm.size(), header.bands, "values",
                          ErrorContext{file, entry->line, entry->key});
    }
    if (const Entry* entry = find("band names")) {
        header.band_names = split_list(entry->value);
        check_list_length(header.band_names.size(), header.bands, "names",
                          ErrorContext{file, entry->line, entry->key});
    }
    try {
        std::uint64_t total = header.data_bytes();
        if (__builtin_add_overflow(total, header.header_offset, &total)) {
            throw input_error("header offset + image size overflows 64 bits");
        }
    } catch (const Error& error) {
        throw error.with_file(file);
    }
    return header;
}

}  // namespace glint::io
