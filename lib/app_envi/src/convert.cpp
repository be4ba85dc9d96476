// SPDX-License-Identifier: Apache-2.0
// `glint-envi convert`: option checks, band selection, stretch passes and the writing pass
// to an image (io::ImageWriter) or an ENVI file (io::EnviWriter). The rules are documented
// at the top of convert.h.
#include "glint/app_envi/convert.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <set>

#include "glint/app_envi/bin_commands.h"
#include "glint/core/error.h"
#include "glint/core/runner.h"
#include "glint/core/text.h"
#include "source.h"

namespace glint::app_envi {
namespace {

namespace fs = std::filesystem;
using internal::format_number;
using internal::RasterSource;
using io::OutputKind;
using io::PercentileHistogram;
using io::StretchLimits;

enum class StretchMode { none, minmax, percent, fixed };

/// Whether a stretch option other than --raw is given.
bool asks_for_stretch(const ConvertOptions& o) {
    return o.percent || o.min || o.per_band || (o.gamma && *o.gamma != 1.0);
}

void check_options(const ConvertOptions& o, OutputKind kind) {
    if (o.input.empty()) throw usage_error("no input file named");
    if (o.output.empty()) throw usage_error("no output file named");
    if (o.band && !o.bands.empty()) throw usage_error("give --band or --bands, not both");
    io::check_stretch_request({o.gamma, o.percent, o.min, o.max});
    const bool stretch_asked = asks_for_stretch(o);
    if (o.colormap == Colormap::index) {
        if (kind == OutputKind::envi) {
            throw usage_error(
                "--colormap index applies to image outputs; ENVI outputs keep the values");
        }
        if (o.raw || stretch_asked) {
            throw usage_error(
                "--colormap index gives each value its own colour; it excludes --percent, "
                "--min/--max, --per-band, --gamma and --raw");
        }
    }
    if (o.raw && stretch_asked) {
        throw usage_error(
            "--raw writes values unchanged; it excludes --percent, --min/--max, "
            "--per-band and --gamma");
    }
    if (kind == OutputKind::envi) {
        if (stretch_asked) {
            throw usage_error(
                "--percent, --min/--max, --per-band and --gamma apply to image "
                "outputs; ENVI outputs keep the values");
        }
    } else if (o.data_type) {
        throw usage_error("--data-type applies to ENVI outputs; use --bit-depth for images");
    }
}

/// Nearest-wavelength R, G, B bands, when the header has wavelengths in µm or nm.
std::optional<std::vector<std::size_t>> rgb_by_wavelength(const io::EnviHeader& h) {
    if (h.wavelength.size() != h.bands) return std::nullopt;
    const std::string units = to_lower(h.wavelength_units);
    double to_um = 0;
    if (units == "microns" || units == "micrometers" || units == "um" || units == "micrometer") {
        to_um = 1;
    } else if (units == "nanometers" || units == "nm" || units == "nanometer") {
        to_um = 1e-3;
    }
    if (to_um == 0) return std::nullopt;
    std::vector<std::size_t> picked;
    for (double target : {0.64, 0.55, 0.46}) {
        std::size_t best = 0;
        for (std::size_t b = 1; b < h.bands; ++b) {
            if (std::fabs(h.wavelength[b] * to_um - target) <
                std::fabs(h.wavelength[best] * to_um - target)) {
                best = b;
            }
        }
        picked.push_back(best);
    }
    if (picked[0] == picked[1] || picked[1] == picked[2] || picked[0] == picked[2]) {
        return std::nullopt;
    }
    return picked;
}

std::vector<std::size_t> select_bands(const ConvertOptions& o, const RasterSource& source,
                                      OutputKind kind) {
    std::vector<std::size_t> bands;
    if (o.band) {
        bands = {*o.band};
    } else if (!o.bands.empty()) {
        bands = o.bands;
    } else if (kind == OutputKind::envi) {
        for (std::size_t b = 0; b < source.bands(); ++b) bands.push_back(b);
    } else if (source.bands() < 3) {
        bands = {0};
    } else if (source.bands() == 3) {
        bands = {0, 1, 2};
    } else {
        std::optional<std::vector<std::size_t>> rgb;
        if (source.envi_header() != nullptr) rgb = rgb_by_wavelength(*source.envi_header());
        bands = rgb ? *rgb : std::vector<std::size_t>{0, 1, 2};
    }
    for (std::size_t b : bands) {
        if (b >= source.bands()) {
            throw usage_error("band " + std::to_string(b) + " does not exist: " +
                              source.path().string() + " has " + std::to_string(source.bands()) +
                              " band" + (source.bands() == 1 ? "" : "s") + " (numbered from 0)");
        }
    }
    return bands;
}

/// Whether one band of labels is drawn with the index colour map (see convert.h).
bool use_index_colours(const ConvertOptions& o, const RasterSource& source,
                       const std::vector<std::size_t>& bands, bool integer_output) {
    if (o.colormap != Colormap::automatic) return o.colormap == Colormap::index;
    if (!integer_output || bands.size() != 1 || o.raw || asks_for_stretch(o)) return false;
    const std::size_t b = bands.front();
    const auto& names = source.band_names();
    const auto& units = source.band_units();
    return is_index_band(b < names.size() ? names[b] : std::string(),
                         b < units.size() ? units[b] : std::string());
}

/// The stretch of an image output (see convert.h); none for index colours.
StretchMode stretch_mode(const ConvertOptions& o, bool integer_output, bool index_colours) {
    if (index_colours) return StretchMode::none;
    if (o.min) return StretchMode::fixed;
    if (o.percent) return StretchMode::percent;
    if (!o.raw && (integer_output || o.per_band || o.gamma.value_or(1.0) != 1.0)) {
        return StretchMode::minmax;
    }
    return StretchMode::none;
}

/// Reads every line, handing the selected values of each pixel to `visit(channel, value)`;
/// no data (NaN, the data ignore value) comes as NaN.
template <typename Visit>
void scan(RasterSource& source, const std::vector<std::size_t>& bands, Context& ctx,
          const std::string& label, Visit&& visit) {
    std::vector<double> line(source.width() * source.bands());
    for (std::size_t y = 0; y < source.height(); ++y) {
        ctx.cancel.throw_if_cancelled();
        source.read_line(y, line);
        for (std::size_t x = 0; x < source.width(); ++x) {
            const double* pixel = line.data() + x * source.bands();
            for (std::size_t c = 0; c < bands.size(); ++c) {
                const double v = pixel[bands[c]];
                visit(c, source.is_no_data(v) ? std::numeric_limits<double>::quiet_NaN() : v);
            }
        }
        ctx.progress.update(label, y + 1, source.height());
    }
    ctx.progress.finish(label, source.height());
}

std::vector<StretchLimits> data_limits(RasterSource& source, const std::vector<std::size_t>& bands,
                                       double percent, bool per_band, Context& ctx) {
    std::vector<PercentileHistogram> hist(per_band ? bands.size() : 1);
    auto group = [&](std::size_t c) -> PercentileHistogram& { return hist[per_band ? c : 0]; };
    scan(source, bands, ctx, "convert-range",
         [&](std::size_t c, double v) { group(c).observe(v); });
    if (percent > 0) {
        for (auto& h : hist) h.begin_counting();
        scan(source, bands, ctx, "convert-histogram",
             [&](std::size_t c, double v) { group(c).count(v); });
    }
    std::vector<StretchLimits> limits;
    for (std::size_t c = 0; c < bands.size(); ++c) {
        const PercentileHistogram& h = group(c);
        if (h.finite_count() == 0) {
            ctx.log.warning(source.path().string() + ": band " + std::to_string(bands[c]) +
                            " holds no finite values");
        }
        limits.push_back(h.limits(percent));
    }
    return limits;
}

std::vector<std::string> channel_names(const RasterSource& source,
                                       const std::vector<std::size_t>& bands) {
    std::vector<std::string> names;
    if (source.band_names().size() != source.bands()) return names;
    std::set<std::string> seen;
    for (std::size_t b : bands) {
        const std::string& name = source.band_names()[b];
        if (name.empty() || !seen.insert(name).second) return {};
        names.push_back(name);
    }
    return names;
}

ConvertResult to_image(const ConvertOptions& o, OutputKind kind, RasterSource& source,
                       const std::vector<std::size_t>& bands, Context& ctx) {
    const io::ImageFormat format = io::image_format_of(kind);
    const io::PixelType type = io::output_pixel_type(format, o.bit_depth, o.output);
    const bool integer = io::pixel_type_is_integer(type);
    const double gamma = o.gamma.value_or(1.0);
    const bool index_colours = use_index_colours(o, source, bands, integer);
    const StretchMode mode = stretch_mode(o, integer, index_colours);

    ConvertResult result;
    result.kind = kind;
    result.bands = bands;
    result.stored_type = io::pixel_type_name(type);
    result.index_colours = index_colours;
    if (index_colours) {
        const auto& names = source.band_names();
        ctx.log.info("band " + std::to_string(bands[0]) +
                     (bands[0] < names.size() ? " (" + names[bands[0]] + ")" : std::string()) +
                     ": index colour map, one colour per value");
    }
    if (mode == StretchMode::fixed) {
        result.limits.assign(bands.size(), StretchLimits{*o.min, *o.max});
    } else if (mode != StretchMode::none) {
        result.limits = data_limits(source, bands, mode == StretchMode::percent ? *o.percent : 0,
                                    o.per_band, ctx);
    }
    const bool shared = !result.limits.empty() && (mode == StretchMode::fixed || !o.per_band);
    for (std::size_t c = 0; c < (shared ? 1 : result.limits.size()); ++c) {
        ctx.log.info(std::string(shared ? "all bands" : "band " + std::to_string(bands[c])) +
                     ": stretch [" + format_number(result.limits[c].low, 8) + ", " +
                     format_number(result.limits[c].high, 8) + "]");
    }

    io::ImageWriteOptions write;
    write.format = format;
    write.pixel_type = type;
    if (!index_colours) write.channel_names = channel_names(source, bands);
    write.software = std::string("glint-envi ") + version();
    write.date_time_s = ctx.source_date_epoch_s;
    const double scale = integer ? io::pixel_type_max(type) : 1.0;
    const std::size_t channels = index_colours ? 3 : bands.size();
    const double no_data = std::numeric_limits<double>::quiet_NaN();
    io::ImageWriter writer(o.output, source.width(), source.height(), channels, write);
    std::vector<double> line(source.width() * source.bands());
    std::vector<double> out(source.width() * channels);
    for (std::size_t y = 0; y < source.height(); ++y) {
        ctx.cancel.throw_if_cancelled();
        source.read_line(y, line);
        for (std::size_t x = 0; x < source.width(); ++x) {
            const double* pixel = line.data() + x * source.bands();
            double* dst = out.data() + x * channels;
            if (index_colours) {
                const double v = pixel[bands[0]];
                const auto rgb = index_colour(source.is_no_data(v) ? no_data : v);
                for (std::size_t c = 0; c < 3; ++c) dst[c] = scale * rgb[c];
                continue;
            }
            for (std::size_t c = 0; c < bands.size(); ++c) {
                double v = pixel[bands[c]];
                if (!result.limits.empty()) {
                    if (source.is_no_data(v)) v = no_data;
                    v = scale * io::stretch_value(v, result.limits[c], gamma);
                }
                dst[c] = v;
            }
        }
        writer.write_line(out);
        ctx.progress.update("convert-write", y + 1, source.height());
    }
    writer.commit();
    ctx.progress.finish("convert-write", source.height());
    return result;
}

io::EnviDataType default_envi_type(const RasterSource& source) {
    if (const io::EnviHeader* h = source.envi_header()) {
        if (h->data_type == io::EnviDataType::complex64) return io::EnviDataType::float32;
        if (h->data_type == io::EnviDataType::complex128) return io::EnviDataType::float64;
        return h->data_type;
    }
    switch (source.image_info()->sample_type) {
        case io::SampleType::uint8:
            return io::EnviDataType::uint8;
        case io::SampleType::int8:
        case io::SampleType::int16:
            return io::EnviDataType::int16;
        case io::SampleType::uint16:
            return io::EnviDataType::uint16;
        case io::SampleType::int32:
            return io::EnviDataType::int32;
        case io::SampleType::uint32:
            return io::EnviDataType::uint32;
        case io::SampleType::half:
        case io::SampleType::float32:
            return io::EnviDataType::float32;
        case io::SampleType::float64:
            return io::EnviDataType::float64;
    }
    return io::EnviDataType::float64;
}

ConvertResult to_envi(const ConvertOptions& o, RasterSource& source,
                      const std::vector<std::size_t>& bands, Context& ctx) {
    io::EnviHeader h;
    if (const io::EnviHeader* src = source.envi_header()) {
        h.description = src->description;
        h.wavelength_units = src->wavelength_units;
        h.data_units = src->data_units;
        h.extra = src->extra;
        for (std::size_t b : bands) {
            if (!src->wavelength.empty()) h.wavelength.push_back(src->wavelength[b]);
            if (!src->fwhm.empty()) h.fwhm.push_back(src->fwhm[b]);
            if (!src->band_names.empty()) h.band_names.push_back(src->band_names[b]);
        }
    } else {
        h.description = "converted from " + source.path().filename().string() + " by glint-envi";
        for (const auto& name : channel_names(source, bands)) {
            h.band_names.push_back(io::sanitize_band_name(name));
        }
    }
    h.samples = source.width();
    h.lines = source.height();
    h.bands = bands.size();
    h.data_type = default_envi_type(source);
    if (o.bit_depth) {
        switch (*o.bit_depth) {
            case 8:
                h.data_type = io::EnviDataType::uint8;
                break;
            case 16:
                h.data_type = io::EnviDataType::uint16;
                break;
            case 32:
                h.data_type = io::EnviDataType::float32;
                break;
            case 64:
                h.data_type = io::EnviDataType::float64;
                break;
            default:
                throw usage_error("ENVI outputs take a bit depth of 8, 16, 32 or 64, not " +
                                  std::to_string(*o.bit_depth));
        }
    }
    if (o.data_type) h.data_type = *o.data_type;
    h.set_extra("glint tool", "glint-envi convert");
    h.set_extra("glint version", version());
    h.set_extra("glint source", source.path().string());
    if (!ctx.arguments.empty()) h.set_extra("glint command line", ctx.command_line());

    ConvertResult result;
    result.kind = OutputKind::envi;
    result.bands = bands;
    result.stored_type = io::envi_type_name(h.data_type);
    io::EnviWriter writer(o.output, std::move(h));
    std::vector<double> line(source.width() * source.bands());
    std::vector<double> out(source.width() * bands.size());
    for (std::size_t y = 0; y < source.height(); ++y) {
        ctx.cancel.throw_if_cancelled();
        source.read_line(y, line);
        for (std::size_t x = 0; x < source.width(); ++x) {
            for (std::size_t c = 0; c < bands.size(); ++c) {
                out[x * bands.size() + c] = line[x * source.bands() + bands[c]];
            }
        }
        writer.write_line(out);
        ctx.progress.update("convert-write", y + 1, source.height());
    }
    writer.commit();
    ctx.progress.finish("convert-write", source.height());
    return result;
}

}  // namespace

ConvertResult convert_file(const ConvertOptions& o, Context& ctx) {
    if (is_lidar_bin(o.input)) {
        // A DIRSIG lidar BIN file: ENVI cubes of its pulses, values unchanged.
        if (o.band || !o.bands.empty() || o.gamma || o.percent || o.min || o.max || o.raw ||
            o.bit_depth || o.data_type || o.per_band || !o.format.empty()) {
            throw usage_error(
                "a lidar BIN input converts to float64 ENVI cubes as they are: "
                "band, stretch, format and type options apply to the cubes");
        }
        ensure_not_an_input(o.output, std::vector<fs::path>{o.input});
        convert_bin(o.input, o.output, o.pulse, o.range, ctx);
        ConvertResult result;
        result.kind = OutputKind::envi;
        result.stored_type = "float64";
        return result;
    }
    if (o.pulse) throw usage_error("--pulse applies to a DIRSIG lidar BIN input only");
    if (o.range) throw usage_error("--range applies to a DIRSIG lidar BIN input only");
    const OutputKind kind = io::output_kind_of(o.output, o.format);
    check_options(o, kind);
    std::unique_ptr<RasterSource> source;
    try {
        source = RasterSource::open(o.input, ctx.max_memory_bytes);
    } catch (const Error& e) {
        throw e.with_file(o.input.string());
    }
    ensure_not_an_input(o.output, source->files());
    if (kind == OutputKind::envi) {
        fs::path header = o.output;
        header += ".hdr";
        ensure_not_an_input(header, source->files());
    }
    for (const std::string& warning : source->warnings()) {
        ctx.log.warning(o.input.string() + ": " + warning);
    }
    const std::vector<std::size_t> bands = select_bands(o, *source, kind);
    if (o.colormap == Colormap::index && bands.size() != 1) {
        throw usage_error("--colormap index colours one band; " + std::to_string(bands.size()) +
                          " are selected (choose one with --band N)");
    }
    ctx.log.info("converting " + o.input.string() + " (" + std::to_string(source->width()) + " x " +
                 std::to_string(source->height()) + " x " + std::to_string(source->bands()) + ", " +
                 source->type_name() + ") to " + o.output.string());
    if (kind == OutputKind::envi) return to_envi(o, *source, bands, ctx);
    return to_image(o, kind, *source, bands, ctx);
}

}  // namespace glint::app_envi
