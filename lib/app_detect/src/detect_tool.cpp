// SPDX-License-Identifier: Apache-2.0
// glint-detect's run(): open the input, choose the focal plane and settings, check that the
// cube fits them, then stream it through the detection chain into the output.
#include "glint/app_detect/detect_tool.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include "glint/core/atomic_file.h"
#include "glint/core/error.h"
#include "glint/core/runner.h"
#include "glint/core/stdio_name.h"
#include "glint/core/text.h"
#include "glint/detect/adc.h"
#include "glint/detect/chain.h"
#include "input.h"
#include "output_header.h"
#include "stream.h"

namespace glint::app_detect {
namespace {

using internal::CaptureMap;
using internal::FocalPlaneChoice;

/// Units text without spaces, lowercase ("Photons/cm2" → "photons/cm2").
std::string normalized_units(const std::string& units) {
    std::string out;
    for (char c : units) {
        if (!std::isspace(static_cast<unsigned char>(c))) {
            out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        }
    }
    return out;
}

void check_units(const io::EnviHeader& header, const std::string& file,
                 const detect::DetectionSettings& settings) {
    if (!settings.detector) return;
    const std::string units = normalized_units(header.data_units);
    if (units == "photons/cm2" || units == "electrons/cm2") return;
    throw input_error(
        "data units " + (header.data_units.empty() ? "(none)" : "\"" + header.data_units + "\"") +
            " cannot be detected: the detector model of focal plane \"" + settings.focal_plane +
            "\" expects the photon fluence at the focal plane, \"Photons/cm2\" (or "
            "\"Electrons/cm2\"), which glint-render --radiance-only writes for focal planes "
            "with a <detectormodel>",
        ErrorContext{file, 0, "data units"});
}

void check_bands(const io::EnviHeader& header, const std::string& file,
                 const detect::DetectionSettings& settings) {
    if (header.bands == settings.channels()) return;
    std::string names;
    for (std::size_t i = 0; i < settings.channel_names.size(); ++i) {
        names += (i ? ", \"" : "\"") + settings.channel_names[i] + "\"";
    }
    throw input_error("the cube has " + std::to_string(header.bands) + " band" +
                          (header.bands == 1 ? "" : "s") + ", but focal plane \"" +
                          settings.focal_plane + "\" has " + std::to_string(settings.channels()) +
                          " channel" + (settings.channels() == 1 ? "" : "s") + " (" + names + ")",
                      ErrorContext{file, 0, "bands"});
}

std::size_t scaled_count(std::size_t count, double factor) {
    return static_cast<std::size_t>(std::max(1.0, std::round(static_cast<double>(count) * factor)));
}

void log_summary(const detect::DetectionSettings& s, const Result& r, Context& ctx) {
    std::string text = "focal plane \"" + s.focal_plane + "\": " + std::to_string(r.samples) +
                       " x " + std::to_string(r.lines) + " x " + std::to_string(s.channels()) +
                       ", " + std::to_string(r.captures) + " capture(s) of " +
                       std::to_string(r.lines_per_capture) + " line(s), seed " +
                       std::to_string(s.seed);
    if (const auto& d = s.detector) {
        text += "; QE " + format_shortest(d->quantum_efficiency) + ", read noise " +
                format_shortest(d->read_noise_e) + " e, dark " +
                format_shortest(d->dark_electrons(s.tdi_stages)) + " e, ADC [" +
                format_shortest(d->min_electrons) + ", " + format_shortest(d->max_electrons) +
                "] e -> " + std::to_string(d->bit_depth) + " bits (" +
                format_shortest(d->gain_dn_per_e()) + " DN/e)" + (s.noise ? "" : ", no noise");
    }
    if (s.tdi_stages > 1) {
        text += "; TDI " + std::to_string(s.tdi_stages) + " stages, " +
                detect::tdi_mode_name(s.tdi_mode);
    }
    if (s.cfa) text += std::string("; ") + detect::cfa_pattern_name(s.cfa->pattern) + " mosaic";
    ctx.log.info(text);
}

}  // namespace

Result detect_file(const Options& options, Context& ctx) {
    if (options.input.empty()) throw usage_error("no input file named");
    if (options.output.empty()) throw usage_error("no output file named (-o FILE)");
    const std::string input_name = options.input.string();
    std::optional<io::EnviReader> reader;
    try {
        reader.emplace(options.input, io::EnviReader::LineUse::read_lines, ctx.max_memory_bytes);
    } catch (const Error& e) {
        throw e.with_file(input_name);
    }
    const io::EnviHeader& header = reader->header();
    const std::string header_file = reader->header_path().string();
    std::filesystem::path output_header_path = options.output;
    output_header_path += ".hdr";
    for (const auto& out : {options.output, output_header_path}) {
        const std::filesystem::path inputs[] = {reader->data_path(), reader->header_path()};
        ensure_not_an_input(out, inputs);
    }

    FocalPlaneChoice choice;
    internal::choose_focal_plane(options, header, reader->header_path(), ctx, choice);
    detect::DetectorOverrides overrides = options.overrides;
    overrides.scale_resolution = internal::scale_resolution(header, header_file);
    const std::uint64_t seed = internal::choose_seed(options, header, header_file);
    detect::DetectionSettings settings = detect::resolve_detection(
        *choice.focal_plane, choice.instrument->properties, overrides, seed);
    check_bands(header, header_file, settings);
    check_units(header, header_file, settings);

    const model::DetectorArray& array = choice.focal_plane->detector_array;
    const std::size_t default_lines =
        settings.tdi_stages > 1 ? 1 : scaled_count(array.y_count, overrides.scale_resolution);
    const CaptureMap captures = internal::capture_map(header, header_file, default_lines);
    const std::size_t expected_samples = scaled_count(array.x_count, overrides.scale_resolution);
    if (header.samples != expected_samples) {
        ctx.log.warning(input_name + " has " + std::to_string(header.samples) +
                        " samples per line; focal plane \"" + settings.focal_plane + "\" has " +
                        std::to_string(expected_samples) + " (detecting it anyway)");
    }
    if (settings.detector && header.data_type != io::EnviDataType::float32 &&
        header.data_type != io::EnviDataType::float64) {
        ctx.log.warning(input_name + " stores the photon fluence as " +
                        io::envi_type_name(header.data_type) +
                        " (rounded and clamped to that type); a float64 product keeps it exact");
    }
    if (settings.tdi_stages <= 1 && options.overrides.tdi_mode) {
        ctx.log.warning("--tdi-mode is ignored: focal plane \"" + settings.focal_plane +
                        "\" is not a TDI array");
    }
    if (const auto& d = settings.detector) {
        if (settings.output == detect::DetectOutput::counts &&
            detect::lossless_count_bits(settings.data_type) < d->bit_depth) {
            ctx.log.warning(std::to_string(d->bit_depth) + "-bit counts stored as " +
                            io::envi_type_name(settings.data_type) + " keep their low " +
                            std::to_string(detect::lossless_count_bits(settings.data_type)) +
                            " bits (the upper bits are lost, as the manual says)");
        }
    }

    Result result;
    result.samples = header.samples;
    result.lines = header.lines;
    result.captures = captures.indices.size();
    result.lines_per_capture = captures.lines_per_capture;
    log_summary(settings, result, ctx);

    internal::HeaderSources sources;
    sources.input = &header;
    sources.input_path = options.input;
    sources.platform_path = choice.platform_path;
    sources.instrument = choice.instrument_name;
    sources.command_line = ctx.command_line();
    sources.captures = &captures;
    io::EnviHeader out_header = internal::output_header(settings, sources);
    const detect::DetectionChain chain(settings, header.samples);

    std::optional<io::EnviWriter> writer;
    writer.emplace(options.output, std::move(out_header));
    try {
        internal::stream_lines(*reader, *writer, chain, captures, ctx.threads, ctx);
    } catch (const Error& e) {
        if (e.category() == ErrorCategory::input) throw e.with_file(input_name);
        throw;
    }
    writer->commit();
    result.settings = std::move(settings);
    return result;
}

int run(const Options& options, Context& ctx, std::ostream& /*out*/) {
    refuse_stdio_image_files(options.input, options.output, "glint-detect");
    detect_file(options, ctx);
    return kExitSuccess;
}

}  // namespace glint::app_detect
