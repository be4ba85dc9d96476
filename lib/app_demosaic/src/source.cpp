// SPDX-License-Identifier: Apache-2.0
// The mosaic of glint-demosaic: a one-band ENVI file (any data type, through io::EnviReader)
// or a one-channel image (through io::ImageReader), described once and read line by line as
// doubles, once per pass.
#include <memory>
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

/// Adds the mosaic's name to an error that lacks one (cancellation passes unchanged).
template <typename Function>
auto naming_errors(const fs::path& path, Function&& function) {
    try {
        return function();
    } catch (const Error& e) {
        if (e.category() == ErrorCategory::cancelled) throw;
        throw e.with_file(path.string());
    }
}

}  // namespace

MosaicSource open_mosaic(const fs::path& path, std::size_t max_memory_bytes) {
    return naming_errors(path, [&path, max_memory_bytes] {
        MosaicSource source;
        source.path = path;
        source.max_memory_bytes = max_memory_bytes;
        if (io::image_format_from_extension(path)) {
            const io::ImageReader reader(path, max_memory_bytes);
            const io::ImageInfo& info = reader.info();
            if (info.channels != 1) throw not_one_band(path, info.channels);
            source.width = info.width;
            source.height = info.height;
            source.type_name = io::sample_type_name(info.sample_type);
            source.files = {path};
            return source;
        }
        const io::EnviReader reader(path, io::EnviReader::LineUse::read_lines, max_memory_bytes);
        const io::EnviHeader& h = reader.header();
        if (h.bands != 1) throw not_one_band(path, h.bands);
        source.width = h.samples;
        source.height = h.lines;
        source.envi = h;
        source.type_name = io::envi_type_name(h.data_type);
        source.files = {reader.data_path(), reader.header_path()};
        return source;
    });
}

demosaic::MosaicLineReader line_reader(const MosaicSource& source) {
    const fs::path path = source.path;
    const std::size_t max_memory = source.max_memory_bytes;
    if (source.envi) {
        auto reader = std::make_shared<io::EnviReader>(naming_errors(path, [&path, max_memory] {
            return io::EnviReader(path, io::EnviReader::LineUse::read_lines, max_memory);
        }));
        return [reader, path](std::size_t y, std::span<double> out) {
            naming_errors(path, [&] { reader->read_line(y, out); });
        };
    }
    auto reader = std::make_shared<io::ImageReader>(
        naming_errors(path, [&path, max_memory] { return io::ImageReader(path, max_memory); }));
    return [reader, path](std::size_t y, std::span<double> out) {
        naming_errors(path, [&] { reader->read_line(y, out); });
    };
}

}  // namespace glint::app_demosaic::internal
