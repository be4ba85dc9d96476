// SPDX-License-Identifier: Apache-2.0
// `glint-envi info FILE...`: what an ENVI file is — sizes, data type, interleave, byte order,
// header offset, bands (names, wavelengths, FWHM), units, description, the glint provenance
// keys (`glint ...`) and any other header keys — as text or JSON.
//
// JSON (one object per file; several files give an array of the objects of the files that
// could be read):
//   {"file", "header_file", "data_file", "description", "samples", "lines", "bands",
//    "header_offset", "file_type", "data_type" (name), "data_type_code", "interleave",
//    "byte_order" ("little"|"big"), "data_bytes", "wavelength_units", "data_units",
//    "band_info": [{"index", "name", "wavelength", "fwhm"}],   (absent fields omitted)
//    "glint": {key without the "glint " prefix: value},  "extra": {key: value}}
// Header values of extra keys are reported verbatim (brace lists stay strings).
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "glint/app_envi/report.h"
#include "glint/core/context.h"
#include "glint/io/envi.h"

namespace glint::app_envi {

/// Options of `info`.
struct InfoOptions {
    std::vector<std::filesystem::path> files;  ///< data files or headers
    ReportFormat format = ReportFormat::text;
};

/// Reports on every file to `out`. A file that cannot be read is reported through
/// ctx.log.error (naming it) and skipped; the others are still reported.
/// Returns 0 when every file was reported, 1 otherwise.
int report_info(const InfoOptions& options, Context& ctx, std::ostream& out);

/// The text report of one file (what report_info prints for it).
std::string format_info_text(const std::filesystem::path& file, const io::EnviHeader& header,
                             const std::filesystem::path& data_path,
                             const std::filesystem::path& header_path);
/// The JSON object of one file, serialized with 2-space indentation.
std::string format_info_json(const std::filesystem::path& file, const io::EnviHeader& header,
                             const std::filesystem::path& data_path,
                             const std::filesystem::path& header_path);

}  // namespace glint::app_envi
