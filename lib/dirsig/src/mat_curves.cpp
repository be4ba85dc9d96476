// SPDX-License-Identifier: Apache-2.0
// The `.mat` reader's curve files (mat_curves.h): a two-column curve (wavelength µm, value)
// or a classic DIRSIG `.ems` — a curve count, an angular table (read, not applied), then
// the curves after `CURVE_BEGIN` in µm or as rows of descending wavenumber in cm⁻¹; the
// first curve is used. A text that fits neither layout is one error, not one per row.
#include "mat_curves.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <optional>
#include <sstream>
#include <vector>

#include "glint/core/text.h"

namespace glint::dirsig::detail {
namespace {

/// One non-blank, non-comment row of a curve file, split into columns.
struct Row {
    int line = 0;
    std::vector<std::string> columns;
};

/// The rows of `text`: `#` starts a comment; blanks, tabs, commas and semicolons separate.
std::vector<Row> split_rows(const std::string& text) {
    std::vector<Row> rows;
    std::istringstream lines(text);
    std::string line;
    int number = 0;
    while (std::getline(lines, line)) {
        ++number;
        const std::size_t hash = line.find('#');
        if (hash != std::string::npos) line.resize(hash);
        for (char& c : line) {
            if (c == ',' || c == '\t' || c == ';' || c == '\r') c = ' ';
        }
        std::istringstream fields(line);
        Row row{number, {}};
        for (std::string word; fields >> word;) row.columns.push_back(word);
        if (!row.columns.empty()) rows.push_back(std::move(row));
    }
    return rows;
}

bool is_keyword(const Row& row, std::string_view keyword) {
    return row.columns.size() == 1 && to_lower(row.columns[0]) == to_lower(keyword);
}

/// A whole number of at most 6 digits (a classic `.ems`'s curve count or curve number).
std::optional<std::size_t> parse_whole(const std::string& text) {
    if (text.empty() || text.size() > 6) return std::nullopt;
    if (!std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; })) {
        return std::nullopt;
    }
    return std::stoul(text);
}

/// A whole number ≥ 1 (the curve count of a classic `.ems`).
std::optional<std::size_t> parse_count(const std::string& text) {
    const std::optional<std::size_t> n = parse_whole(text);
    if (n == 0) return std::nullopt;
    return n;
}

/// One curve as read: its first row's line and its samples in file order.
struct Curve {
    int line = 0;
    std::vector<double> x;  ///< wavelength µm or wavenumber cm⁻¹, as the layout says
    std::vector<double> values;
};

/// `value` to 6 significant digits (an excess of 0.10000000000000009 reads "0.1").
std::string short_number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

struct Parser {
    const CurveSource& source;
    Diagnostics& diagnostics;

    ErrorContext at(int line) const { return {source.file, line, source.element}; }

    /// The two numbers of `row`; an error (and nothing) when it is not two numbers, or when
    /// the value lies outside [0, source.max_value].
    std::optional<std::pair<double, double>> numbers(const Row& row, const char* x_name) {
        if (row.columns.size() != 2) {
            diagnostics.error(at(row.line), "expected 2 columns (" + std::string(x_name) +
                                                " value), got " +
                                                std::to_string(row.columns.size()));
            return std::nullopt;
        }
        const auto x = parse_double(row.columns[0]);
        const auto v = parse_double(row.columns[1]);
        if (!x || !v) {
            diagnostics.error(at(row.line), "expected two numbers, got \"" + row.columns[0] +
                                                "\" and \"" + row.columns[1] + "\"");
            return std::nullopt;
        }
        if (!(*v >= 0.0 && *v <= source.max_value && std::isfinite(*v))) {
            const bool bounded = std::isfinite(source.max_value);
            diagnostics.error(
                at(row.line),
                source.quantity + " " + format_shortest(*v) +
                    (bounded ? " is outside [0, " + format_shortest(source.max_value) + "]"
                             : " is not a finite number >= 0"));
            return std::nullopt;
        }
        return std::make_pair(*x, *v);
    }

    /// Adds a wavelength row to `table`, refusing a non-increasing or non-positive one.
    void add_wavelength(const Row& row, double w_um, double value, model::SpectralTable& table) {
        if (!(w_um > 0.0) || (!table.empty() && !(w_um > table.wavelengths_um.back()))) {
            diagnostics.error(at(row.line), "wavelength " + format_shortest(w_um) +
                                                " um is not positive and strictly increasing");
            return;
        }
        table.wavelengths_um.push_back(w_um);
        table.values.push_back(value);
    }

    void two_column(const std::vector<Row>& rows, model::SpectralTable& table) {
        for (const Row& row : rows) {
            if (const auto xv = numbers(row, "wavelength_um")) {
                add_wavelength(row, xv->first, xv->second, table);
            }
        }
    }

    /// The angular table from `rows[i]` on: rows of one scale (1° steps from 0°) or of
    /// `angle_deg scale` with angles increasing within 0–90°. Returns the first row after it.
    std::size_t angular_table(const std::vector<Row>& rows, std::size_t i) {
        const std::size_t first = i;
        bool all_one = true;
        double previous_deg = -1.0;
        for (; i < rows.size(); ++i) {
            const Row& row = rows[i];
            std::optional<double> scale;
            if (row.columns.size() == 1) {
                scale = parse_double(row.columns[0]);
                previous_deg += 1.0;
                if (!scale || previous_deg > 90.0) break;
            } else if (row.columns.size() == 2) {
                const auto angle = parse_double(row.columns[0]);
                scale = parse_double(row.columns[1]);
                if (!angle || !scale || !(*angle > previous_deg) || *angle > 90.0) break;
                previous_deg = *angle;
            } else {
                break;
            }
            all_one = all_one && *scale == 1.0;
        }
        if (i > first && !all_one) {
            diagnostics.warning(at(rows[first].line),
                                "the angular emissivity table (lines " +
                                    std::to_string(rows[first].line) + "-" +
                                    std::to_string(rows[i - 1].line) +
                                    ") is read, not applied: glint's surfaces emit as "
                                    "Lambertian, with the curve's values at every angle");
        }
        return i;
    }

    /// The `CURVE_BEGIN` layout: rows `wavelength_um value` after each CURVE_BEGIN, an
    /// optional CURVE_END after each curve.
    std::vector<Curve> wavelength_curves(const std::vector<Row>& rows, std::size_t i) {
        std::vector<Curve> curves;
        bool open = false;
        for (; i < rows.size(); ++i) {
            const Row& row = rows[i];
            if (is_keyword(row, "CURVE_BEGIN")) {
                curves.push_back(Curve{row.line, {}, {}});
                open = true;
                continue;
            }
            if (is_keyword(row, "CURVE_END")) {
                if (!open) diagnostics.error(at(row.line), "CURVE_END without CURVE_BEGIN");
                open = false;
                continue;
            }
            if (!open) {
                diagnostics.error(at(row.line),
                                  "expected CURVE_BEGIN, got \"" + row.columns[0] + "\"");
                continue;
            }
            const auto xv = numbers(row, "wavelength_um");
            if (!xv) continue;
            Curve& curve = curves.back();
            if (!(xv->first > 0.0) || (!curve.x.empty() && !(xv->first > curve.x.back()))) {
                diagnostics.error(at(row.line), "wavelength " + format_shortest(xv->first) +
                                                    " um is not positive and strictly increasing");
                continue;
            }
            curve.x.push_back(xv->first);
            curve.values.push_back(xv->second);
        }
        return curves;
    }

    /// The wavenumber layout: rows `wavenumber_cm-1 value` in descending wavenumber. A curve
    /// starts at a line holding its number alone (0, 1, …: DIRSIG's "old" .ems format), or,
    /// without such lines, at a row whose wavenumber is not below the previous one.
    std::vector<Curve> wavenumber_curves(const std::vector<Row>& rows, std::size_t i) {
        std::vector<Curve> curves;
        bool numbered = false;  // the curve just begun was started by its number line
        for (; i < rows.size(); ++i) {
            const Row& row = rows[i];
            if (row.columns.size() == 1) {
                const std::optional<std::size_t> index = parse_whole(row.columns[0]);
                if (!index || *index != curves.size()) {
                    diagnostics.error(at(row.line),
                                      "expected curve number " + std::to_string(curves.size()) +
                                          " or a row \"wavenumber_cm-1 value\", got \"" +
                                          row.columns[0] + "\"");
                }
                if (index) {  // a curve starts here, its number right or wrong
                    curves.push_back(Curve{row.line, {}, {}});
                    numbered = true;
                }
                continue;
            }
            const auto xv = numbers(row, "wavenumber_cm-1");
            if (!xv) continue;
            if (!(xv->first > 0.0)) {
                diagnostics.error(at(row.line), "wavenumber " + format_shortest(xv->first) +
                                                    " cm-1 is not positive");
                continue;
            }
            const bool begun = numbered && curves.back().x.empty();
            if (!begun && (curves.empty() || !(xv->first < curves.back().x.back()))) {
                if (numbered) {
                    diagnostics.error(at(row.line),
                                      "wavenumber " + format_shortest(xv->first) +
                                          " cm-1 is not below the previous row's (a numbered "
                                          "curve's rows descend)");
                    continue;
                }
                curves.push_back(Curve{row.line, {}, {}});
            }
            curves.back().x.push_back(xv->first);
            curves.back().values.push_back(xv->second);
        }
        return curves;
    }

    void classic_ems(const std::vector<Row>& rows, std::size_t count, model::SpectralTable& table,
                     std::vector<model::SpectralTable>* classes) {
        const std::size_t errors = diagnostics.error_count();
        const int count_line = rows.front().line;
        const std::size_t start = angular_table(rows, 1);
        const bool wavenumbers = start < rows.size() && !is_keyword(rows[start], "CURVE_BEGIN");
        std::vector<Curve> curves =
            wavenumbers ? wavenumber_curves(rows, start) : wavelength_curves(rows, start);
        if (diagnostics.error_count() != errors) return;
        if (curves.size() != count) {
            std::string message = "classic .ems: the first line gives " + std::to_string(count) +
                                  " curve(s), the file holds " + std::to_string(curves.size());
            if (wavenumbers) {
                message +=
                    " (without CURVE_BEGIN the rows are read as wavenumbers in cm-1, each curve "
                    "in descending order; a row not below the previous one starts a curve)";
            }
            diagnostics.error(at(count_line), message);
            return;
        }
        const Curve& first = curves.front();
        if (count > 1) {
            diagnostics.warning(at(count_line),
                                "classic .ems with " + std::to_string(count) +
                                    " curves (texture classes): glint uses the first (line " +
                                    std::to_string(first.line) +
                                    ") unless an enabled <texturemap> covers the material");
        }
        const auto convert = [&](const Curve& curve, model::SpectralTable& out) {
            if (wavenumbers) {
                // Descending cm⁻¹ is increasing µm: λ = 10⁴ / ν, in file order.
                for (std::size_t k = 0; k < curve.x.size(); ++k) {
                    out.wavelengths_um.push_back(1.0e4 / curve.x[k]);
                    out.values.push_back(curve.values[k]);
                }
            } else {
                out.wavelengths_um = curve.x;
                out.values = curve.values;
            }
        };
        convert(first, table);
        if (table.empty()) {
            diagnostics.error(at(first.line), "classic .ems: the first curve has no samples");
        }
        if (classes == nullptr || count < 2) return;
        for (const Curve& curve : curves) {
            model::SpectralTable& out = classes->emplace_back();
            out.file = table.file;
            out.where = at(curve.line);
            convert(curve, out);
            if (out.empty()) {
                diagnostics.error(at(curve.line), "classic .ems: a curve has no samples");
            }
        }
    }
};

}  // namespace

void parse_curve_text(const std::string& text, const CurveSource& source,
                      model::SpectralTable& table, Diagnostics& diagnostics,
                      std::vector<model::SpectralTable>* classes) {
    Parser parser{source, diagnostics};
    if (text.find('\0') != std::string::npos) {
        diagnostics.error(parser.at(0),
                          "binary data (a NUL byte), expected a text curve file (two columns "
                          "or a classic DIRSIG .ems)");
        return;
    }
    const std::vector<Row> rows = split_rows(text);
    if (rows.empty()) {
        diagnostics.error(parser.at(0), source.quantity + " curve file has no samples");
        return;
    }
    const Row& head = rows.front();
    if (head.columns.size() == 1) {
        if (const auto count = parse_count(head.columns[0])) {
            parser.classic_ems(rows, *count, table, classes);
            return;
        }
        diagnostics.error(parser.at(head.line),
                          "\"" + head.columns[0] +
                              "\" is not a curve file's first line: expected \"wavelength_um "
                              "value\" (a two-column curve) or a curve count (a classic DIRSIG "
                              ".ems)");
        return;
    }
    const std::size_t errors = diagnostics.error_count();
    parser.two_column(rows, table);
    if (table.empty() && diagnostics.error_count() == errors) {
        diagnostics.error(parser.at(0), source.quantity + " curve file has no samples");
    }
}

void limit_reflectance(model::Material& material, Diagnostics& diagnostics) {
    const auto [lo_um, hi_um] = model::measured_range_um(material);
    std::vector<double> knots = material.reflectance.wavelengths_um;
    for (const double w : material.emissivity.wavelengths_um) {
        if (w >= lo_um && w <= hi_um) knots.push_back(w);
    }
    std::sort(knots.begin(), knots.end());
    knots.erase(std::unique(knots.begin(), knots.end()), knots.end());
    double worst = 0.0;
    double worst_at_um = 0.0;
    std::vector<double> values;
    for (const double w : knots) {
        const double rho = model::sample_held(material.reflectance, w);
        if (w < lo_um || w > hi_um) {
            values.push_back(rho);
            continue;
        }
        const double eps = model::sample_held(material.emissivity, w);
        if (eps + rho - 1.0 > worst) {
            worst = eps + rho - 1.0;
            worst_at_um = w;
        }
        values.push_back(std::clamp(std::min(rho, 1.0 - eps), 0.0, 1.0));
    }
    if (!(worst > model::kEmissivityReflectanceSlack)) return;
    diagnostics.warning(material.where,
                        "material '" + material.id +
                            "': emissivity + reflectance exceed 1 by up "
                            "to " +
                            short_number(worst) + " (at " + short_number(worst_at_um) +
                            " um); the reflectance is lowered to 1 - emissivity there");
    material.reflectance.wavelengths_um = std::move(knots);
    material.reflectance.values = std::move(values);
}

}  // namespace glint::dirsig::detail
