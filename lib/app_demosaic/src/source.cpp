// SPDX-License-Identifier: Apache-2.0
// Reading the mosaic of glint-demosaic: a one-band ENVI file (any data type, through
// io::EnviReader) or a one-channel image (through io::ImageReader), into doubles.
#include <string>

#include "glint/core/error.h"
#include "glint/io/image.h"
#include "stages.h"

namespace glint::app_demosaic::internal {
namespace {

namespace fs = std::filesystem;

Error not_one_band(const fs::path& path, std::size_t bands) {
    return input_error(
        "a colour filter array mosaic has one band, this file has " + std::to_string(bands),
        ErrorContext{path.string(), 0, {}});
}

MosaicSource read_envi(const fs::path& path, Context& ctx) {
    io::EnviReader reader(path);
    const io::EnviHeader& h = reader.header();
    if (h.bands != 1) throw not_one_band(path, h.bands);
    MosaicSource source;
    source.envi = h;
    source.type_name = io::envi_type_name(h.data_type);
    source.files = {reader.data_path(), reader.header_path()};
    source.plane = {h.samples, h.lines, std::vector<double>(h.samples * h.lines)};
    for (std::size_t y = 0; y < h.lines; ++y) {
        ctx.cancel.throw_if_cancelled();
        reader.read_line(y,
                         std::span<double>(source.plane.values).subspan(y * h.samples, h.samples));
        ctx.progress.update("demosaic-read", y + 1, h.lines);
    }
    ctx.progress.finish("demosaic-read", h.lines);
    return source;
}

MosaicSource read_picture(const fs::path& path, Context& ctx) {
    io::ImageReader reader(path);
    const io::ImageInfo& info = reader.info();
    if (info.channels != 1) throw not_one_band(path, info.channels);
    MosaicSource source;
    source.type_name = io::sample_type_name(info.sample_type);
    source.files = {path};
    source.plane = {info.width, info.height, std::vector<double>(info.width * info.height)};
    for (std::size_t y = 0; y < info.height; ++y) {
        ctx.cancel.throw_if_cancelled();
        reader.read_line(
            y, std::span<double>(source.plane.values).subspan(y * info.width, info.width));
        ctx.progress.update("demosaic-read", y + 1, info.height);
    }
    ctx.progress.finish("demosaic-read", info.height);
    return source;
}

}  // namespace

MosaicSource read_mosaic(const fs::path& path, Context& ctx) {
    try {
        if (io::image_format_from_extension(path)) return read_picture(path, ctx);
        return read_envi(path, ctx);
    } catch (const Error& e) {
        if (e.category() == ErrorCategory::cancelled) throw;
        throw e.with_file(path.string());
    }
}

}  // namespace glint::app_demosaic::internal
