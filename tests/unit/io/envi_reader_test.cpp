// SPDX-License-Identifier: Apache-2.0
// Unit tests of EnviReader on files whose bytes the test writes itself: every interleave,
// big- and little-endian data, a header offset, complex types, the `<name>.hdr` naming, and
// the errors for missing or short files.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <complex>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "glint/core/error.h"
#include "glint/io/envi.h"
#include "glint/test/temp_dir.h"

namespace glint::io {
namespace envi_reader_test {

using ::testing::HasSubstr;

using glint::test::TempDir;

void write_bytes(const std::filesystem::path& path, const std::vector<std::byte>& bytes) {
    std::ofstream stream(path, std::ios::binary);
    stream.write(reinterpret_cast<const char*>(bytes.data()),
                 static_cast<std::streamsize>(bytes.size()));
}

void write_text(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

/// Appends `value` in the given byte order.
template <typename T>
void append(std::vector<std::byte>& out, T value, ByteOrder order) {
    std::byte bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if (order != native_byte_order()) std::reverse(bytes, bytes + sizeof(T));
    out.insert(out.end(), bytes, bytes + sizeof(T));
}

constexpr std::size_t kSamples = 5;
constexpr std::size_t kLines = 4;
constexpr std::size_t kBands = 3;

/// The test image: a distinct value for every (x, y, b), 0..234 so that it fits every type.
double value_at(std::size_t x, std::size_t y, std::size_t b) {
    return static_cast<double>(100 * b + 10 * y + x);
}

/// Bytes of the test image in `interleave` and `order` as values of type T.
template <typename T>
std::vector<std::byte> image_bytes(Interleave interleave, ByteOrder order) {
    std::vector<std::byte> out;
    const auto put = [&](std::size_t x, std::size_t y, std::size_t b) {
        append(out, static_cast<T>(value_at(x, y, b)), order);
    };
    switch (interleave) {
        case Interleave::bsq:
            for (std::size_t b = 0; b < kBands; ++b)
                for (std::size_t y = 0; y < kLines; ++y)
                    for (std::size_t x = 0; x < kSamples; ++x) put(x, y, b);
            break;
        case Interleave::bil:
            for (std::size_t y = 0; y < kLines; ++y)
                for (std::size_t b = 0; b < kBands; ++b)
                    for (std::size_t x = 0; x < kSamples; ++x) put(x, y, b);
            break;
        case Interleave::bip:
            for (std::size_t y = 0; y < kLines; ++y)
                for (std::size_t x = 0; x < kSamples; ++x)
                    for (std::size_t b = 0; b < kBands; ++b) put(x, y, b);
            break;
    }
    return out;
}

std::string header_text(int type_code, Interleave interleave, ByteOrder order,
                        std::uint64_t offset) {
    return "ENVI\nsamples = " + std::to_string(kSamples) + "\nlines = " + std::to_string(kLines) +
           "\nbands = " + std::to_string(kBands) + "\nheader offset = " + std::to_string(offset) +
           "\ndata type = " + std::to_string(type_code) +
           "\ninterleave = " + interleave_name(interleave) +
           "\nbyte order = " + std::to_string(static_cast<int>(order)) + "\n";
}

/// Checks every line of `reader` against value_at, as doubles in BIP order.
void expect_test_image(EnviReader& reader) {
    ASSERT_EQ(reader.header().samples, kSamples);
    ASSERT_EQ(reader.header().lines, kLines);
    ASSERT_EQ(reader.header().bands, kBands);
    std::vector<double> line(kSamples * kBands);
    // Lines in a scattered order: each read seeks.
    for (std::size_t y : {2u, 0u, 3u, 1u}) {
        reader.read_line(y, line);
        for (std::size_t x = 0; x < kSamples; ++x) {
            for (std::size_t b = 0; b < kBands; ++b) {
                EXPECT_EQ(line[x * kBands + b], value_at(x, y, b))
                    << "x=" << x << " y=" << y << " b=" << b;
            }
        }
    }
}

struct ReadCase {
    Interleave interleave;
    ByteOrder order;
    std::uint64_t offset;
};

class EnviReadLayout : public ::testing::TestWithParam<ReadCase> {};

TEST_P(EnviReadLayout, EveryTypeComesBackInBipNativeOrder) {
    const ReadCase c = GetParam();
    TempDir dir;
    const auto check = [&](int code, std::vector<std::byte> bytes) {
        const auto path = dir.path() / ("t" + std::to_string(code) + ".img");
        std::vector<std::byte> data(c.offset, std::byte{0xAB});  // garbage before the image
        data.insert(data.end(), bytes.begin(), bytes.end());
        write_bytes(path, data);
        write_text(dir.path() / ("t" + std::to_string(code) + ".img.hdr"),
                   header_text(code, c.interleave, c.order, c.offset));
        EnviReader reader(path);
        EXPECT_EQ(reader.header().interleave, c.interleave);
        EXPECT_EQ(reader.header().byte_order, c.order);
        EXPECT_EQ(reader.header().header_offset, c.offset);
        SCOPED_TRACE("data type " + std::to_string(code));
        expect_test_image(reader);
    };
    check(2, image_bytes<std::int16_t>(c.interleave, c.order));
    check(3, image_bytes<std::int32_t>(c.interleave, c.order));
    check(4, image_bytes<float>(c.interleave, c.order));
    check(5, image_bytes<double>(c.interleave, c.order));
    check(14, image_bytes<std::int64_t>(c.interleave, c.order));
}

TEST_P(EnviReadLayout, RawLinesAreByteSwappedToNative) {
    const ReadCase c = GetParam();
    TempDir dir;
    const auto path = dir.path() / "u16.dat";
    std::vector<std::byte> data(c.offset, std::byte{0});
    const std::vector<std::byte> image = image_bytes<std::uint16_t>(c.interleave, c.order);
    data.insert(data.end(), image.begin(), image.end());
    write_bytes(path, data);
    write_text(dir.path() / "u16.hdr", header_text(12, c.interleave, c.order, c.offset));
    EnviReader reader(dir.path() / "u16.hdr");
    EXPECT_EQ(reader.data_path(), path);
    std::vector<std::uint16_t> line(kSamples * kBands);
    reader.read_line_raw(3, std::as_writable_bytes(std::span(line)));
    for (std::size_t x = 0; x < kSamples; ++x) {
        for (std::size_t b = 0; b < kBands; ++b) {
            EXPECT_EQ(line[x * kBands + b], static_cast<std::uint16_t>(value_at(x, 3, b)));
        }
    }
}

INSTANTIATE_TEST_SUITE_P(AllLayouts, EnviReadLayout,
                         ::testing::Values(ReadCase{Interleave::bsq, ByteOrder::little, 0},
                                           ReadCase{Interleave::bil, ByteOrder::little, 0},
                                           ReadCase{Interleave::bip, ByteOrder::little, 0},
                                           ReadCase{Interleave::bsq, ByteOrder::big, 0},
                                           ReadCase{Interleave::bil, ByteOrder::big, 0},
                                           ReadCase{Interleave::bip, ByteOrder::big, 0},
                                           ReadCase{Interleave::bsq, ByteOrder::big, 7},
                                           ReadCase{Interleave::bil, ByteOrder::little, 512},
                                           ReadCase{Interleave::bip, ByteOrder::big, 3}),
                         [](const ::testing::TestParamInfo<ReadCase>& param_info) {
                             const ReadCase& c = param_info.param;
                             return std::string(interleave_name(c.interleave)) +
                                    (c.order == ByteOrder::big ? "_big" : "_little") + "_offset" +
                                    std::to_string(c.offset);
                         });

TEST(EnviReader, ComplexValuesDeliverTheirRealPart) {
    TempDir dir;
    for (const ByteOrder order : {ByteOrder::little, ByteOrder::big}) {
        std::vector<std::byte> c64;
        std::vector<std::byte> c128;
        for (std::size_t y = 0; y < kLines; ++y) {
            for (std::size_t x = 0; x < kSamples; ++x) {
                for (std::size_t b = 0; b < kBands; ++b) {
                    append(c64, static_cast<float>(value_at(x, y, b)), order);
                    append(c64, -7.5f, order);
                    append(c128, value_at(x, y, b), order);
                    append(c128, 1e300, order);
                }
            }
        }
        write_bytes(dir.path() / "c64.img", c64);
        write_text(dir.path() / "c64.img.hdr", header_text(6, Interleave::bip, order, 0));
        write_bytes(dir.path() / "c128.img", c128);
        write_text(dir.path() / "c128.img.hdr", header_text(9, Interleave::bip, order, 0));
        EnviReader r64(dir.path() / "c64.img");
        expect_test_image(r64);
        EnviReader r128(dir.path() / "c128.img");
        expect_test_image(r128);
        // Raw complex values: both parts, each swapped on its own.
        std::vector<std::complex<float>> raw(kSamples * kBands);
        r64.read_line_raw(1, std::as_writable_bytes(std::span(raw)));
        EXPECT_EQ(raw[4], std::complex<float>(static_cast<float>(value_at(1, 1, 1)), -7.5f));
    }
}

TEST(EnviReader, ReadEnviBipOfBsqFile) {
    TempDir dir;
    write_bytes(dir.path() / "s.img", image_bytes<float>(Interleave::bsq, ByteOrder::big));
    write_text(dir.path() / "s.hdr", header_text(4, Interleave::bsq, ByteOrder::big, 0));
    EnviHeader header;
    const std::vector<double> all = read_envi_bip(dir.path() / "s.img", &header);
    EXPECT_EQ(header.interleave, Interleave::bsq);
    ASSERT_EQ(all.size(), kSamples * kLines * kBands);
    for (std::size_t y = 0; y < kLines; ++y) {
        for (std::size_t x = 0; x < kSamples; ++x) {
            for (std::size_t b = 0; b < kBands; ++b) {
                EXPECT_EQ(all[(y * kSamples + x) * kBands + b], value_at(x, y, b));
            }
        }
    }
}

TEST(EnviReader, UnitsAndListsOfAForeignHeader) {
    TempDir dir;
    write_bytes(dir.path() / "f.img", image_bytes<std::uint8_t>(Interleave::bil, ByteOrder::big));
    write_text(dir.path() / "f.img.hdr",
               "ENVI\n"
               "description = {\n  Written by some other program}\n"
               "samples = 5\nlines = 4\nbands = 3\ndata type = 1\n"
               "interleave = bil\n"
               "wavelength units = Nanometers\n"
               "wavelength = { 450.5, 550,\n 650.25 }\n"
               "band names = {\n b1, b2,\n b3 }\n");
    EnviReader reader(dir.path() / "f.img");
    EXPECT_EQ(reader.header().description, "Written by some other program");
    EXPECT_EQ(reader.header().wavelength, (std::vector<double>{450.5, 550, 650.25}));
    EXPECT_EQ(reader.header().band_names, (std::vector<std::string>{"b1", "b2", "b3"}));
    EXPECT_EQ(reader.header().byte_order, native_byte_order());  // absent: native
    std::vector<double> line(kSamples * kBands);
    reader.read_line(0, line);
    EXPECT_EQ(line[0], static_cast<double>(static_cast<std::uint8_t>(value_at(0, 0, 0))));
}

// ---- file-level errors -------------------------------------------------------------------

std::string open_error(const std::filesystem::path& path) {
    try {
        EnviReader reader(path);
    } catch (const Error& error) {
        return error.what();
    }
    return "no error";
}

TEST(EnviReaderErrors, DataFileShorterThanTheHeaderSays) {
    TempDir dir;
    std::vector<std::byte> bytes = image_bytes<double>(Interleave::bip, ByteOrder::little);
    bytes.resize(bytes.size() - 1);
    write_bytes(dir.path() / "short.img", bytes);
    write_text(dir.path() / "short.img.hdr",
               header_text(5, Interleave::bip, ByteOrder::little, 16));
    EXPECT_THAT(open_error(dir.path() / "short.img"),
                HasSubstr("short.img: data file is too short: 479 bytes, expected at least 496 "
                          "bytes (header offset 16 + 5 samples x 4 lines x 3 bands x 8 bytes)"));
}

TEST(EnviReaderErrors, HeaderErrorsNameTheHeaderFile) {
    TempDir dir;
    write_bytes(dir.path() / "bad.img", std::vector<std::byte>(1000));
    write_text(dir.path() / "bad.img.hdr",
               "ENVI\nsamples = 5\nlines = 4\nbands = 3\ndata type = 7\n");
    EXPECT_THAT(open_error(dir.path() / "bad.img"),
                HasSubstr("bad.img.hdr:5: data type: unknown ENVI data type code 7"));
    write_text(dir.path() / "bad.img.hdr", "\x89PNG\r\n");
    EXPECT_THAT(open_error(dir.path() / "bad.img"), HasSubstr("bad.img.hdr:1: missing ENVI magic"));
}

TEST(EnviReaderErrors, MissingHeaderOrData) {
    TempDir dir;
    write_bytes(dir.path() / "lonely.img", std::vector<std::byte>(10));
    EXPECT_THAT(open_error(dir.path() / "lonely.img"),
                HasSubstr("lonely.img: no ENVI header found (looked for "));
    EXPECT_THAT(open_error(dir.path() / "lonely.img"), HasSubstr("lonely.img.hdr or "));
    write_text(dir.path() / "orphan.hdr", header_text(1, Interleave::bip, ByteOrder::little, 0));
    EXPECT_THAT(open_error(dir.path() / "orphan.hdr"),
                HasSubstr("orphan.hdr: no data file for this header (looked for "));
    EXPECT_THAT(open_error(dir.path() / "absent.img.hdr"),
                HasSubstr("absent.img.hdr: cannot open header: No such file or directory"));
}

}  // namespace envi_reader_test
}  // namespace glint::io
