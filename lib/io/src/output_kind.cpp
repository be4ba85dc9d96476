// SPDX-License-Identifier: Apache-2.0
// Output kinds of raster tools (rules at the top of output_kind.h).
#include "glint/io/output_kind.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::io {
namespace {

OutputKind kind_of(ImageFormat format) {
    switch (format) {
        case ImageFormat::png:
            return OutputKind::png;
        case ImageFormat::tiff:
            return OutputKind::tiff;
        case ImageFormat::jpeg:
            return OutputKind::jpeg;
        case ImageFormat::exr:
            return OutputKind::exr;
        case ImageFormat::ppm:
            return OutputKind::ppm;
    }
    return OutputKind::png;
}

}  // namespace

std::optional<OutputKind> output_kind_from_name(std::string_view name) {
    if (to_lower(name) == "envi") return OutputKind::envi;
    const auto format = image_format_from_name(name);
    if (!format) return std::nullopt;
    return kind_of(*format);
}

OutputKind output_kind_of(const std::filesystem::path& output, std::string_view format) {
    if (!format.empty()) {
        const auto kind = output_kind_from_name(format);
        if (!kind) {
            throw usage_error("unknown output format '" + std::string(format) +
                              "' (expected png, tiff, jpeg, exr, ppm or envi)");
        }
        return *kind;
    }
    if (const auto image = image_format_from_extension(output)) return kind_of(*image);
    const std::string ext = to_lower(output.extension().string());
    for (const char* envi : {".img", ".dat", ".raw", ".bsq", ".bil", ".bip", ".envi"}) {
        if (ext == envi) return OutputKind::envi;
    }
    throw usage_error("cannot tell the output format from the name " + output.string() +
                      "; use --format png|tiff|jpeg|exr|ppm|envi");
}

ImageFormat image_format_of(OutputKind kind) {
    switch (kind) {
        case OutputKind::png:
            return ImageFormat::png;
        case OutputKind::tiff:
            return ImageFormat::tiff;
        case OutputKind::jpeg:
            return ImageFormat::jpeg;
        case OutputKind::exr:
            return ImageFormat::exr;
        case OutputKind::ppm:
            return ImageFormat::ppm;
        case OutputKind::envi:
            break;
    }
    throw internal_error("image_format_of: ENVI is not an image format");
}

PixelType output_pixel_type(ImageFormat format, std::optional<int> bit_depth,
                            const std::filesystem::path& output) {
    if (!bit_depth) return default_pixel_type(format);
    const std::optional<PixelType> chosen = pixel_type_for_bit_depth(format, *bit_depth);
    if (!chosen) {
        throw usage_error(std::string(image_format_name(format)) + " cannot store a bit depth of " +
                          std::to_string(*bit_depth) + " (" + output.string() + ")");
    }
    return *chosen;
}

}  // namespace glint::io
