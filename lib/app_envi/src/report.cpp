// SPDX-License-Identifier: Apache-2.0
// Report formats shared by `info` and `stats`.
#include "glint/app_envi/report.h"

namespace glint::app_envi {

std::optional<ReportFormat> report_format_from_name(std::string_view name) {
    if (name == "text") return ReportFormat::text;
    if (name == "json") return ReportFormat::json;
    return std::nullopt;
}

}  // namespace glint::app_envi
