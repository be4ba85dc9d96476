// SPDX-License-Identifier: Apache-2.0
// Writing the demosaiced image of glint-demosaic line by line as it is demosaiced: ENVI
// through io::EnviWriter (values unchanged, provenance keys) or an image through
// io::ImageWriter with glint-envi's stretch (the rules are at the top of demosaic.h), whose
// limits come from earlier passes over the mosaic.
#include <cmath>
#include <string>

#include "glint/core/error.h"
#include "glint/core/runner.h"
#include "glint/core/text.h"
#include "glint/io/image.h"
#include "stages.h"

namespace glint::app_demosaic::internal {
namespace {

namespace fs = std::filesystem;

io::EnviDataType default_envi_type(const MosaicSource& source) {
    if (!source.envi) return io::EnviDataType::float32;
    switch (source.envi->data_type) {
        case io::EnviDataType::complex64:
            return io::EnviDataType::float32;
        case io::EnviDataType::complex128:
            return io::EnviDataType::float64;
        default:
            return source.envi->data_type;
    }
}

/// Min/max or percentile limits over the three channels together: one pass of the
/// demosaic for the range, a second for the percentiles.
io::StretchLimits data_limits(const MosaicSource& source, const demosaic::DemosaicOptions& used,
                              double percent, Context& ctx) {
    io::PercentileHistogram histogram;
    demosaic_pass(source, used, "demosaic-range", ctx,
                  [&histogram](std::size_t, std::span<const double> rgb) {
                      for (double v : rgb) histogram.observe(v);
                  });
    if (percent > 0) {
        histogram.begin_counting();
        demosaic_pass(source, used, "demosaic-percentiles", ctx,
                      [&histogram](std::size_t, std::span<const double> rgb) {
                          for (double v : rgb) histogram.count(v);
                      });
    }
    if (histogram.finite_count() == 0) ctx.log.warning("the image holds no finite values");
    return histogram.limits(percent);
}

}  // namespace

std::string describe(const Provenance& p) {
    std::string text = demosaic::cfa_pattern_name(p.used.pattern);
    if (p.used.pattern == demosaic::CfaPattern::bayer) {
        text += std::string(" ") + demosaic::bayer_phase_name(p.used.phase);
    }
    return text + " " + demosaic::demosaic_method_name(p.used.method) + " demosaic of " +
           p.source.filename().string();
}

std::string write_envi(const fs::path& output, const MosaicSource& source,
                       const Provenance& provenance, std::optional<io::EnviDataType> data_type,
                       Context& ctx) {
    io::EnviHeader h;
    h.description = "glint-demosaic: " + describe(provenance);
    h.samples = source.width;
    h.lines = source.height;
    h.bands = 3;
    h.data_type = data_type.value_or(default_envi_type(source));
    h.band_names = {"R", "G", "B"};
    if (source.envi) h.data_units = source.envi->data_units;
    h.set_extra("glint tool", "glint-demosaic");
    h.set_extra("glint version", version());
    h.set_extra("glint source", provenance.source.string());
    if (!provenance.command_line.empty())
        h.set_extra("glint command line", provenance.command_line);
    h.set_extra("glint cfa pattern", demosaic::cfa_pattern_name(provenance.used.pattern));
    if (provenance.used.pattern == demosaic::CfaPattern::bayer) {
        h.set_extra("glint cfa phase", demosaic::bayer_phase_name(provenance.used.phase));
    }
    h.set_extra("glint demosaic method", demosaic::demosaic_method_name(provenance.used.method));
    const std::string type_name = io::envi_type_name(h.data_type);

    io::EnviWriter writer(output, std::move(h));
    demosaic_pass(source, provenance.used, "demosaic", ctx,
                  [&writer](std::size_t, std::span<const double> rgb) { writer.write_line(rgb); });
    writer.commit();
    return type_name;
}

void write_picture(const Options& o, io::OutputKind kind, const MosaicSource& source,
                   const Provenance& provenance, Result& result, Context& ctx) {
    const io::ImageFormat format = io::image_format_of(kind);
    const io::PixelType type = io::output_pixel_type(format, o.bit_depth, o.output);
    const bool integer = io::pixel_type_is_integer(type);
    const double gamma = o.gamma.value_or(1.0);
    if (o.min) {
        result.limits = io::StretchLimits{*o.min, *o.max};
    } else if (o.percent) {
        result.limits = data_limits(source, provenance.used, *o.percent, ctx);
    } else if (!o.raw && (integer || gamma != 1.0)) {
        result.limits = data_limits(source, provenance.used, 0.0, ctx);
    }
    if (result.limits) {
        ctx.log.info("stretch [" + format_shortest(result.limits->low) + ", " +
                     format_shortest(result.limits->high) + "]");
    }
    result.stored_type = io::pixel_type_name(type);

    io::ImageWriteOptions write;
    write.format = format;
    write.pixel_type = type;
    write.channel_names = {"R", "G", "B"};
    write.software = std::string("glint-demosaic ") + version();
    write.date_time_s = ctx.source_date_epoch_s;
    write.description = "glint-demosaic: " + describe(provenance);
    const double scale = integer ? io::pixel_type_max(type) : 1.0;
    io::ImageWriter writer(o.output, source.width, source.height, 3, write);
    std::vector<double> line(source.width * 3);
    demosaic_pass(source, provenance.used, "demosaic", ctx,
                  [&](std::size_t, std::span<const double> rgb) {
                      for (std::size_t i = 0; i < line.size(); ++i) {
                          line[i] = result.limits
                                        ? scale * io::stretch_value(rgb[i], *result.limits, gamma)
                                        : rgb[i];
                      }
                      writer.write_line(line);
                  });
    writer.commit();
}

}  // namespace glint::app_demosaic::internal
