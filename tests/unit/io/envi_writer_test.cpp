// SPDX-License-Identifier: Apache-2.0
// Unit tests of EnviWriter with EnviReader: a write/read round trip for every writable data
// type at the type's extremes, the double conversion (rounding, clamping, NaN), the header
// that lands beside the data, and the atomic behaviour (nothing left behind without commit,
// wrong line counts and bad headers leave no file).
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "glint/core/error.h"
#include "glint/io/envi.h"
#include "glint/test/temp_dir.h"

namespace glint::io {
namespace envi_writer_test {

using ::testing::HasSubstr;

using glint::test::TempDir;

std::vector<std::string> folder_entries(const std::filesystem::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

std::string read_text(const std::filesystem::path& path) {
    std::ifstream stream(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
}

EnviHeader header_for(EnviDataType type, std::size_t samples, std::size_t lines,
                      std::size_t bands) {
    EnviHeader h;
    h.samples = samples;
    h.lines = lines;
    h.bands = bands;
    h.data_type = type;
    return h;
}

// ---- every writable type at its extremes -------------------------------------------------

template <typename T, EnviDataType kType>
struct TypeCase {
    using Value = T;
    static constexpr EnviDataType type = kType;
};

using WritableTypes = ::testing::Types<
    TypeCase<std::uint8_t, EnviDataType::uint8>, TypeCase<std::int16_t, EnviDataType::int16>,
    TypeCase<std::int32_t, EnviDataType::int32>, TypeCase<float, EnviDataType::float32>,
    TypeCase<double, EnviDataType::float64>, TypeCase<std::uint16_t, EnviDataType::uint16>,
    TypeCase<std::uint32_t, EnviDataType::uint32>, TypeCase<std::int64_t, EnviDataType::int64>,
    TypeCase<std::uint64_t, EnviDataType::uint64>>;

template <typename Case>
class EnviRoundTrip : public ::testing::Test {};
TYPED_TEST_SUITE(EnviRoundTrip, WritableTypes);

template <typename T>
std::vector<T> extreme_values() {
    using L = std::numeric_limits<T>;
    std::vector<T> values = {L::lowest(), L::max(), T(0), T(1), static_cast<T>(L::max() - 1)};
    if constexpr (L::is_signed) values.push_back(T(-1));
    if constexpr (!L::is_integer) {
        values.insert(values.end(), {L::min(), L::denorm_min(), -L::denorm_min(), L::infinity(),
                                     -L::infinity(), T(-0.0), L::quiet_NaN(), L::epsilon()});
    } else {
        values.push_back(static_cast<T>(L::lowest() + 1));
    }
    return values;
}

TYPED_TEST(EnviRoundTrip, RawValuesAtTheTypeExtremesComeBackBitExact) {
    using T = typename TypeParam::Value;
    TempDir dir;
    const std::vector<T> values = extreme_values<T>();
    // 3 bands, enough samples for every value, 2 lines (the second line reversed).
    constexpr std::size_t kBands = 3;
    const std::size_t samples = values.size();
    const auto path = dir.path() / "cube.img";
    EnviHeader h = header_for(TypeParam::type, samples, 2, kBands);
    h.interleave = Interleave::bsq;  // overridden: glint writes BIP
    h.header_offset = 99;            // overridden: no header offset
    std::vector<std::vector<T>> lines(2, std::vector<T>(samples * kBands));
    for (std::size_t i = 0; i < samples * kBands; ++i) {
        lines[0][i] = values[i % values.size()];
        lines[1][i] = values[(values.size() - 1) - (i % values.size())];
    }
    {
        EnviWriter writer(path, h);
        EXPECT_EQ(writer.header().interleave, Interleave::bip);
        EXPECT_EQ(writer.header().header_offset, 0u);
        for (const auto& line : lines) writer.write_line_raw(std::as_bytes(std::span(line)));
        EXPECT_EQ(writer.lines_written(), 2u);
        writer.commit();
    }
    EXPECT_EQ(folder_entries(dir.path()), (std::vector<std::string>{"cube.img", "cube.img.hdr"}));
    EXPECT_EQ(std::filesystem::file_size(path), 2 * samples * kBands * sizeof(T));

    EnviReader reader(path);
    EXPECT_EQ(reader.header_path(), dir.path() / "cube.img.hdr");
    EXPECT_EQ(reader.header().data_type, TypeParam::type);
    EXPECT_EQ(reader.header().samples, samples);
    EXPECT_EQ(reader.header().lines, 2u);
    EXPECT_EQ(reader.header().bands, kBands);
    EXPECT_EQ(reader.header().interleave, Interleave::bip);
    EXPECT_EQ(reader.header().byte_order, native_byte_order());
    EXPECT_EQ(reader.header().header_offset, 0u);
    for (std::size_t y = 0; y < 2; ++y) {
        std::vector<T> back(samples * kBands);
        reader.read_line_raw(y, std::as_writable_bytes(std::span(back)));
        EXPECT_EQ(std::memcmp(back.data(), lines[y].data(), back.size() * sizeof(T)), 0) << y;
        // read_line: the same values as doubles.
        std::vector<double> as_double(samples * kBands);
        reader.read_line(y, as_double);
        for (std::size_t i = 0; i < as_double.size(); ++i) {
            const double expected = static_cast<double>(lines[y][i]);
            if (std::isnan(expected)) {
                EXPECT_TRUE(std::isnan(as_double[i])) << i;
            } else {
                EXPECT_EQ(as_double[i], expected) << i;
            }
        }
    }
}

TYPED_TEST(EnviRoundTrip, DoubleLinesRoundTripThroughReadLine) {
    using T = typename TypeParam::Value;
    TempDir dir;
    const auto path = dir.path() / "d.img";
    std::vector<double> line;
    for (T value : extreme_values<T>()) {
        const double d = static_cast<double>(value);
        // Integers beyond 2^53 do not survive double; the clamping test covers them.
        if (std::numeric_limits<T>::is_integer && std::fabs(d) >= 9007199254740992.0) continue;
        line.push_back(d);
    }
    {
        EnviWriter writer(path, header_for(TypeParam::type, line.size(), 1, 1));
        writer.write_line(line);
        writer.commit();
    }
    EnviHeader header;
    const std::vector<double> back = read_envi_bip(path, &header);
    EXPECT_EQ(header.samples, line.size());
    ASSERT_EQ(back.size(), line.size());
    for (std::size_t i = 0; i < line.size(); ++i) {
        if (std::isnan(line[i])) {
            EXPECT_TRUE(std::isnan(back[i]));
        } else {
            EXPECT_EQ(back[i], line[i]) << i;
        }
    }
}

// ---- double conversion -------------------------------------------------------------------

/// Writes `values` as one line of `type` and reads them back as doubles.
std::vector<double> through(EnviDataType type, const std::vector<double>& values) {
    TempDir dir;
    const auto path = dir.path() / "c.img";
    EnviWriter writer(path, header_for(type, values.size(), 1, 1));
    writer.write_line(values);
    writer.commit();
    return read_envi_bip(path, nullptr);
}

TEST(EnviWriteLine, IntegersAreRoundedToNearestAndClamped) {
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    constexpr double kInf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(through(EnviDataType::uint8,
                      {-1.0, 0.4, 0.5, 2.5, 254.6, 255.4, 255.6, 300.0, kNaN, kInf, -kInf}),
              (std::vector<double>{0, 0, 1, 3, 255, 255, 255, 255, 0, 255, 0}));
    EXPECT_EQ(through(EnviDataType::int16, {-40000.0, -32768.4, -2.5, -0.4, 32767.4, 1e9, kNaN}),
              (std::vector<double>{-32768, -32768, -3, 0, 32767, 32767, 0}));
    EXPECT_EQ(through(EnviDataType::uint16, {-0.6, 65535.49, 65536.0, 1e300}),
              (std::vector<double>{0, 65535, 65535, 65535}));
    EXPECT_EQ(through(EnviDataType::int32, {-3e9, 3e9, 2147483646.5, -kInf}),
              (std::vector<double>{-2147483648.0, 2147483647.0, 2147483647.0, -2147483648.0}));
    EXPECT_EQ(through(EnviDataType::uint32, {-5.0, 5e9, 4294967294.6}),
              (std::vector<double>{0, 4294967295.0, 4294967295.0}));
    EXPECT_EQ(through(EnviDataType::float32, {0.1, 1e300, -1e300}),
              (std::vector<double>{static_cast<double>(0.1f), kInf, -kInf}));
    // Beyond FLT_MAX: IEEE rounding to nearest (FLT_MAX up to half an ulp above it).
    constexpr double kFltMax = std::numeric_limits<float>::max();
    EXPECT_EQ(through(EnviDataType::float32, {kFltMax + 0x1p102, -kFltMax - 0x1p103}),
              (std::vector<double>{kFltMax, -kInf}));
    const std::vector<double> f32_nan = through(EnviDataType::float32, {kNaN});
    EXPECT_TRUE(std::isnan(f32_nan[0]));
}

TEST(EnviWriteLine, SixtyFourBitIntegersClampAtTheirLimits) {
    TempDir dir;
    const auto path = dir.path() / "i64.img";
    const std::vector<double> values = {1e19,
                                        -1e19,
                                        9223372036854775808.0,
                                        -9223372036854775808.0,
                                        -1.5,
                                        std::numeric_limits<double>::quiet_NaN()};
    {
        EnviWriter writer(path, header_for(EnviDataType::int64, values.size(), 2, 1));
        writer.write_line(values);
        writer.write_line(values);
        writer.commit();
    }
    EnviReader reader(path);
    std::vector<std::int64_t> raw(values.size());
    reader.read_line_raw(1, std::as_writable_bytes(std::span(raw)));
    using L = std::numeric_limits<std::int64_t>;
    EXPECT_EQ(raw, (std::vector<std::int64_t>{L::max(), L::min(), L::max(), L::min(), -2, 0}));

    const auto upath = dir.path() / "u64.img";
    const std::vector<double> uvalues = {1e20, 18446744073709551616.0, -5.0, 1e19, 0.5};
    {
        EnviWriter writer(upath, header_for(EnviDataType::uint64, uvalues.size(), 1, 1));
        writer.write_line(uvalues);
        writer.commit();
    }
    EnviReader ureader(upath);
    std::vector<std::uint64_t> uraw(uvalues.size());
    ureader.read_line_raw(0, std::as_writable_bytes(std::span(uraw)));
    using U = std::numeric_limits<std::uint64_t>;
    EXPECT_EQ(uraw,
              (std::vector<std::uint64_t>{U::max(), U::max(), 0, 10000000000000000000ull, 1}));
}

// ---- the header beside the data ----------------------------------------------------------

TEST(EnviWriterHeader, MetadataAndProvenanceAreWrittenAndReadBack) {
    TempDir dir;
    const auto path = dir.path() / "radiance.img";
    EnviHeader h = header_for(EnviDataType::float32, 2, 2, 3);
    h.description = "glint radiance, capture 0";
    h.wavelength_units = "Microns";
    h.wavelength = {0.45, 0.55, 0.65};
    h.fwhm = {0.05, 0.05, 0.05};
    h.band_names = {"Blue", "Green, wide", "Red"};
    h.data_units = "Watts/(cm2 sr um)";
    h.set_extra("glint version", "0.1.0");
    h.set_extra("glint seed", "42");
    {
        EnviWriter writer(path, h);
        const std::vector<double> line(6, 1.5);
        writer.write_line(line);
        writer.write_line(line);
        writer.commit();
    }
    const std::string text = read_text(dir.path() / "radiance.img.hdr");
    EXPECT_EQ(text.rfind("ENVI\ndescription = {glint radiance, capture 0}\nsamples = 2\n", 0), 0u)
        << text;
    EXPECT_THAT(text, HasSubstr("interleave = bip\nbyte order = " +
                                std::to_string(static_cast<int>(native_byte_order())) + "\n"));
    EXPECT_THAT(text, HasSubstr("band names = {Blue, Green; wide, Red}\n"));
    EXPECT_THAT(text, HasSubstr("data units = Watts/(cm2 sr um)\nglint version = 0.1.0\n"
                                "glint seed = 42\n"));
    EnviReader reader(dir.path() / "radiance.img.hdr");  // opened by its header
    EXPECT_EQ(reader.data_path(), path);
    EXPECT_EQ(reader.header().wavelength, h.wavelength);
    EXPECT_EQ(reader.header().fwhm, h.fwhm);
    EXPECT_EQ(reader.header().band_names, (std::vector<std::string>{"Blue", "Green; wide", "Red"}));
    EXPECT_EQ(reader.header().description, h.description);
    EXPECT_EQ(reader.header().extra, h.extra);
}

TEST(EnviWriterHeader, ExtraKeysSetWhileWritingReachTheHeader) {
    TempDir dir;
    const auto path = dir.path() / "late.img";
    EnviWriter writer(path, header_for(EnviDataType::float64, 1, 1, 1));
    writer.write_line(std::vector<double>{2.0});
    writer.set_extra("glint capture times", "{0.5, 1.5}");
    writer.set_extra("glint capture times", "{0.5}");       // replaces
    EXPECT_THROW(writer.set_extra("samples", "3"), Error);  // a standard key
    writer.commit();
    const std::string text = read_text(dir.path() / "late.img.hdr");
    EXPECT_THAT(text, HasSubstr("glint capture times = {0.5}\n"));
    EXPECT_THROW(writer.set_extra("glint late", "1"), Error);
}

// ---- atomic behaviour --------------------------------------------------------------------

TEST(EnviWriterAtomic, DestroyedWithoutCommitLeavesTheFolderEmpty) {
    TempDir dir;
    {
        EnviWriter writer(dir.path() / "a.img", header_for(EnviDataType::float64, 4, 3, 2));
        const std::vector<double> line(8, 0.25);
        writer.write_line(line);
        writer.write_line(line);
        // A temporary file exists while writing, beside the target.
        EXPECT_EQ(folder_entries(dir.path()).size(), 1u);
    }
    EXPECT_TRUE(folder_entries(dir.path()).empty());
    { EnviWriter writer(dir.path() / "b.img", header_for(EnviDataType::uint8, 1, 1, 1)); }
    EXPECT_TRUE(folder_entries(dir.path()).empty());
}

TEST(EnviWriterAtomic, WrongLineCountIsAnErrorAndLeavesNothing) {
    TempDir dir;
    {
        EnviWriter writer(dir.path() / "short.img", header_for(EnviDataType::int16, 2, 3, 1));
        writer.write_line(std::vector<double>{1, 2});
        try {
            writer.commit();
            ADD_FAILURE() << "commit accepted 1 of 3 lines";
        } catch (const Error& error) {
            EXPECT_EQ(error.category(), ErrorCategory::runtime);
            EXPECT_THAT(error.what(), HasSubstr("short.img: wrote 1 lines, the header declares 3"));
        }
        EXPECT_TRUE(folder_entries(dir.path()).empty());  // even before destruction
    }
    EXPECT_TRUE(folder_entries(dir.path()).empty());
    {
        EnviWriter writer(dir.path() / "long.img", header_for(EnviDataType::int16, 2, 1, 1));
        writer.write_line(std::vector<double>{1, 2});
        try {
            writer.write_line(std::vector<double>{3, 4});
            ADD_FAILURE() << "a second line was accepted";
        } catch (const Error& error) {
            EXPECT_THAT(error.what(), HasSubstr("long.img: more lines than the 1 the header "
                                                "declares"));
        }
    }
    EXPECT_TRUE(folder_entries(dir.path()).empty());
}

TEST(EnviWriterAtomic, BadHeadersAreRejectedBeforeAnyFileIsCreated) {
    TempDir dir;
    const auto path = dir.path() / "bad.img";
    const auto message = [&](const EnviHeader& h) -> std::string {
        try {
            EnviWriter writer(path, h);
        } catch (const Error& error) {
            EXPECT_EQ(error.category(), ErrorCategory::input);
            return error.what();
        }
        return "no error";
    };
    EXPECT_THAT(message(header_for(EnviDataType::complex64, 1, 1, 1)),
                HasSubstr("bad.img.hdr: data type: complex64 cannot be written (complex ENVI "
                          "types 6 and 9 are read only)"));
    EXPECT_THAT(message(header_for(EnviDataType::float32, 0, 1, 1)),
                HasSubstr("bad.img.hdr: samples: must be at least 1, got 0"));
    EnviHeader h = header_for(EnviDataType::float32, 1, 1, 2);
    h.wavelength = {0.5};
    EXPECT_THAT(message(h), HasSubstr("wavelength: has 1 values, expected 2 (one per band)"));
    h = header_for(EnviDataType::float32, std::size_t{1} << 40, std::size_t{1} << 30, 1);
    EXPECT_THAT(message(h), HasSubstr("bad.img.hdr: image size overflows 64 bits"));
    h = header_for(EnviDataType::float32, 1, 1, 1);
    h.set_extra("bands", "3");
    EXPECT_THAT(message(h), HasSubstr("bands: is a standard key and cannot be an extra key"));
    EXPECT_TRUE(folder_entries(dir.path()).empty());
}

TEST(EnviWriterAtomic, MissingFolderIsAnIoError) {
    TempDir dir;
    try {
        EnviWriter writer(dir.path() / "no" / "such" / "x.img",
                          header_for(EnviDataType::uint8, 1, 1, 1));
        ADD_FAILURE() << "writer created in a missing folder";
    } catch (const Error& error) {
        EXPECT_EQ(error.category(), ErrorCategory::io);
        EXPECT_THAT(error.what(), HasSubstr("x.img: cannot create output: No such file"));
    }
}

}  // namespace envi_writer_test
}  // namespace glint::io
