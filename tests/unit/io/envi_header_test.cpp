// SPDX-License-Identifier: Apache-2.0
// Unit tests of ENVI header text: parsing (case, braces over lines, comments, extras), every
// malformed-header error with its message and line, formatting (key order, wrapping at 200
// characters, round-trip digits, sanitized names) and the data/header naming rules.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "glint/core/error.h"
#include "glint/io/envi.h"
#include "glint/test/temp_dir.h"

namespace glint::io {
namespace envi_header_test {

using ::testing::HasSubstr;

using glint::test::TempDir;

void touch(const std::filesystem::path& path) { std::ofstream(path) << "x"; }

/// The message of the glint::Error that parsing `text` as `file` throws ("" if none).
std::string parse_error(const std::string& text, const std::string& file = "cube.img.hdr") {
    try {
        parse_envi_header(text, file);
    } catch (const Error& error) {
        EXPECT_EQ(error.category(), ErrorCategory::input) << error.what();
        return error.what();
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return {};
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream stream(text);
    for (std::string line; std::getline(stream, line);) lines.push_back(line);
    return lines;
}

constexpr const char* kMinimal = "ENVI\nsamples = 4\nlines = 3\nbands = 2\ndata type = 4\n";

TEST(EnviTypes, SizesNamesAndCodes) {
    EXPECT_EQ(envi_type_size(EnviDataType::uint8), 1u);
    EXPECT_EQ(envi_type_size(EnviDataType::int16), 2u);
    EXPECT_EQ(envi_type_size(EnviDataType::uint16), 2u);
    EXPECT_EQ(envi_type_size(EnviDataType::int32), 4u);
    EXPECT_EQ(envi_type_size(EnviDataType::uint32), 4u);
    EXPECT_EQ(envi_type_size(EnviDataType::float32), 4u);
    EXPECT_EQ(envi_type_size(EnviDataType::float64), 8u);
    EXPECT_EQ(envi_type_size(EnviDataType::int64), 8u);
    EXPECT_EQ(envi_type_size(EnviDataType::uint64), 8u);
    EXPECT_EQ(envi_type_size(EnviDataType::complex64), 8u);
    EXPECT_EQ(envi_type_size(EnviDataType::complex128), 16u);
    for (long code : {1, 2, 3, 4, 5, 6, 9, 12, 13, 14, 15}) {
        ASSERT_TRUE(envi_type_from_code(code)) << code;
        EXPECT_EQ(static_cast<long>(*envi_type_from_code(code)), code);
    }
    for (long code : {-1, 0, 7, 8, 10, 11, 16, 99}) EXPECT_FALSE(envi_type_from_code(code));
    EXPECT_STREQ(envi_type_name(EnviDataType::uint16), "uint16");
    EXPECT_STREQ(envi_type_name(EnviDataType::complex128), "complex128");
    EXPECT_STREQ(interleave_name(Interleave::bil), "bil");
}

TEST(EnviTypes, FromStringTakesNamesInAnyCaseAndCodes) {
    for (long code : {1, 2, 3, 4, 5, 6, 9, 12, 13, 14, 15}) {
        const EnviDataType type = *envi_type_from_code(code);
        EXPECT_EQ(envi_type_from_string(envi_type_name(type)), type) << code;
        EXPECT_EQ(envi_type_from_string(std::to_string(code)), type) << code;
    }
    EXPECT_EQ(envi_type_from_string("Float32"), EnviDataType::float32);
    EXPECT_EQ(envi_type_from_string("float"), std::nullopt);
    EXPECT_EQ(envi_type_from_string("7"), std::nullopt);
    EXPECT_EQ(envi_type_from_string(""), std::nullopt);
}

TEST(EnviHeaderParse, MinimalHeaderGetsEnviDefaults) {
    const EnviHeader h = parse_envi_header(kMinimal, "x.hdr");
    EXPECT_EQ(h.samples, 4u);
    EXPECT_EQ(h.lines, 3u);
    EXPECT_EQ(h.bands, 2u);
    EXPECT_EQ(h.data_type, EnviDataType::float32);
    EXPECT_EQ(h.interleave, Interleave::bsq);
    EXPECT_EQ(h.byte_order, native_byte_order());
    EXPECT_EQ(h.header_offset, 0u);
    EXPECT_TRUE(h.wavelength.empty());
    EXPECT_TRUE(h.band_names.empty());
    EXPECT_TRUE(h.extra.empty());
    EXPECT_EQ(h.data_bytes(), 4u * 3u * 2u * 4u);
}

TEST(EnviHeaderParse, KeysAreCaseInsensitiveAndExtrasKeepFileOrder) {
    const EnviHeader h = parse_envi_header(
        "ENVI\r\n"
        "; a comment = not a key\r\n"
        "Samples = 4\r\n"
        "LINES=3\r\n"
        "  Bands   =   2  \r\n"
        "Data  Type = 12\r\n"
        "Interleave = BIL\r\n"
        "Byte Order = 1\r\n"
        "Sensor Type = Unknown\r\n"
        "Map Info = {UTM, 1, 1}\r\n"
        "\r\n"
        "glint seed = 7\r\n",
        "x.hdr");
    EXPECT_EQ(h.samples, 4u);
    EXPECT_EQ(h.lines, 3u);
    EXPECT_EQ(h.bands, 2u);
    EXPECT_EQ(h.data_type, EnviDataType::uint16);
    EXPECT_EQ(h.interleave, Interleave::bil);
    EXPECT_EQ(h.byte_order, ByteOrder::big);
    ASSERT_EQ(h.extra.size(), 3u);
    EXPECT_EQ(h.extra[0].first, "sensor type");
    EXPECT_EQ(h.extra[0].second, "Unknown");
    EXPECT_EQ(h.extra[1].first, "map info");
    EXPECT_EQ(h.extra[1].second, "{UTM, 1, 1}");
    EXPECT_EQ(h.extra[2].first, "glint seed");
    EXPECT_EQ(h.find_extra("glint seed"), "7");
    EXPECT_FALSE(h.find_extra("nothing"));
}

TEST(EnviHeaderParse, RepeatedExtraKeyKeepsItsPlaceAndLastValue) {
    const EnviHeader h = parse_envi_header(
        "ENVI\nsamples = 1\nlines = 1\nbands = 1\ndata type = 4\n"
        "a = 1\nb = 2\nA = 3\n",
        "x.hdr");
    ASSERT_EQ(h.extra.size(), 2u);
    EXPECT_EQ(h.extra[0], (std::pair<std::string, std::string>{"a", "3"}));
    EXPECT_EQ(h.extra[1], (std::pair<std::string, std::string>{"b", "2"}));
}

TEST(EnviHeaderParse, HundredsOfThousandsOfExtraKeys) {
    // A fuzzed header with 160k extra keys took 12.6 s (each key searched the list before
    // it); keys are now found by hash. 200k keys, one repeated at the end.
    std::string text = "ENVI\nsamples = 1\nlines = 1\nbands = 1\ndata type = 4\n";
    constexpr int kKeys = 200'000;
    for (int i = 0; i < kKeys; ++i) {
        text += "key" + std::to_string(i) + " = " + std::to_string(i) + "\n";
    }
    text += "key7 = last\n";
    const EnviHeader h = parse_envi_header(text, "x.hdr");
    ASSERT_EQ(h.extra.size(), static_cast<std::size_t>(kKeys));
    EXPECT_EQ(h.extra[7].second, "last");
    EXPECT_EQ(h.extra.back(), (std::pair<std::string, std::string>{"key199999", "199999"}));
}

TEST(EnviHeaderParse, BraceValuesSpanLines) {
    const EnviHeader h = parse_envi_header(
        "ENVI\n"
        "description = {first line\n"
        "   second line}\n"
        "samples = 1\nlines = 1\nbands = 3\ndata type = 5\n"
        "wavelength = {\n"
        "  0.45,\n"
        "  0.55, 0.65\n"
        "}\n"
        "fwhm = {0.01, 0.02,\n 0.03}\n"
        "band names = {Blue,\n   Green, Red}\n"
        "wavelength units = Microns\n"
        "data units = Watts/(cm2 sr um)\n"
        "geo points = {1, 2,\n 3, 4}\n",
        "x.hdr");
    EXPECT_EQ(h.description, "first line second line");
    EXPECT_EQ(h.wavelength, (std::vector<double>{0.45, 0.55, 0.65}));
    EXPECT_EQ(h.fwhm, (std::vector<double>{0.01, 0.02, 0.03}));
    EXPECT_EQ(h.band_names, (std::vector<std::string>{"Blue", "Green", "Red"}));
    EXPECT_EQ(h.wavelength_units, "Microns");
    EXPECT_EQ(h.data_units, "Watts/(cm2 sr um)");
    EXPECT_EQ(h.find_extra("geo points"), "{1, 2, 3, 4}");
}

TEST(EnviHeaderParse, HeaderOffsetAndLittleEndian) {
    const EnviHeader h = parse_envi_header(
        std::string(kMinimal) + "header offset = 512\nbyte order = 0\ninterleave = bip\n", "x");
    EXPECT_EQ(h.header_offset, 512u);
    EXPECT_EQ(h.byte_order, ByteOrder::little);
    EXPECT_EQ(h.interleave, Interleave::bip);
}

// ---- malformed headers: message text, file and line -------------------------------------

TEST(EnviHeaderErrors, MissingMagic) {
    EXPECT_THAT(parse_error("samples = 4\nlines = 3\nbands = 2\ndata type = 4\n"),
                HasSubstr("cube.img.hdr:1: missing ENVI magic: the first line is \"samples = 4\", "
                          "expected \"ENVI\""));
    EXPECT_THAT(parse_error(""), HasSubstr("cube.img.hdr:1: missing ENVI magic"));
    EXPECT_THAT(parse_error("\nENVI\nsamples = 1\n"),
                HasSubstr("cube.img.hdr:1: missing ENVI magic"));
}

TEST(EnviHeaderErrors, MissingRequiredKey) {
    EXPECT_THAT(parse_error("ENVI\nlines = 3\nbands = 2\ndata type = 4\n"),
                HasSubstr("cube.img.hdr: missing required key \"samples\""));
    EXPECT_THAT(parse_error("ENVI\nsamples = 3\nbands = 2\ndata type = 4\n"),
                HasSubstr("missing required key \"lines\""));
    EXPECT_THAT(parse_error("ENVI\nsamples = 3\nlines = 2\ndata type = 4\n"),
                HasSubstr("missing required key \"bands\""));
    EXPECT_THAT(parse_error("ENVI\nsamples = 3\nlines = 2\nbands = 1\n"),
                HasSubstr("missing required key \"data type\""));
}

TEST(EnviHeaderErrors, NonNumericOrZeroSizes) {
    EXPECT_THAT(parse_error("ENVI\nsamples = four\nlines = 3\nbands = 2\ndata type = 4\n"),
                HasSubstr("cube.img.hdr:2: samples: expected a positive integer, got \"four\""));
    EXPECT_THAT(parse_error("ENVI\nsamples = 4\nlines = 0\nbands = 2\ndata type = 4\n"),
                HasSubstr("cube.img.hdr:3: lines: must be at least 1, got 0"));
    EXPECT_THAT(parse_error("ENVI\nsamples = 4\nlines = 3\nbands = -2\ndata type = 4\n"),
                HasSubstr("cube.img.hdr:4: bands: expected a positive integer, got \"-2\""));
    EXPECT_THAT(parse_error("ENVI\nsamples = 4.5\nlines = 3\nbands = 2\ndata type = 4\n"),
                HasSubstr("samples: expected a positive integer, got \"4.5\""));
    EXPECT_THAT(parse_error("ENVI\nsamples = 99999999999999999999\nlines = 3\nbands = 2\n"
                            "data type = 4\n"),
                HasSubstr("samples: expected a positive integer below 2^64"));
    EXPECT_THAT(parse_error(std::string(kMinimal) + "header offset = x\n"),
                HasSubstr("cube.img.hdr:6: header offset: expected an integer >= 0, got \"x\""));
}

TEST(EnviHeaderErrors, UnknownDataTypeCode) {
    EXPECT_THAT(parse_error("ENVI\nsamples = 4\ndata type = 7\nlines = 3\nbands = 2\n"),
                HasSubstr("cube.img.hdr:3: data type: unknown ENVI data type code 7 (expected 1, "
                          "2, 3, 4, 5, 6, 9, 12, 13, 14 or 15)"));
    EXPECT_THAT(parse_error("ENVI\nsamples = 4\nlines = 3\nbands = 2\ndata type = float\n"),
                HasSubstr("cube.img.hdr:5: data type: expected an ENVI data type code, got "
                          "\"float\""));
}

TEST(EnviHeaderErrors, ListLengthDiffersFromBands) {
    EXPECT_THAT(parse_error(std::string(kMinimal) + "wavelength = {0.4, 0.5, 0.6}\n"),
                HasSubstr("cube.img.hdr:6: wavelength: has 3 values, expected 2 (one per band)"));
    EXPECT_THAT(parse_error(std::string(kMinimal) + "fwhm = {0.4}\n"),
                HasSubstr("cube.img.hdr:6: fwhm: has 1 values, expected 2 (one per band)"));
    EXPECT_THAT(parse_error(std::string(kMinimal) + "band names = {a,\n b,\n c}\n"),
                HasSubstr("cube.img.hdr:6: band names: has 3 names, expected 2 (one per band)"));
    EXPECT_THAT(parse_error(std::string(kMinimal) + "wavelength = {0.4, green}\n"),
                HasSubstr("cube.img.hdr:6: wavelength: value 2 is not a number: \"green\""));
}

TEST(EnviHeaderErrors, SizeOverflows64Bits) {
    EXPECT_THAT(parse_error("ENVI\nsamples = 4294967296\nlines = 4294967296\nbands = 1\n"
                            "data type = 1\n"),
                HasSubstr("cube.img.hdr: image size overflows 64 bits: 4294967296 samples x "
                          "4294967296 lines x 1 bands x 1 bytes"));
    EXPECT_THAT(parse_error("ENVI\nsamples = 4294967296\nlines = 1073741824\nbands = 2\n"
                            "data type = 5\n"),
                HasSubstr("overflows 64 bits"));
    EXPECT_THAT(parse_error("ENVI\nsamples = 1\nlines = 1\nbands = 1\ndata type = 1\n"
                            "header offset = 18446744073709551615\n"),
                HasSubstr("cube.img.hdr: header offset + image size overflows 64 bits"));
}

TEST(EnviHeaderErrors, BadInterleaveByteOrderAndSyntax) {
    EXPECT_THAT(parse_error(std::string(kMinimal) + "interleave = bop\n"),
                HasSubstr("cube.img.hdr:6: interleave: expected bsq, bil or bip, got \"bop\""));
    EXPECT_THAT(parse_error(std::string(kMinimal) + "byte order = 2\n"),
                HasSubstr("cube.img.hdr:6: byte order: expected 0 (little-endian) or 1 "
                          "(big-endian), got \"2\""));
    EXPECT_THAT(parse_error(std::string(kMinimal) + "band names = {a,\n b\n"),
                HasSubstr("cube.img.hdr:6: band names: unterminated brace value"));
    EXPECT_THAT(parse_error(std::string(kMinimal) + "this line has no equals sign\n"),
                HasSubstr("cube.img.hdr:6: expected \"key = value\", got \"this line has no "
                          "equals sign\""));
    EXPECT_THAT(parse_error(std::string(kMinimal) + " = 5\n"),
                HasSubstr("cube.img.hdr:6: expected \"key = value\""));
}

// ---- formatting --------------------------------------------------------------------------

EnviHeader small_header() {
    EnviHeader h;
    h.description = "glint radiance";
    h.samples = 64;
    h.lines = 48;
    h.bands = 2;
    h.data_type = EnviDataType::float64;
    h.interleave = Interleave::bip;
    h.byte_order = ByteOrder::little;
    h.wavelength_units = "Microns";
    h.wavelength = {0.55, 0.1 + 0.2};
    h.fwhm = {0.01, 0.02};
    h.band_names = {"Green", "Red"};
    h.data_units = "Watts/(cm2 sr)";
    h.set_extra("glint version", "0.1.0");
    h.set_extra("glint seed", "42");
    return h;
}

TEST(EnviHeaderFormat, StandardKeysInOrderThenExtras) {
    EXPECT_EQ(format_envi_header(small_header()),
              "ENVI\n"
              "description = {glint radiance}\n"
              "samples = 64\n"
              "lines = 48\n"
              "bands = 2\n"
              "header offset = 0\n"
              "file type = ENVI Standard\n"
              "data type = 5\n"
              "interleave = bip\n"
              "byte order = 0\n"
              "wavelength units = Microns\n"
              "wavelength = {0.55, 0.30000000000000004}\n"
              "fwhm = {0.01, 0.02}\n"
              "band names = {Green, Red}\n"
              "data units = Watts/(cm2 sr)\n"
              "glint version = 0.1.0\n"
              "glint seed = 42\n");
}

TEST(EnviHeaderFormat, OptionalKeysLeftOutWhenEmpty) {
    EnviHeader h;
    h.samples = h.lines = h.bands = 1;
    h.data_type = EnviDataType::uint8;
    h.byte_order = ByteOrder::big;
    h.interleave = Interleave::bsq;
    EXPECT_EQ(format_envi_header(h),
              "ENVI\ndescription = {}\nsamples = 1\nlines = 1\nbands = 1\nheader offset = 0\n"
              "file type = ENVI Standard\ndata type = 1\ninterleave = bsq\nbyte order = 1\n");
}

TEST(EnviHeaderFormat, FormatThenParseIsIdentity) {
    const EnviHeader in = small_header();
    const EnviHeader out = parse_envi_header(format_envi_header(in), "x.hdr");
    EXPECT_EQ(out.description, in.description);
    EXPECT_EQ(out.samples, in.samples);
    EXPECT_EQ(out.lines, in.lines);
    EXPECT_EQ(out.bands, in.bands);
    EXPECT_EQ(out.data_type, in.data_type);
    EXPECT_EQ(out.interleave, in.interleave);
    EXPECT_EQ(out.byte_order, in.byte_order);
    EXPECT_EQ(out.file_type, "ENVI Standard");
    EXPECT_EQ(out.wavelength_units, in.wavelength_units);
    EXPECT_EQ(out.wavelength, in.wavelength);
    EXPECT_EQ(out.fwhm, in.fwhm);
    EXPECT_EQ(out.band_names, in.band_names);
    EXPECT_EQ(out.data_units, in.data_units);
    EXPECT_EQ(out.extra, in.extra);
}

TEST(EnviHeaderFormat, ThousandsOfBandsWrapAt200CharactersAndRoundTrip) {
    constexpr std::size_t kBands = 2500;
    EnviHeader h;
    h.samples = 4;
    h.lines = 3;
    h.bands = kBands;
    h.data_type = EnviDataType::float32;
    for (std::size_t b = 0; b < kBands; ++b) {
        // Values that need all 17 significant digits to round-trip.
        h.wavelength.push_back(0.4 + static_cast<double>(b) * (1.0 / 3.0) * 1e-3);
        h.fwhm.push_back(std::nextafter(0.01, 1.0) * static_cast<double>(b + 1));
        h.band_names.push_back("Band " + std::to_string(b + 1) + " {radiance, total}");
    }
    h.description = std::string(1000, 'x') + " " + std::string(50, 'y') + " " +
                    "many words to wrap over the line limit; " + std::string(150, 'z');
    h.set_extra("geo points", "{" + std::string(150, '1') + ", " + std::string(150, '2') + "}");
    const std::string text = format_envi_header(h);
    const std::vector<std::string> lines = lines_of(text);
    EXPECT_EQ(lines.front(), "ENVI");
    std::size_t longest = 0;
    for (const std::string& line : lines) {
        // A single word longer than a line (the 1,000 x) stands alone on its line.
        if (line.find(std::string(1000, 'x')) != std::string::npos) {
            EXPECT_EQ(line, "  " + std::string(1000, 'x'));
            continue;
        }
        longest = std::max(longest, line.size());
        EXPECT_LE(line.size(), 200u) << line;
    }
    EXPECT_GT(longest, 180u);  // lines are filled, not broken after every item
    const std::vector<std::string> continued(lines.begin() + 1, lines.end());
    for (const std::string& line : continued) {
        if (line.rfind("  ", 0) != 0) {
            EXPECT_NE(line.find(" = "), std::string::npos) << line;
        }
    }

    const EnviHeader back = parse_envi_header(text, "big.hdr");
    EXPECT_EQ(back.bands, kBands);
    EXPECT_EQ(back.wavelength, h.wavelength);  // bit-exact
    EXPECT_EQ(back.fwhm, h.fwhm);
    ASSERT_EQ(back.band_names.size(), kBands);
    EXPECT_EQ(back.band_names[0], "Band 1 (radiance; total)");
    EXPECT_EQ(back.band_names[kBands - 1], "Band 2500 (radiance; total)");
    EXPECT_EQ(back.description, h.description);
    EXPECT_EQ(back.find_extra("geo points"),
              "{" + std::string(150, '1') + ", " + std::string(150, '2') + "}");
}

TEST(EnviHeaderFormat, NumbersUseShortestRoundTripDigits) {
    EnviHeader h;
    h.samples = h.lines = 1;
    h.data_type = EnviDataType::float64;
    h.wavelength = {0.55,   1.0 / 3.0, 1e-300, 12345.678901234567,
                    2.5e10, -0.0,      5e-324, std::numeric_limits<double>::max()};
    h.bands = h.wavelength.size();
    const std::string text = format_envi_header(h);
    EXPECT_THAT(text, HasSubstr("wavelength = {0.55, 0.3333333333333333, 1e-300, "));
    const EnviHeader back = parse_envi_header(text, "x.hdr");
    ASSERT_EQ(back.wavelength.size(), h.wavelength.size());
    for (std::size_t i = 0; i < h.wavelength.size(); ++i) {
        EXPECT_EQ(back.wavelength[i], h.wavelength[i]) << i;
        EXPECT_EQ(std::signbit(back.wavelength[i]), std::signbit(h.wavelength[i])) << i;
    }
}

TEST(EnviHeaderFormat, BandNamesAndDescriptionAreSanitized) {
    EXPECT_EQ(sanitize_band_name("a,b{c}d"), "a;b(c)d");
    EXPECT_EQ(sanitize_band_name("two\nlines\r\n"), "two lines");
    EXPECT_EQ(sanitize_band_name("Abundance 'grass'"), "Abundance 'grass'");
    EnviHeader h;
    h.samples = h.lines = 1;
    h.bands = 3;
    h.data_type = EnviDataType::uint8;
    h.description = "run {a}, b\nnext";
    h.band_names = {"x, y", "{z}", "w\nv"};
    const std::string text = format_envi_header(h);
    EXPECT_THAT(text, HasSubstr("description = {run (a), b next}\n"));
    EXPECT_THAT(text, HasSubstr("band names = {x; y, (z), w v}\n"));
    const EnviHeader back = parse_envi_header(text, "x.hdr");
    EXPECT_EQ(back.band_names, (std::vector<std::string>{"x; y", "(z)", "w v"}));
}

TEST(EnviHeaderValidate, RejectsInconsistentHeaders) {
    EnviHeader h = small_header();
    EXPECT_NO_THROW(validate_envi_header(h, "out.img.hdr"));
    const auto message = [](const EnviHeader& bad) -> std::string {
        try {
            validate_envi_header(bad, "out.img.hdr");
        } catch (const Error& error) {
            return error.what();
        }
        return "no error";
    };
    EnviHeader bad = h;
    bad.samples = 0;
    EXPECT_THAT(message(bad), HasSubstr("out.img.hdr: samples: must be at least 1, got 0"));
    bad = h;
    bad.band_names.pop_back();
    EXPECT_THAT(message(bad), HasSubstr("band names: has 1 names, expected 2"));
    bad = h;
    bad.set_extra("samples", "3");
    EXPECT_THAT(message(bad), HasSubstr("samples: is a standard key and cannot be an extra key"));
    bad = h;
    bad.set_extra("a = b", "3");
    EXPECT_THAT(message(bad), HasSubstr("invalid header key \"a = b\""));
    bad = h;
    bad.lines = std::size_t{1} << 62;
    EXPECT_THAT(message(bad), HasSubstr("overflows 64 bits"));
}

// ---- naming ------------------------------------------------------------------------------

TEST(EnviNaming, HeaderPathForData) {
    TempDir dir;
    const auto img = dir.path() / "cube.img";
    // Neither exists: the glint naming.
    EXPECT_EQ(envi_header_path_for(img), dir.path() / "cube.img.hdr");
    touch(dir.path() / "cube.hdr");
    EXPECT_EQ(envi_header_path_for(img), dir.path() / "cube.hdr");
    touch(dir.path() / "cube.img.hdr");
    EXPECT_EQ(envi_header_path_for(img), dir.path() / "cube.img.hdr");
    EXPECT_EQ(envi_header_path_for(dir.path() / "plain"), dir.path() / "plain.hdr");
}

TEST(EnviNaming, DataPathForHeader) {
    TempDir dir;
    EXPECT_EQ(envi_data_path_for(dir.path() / "cube.img"), dir.path() / "cube.img");
    EXPECT_EQ(envi_data_path_for(dir.path() / "cube.img.hdr"), dir.path() / "cube.img");
    // x.hdr: x, x.img, x.dat, x.raw or x.bin, whichever exists; x when none does.
    EXPECT_EQ(envi_data_path_for(dir.path() / "x.hdr"), dir.path() / "x");
    touch(dir.path() / "x.bin");
    EXPECT_EQ(envi_data_path_for(dir.path() / "x.hdr"), dir.path() / "x.bin");
    touch(dir.path() / "x.dat");
    EXPECT_EQ(envi_data_path_for(dir.path() / "x.hdr"), dir.path() / "x.dat");
    touch(dir.path() / "x.img");
    EXPECT_EQ(envi_data_path_for(dir.path() / "x.HDR"), dir.path() / "x.img");
    touch(dir.path() / "x");
    EXPECT_EQ(envi_data_path_for(dir.path() / "x.hdr"), dir.path() / "x");
}

}  // namespace envi_header_test
}  // namespace glint::io
