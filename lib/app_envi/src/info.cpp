// SPDX-License-Identifier: Apache-2.0
// `glint-envi info`: text and JSON reports of ENVI headers.
#include "glint/app_envi/info.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <sstream>

#include "glint/app_envi/bin_commands.h"
#include "glint/core/error.h"
#include "glint/core/json_text.h"
#include "glint/core/stdio_name.h"
#include "glint/io/input_files.h"
#include "source.h"

namespace glint::app_envi {
namespace {

namespace fs = std::filesystem;
using internal::format_number;

constexpr std::string_view kGlintPrefix = "glint ";

bool is_glint_key(const std::string& key) { return key.rfind(kGlintPrefix, 0) == 0; }

std::string json_key(std::string key) {
    for (char& c : key) {
        if (c == ' ') c = '_';
    }
    return key;
}

const char* byte_order_name(io::ByteOrder order) {
    return order == io::ByteOrder::little ? "little" : "big";
}

nlohmann::ordered_json info_json(const fs::path& file, const io::EnviHeader& h,
                                 const fs::path& data_path, const fs::path& header_path) {
    nlohmann::ordered_json j;
    j["file"] = file.string();
    // A header read from standard input has no data file beside it.
    j["data_file"] =
        data_path.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(data_path.string());
    j["header_file"] = header_path.string();
    j["description"] = h.description;
    j["samples"] = h.samples;
    j["lines"] = h.lines;
    j["bands"] = h.bands;
    j["header_offset"] = h.header_offset;
    j["file_type"] = h.file_type;
    j["data_type"] = io::envi_type_name(h.data_type);
    j["data_type_code"] = static_cast<int>(h.data_type);
    j["interleave"] = io::interleave_name(h.interleave);
    j["byte_order"] = byte_order_name(h.byte_order);
    j["data_bytes"] = h.data_bytes();
    if (!h.wavelength_units.empty()) j["wavelength_units"] = h.wavelength_units;
    if (!h.data_units.empty()) j["data_units"] = h.data_units;
    nlohmann::ordered_json bands = nlohmann::ordered_json::array();
    for (std::size_t b = 0; b < h.bands; ++b) {
        nlohmann::ordered_json band;
        band["index"] = b;
        if (b < h.band_names.size()) band["name"] = h.band_names[b];
        if (b < h.wavelength.size()) band["wavelength"] = h.wavelength[b];
        if (b < h.fwhm.size()) band["fwhm"] = h.fwhm[b];
        bands.push_back(std::move(band));
    }
    j["band_info"] = std::move(bands);
    nlohmann::ordered_json glint = nlohmann::ordered_json::object();
    nlohmann::ordered_json extra = nlohmann::ordered_json::object();
    for (const auto& [key, value] : h.extra) {
        if (is_glint_key(key)) {
            glint[json_key(key.substr(kGlintPrefix.size()))] = value;
        } else {
            extra[key] = value;
        }
    }
    j["glint"] = std::move(glint);
    j["extra"] = std::move(extra);
    return j;
}

void field(std::ostream& out, const std::string& name, const std::string& value) {
    std::string label = name + ":";
    if (label.size() < 19) label.resize(19, ' ');
    out << "  " << label << value << '\n';
}

std::string pad(const std::string& text, std::size_t width) {
    return text.size() >= width ? text : std::string(width - text.size(), ' ') + text;
}

}  // namespace

std::string format_info_text(const fs::path& file, const io::EnviHeader& h,
                             const fs::path& data_path, const fs::path& header_path) {
    std::ostringstream out;
    out << file.string() << '\n';
    field(out, "data file",
          data_path.empty() ? "(none: header from standard input, no data file checked)"
                            : data_path.string());
    field(out, "header file", header_path.string());
    if (!h.description.empty()) field(out, "description", h.description);
    field(out, "samples", std::to_string(h.samples));
    field(out, "lines", std::to_string(h.lines));
    field(out, "bands", std::to_string(h.bands));
    field(out, "data type",
          std::string(io::envi_type_name(h.data_type)) + " (" +
              std::to_string(static_cast<int>(h.data_type)) + ")");
    field(out, "interleave", io::interleave_name(h.interleave));
    field(out, "byte order",
          std::to_string(static_cast<int>(h.byte_order)) + " (" + byte_order_name(h.byte_order) +
              " endian)");
    field(out, "header offset", std::to_string(h.header_offset));
    field(out, "file type", h.file_type);
    field(out, "data bytes", std::to_string(h.data_bytes()));
    if (!h.wavelength_units.empty()) field(out, "wavelength units", h.wavelength_units);
    if (!h.data_units.empty()) field(out, "data units", h.data_units);

    const bool wavelengths = !h.wavelength.empty();
    const bool fwhm = !h.fwhm.empty();
    out << "  band list:\n    " << pad("index", 5);
    if (wavelengths) out << "  " << pad("wavelength", 12);
    if (fwhm) out << "  " << pad("fwhm", 12);
    out << "  name\n";
    for (std::size_t b = 0; b < h.bands; ++b) {
        out << "    " << pad(std::to_string(b), 5);
        if (wavelengths) out << "  " << pad(format_number(h.wavelength[b], 8), 12);
        if (fwhm) out << "  " << pad(format_number(h.fwhm[b], 8), 12);
        out << "  " << (b < h.band_names.size() ? h.band_names[b] : std::string("-")) << '\n';
    }

    bool any_glint = false;
    bool any_other = false;
    for (const auto& entry : h.extra) {
        (is_glint_key(entry.first) ? any_glint : any_other) = true;
    }
    if (any_glint) {
        out << "  glint provenance:\n";
        for (const auto& [key, value] : h.extra) {
            if (is_glint_key(key)) out << "    " << key << " = " << value << '\n';
        }
    }
    if (any_other) {
        out << "  other keys:\n";
        for (const auto& [key, value] : h.extra) {
            if (!is_glint_key(key)) out << "    " << key << " = " << value << '\n';
        }
    }
    return out.str();
}

std::string format_info_json(const fs::path& file, const io::EnviHeader& header,
                             const fs::path& data_path, const fs::path& header_path) {
    return json_text(info_json(file, header, data_path, header_path), 2);
}

namespace {

/// A header and where it came from: a file (checked against its data file) or standard input.
struct Described {
    io::EnviHeader header;
    fs::path data_path;  ///< empty for standard input
    fs::path header_path;
};

Described describe(const fs::path& file) {
    if (is_stdio_name(file)) {
        const std::string text = io::read_standard_input(io::kMaxEnviHeaderBytes, "header");
        return {io::parse_envi_header(text, io::kStandardInputName), {}, file};
    }
    const io::EnviReader reader(file, io::EnviReader::LineUse::describe_only);
    return {reader.header(), reader.data_path(), reader.header_path()};
}

}  // namespace

int report_info(const InfoOptions& options, Context& ctx, std::ostream& out) {
    if (options.files.empty()) throw usage_error("no files to report on");
    if (std::count_if(options.files.begin(), options.files.end(), is_stdio_name) > 1) {
        throw usage_error("standard input ('-') can be named once");
    }
    int status = 0;
    nlohmann::ordered_json all = nlohmann::ordered_json::array();
    bool first = true;
    for (const auto& file : options.files) {
        ctx.cancel.throw_if_cancelled();
        try {
            if (!is_stdio_name(file) && is_lidar_bin(file)) {
                const BinSummary bin = summarize_bin(file, ctx.cancel);
                if (options.format == ReportFormat::json) {
                    all.push_back(nlohmann::ordered_json::parse(format_bin_json(file, bin)));
                } else {
                    if (!first) out << '\n';
                    out << format_bin_text(file, bin);
                    first = false;
                }
                continue;
            }
            const Described d = describe(file);
            if (options.format == ReportFormat::json) {
                all.push_back(info_json(file, d.header, d.data_path, d.header_path));
            } else {
                if (!first) out << '\n';
                out << format_info_text(file, d.header, d.data_path, d.header_path);
                first = false;
            }
        } catch (const Error& e) {
            if (e.category() == ErrorCategory::cancelled) throw;
            ctx.log.error(e.with_file(file.string()).what());
            status = 1;
        }
    }
    if (options.format == ReportFormat::json && !all.empty()) {
        out << json_text(options.files.size() == 1 ? all.front() : all, 2) << '\n';
    }
    return status;
}

}  // namespace glint::app_envi
