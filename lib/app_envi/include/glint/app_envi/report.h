// SPDX-License-Identifier: Apache-2.0
// What the report-writing subcommands of glint-envi (info, stats) share: the output format.
#pragma once

#include <optional>
#include <string_view>

namespace glint::app_envi {

/// `--format text|json` of a report.
enum class ReportFormat { text, json };

/// "text" or "json" → the format; nullopt otherwise.
std::optional<ReportFormat> report_format_from_name(std::string_view name);

}  // namespace glint::app_envi
