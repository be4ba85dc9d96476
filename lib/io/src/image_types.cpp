// SPDX-License-Identifier: Apache-2.0
// Image formats, pixel types and sample types: their names, what each format stores, and the
// largest value of each type (glint/io/image.h).
#include <algorithm>
#include <cctype>
#include <string>

#include "glint/io/image.h"

namespace glint::io {

namespace fs = std::filesystem;

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

}  // namespace glint::io
