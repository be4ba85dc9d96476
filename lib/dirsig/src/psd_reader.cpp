// SPDX-License-Identifier: Apache-2.0
// The PSD table reader and validator (glint/dirsig/psd_reader.h): splits each line of a PSD
// text file into fields, reports every malformed row with its file and line, and applies the
// same value rules to tables read from other inputs.
#include "glint/dirsig/psd_reader.h"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "glint/core/text.h"

namespace glint::dirsig {
namespace {

/// The fields of one line (comment already removed): separated by blanks, or by one comma
/// with optional blanks around it. Returns nullopt for an empty field (",," or a leading or
/// trailing comma).
std::optional<std::vector<std::string_view>> split_fields(std::string_view line) {
    std::vector<std::string_view> fields;
    std::size_t i = 0;
    const std::size_t n = line.size();
    auto skip_blanks = [&] {
        while (i < n && is_blank(line[i])) ++i;
    };
    skip_blanks();
    if (i < n && line[i] == ',') return std::nullopt;
    while (i < n) {
        const std::size_t start = i;
        while (i < n && !is_blank(line[i]) && line[i] != ',') ++i;
        fields.push_back(line.substr(start, i - start));
        skip_blanks();
        if (i < n && line[i] == ',') {
            ++i;
            skip_blanks();
            if (i >= n || line[i] == ',') return std::nullopt;
        }
    }
    return fields;
}

}  // namespace

model::PsdTable read_psd_file(const std::filesystem::path& file, const ReadOptions& options,
                              Diagnostics& diagnostics, const std::string& display_name) {
    model::PsdTable table;
    const std::string name = display_name.empty() ? file.string() : display_name;
    table.where.file = name;
    const std::optional<std::string> read = options.read_text_reported(file, name, diagnostics);
    if (!read) return table;
    const std::string& text = *read;
    std::string_view rest(text);
    if (rest.starts_with("\xEF\xBB\xBF")) rest.remove_prefix(3);

    int line_number = 0;
    int first_row_line = 0;
    std::size_t columns = 0;  // of the first good row: 2 or 3
    std::optional<double> previous_frequency_hz;
    std::size_t rows = 0;  // data rows seen, good or bad
    while (!rest.empty()) {
        ++line_number;
        const std::size_t newline = rest.find('\n');
        std::string_view line = rest.substr(0, newline);
        rest.remove_prefix(newline == std::string_view::npos ? rest.size() : newline + 1);
        if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) {
            line = line.substr(0, hash);
        }
        const ErrorContext where{name, line_number, {}};
        const auto fields = split_fields(line);
        if (!fields) {
            ++rows;
            diagnostics.error(where, "empty field: values are separated by blanks or one comma");
            continue;
        }
        if (fields->empty()) continue;
        ++rows;
        if (first_row_line == 0) first_row_line = line_number;
        if (fields->size() != 2 && fields->size() != 3) {
            diagnostics.error(where, "row has " + std::to_string(fields->size()) +
                                         " values, expected 2 or 3 (frequency psd [phase])");
            continue;
        }
        std::vector<double> values;
        bool numeric = true;
        for (std::size_t i = 0; i < fields->size(); ++i) {
            const std::optional<double> value = parse_double((*fields)[i]);
            if (!value) {
                static constexpr const char* kNames[] = {"frequency", "psd", "phase"};
                diagnostics.error(where, std::string(kNames[i]) + " '" + std::string((*fields)[i]) +
                                             "' is not a finite number");
                numeric = false;
                continue;
            }
            values.push_back(*value);
        }
        if (!numeric) continue;
        if (columns == 0) {
            columns = fields->size();
        } else if (fields->size() != columns) {
            diagnostics.error(where, "row has " + std::to_string(fields->size()) +
                                         " values but earlier rows have " +
                                         std::to_string(columns) +
                                         "; give a phase on every row or on none");
            continue;
        }
        bool good = true;
        model::check_psd_row(values[0], values[1], previous_frequency_hz,
                             [&](const std::string& message) {
                                 diagnostics.error(where, message);
                                 good = false;
                             });
        // A later row is compared with the last row that had a usable frequency.
        if (values[0] >= 0.0 && (!previous_frequency_hz || values[0] > *previous_frequency_hz)) {
            previous_frequency_hz = values[0];
        }
        if (!good) continue;
        table.frequency_hz.push_back(values[0]);
        table.psd.push_back(values[1]);
        if (columns == 3) table.phase_rad.push_back(values[2]);
    }
    table.where.line = first_row_line;
    if (rows < 2) {
        diagnostics.error(
            ErrorContext{name, first_row_line, {}},
            rows == 0 ? "PSD file has no data rows; a PSD needs at least 2 (frequency psd [phase])"
                      : "PSD file has only 1 data row; a PSD needs at least 2");
    }
    return table;
}

}  // namespace glint::dirsig
