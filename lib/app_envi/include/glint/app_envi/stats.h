// SPDX-License-Identifier: Apache-2.0
// `glint-envi stats FILE`: per-band count, min, max, mean and standard deviation of an ENVI
// file (or of any image OpenImageIO reads), streamed line by line. Mean and variance come
// from Neumaier-compensated sums of d = v - K and d^2, K being the band's first finite value
// (the shift keeps the variance free of cancellation for data far from zero; the
// compensation removes the rounding error that grows with the count; integer data give
// exact results). The standard deviation is the population one (divides by the count).
// NaN and ±infinity are not part of the statistics and are counted separately; so are
// values equal to a number the ENVI header gives as `data ignore value` (no data; a NaN
// ignore value, as glint's truth cubes have, is the NaN count).
//
// JSON: {"file", "samples", "lines", "bands", "data_type",
//        "data_ignore_value" (a number, "NaN", or absent),
//        "band_stats": [{"index", "name", "count", "nan", "inf", "ignored", "min", "max",
//                        "mean", "std"}]}   (min..std are null for a band without finite
//                                            values)
#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "glint/app_envi/report.h"
#include "glint/core/context.h"

namespace glint::app_envi {

/// Options of `stats`.
struct StatsOptions {
    std::filesystem::path file;
    ReportFormat format = ReportFormat::text;
};

/// Statistics of one band.
struct BandStatistics {
    std::uint64_t count = 0;     ///< finite values
    std::uint64_t nan = 0;       ///< NaN values
    std::uint64_t infinite = 0;  ///< ±infinity
    std::uint64_t ignored = 0;   ///< equal to a finite data ignore value
    double min = std::numeric_limits<double>::quiet_NaN();
    double max = std::numeric_limits<double>::quiet_NaN();
    double mean = std::numeric_limits<double>::quiet_NaN();
    double std_dev = std::numeric_limits<double>::quiet_NaN();  ///< population
};

/// Statistics of a file.
struct StatsReport {
    std::filesystem::path file;
    std::size_t samples = 0;
    std::size_t lines = 0;
    std::string data_type;
    std::optional<double> ignore_value;   ///< the header's data ignore value (may be NaN)
    std::vector<std::string> band_names;  ///< empty when the file names no bands
    std::vector<BandStatistics> bands;
};

/// Streams the file and computes the statistics of every band. Reports progress, polls
/// the cancel token; throws glint::Error naming the file.
StatsReport compute_stats(const std::filesystem::path& file, Context& ctx);

/// Writes a report as text (a table) or JSON.
void write_stats(const StatsReport& report, ReportFormat format, std::ostream& out);

/// compute_stats + write_stats; returns 0.
int report_stats(const StatsOptions& options, Context& ctx, std::ostream& out);

}  // namespace glint::app_envi
