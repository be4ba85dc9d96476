// SPDX-License-Identifier: Apache-2.0
// glint-demosaic's entry point: option names and checks, the output kind, then read →
// demosaic → write (the stages are in source.cpp and output.cpp).

#include "glint/core/atomic_file.h"
#include "glint/core/error.h"
#include "glint/core/runner.h"
#include "glint/core/stdio_name.h"
#include "glint/core/text.h"
#include "glint/io/envi.h"
#include "glint/io/image.h"
#include "stages.h"

namespace glint::app_demosaic {
namespace {

namespace fs = std::filesystem;
using io::OutputKind;

void check_options(const Options& o, OutputKind kind) {
    if (o.input.empty()) throw usage_error("no input file named");
    if (o.output.empty()) throw usage_error("no output file named");
    io::check_stretch_request({o.gamma, o.percent, o.min, o.max});
    const bool stretch_asked = o.percent || o.min || (o.gamma && *o.gamma != 1.0);
    if (o.raw && stretch_asked) {
        throw usage_error(
            "--raw writes values unchanged; it excludes --percent, --min/--max "
            "and --gamma");
    }
    if (kind == OutputKind::envi) {
        if (stretch_asked || o.raw || o.bit_depth) {
            throw usage_error(
                "--percent, --min/--max, --gamma, --raw and --bit-depth apply to "
                "image outputs; ENVI outputs keep the values (see --data-type)");
        }
    } else if (o.data_type) {
        throw usage_error("--data-type applies to ENVI outputs; use --bit-depth for images");
    }
}

/// What the input's header says about its mosaic (glint-detect's keys), if anything.
struct HeaderCfa {
    std::optional<demosaic::CfaPattern> pattern;
    std::optional<demosaic::BayerPhase> phase;
};

/// A mosaic key of the input's header that names no known value: an input error, or a
/// warning when the option that would override it was given (`overridden`).
void unknown_header_value(const Options& o, std::string_view key, const std::string& value,
                          std::string_view expected, bool overridden, Context& ctx) {
    const std::string header = io::envi_header_path_for(o.input).string();
    const std::string message = quote(value) + " is not known, expected " + std::string(expected);
    if (!overridden) {
        throw input_error(message + " (or give the option that sets it)",
                          ErrorContext{header, 0, std::string(key)});
    }
    ctx.log.warning(format_located(ErrorContext{header, 0, std::string(key)}, message) +
                    "; the option given is used");
}

HeaderCfa header_cfa(const Options& o, const internal::MosaicSource& source, Context& ctx) {
    HeaderCfa cfa;
    if (!source.envi) return cfa;
    if (const auto name = source.envi->find_extra("glint cfa pattern")) {
        cfa.pattern = demosaic::cfa_pattern_from_name(*name);
        if (!cfa.pattern) {
            unknown_header_value(o, "glint cfa pattern", *name, "bayer or truesense",
                                 o.pattern.has_value(), ctx);
        }
    }
    if (const auto name = source.envi->find_extra("glint cfa phase")) {
        cfa.phase = demosaic::bayer_phase_from_name(*name);
        // The phase matters only for a Bayer mosaic: an explicit --pattern other than bayer,
        // or --phase, overrides it.
        if (!cfa.phase) {
            const bool overridden =
                o.phase.has_value() ||
                (o.pattern.has_value() && *o.pattern != demosaic::CfaPattern::bayer);
            unknown_header_value(o, "glint cfa phase", *name, "rggb, grbg, gbrg or bggr",
                                 overridden, ctx);
        }
    }
    return cfa;
}

/// The pattern, phase and method to apply: options first, then the input's header, then the
/// defaults; throws usage errors for a phase or method that does not fit the pattern.
demosaic::DemosaicOptions resolve(const Options& o, const internal::MosaicSource& source,
                                  Context& ctx) {
    const HeaderCfa cfa = header_cfa(o, source, ctx);
    demosaic::DemosaicOptions used;
    used.pattern = o.pattern.value_or(cfa.pattern.value_or(demosaic::CfaPattern::bayer));
    if (o.pattern && cfa.pattern && *o.pattern != *cfa.pattern) {
        ctx.log.warning(o.input.string() + " records a " +
                        demosaic::cfa_pattern_name(*cfa.pattern) + " mosaic; demosaicing it as " +
                        demosaic::cfa_pattern_name(*o.pattern) + " as asked");
    }
    const std::string pattern_name = demosaic::cfa_pattern_name(used.pattern);
    const std::string whose = o.pattern ? "" : " (" + o.input.string() + " records it)";
    if (o.phase && used.pattern != demosaic::CfaPattern::bayer) {
        throw usage_error("--phase applies to the bayer pattern only, not to " + pattern_name +
                          whose);
    }
    if (used.pattern == demosaic::CfaPattern::bayer) {
        used.phase = o.phase.value_or(cfa.phase.value_or(demosaic::BayerPhase::rggb));
        if (o.phase && cfa.phase && *o.phase != *cfa.phase &&
            cfa.pattern == demosaic::CfaPattern::bayer) {
            ctx.log.warning(o.input.string() + " records the Bayer phase " +
                            demosaic::bayer_phase_name(*cfa.phase) + "; using " +
                            demosaic::bayer_phase_name(*o.phase) + " as asked");
        }
    }
    used.method = o.method.value_or(demosaic::default_method(used.pattern));
    if (!demosaic::method_supports(used.method, used.pattern)) {
        throw usage_error(
            "method " + std::string(demosaic::demosaic_method_name(used.method)) +
            " does not apply to the " + pattern_name + " pattern" + whose + " (expected " +
            (used.pattern == demosaic::CfaPattern::bayer ? "bilinear or mhc" : "pan-guided") + ")");
    }
    return used;
}

/// Refuses a mosaic so wide that the demosaic's window of lines and its output lines would
/// need more than --max-memory.
void check_working_memory(const internal::MosaicSource& source, demosaic::DemosaicMethod method,
                          std::size_t max_memory_bytes) {
    const double line_bytes = static_cast<double>(source.width) * 3 * sizeof(double);
    const double needed =
        static_cast<double>(demosaic::DemosaicStream::bytes_held(source.width, method)) +
        2 * line_bytes;
    if (needed <= static_cast<double>(max_memory_bytes)) return;
    throw input_error("a line of " + std::to_string(source.width) + " pixels needs " +
                          format_byte_size(needed) + " of working memory for the " +
                          demosaic::demosaic_method_name(method) +
                          " demosaic (a window of lines), over --max-memory " +
                          format_byte_size(static_cast<double>(max_memory_bytes)),
                      ErrorContext{source.path.string(), 0, {}});
}

}  // namespace

demosaic::CfaPattern parse_pattern(const std::string& name) {
    if (const auto pattern = demosaic::cfa_pattern_from_name(name)) return *pattern;
    throw usage_error("unknown pattern '" + name + "' (expected bayer or truesense)");
}

demosaic::BayerPhase parse_phase(const std::string& name) {
    if (const auto phase = demosaic::bayer_phase_from_name(name)) return *phase;
    throw usage_error("unknown Bayer phase '" + name + "' (expected rggb, grbg, gbrg or bggr)");
}

demosaic::DemosaicMethod parse_method(const std::string& name) {
    if (const auto method = demosaic::demosaic_method_from_name(name)) return *method;
    throw usage_error("unknown method '" + name +
                      "' (expected bilinear or mhc for bayer, "
                      "pan-guided for truesense)");
}

Result demosaic_file(const Options& o, Context& ctx) {
    const OutputKind kind = io::output_kind_of(o.output, o.format);
    check_options(o, kind);
    const internal::MosaicSource source = internal::open_mosaic(o.input, ctx.max_memory_bytes);
    ensure_not_an_input(o.output, source.files);
    if (kind == OutputKind::envi) {
        fs::path header = o.output;
        header += ".hdr";
        ensure_not_an_input(header, source.files);
    }
    Result result;
    result.kind = kind;
    result.used = resolve(o, source, ctx);
    result.width = source.width;
    result.height = source.height;
    check_working_memory(source, result.used.method, ctx.max_memory_bytes);
    const internal::Provenance provenance{o.input, result.used, ctx.command_line()};
    ctx.log.info("demosaicing " + o.input.string() + " (" + std::to_string(result.width) + " x " +
                 std::to_string(result.height) + ", " + source.type_name +
                 "): " + internal::describe(provenance) + " to " + o.output.string());
    if (kind == OutputKind::envi) {
        result.stored_type = internal::write_envi(o.output, source, provenance, o.data_type, ctx);
    } else {
        internal::write_picture(o, kind, source, provenance, result, ctx);
    }
    return result;
}

int run(const Options& options, Context& ctx, std::ostream& /*out*/) {
    refuse_stdio_image_files(options.input, options.output, "glint-demosaic");
    demosaic_file(options, ctx);
    return kExitSuccess;
}

}  // namespace glint::app_demosaic
