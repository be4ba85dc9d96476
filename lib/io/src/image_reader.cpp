// SPDX-License-Identifier: Apache-2.0
// Image reading through OpenImageIO, whose calls live in a module loaded on the first image
// (image_backend.h): line by line (ImageReader), whole (read_image), grey weight images
// (read_grey_image). OIIO's errors are collected right after each failing call and rethrown
// as glint::Error naming the file.
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

template <typename T>
void widen(const unsigned char* bytes, std::span<double> out) {
    for (std::size_t i = 0; i < out.size(); ++i) {
        T value;
        std::memcpy(&value, bytes + i * sizeof(T), sizeof(T));
        out[i] = static_cast<double>(value);
    }
}

}  // namespace

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

}  // namespace glint::io
