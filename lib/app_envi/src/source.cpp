// SPDX-License-Identifier: Apache-2.0
// RasterSource over io::EnviReader and io::ImageReader.
#include "source.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <system_error>

#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::app_envi::internal {
namespace {

namespace fs = std::filesystem;

class EnviSource final : public RasterSource {
public:
    EnviSource(const fs::path& path, std::size_t max_memory_bytes)
        : m_reader(path, io::EnviReader::LineUse::read_lines, max_memory_bytes) {
        m_path = path;
        m_envi = m_reader.header();
        m_width = m_envi->samples;
        m_height = m_envi->lines;
        m_bands = m_envi->bands;
        m_band_names = m_envi->band_names;
        m_type_name = io::envi_type_name(m_envi->data_type);
        m_files = {m_reader.data_path(), m_reader.header_path()};
        read_ignore_value();
        if (const auto units = m_envi->find_extra("glint band units")) {
            m_band_units = io::envi_list_items(*units);
            if (m_band_units.size() != m_bands) {
                m_warnings.push_back("glint band units lists " +
                                     std::to_string(m_band_units.size()) + " units for " +
                                     std::to_string(m_bands) + " bands; units not used");
                m_band_units.clear();
            }
        }
    }
    void read_line(std::size_t y, std::span<double> out) override { m_reader.read_line(y, out); }

private:
    void read_ignore_value() {
        const auto text = m_envi->find_extra("data ignore value");
        if (!text) return;
        if (iequals(trim(*text), "nan")) {
            m_ignore_value = std::numeric_limits<double>::quiet_NaN();
        } else if (const auto value = parse_double(*text)) {
            // What a float32 file stores for it, so that 0.1 matches its float32 pixels.
            const bool as_float = m_envi->data_type == io::EnviDataType::float32 &&
                                  std::fabs(*value) <= std::numeric_limits<float>::max();
            m_ignore_value = as_float ? static_cast<double>(static_cast<float>(*value)) : *value;
        } else {
            m_warnings.push_back("data ignore value " + quote(*text) +
                                 " is not a number; no value is taken as no data");
        }
    }

    io::EnviReader m_reader;
};

class ImageSource final : public RasterSource {
public:
    ImageSource(const fs::path& path, std::size_t max_memory_bytes)
        : m_reader(path, max_memory_bytes) {
        m_path = path;
        m_image = m_reader.info();
        m_width = m_image->width;
        m_height = m_image->height;
        m_bands = m_image->channels;
        m_band_names = m_image->channel_names;
        m_type_name = io::sample_type_name(m_image->sample_type);
        m_files = {path};
    }
    void read_line(std::size_t y, std::span<double> out) override { m_reader.read_line(y, out); }

private:
    io::ImageReader m_reader;
};

}  // namespace

bool is_envi_path(const fs::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".hdr" || ext == ".img" || ext == ".dat" || ext == ".raw" || ext == ".bsq" ||
        ext == ".bil" || ext == ".bip" || ext == ".envi") {
        return true;
    }
    std::error_code ec;
    fs::path header = path;
    header += ".hdr";
    if (fs::exists(header, ec)) return true;
    fs::path sibling = path;
    sibling.replace_extension(".hdr");
    return !path.extension().empty() && fs::exists(sibling, ec) &&
           !io::image_format_from_extension(path);
}

std::unique_ptr<RasterSource> RasterSource::open(const fs::path& path,
                                                 std::size_t max_memory_bytes) {
    if (is_envi_path(path)) return std::make_unique<EnviSource>(path, max_memory_bytes);
    return std::make_unique<ImageSource>(path, max_memory_bytes);
}

std::string format_number(double value, int precision) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*g", precision, value);
    return text;
}

}  // namespace glint::app_envi::internal
