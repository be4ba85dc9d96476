// SPDX-License-Identifier: Apache-2.0
// Tabulated lidar pulse shapes (glint/dirsig/pulse_shape.h).
#include "glint/dirsig/pulse_shape.h"

#include <optional>
#include <string>
#include <vector>

#include "glint/core/error.h"
#include "glint/core/text.h"
#include "named_text.h"

namespace glint::dirsig {

model::PulseShapeTable parse_pulse_shape(std::string_view text, const std::string& file_name,
                                         Diagnostics& diagnostics) {
    model::PulseShapeTable table;
    table.where = ErrorContext{file_name, 0, ""};
    int line = 0;
    int previous_line = 0;
    std::size_t start = 0;
    bool any_error = false;
    double total = 0.0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string row(text.substr(start, end - start));
        start = end + 1;
        ++line;
        if (const std::size_t hash = row.find('#'); hash != std::string::npos) row.resize(hash);
        for (char& c : row) {
            if (c == ',' || c == '\t' || c == '\r') c = ' ';
        }
        std::vector<std::string> fields;
        for (std::size_t i = 0; i < row.size();) {
            while (i < row.size() && row[i] == ' ') ++i;
            const std::size_t begin = i;
            while (i < row.size() && row[i] != ' ') ++i;
            if (i > begin) fields.push_back(row.substr(begin, i - begin));
        }
        if (fields.empty()) continue;
        const ErrorContext where{file_name, line, ""};
        const bool two = fields.size() == 2;
        const std::optional<double> time = two ? parse_double(fields[0]) : std::nullopt;
        const std::optional<double> power = two ? parse_double(fields[1]) : std::nullopt;
        if (!time || !power) {
            any_error = true;
            diagnostics.error(where, "pulse shape row \"" + std::string(trim(row)) +
                                         "\": expected two finite numbers, time (s) and "
                                         "relative power");
            continue;
        }
        if (*power < 0.0) {
            any_error = true;
            diagnostics.error(where, "pulse shape power " + format_shortest(*power) +
                                         " is negative, expected >= 0");
            continue;
        }
        if (!table.time_s.empty() && *time <= table.time_s.back()) {
            any_error = true;
            diagnostics.error(where, "pulse shape time " + format_shortest(*time) +
                                         " s does not follow the previous one (" +
                                         format_shortest(table.time_s.back()) + " s at line " +
                                         std::to_string(previous_line) +
                                         "), expected strictly increasing times");
            continue;
        }
        if (table.time_s.empty()) table.where.line = line;
        table.time_s.push_back(*time);
        table.power.push_back(*power);
        total += *power;
        previous_line = line;
    }
    if (!any_error && (table.time_s.size() < 2 || !(total > 0.0))) {
        diagnostics.error(ErrorContext{file_name, 0, ""},
                          "a pulse shape needs at least 2 rows (time s, relative power) with "
                          "some power > 0, found " +
                              std::to_string(table.time_s.size()) + " rows");
    }
    return table;
}

model::PulseShapeTable read_pulse_shape_file(const std::filesystem::path& file,
                                             const ReadOptions& options, Diagnostics& diagnostics,
                                             const std::string& display_name) {
    const std::string name = display_name.empty() ? file.string() : display_name;
    const std::optional<std::string> text =
        detail::read_named_text(file, name, "pulse shape file", options, diagnostics);
    if (!text) return {};
    return parse_pulse_shape(*text, name, diagnostics);
}

}  // namespace glint::dirsig
