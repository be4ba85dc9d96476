// SPDX-License-Identifier: Apache-2.0
// Raster images through OpenImageIO: reading any format OIIO reads (line by line or whole)
// into doubles, and writing PNG, TIFF, JPEG, OpenEXR and PPM/PGM line by line, atomically
// (OIIO writes the AtomicFile's temporary path, which is renamed into place on commit()).
//
// Values are "code values": an integer pixel type is read and written as its integer
// codes (a uint8 PNG gives 0..255, not 0..1), a floating type as its values. Writers round
// and clamp to an integer type's range (NaN becomes 0). OIIO errors become glint::Error
// naming the file.
#pragma once

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "glint/core/atomic_file.h"
#include "glint/io/line_memory.h"

namespace glint::io {

/// Image file formats glint writes.
enum class ImageFormat { png, tiff, jpeg, exr, ppm };

/// Short name: "png", "tiff", "jpeg", "exr", "ppm".
const char* image_format_name(ImageFormat format);
/// Format for a name given on a command line: png, tif/tiff, jpg/jpeg, exr/openexr,
/// ppm/pgm/pnm (case-insensitive); nullopt otherwise.
std::optional<ImageFormat> image_format_from_name(std::string_view name);
/// Format for a file name's extension (same spellings as image_format_from_name).
std::optional<ImageFormat> image_format_from_extension(const std::filesystem::path& path);

/// Storage type of written pixels.
enum class PixelType { uint8, uint16, half, float32 };

/// "uint8", "uint16", "half", "float".
const char* pixel_type_name(PixelType type);
/// Whether `format` can store `type`: PNG 8/16-bit integers, JPEG and PPM 8-bit (OIIO 2.4's
/// PNM plugin mishandles 16-bit samples), TIFF 8/16-bit integers and 32-bit float, EXR half
/// and float.
bool format_supports(ImageFormat format, PixelType type);
/// The pixel type for a requested bit depth (8, 16, 32) in `format`: 8 → uint8,
/// 16 → uint16 (half for EXR), 32 → float; nullopt when the format cannot store it.
std::optional<PixelType> pixel_type_for_bit_depth(ImageFormat format, int bits);
/// Default pixel type of a format: uint8, except float for EXR.
PixelType default_pixel_type(ImageFormat format);
/// Largest code of an integer type (255, 65535); 1 for floating types.
double pixel_type_max(PixelType type);
/// True for uint8 and uint16.
bool pixel_type_is_integer(PixelType type);

/// Sample type of an image file as OIIO reports it.
enum class SampleType { uint8, int8, uint16, int16, uint32, int32, half, float32, float64 };
const char* sample_type_name(SampleType type);  ///< "uint8", ..., "half", "float", "double"
/// Largest code of an integer sample type (255, 65535, ...); 1 for floating types.
double sample_type_max(SampleType type);

/// What an image file holds (first subimage, full resolution).
struct ImageInfo {
    std::size_t width = 0;
    std::size_t height = 0;
    std::size_t channels = 0;
    std::vector<std::string> channel_names;  ///< as the file names them ("R", "G", "B", ...)
    SampleType sample_type = SampleType::uint8;
    std::string format_name;  ///< OIIO's name of the file format, e.g. "png"
};

/// Reads an image line by line (top line first), channels interleaved, as code values.
class ImageReader {
public:
    /// Opens the file; throws glint::Error naming it when it is missing or unreadable, or when
    /// a line is over `max_memory_bytes` / kLinesPerMaxMemory as doubles (line_memory.h).
    explicit ImageReader(const std::filesystem::path& path,
                         std::size_t max_memory_bytes = kDefaultMaxMemoryBytes);
    ~ImageReader();
    ImageReader(ImageReader&&) noexcept;

    const ImageInfo& info() const { return m_info; }
    const std::filesystem::path& path() const { return m_path; }
    /// Line `y`: width × channels values. `out` must hold exactly that many.
    void read_line(std::size_t y, std::span<double> out);

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
    ImageInfo m_info;
    std::filesystem::path m_path;
};

/// A whole image in memory: width × height × channels code values, row-major, interleaved.
struct Image {
    ImageInfo info;
    std::vector<double> pixels;

    double at(std::size_t x, std::size_t y, std::size_t c) const {
        return pixels[(y * info.width + x) * info.channels + c];
    }
};

/// Reads a whole image (tests and small images; streaming code uses ImageReader).
Image read_image(const std::filesystem::path& path);

/// A grey image's values (the first channel; integer codes divided by the type's largest
/// code, floating values as stored), line 0 at the top: PSF and pixel-mask images.
struct GreyImage {
    std::size_t width = 0;
    std::size_t height = 0;
    std::vector<double> values;  ///< width × height, row-major
};

/// The largest side of a GreyImage read (PSFs and pixel masks are small patterns).
inline constexpr std::size_t kMaxGreyImageSide = 4096;

/// Reads a GreyImage through OpenImageIO. Throws glint::Error (input or io, naming the file)
/// when it cannot be read or a side is over kMaxGreyImageSide.
GreyImage read_grey_image(const std::filesystem::path& path);

/// What makes a GreyImage unusable as sampling weights, if anything: "the image is empty",
/// "the image holds a negative or non-finite value (-1)", "a value is above <max_value>
/// (1.5)", "the image is all zero". The renderer and glint-platform2jsim --check share it.
std::optional<std::string> weight_image_problem(std::span<const double> values,
                                                std::size_t width, std::size_t height,
                                                double max_value = INFINITY);
inline std::optional<std::string> weight_image_problem(const GreyImage& image,
                                                       double max_value = INFINITY) {
    return weight_image_problem(image.values, image.width, image.height, max_value);
}

/// How to write an image.
struct ImageWriteOptions {
    ImageFormat format = ImageFormat::png;
    PixelType pixel_type = PixelType::uint8;
    /// Channel names (e.g. band names); empty = the format's defaults (Y / R,G,B / R,G,B,A).
    std::vector<std::string> channel_names;
    int jpeg_quality = 95;    ///< 1-100
    std::string software;     ///< "Software" metadata, e.g. "glint-envi 0.1.0"; empty = none
    std::string description;  ///< "ImageDescription" metadata; empty = none
    /// "DateTime" metadata, seconds since 1970 UTC (the tools pass SOURCE_DATE_EPOCH); none
    /// = no date-time at all (OpenImageIO would otherwise stamp TIFF and OpenEXR files with
    /// the current time, so two identical runs would differ).
    std::optional<std::int64_t> date_time_s;
};

/// Writes an image line by line into a temporary file beside `path`; commit() closes it
/// and renames it into place. Destroyed without commit(), it leaves nothing behind.
class ImageWriter {
public:
    /// Checks the sizes, the channel count (JPEG and PPM take 1 or 3 channels, PNG 1-4) and
    /// that the format can store the pixel type, then opens the temporary file.
    ImageWriter(const std::filesystem::path& path, std::size_t width, std::size_t height,
                std::size_t channels, const ImageWriteOptions& options);
    ~ImageWriter();

    /// Appends the next line: width × channels code values, interleaved.
    void write_line(std::span<const double> values);
    std::size_t lines_written() const { return m_lines_written; }
    /// Checks that every line was written, closes the image (close errors are failures) and
    /// renames it into place.
    void commit();

private:
    struct Impl;
    AtomicFile m_file;  // destroyed after m_impl: OIIO lets go of the file first
    std::unique_ptr<Impl> m_impl;
    std::size_t m_width;
    std::size_t m_height;
    std::size_t m_channels;
    PixelType m_type;
    std::size_t m_lines_written = 0;
};

/// Writes a whole image (pixels as in Image::pixels) atomically.
void write_image(const std::filesystem::path& path, std::size_t width, std::size_t height,
                 std::size_t channels, std::span<const double> pixels,
                 const ImageWriteOptions& options);

}  // namespace glint::io
