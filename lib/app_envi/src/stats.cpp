// SPDX-License-Identifier: Apache-2.0
// `glint-envi stats`: compensated, shifted sums per band over a streamed raster.
#include "glint/app_envi/stats.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "glint/core/error.h"
#include "glint/core/json_text.h"
#include "source.h"

namespace glint::app_envi {
namespace {

namespace fs = std::filesystem;
using internal::format_number;

/// Neumaier-compensated sum.
struct CompensatedSum {
    double sum = 0;
    double compensation = 0;
    void add(double v) {
        const double t = sum + v;
        compensation += std::fabs(sum) >= std::fabs(v) ? (sum - t) + v : (v - t) + sum;
        sum = t;
    }
    double value() const { return sum + compensation; }
};

/// Shifted compensated sums of d = v - K and d^2, K the band's first finite value: exact
/// for integer data (sums below 2^53), and free of the accumulation error of naive sums.
struct Accumulator {
    std::uint64_t count = 0;
    std::uint64_t nan = 0;
    std::uint64_t infinite = 0;
    std::uint64_t ignored = 0;
    double min = 0;
    double max = 0;
    double shift = 0;
    CompensatedSum sum;
    CompensatedSum sum_squares;

    void add(double v, const internal::RasterSource& source) {
        if (std::isnan(v)) {
            ++nan;
            return;
        }
        if (std::isinf(v)) {
            ++infinite;
            return;
        }
        if (source.is_no_data(v)) {
            ++ignored;
            return;
        }
        if (count == 0) {
            min = max = shift = v;
        } else {
            min = std::min(min, v);
            max = std::max(max, v);
        }
        ++count;
        const double d = v - shift;
        sum.add(d);
        sum_squares.add(d * d);
    }

    BandStatistics result() const {
        BandStatistics s;
        s.count = count;
        s.nan = nan;
        s.infinite = infinite;
        s.ignored = ignored;
        if (count > 0) {
            const double n = static_cast<double>(count);
            const double s1 = sum.value();
            s.min = min;
            s.max = max;
            s.mean = std::clamp(shift + s1 / n, min, max);
            s.std_dev = std::sqrt(std::max(0.0, (sum_squares.value() - s1 * (s1 / n)) / n));
        }
        return s;
    }
};

nlohmann::ordered_json number_or_null(double v) {
    return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

std::string cell(const std::string& text, std::size_t width) {
    return text.size() >= width ? text : std::string(width - text.size(), ' ') + text;
}

std::string stat_text(double v) { return std::isnan(v) ? "-" : format_number(v, 8); }

}  // namespace

StatsReport compute_stats(const fs::path& file, Context& ctx) {
    try {
        auto source = internal::RasterSource::open(file, ctx.max_memory_bytes);
        StatsReport report;
        report.file = file;
        report.samples = source->width();
        report.lines = source->height();
        report.data_type = source->type_name();
        report.ignore_value = source->ignore_value();
        report.band_names = source->band_names();
        for (const std::string& warning : source->warnings()) {
            ctx.log.warning(file.string() + ": " + warning);
        }
        const std::size_t bands = source->bands();
        std::vector<Accumulator> acc(bands);
        std::vector<double> line(source->width() * bands);
        for (std::size_t y = 0; y < source->height(); ++y) {
            ctx.cancel.throw_if_cancelled();
            source->read_line(y, line);
            for (std::size_t x = 0; x < source->width(); ++x) {
                const double* pixel = line.data() + x * bands;
                for (std::size_t b = 0; b < bands; ++b) acc[b].add(pixel[b], *source);
            }
            ctx.progress.update("stats", y + 1, source->height());
        }
        ctx.progress.finish("stats", source->height());
        for (const auto& a : acc) report.bands.push_back(a.result());
        return report;
    } catch (const Error& e) {
        throw e.with_file(file.string());
    }
}

void write_stats(const StatsReport& report, ReportFormat format, std::ostream& out) {
    if (format == ReportFormat::json) {
        nlohmann::ordered_json j;
        j["file"] = report.file.string();
        j["samples"] = report.samples;
        j["lines"] = report.lines;
        j["bands"] = report.bands.size();
        j["data_type"] = report.data_type;
        if (report.ignore_value) {
            j["data_ignore_value"] = std::isnan(*report.ignore_value)
                                         ? nlohmann::ordered_json("NaN")
                                         : nlohmann::ordered_json(*report.ignore_value);
        }
        nlohmann::ordered_json bands = nlohmann::ordered_json::array();
        for (std::size_t b = 0; b < report.bands.size(); ++b) {
            const BandStatistics& s = report.bands[b];
            nlohmann::ordered_json band;
            band["index"] = b;
            if (b < report.band_names.size()) band["name"] = report.band_names[b];
            band["count"] = s.count;
            band["nan"] = s.nan;
            band["inf"] = s.infinite;
            band["ignored"] = s.ignored;
            band["min"] = number_or_null(s.min);
            band["max"] = number_or_null(s.max);
            band["mean"] = number_or_null(s.mean);
            band["std"] = number_or_null(s.std_dev);
            bands.push_back(std::move(band));
        }
        j["band_stats"] = std::move(bands);
        out << json_text(j, 2) << '\n';
        return;
    }
    // An ignored column only for a finite data ignore value (NaN ones are the nan column).
    const bool ignored = report.ignore_value && !std::isnan(*report.ignore_value);
    out << report.file.string() << ": " << report.samples << " samples x " << report.lines
        << " lines x " << report.bands.size() << " bands, " << report.data_type;
    if (report.ignore_value) {
        out << ", data ignore value "
            << (ignored ? format_number(*report.ignore_value, 17) : std::string("NaN"));
    }
    out << '\n' << cell("band", 5) << cell("count", 11) << cell("nan", 8) << cell("inf", 8);
    if (ignored) out << cell("ignored", 11);
    out << cell("min", 16) << cell("max", 16) << cell("mean", 16) << cell("std", 16) << "  name\n";
    for (std::size_t b = 0; b < report.bands.size(); ++b) {
        const BandStatistics& s = report.bands[b];
        out << cell(std::to_string(b), 5) << cell(std::to_string(s.count), 11)
            << cell(std::to_string(s.nan), 8) << cell(std::to_string(s.infinite), 8);
        if (ignored) out << cell(std::to_string(s.ignored), 11);
        out << cell(stat_text(s.min), 16) << cell(stat_text(s.max), 16)
            << cell(stat_text(s.mean), 16) << cell(stat_text(s.std_dev), 16) << "  "
            << (b < report.band_names.size() ? report.band_names[b] : std::string("-")) << '\n';
    }
}

int report_stats(const StatsOptions& options, Context& ctx, std::ostream& out) {
    write_stats(compute_stats(options.file, ctx), options.format, out);
    return 0;
}

}  // namespace glint::app_envi
