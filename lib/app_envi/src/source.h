// SPDX-License-Identifier: Apache-2.0
// Internal: a raster read line by line, whether an ENVI file (through io::EnviReader) or any
// image OpenImageIO reads (through io::ImageReader), so that stats and convert treat both
// alike. Values come as doubles in BIP order (for each sample, all bands). An ENVI source
// also gives its no-data value (`data ignore value`) and band units (`glint band units`).
#pragma once

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "glint/io/envi.h"
#include "glint/io/image.h"

namespace glint::app_envi::internal {

/// True when `path` should be read as ENVI: it names a header, a header exists beside it,
/// or it has an extension ENVI data files use (.img, .dat, .raw, .bsq, .bil, .bip, .envi).
bool is_envi_path(const std::filesystem::path& path);

/// A line-by-line raster source.
class RasterSource {
public:
    /// Opens `path` as ENVI or as an image; throws glint::Error naming the file.
    static std::unique_ptr<RasterSource> open(const std::filesystem::path& path,
                                              std::size_t max_memory_bytes);
    virtual ~RasterSource() = default;

    std::size_t width() const { return m_width; }
    std::size_t height() const { return m_height; }
    std::size_t bands() const { return m_bands; }
    /// Band names (ENVI band names or image channel names); empty if the file names none.
    const std::vector<std::string>& band_names() const { return m_band_names; }
    /// The ENVI header, for ENVI sources.
    const io::EnviHeader* envi_header() const { return m_envi ? &*m_envi : nullptr; }
    /// The image description, for image sources.
    const io::ImageInfo* image_info() const { return m_image ? &*m_image : nullptr; }
    /// Name of the stored value type ("float32", "uint8", ...).
    const std::string& type_name() const { return m_type_name; }
    /// Every file this source reads (data and header for ENVI), for overwrite checks.
    const std::vector<std::filesystem::path>& files() const { return m_files; }
    /// The path as the user named it.
    const std::filesystem::path& path() const { return m_path; }
    /// The ENVI `data ignore value` as the stored type holds it (NaN for "NaN"); nullopt
    /// when the file has none, or one that is not a number (see warnings()).
    std::optional<double> ignore_value() const { return m_ignore_value; }
    /// Whether `value` is no data: NaN, or equal to ignore_value().
    bool is_no_data(double value) const {
        return std::isnan(value) || (m_ignore_value && value == *m_ignore_value);
    }
    /// The unit of each band (`glint band units`); empty when the file gives no such list
    /// with one entry per band.
    const std::vector<std::string>& band_units() const { return m_band_units; }
    /// What was found odd when opening (a header value that cannot be honoured), for the
    /// caller to log.
    const std::vector<std::string>& warnings() const { return m_warnings; }

    /// Line `y`, width × bands values.
    virtual void read_line(std::size_t y, std::span<double> out) = 0;

protected:
    std::filesystem::path m_path;
    std::size_t m_width = 0;
    std::size_t m_height = 0;
    std::size_t m_bands = 0;
    std::vector<std::string> m_band_names;
    std::optional<io::EnviHeader> m_envi;
    std::optional<io::ImageInfo> m_image;
    std::string m_type_name;
    std::vector<std::filesystem::path> m_files;
    std::optional<double> m_ignore_value;
    std::vector<std::string> m_band_units;
    std::vector<std::string> m_warnings;
};

/// "%.*g" formatting (no <format> in g++ 12).
std::string format_number(double value, int precision = 6);

}  // namespace glint::app_envi::internal
