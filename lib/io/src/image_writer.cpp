// SPDX-License-Identifier: Apache-2.0
// Image writing through OpenImageIO (image_backend.h): line by line (ImageWriter), whole
// (write_image), published atomically on commit. OIIO's errors are collected right after each
// failing call and rethrown as glint::Error naming the file.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <system_error>

#include "glint/core/datetime.h"
#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/io/image.h"
#include "glint/io/line_memory.h"
#include "glint/io/regular_file.h"
#include "image_backend.h"
#include "image_detail.h"

namespace glint::io {
namespace {

namespace fs = std::filesystem;

using detail::RawType;
using image_detail::at_file;
using image_detail::one_line;
using image_detail::raw_size;

/// Exif/TIFF "YYYY:MM:DD hh:mm:ss" (UTC) of `seconds` since 1970.
std::string exif_date_time(std::int64_t seconds) {
    const CivilTime t = to_civil_utc(DateTime{seconds, 0.0, 0});
    char text[40];
    std::snprintf(text, sizeof text, "%04d:%02d:%02d %02d:%02d:%02d", t.year, t.month, t.day,
                  t.hour, t.minute, t.second);
    return text;
}

const char* oiio_format_name(ImageFormat format) {
    switch (format) {
        case ImageFormat::png:
            return "png";
        case ImageFormat::tiff:
            return "tiff";
        case ImageFormat::jpeg:
            return "jpeg";
        case ImageFormat::exr:
            return "openexr";
        case ImageFormat::ppm:
            return "pnm";
    }
    return "png";
}

RawType raw_type(PixelType type) {
    switch (type) {
        case PixelType::uint8:
            return RawType::uint8;
        case PixelType::uint16:
            return RawType::uint16;
        case PixelType::half:
            return RawType::half;
        case PixelType::float32:
            return RawType::float32;
    }
    return RawType::uint8;
}

template <typename T>
void narrow_integer(std::span<const double> values, unsigned char* bytes) {
    constexpr double kMax = static_cast<double>(std::numeric_limits<T>::max());
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double v = values[i];
        const T code =
            std::isnan(v) ? T(0) : static_cast<T>(std::nearbyint(std::clamp(v, 0.0, kMax)));
        std::memcpy(bytes + i * sizeof(T), &code, sizeof(T));
    }
}

}  // namespace

struct ImageWriter::Impl {
    std::unique_ptr<detail::OutputBackend> output;
    RawType file_type = RawType::uint8;
    std::vector<unsigned char> scratch;
    bool open = false;
    int next_line = 0;
    int height = 0;

    /// Abandoned before commit(): the file is removed anyway, but OIIO closes it on
    /// destruction, and libpng prints "No IDATs written" (or similar) to stderr when an image
    /// ends early. Completing it with zero lines first keeps stderr clean.
    ~Impl() {
        if (!output || !open) return;
        std::fill(scratch.begin(), scratch.end(), 0);
        for (; next_line < height; ++next_line) {
            if (!output->write_line(next_line, file_type, scratch.data())) break;
        }
        output->close();
        (void)output->error();
    }
};

ImageWriter::ImageWriter(const fs::path& path, std::size_t width, std::size_t height,
                         std::size_t channels, const ImageWriteOptions& options)
    : m_file(path),
      m_impl(std::make_unique<Impl>()),
      m_width(width),
      m_height(height),
      m_channels(channels),
      m_type(options.pixel_type) {
    const std::string name = path.string();
    const char* format = image_format_name(options.format);
    constexpr std::size_t kMaxSide = 1u << 30;
    if (width == 0 || height == 0 || width > kMaxSide || height > kMaxSide) {
        throw usage_error("cannot write a " + std::to_string(width) + " x " +
                          std::to_string(height) + " image to " + name);
    }
    if (!format_supports(options.format, options.pixel_type)) {
        throw usage_error(std::string(format) + " cannot store " +
                          pixel_type_name(options.pixel_type) + " pixels (" + name + ")");
    }
    const bool one_or_three =
        options.format == ImageFormat::jpeg || options.format == ImageFormat::ppm;
    if (channels == 0 || (one_or_three && channels != 1 && channels != 3) ||
        (options.format == ImageFormat::png && channels > 4) || channels > 1024) {
        throw usage_error(std::string(format) + " cannot store " + std::to_string(channels) +
                          " channels (" + name + "); select 1 or 3 bands");
    }

    detail::OutputSpec spec;
    spec.format = oiio_format_name(options.format);
    spec.width = static_cast<int>(width);
    spec.height = static_cast<int>(height);
    spec.channels = static_cast<int>(channels);
    spec.type = raw_type(options.pixel_type);
    if (options.channel_names.size() == channels) spec.channel_names = options.channel_names;
    spec.software = options.software;
    spec.description = options.description;
    spec.date_time = options.date_time_s ? exif_date_time(*options.date_time_s) : "";
    if (options.format == ImageFormat::jpeg) {
        spec.compression = "jpeg:" + std::to_string(std::clamp(options.jpeg_quality, 1, 100));
    }
    const detail::ImageBackend& backend = detail::image_backend();
    m_file.release_for_external_writer();
    std::string why;
    m_impl->output = backend.create_output(spec, why);
    if (!m_impl->output) {
        throw io_error("cannot create a " + std::string(format) + " writer: " + one_line(why),
                       name);
    }
    if (!m_impl->output->open(m_file.temp_path().string())) {
        throw io_error("cannot write image: " + one_line(m_impl->output->error()), name);
    }
    m_impl->open = true;
    m_impl->file_type = spec.type;
    m_impl->height = static_cast<int>(height);
    m_impl->scratch.resize(width * channels *
                           std::max<std::size_t>(sizeof(float), raw_size(spec.type)));
}

ImageWriter::~ImageWriter() = default;

void ImageWriter::write_line(std::span<const double> values) {
    const std::string name = m_file.target().string();
    if (values.size() != m_width * m_channels || m_lines_written >= m_height) {
        throw internal_error("ImageWriter::write_line: bad line size or too many lines for " +
                             name);
    }
    unsigned char* bytes = m_impl->scratch.data();
    RawType type = RawType::float32;
    if (m_type == PixelType::uint8) {
        narrow_integer<std::uint8_t>(values, bytes);
        type = RawType::uint8;
    } else if (m_type == PixelType::uint16) {
        narrow_integer<std::uint16_t>(values, bytes);
        type = RawType::uint16;
    } else {
        for (std::size_t i = 0; i < values.size(); ++i) {
            const float f = static_cast<float>(values[i]);
            std::memcpy(bytes + i * sizeof(float), &f, sizeof(float));
        }
    }
    if (!m_impl->output->write_line(static_cast<int>(m_lines_written), type, bytes)) {
        throw io_error("cannot write line " + std::to_string(m_lines_written) + ": " +
                           one_line(m_impl->output->error()),
                       name);
    }
    ++m_lines_written;
    m_impl->next_line = static_cast<int>(m_lines_written);
}

void ImageWriter::commit() {
    const std::string name = m_file.target().string();
    if (m_lines_written != m_height) {
        throw internal_error("ImageWriter::commit: " + std::to_string(m_lines_written) + " of " +
                             std::to_string(m_height) + " lines written to " + name);
    }
    m_impl->open = false;
    if (!m_impl->output->close()) {
        throw io_error("cannot finish image: " + one_line(m_impl->output->error()), name);
    }
    m_file.commit();
}

void write_image(const fs::path& path, std::size_t width, std::size_t height, std::size_t channels,
                 std::span<const double> pixels, const ImageWriteOptions& options) {
    const std::size_t row = width * channels;
    if (pixels.size() != row * height) {
        throw internal_error("write_image: pixel buffer size does not match " + path.string());
    }
    ImageWriter writer(path, width, height, channels, options);
    for (std::size_t y = 0; y < height; ++y) writer.write_line(pixels.subspan(y * row, row));
    writer.commit();
}

}  // namespace glint::io
