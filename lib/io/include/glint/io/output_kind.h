// SPDX-License-Identifier: Apache-2.0
// What a raster tool writes (glint-envi convert, glint-demosaic): one of the image formats
// of image.h or ENVI. Chosen by an explicit format name, else by the output's extension:
// the image spellings of image.h, or .img .dat .raw .bsq .bil .bip .envi for ENVI.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

#include "glint/io/image.h"

namespace glint::io {

enum class OutputKind { png, tiff, jpeg, exr, ppm, envi };

/// Kind for a format name (the image.h spellings or "envi", case-insensitive); nullopt
/// otherwise.
std::optional<OutputKind> output_kind_from_name(std::string_view name);

/// Kind of `output`: `format` when it is not empty, else the file name's extension. Throws a
/// usage error naming the expected spellings when neither tells.
OutputKind output_kind_of(const std::filesystem::path& output, std::string_view format);

/// The image format of an image kind; OutputKind::envi is a caller bug (internal error).
ImageFormat image_format_of(OutputKind kind);

/// The pixel type of an image output: the format's default, or the one for a requested bit
/// depth (pixel_type_for_bit_depth). Throws a usage error naming `output` when the format
/// cannot store that depth.
PixelType output_pixel_type(ImageFormat format, std::optional<int> bit_depth,
                            const std::filesystem::path& output);

}  // namespace glint::io
