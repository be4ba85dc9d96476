// SPDX-License-Identifier: Apache-2.0
// Map images decoded into rasters (map_parts.h): a material map's digital counts through its
// look-up table into one- or two-byte slots, a mixture map's bands into normalised weights.
// Images are read line by line (OpenImageIO's formats, ENVI with a header beside the data,
// binary PNM by glint itself). A class map in a binary PGM/PPM is then memory-mapped as it
// is (its counts are looked up per hit), so a 20k × 20k class map costs the pages rays touch;
// other formats keep one or two bytes a texel.
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <system_error>
#include <utility>

#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/io/envi.h"
#include "glint/io/image.h"
#include "glint/io/mapped_file.h"
#include "map_parts.h"

namespace glint::dirsig::detail {
namespace {

/// An opened map image: its size, channels, whether it holds integer codes, and its lines
/// (each width × channels values, channels interleaved; line 0 the top).
struct LineSource {
    std::size_t width = 0;
    std::size_t height = 0;
    std::size_t channels = 0;
    bool integer = true;
    std::string type_name;
    std::function<void(std::size_t, std::span<double>)> read;
    /// Bytes a code takes: 1 when the format's codes are below 256, else 2.
    std::size_t code_bytes = 1;
    /// The largest code of an integer image (a PNM's maxval, the type's largest otherwise).
    double max_code = 1.0;
    /// A binary PNM's: where its texels start in the file (big-endian codes, channels
    /// interleaved).
    std::optional<std::size_t> pnm_data_offset;
};

/// The slot_of_code entry of a count <dcmatlut> does not list.
constexpr std::uint16_t kUnlistedSlot = 0xffffu;

bool is_envi(const std::filesystem::path& path) {
    std::error_code ec;
    if (path.extension() == ".hdr") return true;
    return std::filesystem::is_regular_file(path.string() + ".hdr", ec) ||
           std::filesystem::is_regular_file(std::filesystem::path(path).replace_extension(".hdr"),
                                            ec);
}

bool envi_integer(io::EnviDataType type) {
    switch (type) {
        case io::EnviDataType::float32:
        case io::EnviDataType::float64:
        case io::EnviDataType::complex64:
        case io::EnviDataType::complex128:
            return false;
        default:
            return true;
    }
}

ErrorContext at_file(const std::filesystem::path& path) { return {path.string(), 0, {}}; }

/// A binary PNM (P5 grey, P6 colour) read as its own codes: OpenImageIO rescales a PNM's
/// codes to its type's full range (a maxval of 200 or 1023 changes every count) and, in 2.4,
/// gives 16-bit codes above 32768 one less than written. Nullopt: not a binary PNM.
std::optional<LineSource> open_pnm(const std::filesystem::path& path) {
    auto file = std::make_shared<std::ifstream>(path, std::ios::binary);
    char magic[2] = {};
    if (!file->read(magic, 2) || magic[0] != 'P' || (magic[1] != '5' && magic[1] != '6')) {
        return std::nullopt;
    }
    std::array<std::uint64_t, 3> fields{};  // width, height, maxval
    for (std::uint64_t& field : fields) {
        int c = file->get();
        while (c == '#' || std::isspace(c)) {
            if (c == '#') {
                while (c != '\n' && c != EOF) c = file->get();
            }
            c = file->get();
        }
        if (!std::isdigit(c)) throw input_error("malformed PNM header", at_file(path));
        while (std::isdigit(c) && field < (std::uint64_t{1} << 40)) {
            field = field * 10 + static_cast<std::uint64_t>(c - '0');
            c = file->get();
        }
        if (!std::isspace(c)) throw input_error("malformed PNM header", at_file(path));
    }
    if (fields[2] == 0 || fields[2] > 65535) {
        throw input_error("PNM maxval " + std::to_string(fields[2]) + " is not in 1–65535",
                          at_file(path));
    }
    LineSource source;
    source.width = fields[0];
    source.height = fields[1];
    source.channels = magic[1] == '5' ? 1 : 3;
    source.type_name = fields[2] > 255 ? "uint16" : "uint8";
    const std::size_t sample_bytes = fields[2] > 255 ? 2 : 1;
    source.code_bytes = sample_bytes;
    source.max_code = static_cast<double>(fields[2]);
    const std::streamoff data = file->tellg();
    source.pnm_data_offset = static_cast<std::size_t>(data);
    const std::size_t line_bytes = source.width * source.channels * sample_bytes;
    auto bytes = std::make_shared<std::vector<unsigned char>>(line_bytes);
    source.read = [file, bytes, data, line_bytes, sample_bytes, path](std::size_t y,
                                                                      std::span<double> out) {
        file->seekg(data + static_cast<std::streamoff>(y * line_bytes));
        if (!file->read(reinterpret_cast<char*>(bytes->data()),
                        static_cast<std::streamsize>(line_bytes))) {
            throw input_error("PNM data ends before line " + std::to_string(y + 1), at_file(path));
        }
        for (std::size_t i = 0; i < out.size(); ++i) {
            out[i] =
                sample_bytes == 1 ? (*bytes)[i] : (*bytes)[2 * i] * 256.0 + (*bytes)[2 * i + 1];
        }
    };
    return source;
}

/// Opens `path`; throws glint::Error (input or io) as the image readers do.
LineSource open_lines(const std::filesystem::path& path) {
    if (auto pnm = open_pnm(path)) return std::move(*pnm);
    LineSource source;
    if (is_envi(path)) {
        auto reader = std::make_shared<io::EnviReader>(path);
        const io::EnviHeader& h = reader->header();
        source.width = h.samples;
        source.height = h.lines;
        source.channels = h.bands;
        source.integer = envi_integer(h.data_type);
        source.code_bytes = h.value_bytes() == 1 ? 1 : 2;
        source.max_code = std::pow(2.0, 8.0 * static_cast<double>(h.value_bytes())) - 1.0;
        source.type_name =
            std::string("ENVI data type ") + std::to_string(static_cast<int>(h.data_type));
        source.read = [reader](std::size_t y, std::span<double> out) { reader->read_line(y, out); };
        return source;
    }
    auto reader = std::make_shared<io::ImageReader>(path);
    const io::ImageInfo& info = reader->info();
    source.width = info.width;
    source.height = info.height;
    source.channels = info.channels;
    source.integer = io::sample_type_max(info.sample_type) > 1.0;
    source.code_bytes = io::sample_type_max(info.sample_type) > 255.0 ? 2 : 1;
    source.max_code = io::sample_type_max(info.sample_type);
    source.type_name = io::sample_type_name(info.sample_type);
    source.read = [reader](std::size_t y, std::span<double> out) { reader->read_line(y, out); };
    return source;
}

/// Opens the map's image, checking its size; errors at the map (nullopt).
std::optional<LineSource> open_map_image(const model::PropertyMap& map, const model::FileRef& image,
                                         Diagnostics& diagnostics) {
    const std::string label = map_label_text(map) + " image " + quote(image.text);
    try {
        LineSource source = open_lines(image.resolved);
        // Each side first: their product must not wrap.
        const bool huge = source.width > kMaxMapTexels || source.height > kMaxMapTexels;
        const std::uint64_t texels =
            huge ? kMaxMapTexels + 1 : std::uint64_t{source.width} * source.height;
        if (texels == 0 || source.channels == 0) {
            diagnostics.error(map.where, label + " is empty");
            return std::nullopt;
        }
        if (texels > kMaxMapTexels) {
            diagnostics.error(map.where, label + " is " + std::to_string(source.width) + " x " +
                                             std::to_string(source.height) + " texels, more than " +
                                             std::to_string(kMaxMapTexels));
            return std::nullopt;
        }
        return source;
    } catch (const Error& e) {
        if (e.category() != ErrorCategory::input && e.category() != ErrorCategory::io) throw;
        diagnostics.error(map.where, label + ": " + e.message());
        return std::nullopt;
    }
}

}  // namespace

std::shared_ptr<const model::MapRaster> read_class_raster(model::PropertyMap& map,
                                                          Diagnostics& diagnostics) {
    std::optional<LineSource> source = open_map_image(map, map.image, diagnostics);
    if (!source) return nullptr;
    const std::string label = map_label_text(map) + " image " + quote(map.image.text);
    if (!source->integer) {
        diagnostics.error(map.where, label + " holds " + source->type_name +
                                         " values; a material map's texels are digital counts "
                                         "(8- or 16-bit integers)");
        return nullptr;
    }
    if (source->channels > 1) {
        diagnostics.warning(map.where, label + " has " + std::to_string(source->channels) +
                                           " channels; the first holds the digital counts, the "
                                           "others are not used");
    }
    // The table's distinct materials become the slots, in the table's order.
    auto raster = std::make_shared<model::MapRaster>();
    raster->width = source->width;
    raster->height = source->height;
    raster->slot_of_code.assign(65536, kUnlistedSlot);
    map.slot_materials.clear();
    for (const auto& [dc, material] : map.dc_materials) {
        std::uint16_t slot = 0;
        while (slot < map.slot_materials.size() && map.slot_materials[slot] != material) ++slot;
        if (slot == map.slot_materials.size()) map.slot_materials.push_back(material);
        raster->slot_of_code[dc] = slot;
    }
    // Every texel's count must be listed: read once, line by line. A binary PGM/PPM is then
    // mapped as it is; any other format's counts are kept, one or two bytes each.
    const bool mapped = source->pnm_data_offset.has_value();
    raster->code_bytes = source->code_bytes;
    raster->code_stride = mapped ? source->code_bytes * source->channels : source->code_bytes;
    std::shared_ptr<std::uint8_t> decoded;
    if (!mapped) {
        decoded = std::shared_ptr<std::uint8_t>(
            new std::uint8_t[raster->width * raster->height * raster->code_bytes],
            std::default_delete<std::uint8_t[]>());
    }
    std::vector<double> line(source->width * source->channels);
    std::map<double, std::uint64_t> unlisted;  // DC → texels
    try {
        for (std::size_t y = 0; y < source->height; ++y) {
            source->read(y, line);
            for (std::size_t x = 0; x < source->width; ++x) {
                const double dc = line[x * source->channels];
                const bool in_range = dc >= 0.0 && dc < 65536.0;
                const auto code = in_range ? static_cast<std::uint32_t>(dc) : 0u;
                if (!in_range || raster->slot_of_code[code] == kUnlistedSlot) {
                    ++unlisted[dc];
                    continue;
                }
                if (decoded) {
                    std::uint8_t* out =
                        decoded.get() + (y * raster->width + x) * raster->code_bytes;
                    if (raster->code_bytes == 2) *out++ = static_cast<std::uint8_t>(code >> 8);
                    *out = static_cast<std::uint8_t>(code & 0xffu);
                }
            }
        }
        if (unlisted.empty() && mapped) {
            raster->codes =
                io::map_file_bytes(map.image.resolved, *source->pnm_data_offset,
                                   raster->width * raster->height * raster->code_stride);
        }
    } catch (const Error& e) {
        if (e.category() != ErrorCategory::input && e.category() != ErrorCategory::io) throw;
        diagnostics.error(map.where, label + ": " + e.message());
        return nullptr;
    }
    if (!unlisted.empty()) {
        std::string list;
        std::size_t shown = 0;
        for (const auto& [dc, count] : unlisted) {
            if (shown++ == 5) {
                list += ", ...";
                break;
            }
            list += (list.empty() ? "" : ", ") + format_shortest(dc) + " (" +
                    std::to_string(count) + (count == 1 ? " texel)" : " texels)");
        }
        diagnostics.error(map.where,
                          label + " holds " + std::to_string(unlisted.size()) +
                              (unlisted.size() == 1 ? " digital count" : " digital counts") +
                              " that <dcmatlut> does not list: " + list);
        return nullptr;
    }
    if (decoded) raster->codes = decoded;
    raster->slot_of_code.resize(std::size_t{1} << (8 * raster->code_bytes));
    return raster;
}

std::shared_ptr<const model::MapRaster> read_weight_raster(const model::PropertyMap& map,
                                                           Diagnostics& diagnostics) {
    std::optional<LineSource> source = open_map_image(map, map.image, diagnostics);
    if (!source) return nullptr;
    const std::string label = map_label_text(map) + " image " + quote(map.image.text);
    if (source->channels != map.band_materials.size()) {
        diagnostics.error(map.where, label + " has " + std::to_string(source->channels) +
                                         (source->channels == 1 ? " band" : " bands") + " but " +
                                         std::to_string(map.band_materials.size()) +
                                         " materials are listed (one per band)");
        return nullptr;
    }
    auto raster = std::make_shared<model::MapRaster>();
    raster->width = source->width;
    raster->height = source->height;
    raster->bands = source->channels;
    raster->weights.resize(raster->width * raster->height * raster->bands);
    std::vector<double> line(source->width * source->channels);
    try {
        for (std::size_t y = 0; y < source->height; ++y) {
            source->read(y, line);
            float* out = raster->weights.data() + y * raster->width * raster->bands;
            for (std::size_t x = 0; x < source->width; ++x) {
                const double* w = line.data() + x * raster->bands;
                double sum = 0.0;
                for (std::size_t b = 0; b < raster->bands; ++b) {
                    if (!(w[b] >= 0.0) || !std::isfinite(w[b])) {
                        diagnostics.error(map.where, label + ": texel (" + std::to_string(x) +
                                                         ", " + std::to_string(y) + ") band " +
                                                         std::to_string(b + 1) + " is " +
                                                         format_shortest(w[b]) +
                                                         ", expected a finite weight >= 0");
                        return nullptr;
                    }
                    sum += w[b];
                }
                for (std::size_t b = 0; b < raster->bands; ++b) {
                    out[x * raster->bands + b] = sum > 0.0 ? static_cast<float>(w[b] / sum) : 0.0f;
                }
            }
        }
    } catch (const Error& e) {
        if (e.category() != ErrorCategory::input && e.category() != ErrorCategory::io) throw;
        diagnostics.error(map.where, label + ": " + e.message());
        return nullptr;
    }
    return raster;
}

std::optional<MapBrightness> read_brightness(const model::PropertyMap& map,
                                             const model::FileRef& image,
                                             Diagnostics& diagnostics) {
    std::optional<LineSource> source = open_map_image(map, image, diagnostics);
    if (!source) return std::nullopt;
    const std::string label = map_label_text(map) + " image " + quote(image.text);
    if (source->channels > 1) {
        diagnostics.warning(map.where, label + " has " + std::to_string(source->channels) +
                                           " channels; the first holds the brightness, the "
                                           "others are not used");
    }
    MapBrightness out;
    out.integer = source->integer;
    out.max_code = source->max_code;
    out.width = source->width;
    out.height = source->height;
    out.values.resize(out.width * out.height);
    std::vector<double> line(source->width * source->channels);
    try {
        for (std::size_t y = 0; y < source->height; ++y) {
            source->read(y, line);
            for (std::size_t x = 0; x < source->width; ++x) {
                const double v = line[x * source->channels];
                if (!(std::abs(v) <= std::numeric_limits<float>::max())) {
                    diagnostics.error(map.where, label + ": texel (" + std::to_string(x) + ", " +
                                                     std::to_string(y) +
                                                     ") is not a finite single-precision number");
                    return std::nullopt;
                }
                out.values[y * out.width + x] = static_cast<float>(v);
            }
        }
    } catch (const Error& e) {
        if (e.category() != ErrorCategory::input && e.category() != ErrorCategory::io) throw;
        diagnostics.error(map.where, label + ": " + e.message());
        return std::nullopt;
    }
    return out;
}

}  // namespace glint::dirsig::detail
