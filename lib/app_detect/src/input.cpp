// SPDX-License-Identifier: Apache-2.0
// glint-detect's inputs besides the pixels: the focal plane, the seed, the capture map.
#include "input.h"

#include <cmath>
#include <string>

#include "glint/core/diagnostics.h"
#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/dirsig/readers.h"
#include "glint/io/envi.h"
#include "glint/io/envi_part.h"

namespace glint::app_detect::internal {
namespace {

std::string trim(const std::string& text) {
    const auto begin = text.find_first_not_of(" \t\r\n");
    if (begin == std::string::npos) return {};
    const auto end = text.find_last_not_of(" \t\r\n");
    return text.substr(begin, end - begin + 1);
}

std::optional<std::uint64_t> parse_unsigned(const std::string& text) {
    const std::string t = trim(text);
    if (t.empty() || t.size() > 20 || t.find_first_not_of("0123456789") != std::string::npos) {
        return std::nullopt;
    }
    try {
        return std::stoull(t);
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

/// The platform path named by the header: as written when it exists (absolute, or relative
/// to the current folder), else relative to the header's folder.
std::filesystem::path header_platform(const std::string& text,
                                      const std::filesystem::path& header_path) {
    const std::filesystem::path named(text);
    std::error_code ec;
    if (named.is_absolute() || std::filesystem::exists(named, ec)) return named;
    const std::filesystem::path beside = header_path.parent_path() / named;
    if (std::filesystem::exists(beside, ec)) return beside;
    return named;
}

std::string located(const std::string& instrument, const std::string& focal_plane) {
    return "\"" + instrument + "\" / \"" + focal_plane + "\"";
}

}  // namespace

void choose_focal_plane(const Options& options, const io::EnviHeader& header,
                        const std::filesystem::path& header_path, Context& ctx,
                        FocalPlaneChoice& choice) {
    const std::string header_file = header_path.string();
    if (!options.platform.empty()) {
        choice.platform_path = options.platform;
    } else if (const auto named = header.find_extra("glint platform")) {
        choice.platform_path = header_platform(trim(*named), header_path);
    } else {
        throw usage_error(header_file +
                          " names no platform (no 'glint platform' key): give --platform FILE "
                          "--focal-plane NAME");
    }
    std::string focal_plane = options.focal_plane;
    if (focal_plane.empty()) {
        if (const auto named = header.find_extra("glint focal plane")) {
            focal_plane = trim(*named);
        } else {
            throw usage_error(header_file +
                              " names no focal plane (no 'glint focal plane' key): give "
                              "--focal-plane NAME");
        }
    }
    std::string instrument = options.instrument;
    if (instrument.empty() && options.focal_plane.empty()) {
        if (const auto named = header.find_extra("glint instrument")) instrument = trim(*named);
    }

    std::error_code ec;
    if (!std::filesystem::exists(choice.platform_path, ec)) {
        throw io_error("cannot read the platform: no such file", choice.platform_path.string());
    }
    Diagnostics diagnostics;
    choice.platform = dirsig::read_platform(choice.platform_path, {}, diagnostics);
    // Warnings, and every error after the first (which the thrown error carries).
    bool first_error = true;
    for (const Diagnostic& d : diagnostics.items()) {
        if (d.severity == Diagnostic::Severity::warning) {
            ctx.log.warning(d.text());
        } else if (!first_error) {
            ctx.log.error(d.text());
        } else {
            first_error = false;
        }
    }
    diagnostics.throw_if_errors();

    std::vector<std::string> available;
    for (const model::InstrumentPath& path : model::list_instruments(choice.platform)) {
        for (const model::FocalPlane& fp : path.instrument->focal_planes) {
            available.push_back(located(path.instrument->name, fp.name));
            if (fp.name != focal_plane) continue;
            if (!instrument.empty() && path.instrument->name != instrument) continue;
            if (choice.focal_plane != nullptr) {
                throw input_error("several focal planes are named \"" + focal_plane +
                                      "\" (in instruments \"" + choice.instrument->name +
                                      "\" and \"" + path.instrument->name +
                                      "\"): give --instrument NAME",
                                  ErrorContext{choice.platform_path.string(), 0, {}});
            }
            choice.instrument = path.instrument;
            choice.focal_plane = &fp;
        }
    }
    if (choice.focal_plane == nullptr) {
        std::string list;
        for (std::size_t i = 0; i < available.size(); ++i) list += (i ? ", " : "") + available[i];
        throw input_error("no focal plane \"" + focal_plane + "\"" +
                              (instrument.empty() ? "" : " in instrument \"" + instrument + "\"") +
                              " (instrument / focal plane: " + (list.empty() ? "none" : list) + ")",
                          ErrorContext{choice.platform_path.string(), 0, {}});
    }
    choice.instrument_name = choice.instrument->name;
}

std::uint64_t choose_seed(const Options& options, const io::EnviHeader& header,
                          const std::string& header_file) {
    if (options.seed) return *options.seed;
    if (const auto text = header.find_extra("glint seed")) {
        const auto seed = parse_unsigned(*text);
        if (!seed) {
            throw input_error("'" + trim(*text) + "' is not a seed (an unsigned 64-bit integer)",
                              ErrorContext{header_file, 0, "glint seed"});
        }
        return *seed;
    }
    return kDefaultSeed;
}

double scale_resolution(const io::EnviHeader& header, const std::string& header_file) {
    const auto text = header.find_extra("glint scale resolution");
    if (!text) return 1.0;
    const std::optional<double> value = parse_double(*text);
    if (!value || *value <= 0.0) {
        throw input_error("'" + trim(*text) + "' is not a scale factor (a number > 0)",
                          ErrorContext{header_file, 0, "glint scale resolution"});
    }
    return *value;
}

CaptureMap capture_map(const io::EnviHeader& header, const std::string& header_file,
                       std::size_t default_lines_per_capture) {
    CaptureMap map;
    const auto per_capture_text = header.find_extra("glint lines per capture");
    const auto indices_text = header.find_extra("glint capture indices");
    if (per_capture_text) {
        const auto value = parse_unsigned(*per_capture_text);
        if (!value || *value == 0 || header.lines % *value != 0) {
            throw input_error("'" + trim(*per_capture_text) + "' does not divide the " +
                                  std::to_string(header.lines) + " lines into captures",
                              ErrorContext{header_file, 0, "glint lines per capture"});
        }
        map.lines_per_capture = static_cast<std::size_t>(*value);
    } else if (default_lines_per_capture > 0 && header.lines % default_lines_per_capture == 0) {
        map.lines_per_capture = default_lines_per_capture;
    } else {
        map.lines_per_capture = header.lines;
    }
    const std::size_t captures = header.lines / map.lines_per_capture;
    if (indices_text) {
        for (const std::string& item : io::envi_list_items(*indices_text)) {
            const auto index = parse_unsigned(item);
            if (!index) {
                throw input_error("'" + item + "' is not a capture index",
                                  ErrorContext{header_file, 0, "glint capture indices"});
            }
            map.indices.push_back(*index);
        }
        if (map.indices.size() != captures) {
            throw input_error(std::to_string(map.indices.size()) + " capture indices for " +
                                  std::to_string(captures) + " captures of " +
                                  std::to_string(map.lines_per_capture) + " lines",
                              ErrorContext{header_file, 0, "glint capture indices"});
        }
    } else {
        for (std::size_t i = 0; i < captures; ++i) map.indices.push_back(i);
    }
    if (const auto rows = header.find_extra(io::kPartRowsKey)) {
        const std::vector<std::string> band = io::envi_list_items(*rows);
        const auto first = band.size() == 2 ? parse_unsigned(band[0]) : std::nullopt;
        const auto end = band.size() == 2 ? parse_unsigned(band[1]) : std::nullopt;
        if (!first || !end || *end <= *first || *end - *first != map.lines_per_capture) {
            throw input_error("'" + trim(*rows) + "' is not the band {A, B} of the part's " +
                                  std::to_string(map.lines_per_capture) + " lines per capture",
                              ErrorContext{header_file, 0, io::kPartRowsKey});
        }
        map.first_line = static_cast<std::size_t>(*first);
    }
    return map;
}

}  // namespace glint::app_detect::internal
