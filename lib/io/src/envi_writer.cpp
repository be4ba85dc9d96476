// SPDX-License-Identifier: Apache-2.0
// EnviWriter: streams BIP lines in native byte order into a temporary file beside the target,
// and on commit() publishes the data file and then its `<data>.hdr` header, both atomically.
// Doubles are converted to the header's type here (round to nearest, clamp, NaN to 0).
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

#include "glint/core/error.h"
#include "glint/io/envi.h"

namespace glint::io {
namespace {

/// The header as written: BIP, native byte order, no header offset; validated.
EnviHeader prepared_for_writing(EnviHeader header, const std::filesystem::path& data_path) {
    header.interleave = Interleave::bip;
    header.byte_order = native_byte_order();
    header.header_offset = 0;
    if (header.file_type.empty()) header.file_type = "ENVI Standard";
    std::filesystem::path header_path = data_path;
    header_path += ".hdr";
    validate_envi_header(header, header_path.string());
    if (header.data_type == EnviDataType::complex64 ||
        header.data_type == EnviDataType::complex128) {
        throw input_error(std::string(envi_type_name(header.data_type)) +
                              " cannot be written (complex ENVI types 6 and 9 are read only)",
                          ErrorContext{header_path.string(), 0, "data type"});
    }
    return header;
}

template <typename T>
T to_integer(double value) {
    if (std::isnan(value)) return 0;
    constexpr double kLowest = static_cast<double>(std::numeric_limits<T>::lowest());
    // max + 1 is a power of two, exact in double even where max itself is not.
    constexpr double kAboveMax = static_cast<double>(std::numeric_limits<T>::max()) + 1.0;
    const double rounded = std::round(value);
    if (rounded <= kLowest) return std::numeric_limits<T>::lowest();
    if (rounded >= kAboveMax) return std::numeric_limits<T>::max();
    return static_cast<T>(rounded);
}

/// IEEE conversion to float, spelled out because C++ leaves out-of-range values undefined:
/// beyond FLT_MAX + half an ulp the result is infinity, below it FLT_MAX.
float to_float(double value) {
    constexpr double kMax = std::numeric_limits<float>::max();
    if (!(std::fabs(value) > kMax) || std::isinf(value)) return static_cast<float>(value);
    constexpr double kHalfUlp = 0x1p103;  // the ulp of FLT_MAX is 2^104
    const float magnitude = std::fabs(value) >= kMax + kHalfUlp
                                ? std::numeric_limits<float>::infinity()
                                : std::numeric_limits<float>::max();
    return std::signbit(value) ? -magnitude : magnitude;
}

template <typename T>
void convert_from_double(const double* in, std::byte* out, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
        T value;
        if constexpr (std::numeric_limits<T>::is_integer) {
            value = to_integer<T>(in[i]);
        } else if constexpr (sizeof(T) == sizeof(float)) {
            value = to_float(in[i]);
        } else {
            value = static_cast<T>(in[i]);
        }
        std::memcpy(out + i * sizeof(T), &value, sizeof(T));
    }
}

void double_to_raw(EnviDataType type, const double* in, std::byte* out, std::size_t count) {
    switch (type) {
        case EnviDataType::uint8:
            return convert_from_double<std::uint8_t>(in, out, count);
        case EnviDataType::int16:
            return convert_from_double<std::int16_t>(in, out, count);
        case EnviDataType::int32:
            return convert_from_double<std::int32_t>(in, out, count);
        case EnviDataType::float32:
            return convert_from_double<float>(in, out, count);
        case EnviDataType::float64:
            return convert_from_double<double>(in, out, count);
        case EnviDataType::uint16:
            return convert_from_double<std::uint16_t>(in, out, count);
        case EnviDataType::uint32:
            return convert_from_double<std::uint32_t>(in, out, count);
        case EnviDataType::int64:
            return convert_from_double<std::int64_t>(in, out, count);
        case EnviDataType::uint64:
            return convert_from_double<std::uint64_t>(in, out, count);
        case EnviDataType::complex64:
        case EnviDataType::complex128:
            break;
    }
    throw internal_error("double_to_raw: type cannot be written");
}

}  // namespace

EnviWriter::EnviWriter(const std::filesystem::path& data_path, EnviHeader header)
    : m_header(prepared_for_writing(std::move(header), data_path)),
      m_data(data_path),
      m_header_path(data_path.string() + ".hdr") {
    m_scratch.resize(m_header.samples * m_header.bands * m_header.value_bytes());
}

void EnviWriter::write_line_raw(std::span<const std::byte> line) {
    if (m_data.committed()) throw internal_error("EnviWriter: write after commit");
    if (line.size() != m_scratch.size()) {
        throw internal_error("EnviWriter: line of " + std::to_string(line.size()) +
                             " bytes, expected " + std::to_string(m_scratch.size()));
    }
    if (m_lines_written >= m_header.lines) {
        throw Error(
            ErrorCategory::runtime,
            "more lines than the " + std::to_string(m_header.lines) + " the header declares",
            ErrorContext{m_data.target().string(), 0, {}});
    }
    m_data.write(line.data(), line.size());
    ++m_lines_written;
}

void EnviWriter::write_line(std::span<const double> line) {
    const std::size_t values = m_header.samples * m_header.bands;
    if (line.size() != values) {
        throw internal_error("EnviWriter: line of " + std::to_string(line.size()) +
                             " values, expected " + std::to_string(values));
    }
    double_to_raw(m_header.data_type, line.data(), m_scratch.data(), values);
    write_line_raw(m_scratch);
}

void EnviWriter::set_extra(const std::string& key, const std::string& value) {
    if (m_data.committed()) throw internal_error("EnviWriter: set_extra after commit");
    EnviHeader updated = m_header;
    updated.set_extra(key, value);
    validate_envi_header(updated, m_data.target().string());
    m_header = std::move(updated);
}

void EnviWriter::commit() {
    if (m_data.committed()) throw internal_error("EnviWriter: commit called twice");
    if (m_lines_written != m_header.lines) {
        m_data.abandon();
        throw Error(ErrorCategory::runtime,
                    "wrote " + std::to_string(m_lines_written) + " lines, the header declares " +
                        std::to_string(m_header.lines),
                    ErrorContext{m_data.target().string(), 0, {}});
    }
    // The header is complete in its temporary file before the data is published, so the
    // window in which the data exists without its header is a single rename.
    AtomicFile header_file(m_header_path);
    header_file.write(format_envi_header(m_header));
    m_data.commit();
    try {
        header_file.commit();
    } catch (...) {
        std::error_code ec;
        std::filesystem::remove(m_data.target(), ec);
        throw;
    }
}

}  // namespace glint::io
