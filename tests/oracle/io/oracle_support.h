// SPDX-License-Identifier: Apache-2.0
// Shared helpers of the ENVI oracle tests: running an external program (through glint's
// process runner: argv, no shell), and a small test image of any writable type written with
// EnviWriter whose expected values are kept as JSON numbers (exact for 64-bit integers).
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "glint/io/envi.h"
#include "glint/test/oracle.h"
#include "glint/test/temp_dir.h"

namespace glint::io::oracle {

using glint::test::CommandResult;
using glint::test::program_exists;
using glint::test::python_command;
using glint::test::python_has;
using glint::test::read_text;
using glint::test::run_command;
using glint::test::TempDir;

/// GDAL's name for a data type.
inline const char* gdal_type_name(EnviDataType type) {
    switch (type) {
        case EnviDataType::uint8:
            return "Byte";
        case EnviDataType::int16:
            return "Int16";
        case EnviDataType::int32:
            return "Int32";
        case EnviDataType::float32:
            return "Float32";
        case EnviDataType::float64:
            return "Float64";
        case EnviDataType::uint16:
            return "UInt16";
        case EnviDataType::uint32:
            return "UInt32";
        case EnviDataType::int64:
            return "Int64";
        case EnviDataType::uint64:
            return "UInt64";
        case EnviDataType::complex64:
            return "CFloat32";
        case EnviDataType::complex128:
            return "CFloat64";
    }
    return "?";
}

/// NumPy's dtype string ("<i4") for a type in the native byte order.
inline std::string numpy_dtype(EnviDataType type) {
    const char order = native_byte_order() == ByteOrder::little ? '<' : '>';
    switch (type) {
        case EnviDataType::uint8:
            return "|u1";
        case EnviDataType::int16:
            return std::string(1, order) + "i2";
        case EnviDataType::int32:
            return std::string(1, order) + "i4";
        case EnviDataType::float32:
            return std::string(1, order) + "f4";
        case EnviDataType::float64:
            return std::string(1, order) + "f8";
        case EnviDataType::uint16:
            return std::string(1, order) + "u2";
        case EnviDataType::uint32:
            return std::string(1, order) + "u4";
        case EnviDataType::int64:
            return std::string(1, order) + "i8";
        case EnviDataType::uint64:
            return std::string(1, order) + "u8";
        case EnviDataType::complex64:
            return std::string(1, order) + "c8";
        case EnviDataType::complex128:
            return std::string(1, order) + "c16";
    }
    return "?";
}

constexpr EnviDataType kWritableTypes[] = {
    EnviDataType::uint8,   EnviDataType::int16,   EnviDataType::int32,
    EnviDataType::float32, EnviDataType::float64, EnviDataType::uint16,
    EnviDataType::uint32,  EnviDataType::int64,   EnviDataType::uint64,
};

/// An image written with EnviWriter and what an oracle should find in it.
struct TestImage {
    std::filesystem::path data;
    std::filesystem::path header_path;
    EnviHeader header;
    nlohmann::json values;  ///< [line][sample][band]
};

template <typename T>
nlohmann::json write_values(EnviWriter& writer) {
    using L = std::numeric_limits<T>;
    const EnviHeader& h = writer.header();
    nlohmann::json values = nlohmann::json::array();
    std::size_t i = 0;
    for (std::size_t y = 0; y < h.lines; ++y) {
        std::vector<T> line(h.samples * h.bands);
        nlohmann::json json_line = nlohmann::json::array();
        for (std::size_t x = 0; x < h.samples; ++x) {
            nlohmann::json pixel = nlohmann::json::array();
            for (std::size_t b = 0; b < h.bands; ++b, ++i) {
                T value;
                if (i == 0) {
                    value = L::lowest();  // the extremes (finite: JSON has no inf/nan)
                } else if (i == 1) {
                    value = L::max();
                } else if constexpr (L::is_integer) {
                    value = static_cast<T>(static_cast<long>((i * 37) % 200) -
                                           (L::is_signed ? 100 : 0));
                } else {
                    value = static_cast<T>(static_cast<double>(i) * 0.37 - 10.0);
                }
                line[x * h.bands + b] = value;
                pixel.push_back(value);
            }
            json_line.push_back(std::move(pixel));
        }
        values.push_back(std::move(json_line));
        writer.write_line_raw(std::as_bytes(std::span(line)));
    }
    return values;
}

/// Writes `<dir>/<name>.img` of `type` with wavelengths, band names, units and provenance.
inline TestImage write_test_image(const TempDir& dir, const std::string& name, EnviDataType type,
                                  std::size_t samples, std::size_t lines, std::size_t bands) {
    EnviHeader h;
    h.description = "glint oracle test image, " + std::string(envi_type_name(type));
    h.samples = samples;
    h.lines = lines;
    h.bands = bands;
    h.data_type = type;
    h.wavelength_units = "Microns";
    for (std::size_t b = 0; b < bands; ++b) {
        h.wavelength.push_back(0.4 + static_cast<double>(b) / 3.0 * 1e-3);
        h.fwhm.push_back(0.001 + static_cast<double>(b) * 1e-6);
        h.band_names.push_back("Band " + std::to_string(b + 1) + ", {total}");
    }
    h.data_units = "Watts/(cm2 sr um)";
    h.set_extra("glint version", "0.1.0");
    h.set_extra("glint seed", "42");
    TestImage image;
    image.data = dir.path() / (name + ".img");
    image.header_path = dir.path() / (name + ".img.hdr");
    EnviWriter writer(image.data, h);
    switch (type) {
        case EnviDataType::uint8:
            image.values = write_values<std::uint8_t>(writer);
            break;
        case EnviDataType::int16:
            image.values = write_values<std::int16_t>(writer);
            break;
        case EnviDataType::int32:
            image.values = write_values<std::int32_t>(writer);
            break;
        case EnviDataType::float32:
            image.values = write_values<float>(writer);
            break;
        case EnviDataType::float64:
            image.values = write_values<double>(writer);
            break;
        case EnviDataType::uint16:
            image.values = write_values<std::uint16_t>(writer);
            break;
        case EnviDataType::uint32:
            image.values = write_values<std::uint32_t>(writer);
            break;
        case EnviDataType::int64:
            image.values = write_values<std::int64_t>(writer);
            break;
        case EnviDataType::uint64:
            image.values = write_values<std::uint64_t>(writer);
            break;
        case EnviDataType::complex64:
        case EnviDataType::complex128:
            break;
    }
    writer.commit();
    image.header = writer.header();
    return image;
}

}  // namespace glint::io::oracle
