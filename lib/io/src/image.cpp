// SPDX-License-Identifier: Apache-2.0
// Image reading and writing through OpenImageIO, whose calls live in a module loaded on the
// first image (image_backend.h). OIIO's errors are collected right after each failing call
// and rethrown as glint::Error naming the file.
#include "glint/io/image.h"

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
#include "glint/io/line_memory.h"
#include "glint/io/regular_file.h"
#include "image_backend.h"

namespace glint::io {
namespace {

namespace fs = std::filesystem;

ErrorContext at_file(const fs::path& path) { return ErrorContext{path.string(), 0, {}}; }

/// Exif/TIFF "YYYY:MM:DD hh:mm:ss" (UTC) of `seconds` since 1970.
std::string exif_date_time(std::int64_t seconds) {
    const CivilTime t = to_civil_utc(DateTime{seconds, 0.0, 0});
    char text[40];
    std::snprintf(text, sizeof text, "%04d:%02d:%02d %02d:%02d:%02d", t.year, t.month, t.day,
                  t.hour, t.minute, t.second);
    return text;
}

/// OIIO messages may span lines; diagnostics are one line.
std::string one_line(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    for (char& c : text) {
        if (c == '\n') c = ' ';
    }
    return text.empty() ? std::string("unknown OpenImageIO error") : text;
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

using detail::RawType;

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

/// The sample type glint reports for an image's storage, and the type it reads the pixels as.
std::pair<SampleType, RawType> sample_type_of(const detail::InputSpec& spec) {
    if (spec.mixed_types) return {SampleType::float64, RawType::float64};  // per-channel types
    switch (spec.type) {
        case RawType::uint8:
            return {SampleType::uint8, RawType::uint8};
        case RawType::int8:
            return {SampleType::int8, RawType::int8};
        case RawType::uint16:
            return {SampleType::uint16, RawType::uint16};
        case RawType::int16:
            return {SampleType::int16, RawType::int16};
        case RawType::uint32:
            return {SampleType::uint32, RawType::uint32};
        case RawType::int32:
            return {SampleType::int32, RawType::int32};
        case RawType::half:
            return {SampleType::half, RawType::float32};
        case RawType::float32:
            return {SampleType::float32, RawType::float32};
        case RawType::float64:
            break;
    }
    return {SampleType::float64, RawType::float64};
}

/// Bytes of one value stored as `type`.
std::size_t raw_size(RawType type) {
    switch (type) {
        case RawType::uint8:
        case RawType::int8:
            return 1;
        case RawType::uint16:
        case RawType::int16:
        case RawType::half:
            return 2;
        case RawType::uint32:
        case RawType::int32:
        case RawType::float32:
            return 4;
        case RawType::float64:
            return 8;
    }
    return 8;
}

template <typename T>
void widen(const unsigned char* bytes, std::span<double> out) {
    for (std::size_t i = 0; i < out.size(); ++i) {
        T value;
        std::memcpy(&value, bytes + i * sizeof(T), sizeof(T));
        out[i] = static_cast<double>(value);
    }
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

// ---------------------------------------------------------------------------------------
// Names and capabilities

const char* image_format_name(ImageFormat format) {
    switch (format) {
        case ImageFormat::png:
            return "png";
        case ImageFormat::tiff:
            return "tiff";
        case ImageFormat::jpeg:
            return "jpeg";
        case ImageFormat::exr:
            return "exr";
        case ImageFormat::ppm:
            return "ppm";
    }
    return "png";
}

std::optional<ImageFormat> image_format_from_name(std::string_view name) {
    const std::string n = to_lower(name);
    if (n == "png") return ImageFormat::png;
    if (n == "tif" || n == "tiff") return ImageFormat::tiff;
    if (n == "jpg" || n == "jpeg") return ImageFormat::jpeg;
    if (n == "exr" || n == "openexr") return ImageFormat::exr;
    if (n == "ppm" || n == "pgm" || n == "pnm") return ImageFormat::ppm;
    return std::nullopt;
}

std::optional<ImageFormat> image_format_from_extension(const fs::path& path) {
    const std::string ext = path.extension().string();
    if (ext.size() < 2) return std::nullopt;
    return image_format_from_name(std::string_view(ext).substr(1));
}

const char* pixel_type_name(PixelType type) {
    switch (type) {
        case PixelType::uint8:
            return "uint8";
        case PixelType::uint16:
            return "uint16";
        case PixelType::half:
            return "half";
        case PixelType::float32:
            return "float";
    }
    return "uint8";
}

bool format_supports(ImageFormat format, PixelType type) {
    switch (format) {
        case ImageFormat::png:
            return type == PixelType::uint8 || type == PixelType::uint16;
        // OIIO 2.4's PNM plugin garbles 16-bit samples (writing) and maps 65535 to 65534
        // (reading), so glint writes 8-bit PPM/PGM only.
        case ImageFormat::ppm:
            return type == PixelType::uint8;
        case ImageFormat::jpeg:
            return type == PixelType::uint8;
        case ImageFormat::tiff:
            return type != PixelType::half;
        case ImageFormat::exr:
            return type == PixelType::half || type == PixelType::float32;
    }
    return false;
}

std::optional<PixelType> pixel_type_for_bit_depth(ImageFormat format, int bits) {
    std::optional<PixelType> type;
    if (bits == 8) type = PixelType::uint8;
    if (bits == 16) type = format == ImageFormat::exr ? PixelType::half : PixelType::uint16;
    if (bits == 32) type = PixelType::float32;
    if (type && !format_supports(format, *type)) type.reset();
    return type;
}

PixelType default_pixel_type(ImageFormat format) {
    return format == ImageFormat::exr ? PixelType::float32 : PixelType::uint8;
}

double pixel_type_max(PixelType type) {
    switch (type) {
        case PixelType::uint8:
            return 255.0;
        case PixelType::uint16:
            return 65535.0;
        default:
            return 1.0;
    }
}

bool pixel_type_is_integer(PixelType type) {
    return type == PixelType::uint8 || type == PixelType::uint16;
}

const char* sample_type_name(SampleType type) {
    switch (type) {
        case SampleType::uint8:
            return "uint8";
        case SampleType::int8:
            return "int8";
        case SampleType::uint16:
            return "uint16";
        case SampleType::int16:
            return "int16";
        case SampleType::uint32:
            return "uint32";
        case SampleType::int32:
            return "int32";
        case SampleType::half:
            return "half";
        case SampleType::float32:
            return "float";
        case SampleType::float64:
            return "double";
    }
    return "uint8";
}

double sample_type_max(SampleType type) {
    switch (type) {
        case SampleType::uint8:
            return 255.0;
        case SampleType::int8:
            return 127.0;
        case SampleType::uint16:
            return 65535.0;
        case SampleType::int16:
            return 32767.0;
        case SampleType::uint32:
            return 4294967295.0;
        case SampleType::int32:
            return 2147483647.0;
        case SampleType::half:
        case SampleType::float32:
        case SampleType::float64:
            return 1.0;
    }
    return 1.0;
}

GreyImage read_grey_image(const fs::path& path) {
    ImageReader reader(path);
    const ImageInfo& info = reader.info();
    if (info.width > kMaxGreyImageSide || info.height > kMaxGreyImageSide) {
        throw input_error("the image is " + std::to_string(info.width) + " x " +
                              std::to_string(info.height) + " pixels; glint reads at most " +
                              std::to_string(kMaxGreyImageSide) + " x " +
                              std::to_string(kMaxGreyImageSide),
                          at_file(path));
    }
    const double scale = 1.0 / sample_type_max(info.sample_type);
    GreyImage image{info.width, info.height, std::vector<double>(info.width * info.height)};
    std::vector<double> line(info.width * info.channels);
    for (std::size_t y = 0; y < info.height; ++y) {
        reader.read_line(y, line);
        for (std::size_t x = 0; x < info.width; ++x) {
            image.values[y * info.width + x] = line[x * info.channels] * scale;
        }
    }
    return image;
}

std::optional<std::string> weight_image_problem(std::span<const double> values, std::size_t width,
                                                std::size_t height, double max_value) {
    if (width == 0 || height == 0 || values.size() != width * height) return "the image is empty";
    bool any = false;
    for (const double v : values) {
        if (!std::isfinite(v) || v < 0.0) {
            return "the image holds a negative or non-finite value (" + format_shortest(v) + ")";
        }
        if (v > max_value) {
            return "a value is above " + format_shortest(max_value) + " (" + format_shortest(v) +
                   ")";
        }
        any = any || v > 0.0;
    }
    if (!any) return "the image is all zero";
    return std::nullopt;
}

// ---------------------------------------------------------------------------------------
// Reading

struct ImageReader::Impl {
    std::unique_ptr<detail::InputBackend> input;
    RawType read_type = RawType::float64;
    int y_origin = 0;
    std::vector<unsigned char> scratch;
};

ImageReader::ImageReader(const fs::path& path, std::size_t max_memory_bytes)
    : m_impl(std::make_unique<Impl>()), m_path(path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw input_error("no such file", at_file(path));
    if (fs::is_directory(path, ec)) {
        throw input_error("is a folder, not an image", at_file(path));
    }
    // A FIFO, /dev/zero or a socket would make the image library block or read forever.
    if (const auto what = not_a_regular_file(path)) {
        throw input_error(*what + ", not an image file", at_file(path));
    }
    std::string why;
    m_impl->input = detail::image_backend().open_input(path.string(), why);
    if (!m_impl->input) throw input_error("cannot read image: " + one_line(why), at_file(path));
    const detail::InputSpec& spec = m_impl->input->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.channels <= 0 || spec.depth > 1) {
        throw input_error("unsupported image layout (size, channels or volume)", at_file(path));
    }
    m_info.width = static_cast<std::size_t>(spec.width);
    m_info.height = static_cast<std::size_t>(spec.height);
    m_info.channels = static_cast<std::size_t>(spec.channels);
    for (int c = 0; c < spec.channels; ++c) {
        m_info.channel_names.push_back(c < static_cast<int>(spec.channel_names.size())
                                           ? spec.channel_names[static_cast<std::size_t>(c)]
                                           : "channel" + std::to_string(c));
    }
    auto [sample, read_type] = sample_type_of(spec);
    m_info.sample_type = sample;
    m_info.format_name = spec.format_name;
    m_impl->read_type = read_type;
    m_impl->y_origin = spec.y_origin;
    check_line_memory(m_info.width, m_info.channels, max_memory_bytes, path);
    m_impl->scratch.resize(m_info.width * m_info.channels * raw_size(read_type));
}

ImageReader::~ImageReader() {
    if (m_impl && m_impl->input) m_impl->input->close();
}

ImageReader::ImageReader(ImageReader&&) noexcept = default;

void ImageReader::read_line(std::size_t y, std::span<double> out) {
    if (y >= m_info.height || out.size() != m_info.width * m_info.channels) {
        throw internal_error("ImageReader::read_line: bad line or buffer size for " +
                             m_path.string());
    }
    const int line = m_impl->y_origin + static_cast<int>(y);
    if (!m_impl->input->read_line(line, m_impl->read_type, m_impl->scratch.data())) {
        throw input_error(
            "cannot read line " + std::to_string(y) + ": " + one_line(m_impl->input->error()),
            at_file(m_path));
    }
    const unsigned char* bytes = m_impl->scratch.data();
    switch (m_impl->read_type) {
        case RawType::uint8:
            widen<std::uint8_t>(bytes, out);
            break;
        case RawType::int8:
            widen<std::int8_t>(bytes, out);
            break;
        case RawType::uint16:
            widen<std::uint16_t>(bytes, out);
            break;
        case RawType::int16:
            widen<std::int16_t>(bytes, out);
            break;
        case RawType::uint32:
            widen<std::uint32_t>(bytes, out);
            break;
        case RawType::int32:
            widen<std::int32_t>(bytes, out);
            break;
        case RawType::float32:
            widen<float>(bytes, out);
            break;
        default:  // read as double (half is read as float)
            widen<double>(bytes, out);
            break;
    }
}

Image read_image(const fs::path& path) {
    ImageReader reader(path);
    Image image;
    image.info = reader.info();
    const std::size_t row = image.info.width * image.info.channels;
    if (image.info.height > std::numeric_limits<std::size_t>::max() / sizeof(double) / row) {
        throw input_error("image too large to hold in memory", at_file(path));
    }
    image.pixels.resize(row * image.info.height);
    for (std::size_t y = 0; y < image.info.height; ++y) {
        reader.read_line(y, std::span<double>(image.pixels).subspan(y * row, row));
    }
    return image;
}

// ---------------------------------------------------------------------------------------
// Writing

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
