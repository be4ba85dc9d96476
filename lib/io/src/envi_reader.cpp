// SPDX-License-Identifier: Apache-2.0
// EnviReader: finds the header of a data file (or the data of a header), validates the header
// and the data file size before allocating anything data-sized, then reads one image line at
// a time with positioned reads (one per line for BIP/BIL, one per band for BSQ), delivering
// BIP values in native byte order, raw or converted to double.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <iterator>
#include <new>

#include "glint/core/error.h"
#include "glint/io/envi.h"
#include "glint/io/input_files.h"
#include "glint/io/regular_file.h"

namespace glint::io {
namespace {

std::string read_header_text(const std::filesystem::path& path) {
    return read_input_file(path, path.string(), kMaxEnviHeaderBytes, "header");
}

/// Reads exactly `size` bytes at `offset`.
void read_exact(int fd, std::byte* out, std::size_t size, std::uint64_t offset,
                const std::filesystem::path& path) {
    std::size_t done = 0;
    while (done < size) {
        const ssize_t n = ::pread(fd, out + done, size - done, static_cast<off_t>(offset + done));
        if (n < 0) {
            if (errno == EINTR) continue;
            const int code = errno;
            throw io_error("read failed: " + errno_text(code), path.string());
        }
        if (n == 0) {
            throw io_error("unexpected end of data at byte " + std::to_string(offset + done) +
                               " (was the file truncated while being read?)",
                           path.string());
        }
        done += static_cast<std::size_t>(n);
    }
}

void byteswap_values(std::byte* data, std::size_t count, std::size_t size) {
    for (std::size_t i = 0; i < count; ++i) std::reverse(data + i * size, data + (i + 1) * size);
}

template <typename T>
void convert_to_double(const std::byte* in, double* out, std::size_t count, std::size_t stride) {
    for (std::size_t i = 0; i < count; ++i) {
        T value;
        std::memcpy(&value, in + i * stride, sizeof value);
        out[i] = static_cast<double>(value);
    }
}

/// Converts `count` raw values; complex values give their real part (the first half).
void raw_to_double(EnviDataType type, const std::byte* in, double* out, std::size_t count) {
    const std::size_t stride = envi_type_size(type);
    switch (type) {
        case EnviDataType::uint8:
            return convert_to_double<std::uint8_t>(in, out, count, stride);
        case EnviDataType::int16:
            return convert_to_double<std::int16_t>(in, out, count, stride);
        case EnviDataType::int32:
            return convert_to_double<std::int32_t>(in, out, count, stride);
        case EnviDataType::float32:
            return convert_to_double<float>(in, out, count, stride);
        case EnviDataType::float64:
            return convert_to_double<double>(in, out, count, stride);
        case EnviDataType::complex64:
            return convert_to_double<float>(in, out, count, stride);
        case EnviDataType::complex128:
            return convert_to_double<double>(in, out, count, stride);
        case EnviDataType::uint16:
            return convert_to_double<std::uint16_t>(in, out, count, stride);
        case EnviDataType::uint32:
            return convert_to_double<std::uint32_t>(in, out, count, stride);
        case EnviDataType::int64:
            return convert_to_double<std::int64_t>(in, out, count, stride);
        case EnviDataType::uint64:
            return convert_to_double<std::uint64_t>(in, out, count, stride);
    }
    throw internal_error("raw_to_double: invalid EnviDataType");
}

bool is_complex(EnviDataType type) {
    return type == EnviDataType::complex64 || type == EnviDataType::complex128;
}

std::string no_header_message(const std::filesystem::path& data_path) {
    std::filesystem::path appended = data_path;
    appended += ".hdr";
    std::filesystem::path replaced = data_path;
    replaced.replace_extension(".hdr");
    std::string tried = appended.string();
    if (replaced != appended) tried += " or " + replaced.string();
    return "no ENVI header found (looked for " + tried + ")";
}

}  // namespace

struct EnviReader::Impl {
    int fd = -1;
    std::size_t line_values = 0;    ///< samples × bands
    std::vector<std::byte> stored;  ///< BIL/BSQ: one line as stored, band after band
    std::vector<std::byte> raw;     ///< read_line: the raw BIP line before conversion
    bool describe_only = false;     ///< opened by info: no line may be read

    Impl() = default;
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;
    ~Impl() {
        if (fd >= 0) ::close(fd);
    }
};

EnviReader::EnviReader(const std::filesystem::path& path, LineUse line_use,
                       std::size_t max_memory_bytes)
    : m_impl(std::make_unique<Impl>()) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const bool given_header = extension == ".hdr";
    std::error_code ec;
    m_data_path = envi_data_path_for(path);
    if (given_header) {
        m_header_path = path;
        if (!std::filesystem::exists(path, ec)) {
            throw io_error("cannot open header: " + errno_text(ENOENT), path.string());
        }
        if (!std::filesystem::is_regular_file(m_data_path, ec)) {
            std::filesystem::path stem = path;
            stem.replace_extension();
            throw io_error("no data file for this header (looked for " + stem.string() +
                               " and that name + .img, .dat, .raw or .bin)",
                           path.string());
        }
    } else {
        m_header_path = envi_header_path_for(m_data_path);
        if (!std::filesystem::exists(m_header_path, ec)) {
            throw io_error(no_header_message(m_data_path), m_data_path.string());
        }
    }

    m_header = parse_envi_header(read_header_text(m_header_path), m_header_path.string());

    require_regular_file(m_data_path, m_data_path.string(), "data file");
    m_impl->fd = ::open(m_data_path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (m_impl->fd < 0) {
        const int code = errno;
        throw io_error("cannot open data file: " + errno_text(code), m_data_path.string());
    }
    struct stat info {};
    if (::fstat(m_impl->fd, &info) != 0) {
        const int code = errno;
        throw io_error("cannot stat data file: " + errno_text(code), m_data_path.string());
    }
    if (!S_ISREG(info.st_mode)) {
        throw io_error("data file is not a regular file", m_data_path.string());
    }
    // parse_envi_header has checked that neither product overflows.
    const std::uint64_t needed = m_header.header_offset + m_header.data_bytes();
    const auto actual = static_cast<std::uint64_t>(info.st_size);
    if (actual < needed) {
        throw input_error("data file is too short: " + std::to_string(actual) +
                              " bytes, expected at least " + std::to_string(needed) +
                              " bytes (header offset " + std::to_string(m_header.header_offset) +
                              " + " + std::to_string(m_header.samples) + " samples x " +
                              std::to_string(m_header.lines) + " lines x " +
                              std::to_string(m_header.bands) + " bands x " +
                              std::to_string(m_header.value_bytes()) + " bytes)",
                          ErrorContext{m_data_path.string(), 0, {}});
    }
    m_impl->line_values = m_header.samples * m_header.bands;
    if (line_use == LineUse::describe_only) {
        m_impl->describe_only = true;
        return;
    }
    check_line_memory(m_header.samples, m_header.bands, max_memory_bytes, m_header_path);
    if (m_header.interleave != Interleave::bip) {
        m_impl->stored.resize(m_impl->line_values * m_header.value_bytes());
    }
}

EnviReader::~EnviReader() = default;
EnviReader::EnviReader(EnviReader&&) noexcept = default;

void EnviReader::read_line_raw(std::size_t y, std::span<std::byte> out) {
    if (m_impl->describe_only) throw internal_error("read_line_raw on a describe-only reader");
    const EnviHeader& h = m_header;
    const std::size_t value_bytes = h.value_bytes();
    const std::size_t line_bytes = m_impl->line_values * value_bytes;
    if (y >= h.lines) {
        throw internal_error("read_line_raw: line " + std::to_string(y) + " of an image with " +
                             std::to_string(h.lines) + " lines");
    }
    if (out.size() < line_bytes) {
        throw internal_error("read_line_raw: buffer of " + std::to_string(out.size()) +
                             " bytes for a line of " + std::to_string(line_bytes) + " bytes");
    }
    const int fd = m_impl->fd;
    const std::uint64_t band_bytes = static_cast<std::uint64_t>(h.samples) * value_bytes;
    switch (h.interleave) {
        case Interleave::bip:
            read_exact(fd, out.data(), line_bytes, h.header_offset + y * line_bytes, m_data_path);
            break;
        case Interleave::bil:
            read_exact(fd, m_impl->stored.data(), line_bytes, h.header_offset + y * line_bytes,
                       m_data_path);
            break;
        case Interleave::bsq:
            for (std::size_t b = 0; b < h.bands; ++b) {
                const std::uint64_t offset =
                    h.header_offset + (static_cast<std::uint64_t>(b) * h.lines + y) * band_bytes;
                read_exact(fd, m_impl->stored.data() + b * band_bytes, band_bytes, offset,
                           m_data_path);
            }
            break;
    }
    if (h.interleave != Interleave::bip) {
        // stored[b][x] -> out[x][b]
        const std::byte* in = m_impl->stored.data();
        for (std::size_t b = 0; b < h.bands; ++b) {
            for (std::size_t x = 0; x < h.samples; ++x) {
                std::memcpy(out.data() + (x * h.bands + b) * value_bytes,
                            in + (b * h.samples + x) * value_bytes, value_bytes);
            }
        }
    }
    if (h.byte_order != native_byte_order() && value_bytes > 1) {
        const std::size_t part = is_complex(h.data_type) ? value_bytes / 2 : value_bytes;
        byteswap_values(out.data(), line_bytes / part, part);
    }
}

void EnviReader::read_line(std::size_t y, std::span<double> out) {
    if (out.size() < m_impl->line_values) {
        throw internal_error("read_line: buffer of " + std::to_string(out.size()) +
                             " values for a line of " + std::to_string(m_impl->line_values));
    }
    m_impl->raw.resize(m_impl->line_values * m_header.value_bytes());
    read_line_raw(y, m_impl->raw);
    raw_to_double(m_header.data_type, m_impl->raw.data(), out.data(), m_impl->line_values);
}

std::vector<double> read_envi_bip(const std::filesystem::path& path, EnviHeader* header_out) {
    EnviReader reader(path);
    const EnviHeader& header = reader.header();
    const std::uint64_t count = header.data_bytes() / header.value_bytes();
    std::vector<double> values;
    try {
        values.resize(count);
    } catch (const std::bad_alloc&) {
        throw runtime_error("not enough memory to read " + std::to_string(count) + " values of " +
                            reader.data_path().string());
    } catch (const std::length_error&) {
        throw runtime_error("not enough memory to read " + std::to_string(count) + " values of " +
                            reader.data_path().string());
    }
    const std::size_t line_values = header.samples * header.bands;
    for (std::size_t y = 0; y < header.lines; ++y) {
        reader.read_line(y, std::span<double>(values.data() + y * line_values, line_values));
    }
    if (header_out) *header_out = header;
    return values;
}

}  // namespace glint::io
