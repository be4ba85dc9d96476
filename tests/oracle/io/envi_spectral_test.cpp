// SPDX-License-Identifier: Apache-2.0
// Spectral Python as an oracle for glint's ENVI files: `spectral.envi.open(HDR, DATA)` must
// see the size, dtype, interleave, byte order, wavelengths, band names, provenance keys and
// pixel values we wrote; and ENVI files that Spectral writes (BSQ/BIL/BIP, big- and
// little-endian, `<name>.hdr` naming) must read back in glint as Spectral reads them.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "glint/io/envi.h"
#include "oracle_support.h"

namespace glint::io::oracle {
namespace envi_spectral_test {

using nlohmann::json;

#define SKIP_WITHOUT_SPECTRAL()                                                          \
    do {                                                                                 \
        if (!python_has("spectral, numpy")) {                                            \
            GTEST_SKIP() << GLINT_ORACLE_PYTHON                                          \
                         << " cannot import spectral (install python3-spectral for the " \
                            "oracle)";                                                   \
        }                                                                                \
    } while (0)

/// What Spectral makes of an ENVI pair; values [line][sample][band] unless "nopixels".
constexpr const char* kSpectralRead = R"(
import json, sys
import numpy as np
import spectral
img = spectral.envi.open(sys.argv[1], sys.argv[2])
out = {
    "class": type(img).__name__,
    "nrows": img.nrows, "ncols": img.ncols, "nbands": img.nbands,
    "dtype": np.dtype(img.dtype).str,
    "interleave": {spectral.BSQ: "bsq", spectral.BIL: "bil", spectral.BIP: "bip"}[img.interleave],
    "byte_order": img.byte_order,
    "offset": img.offset,
    "centers": img.bands.centers,
    "bandwidths": img.bands.bandwidths,
    "band_unit": img.bands.band_unit,
    "band_names": img.metadata.get("band names"),
    "description": img.metadata.get("description"),
    "data_units": img.metadata.get("data units"),
    "glint_version": img.metadata.get("glint version"),
    "glint_seed": img.metadata.get("glint seed"),
}
if len(sys.argv) < 4:
    out["values"] = np.asarray(img.open_memmap(interleave="bip")).tolist()
    out["pixel_1_2"] = img.read_pixel(1, 2).tolist()
print(json.dumps(out))
)";

json spectral_read(const TempDir& dir, const TestImage& image, bool pixels = true) {
    std::vector<std::string> args = {image.header_path.string(), image.data.string()};
    if (!pixels) args.push_back("nopixels");
    const CommandResult result = run_command(python_command(dir, kSpectralRead, args));
    EXPECT_EQ(result.exit_status, 0) << result.err;
    return json::parse(result.out);
}

/// The band names of write_test_image as they should be read: "Band N, {total}" sanitized.
std::vector<std::string> expected_names(std::size_t bands) {
    std::vector<std::string> names;
    for (std::size_t b = 0; b < bands; ++b)
        names.push_back("Band " + std::to_string(b + 1) + "; (total)");
    return names;
}

TEST(SpectralOracle, ReadsEveryWritableType) {
    SKIP_WITHOUT_SPECTRAL();
    TempDir dir;
    for (const EnviDataType type : kWritableTypes) {
        SCOPED_TRACE(envi_type_name(type));
        const TestImage image =
            write_test_image(dir, std::string("cube_") + envi_type_name(type), type, 4, 3, 2);
        const json read = spectral_read(dir, image);
        EXPECT_EQ(read["class"], "BipFile");
        EXPECT_EQ(read["nrows"], 3);
        EXPECT_EQ(read["ncols"], 4);
        EXPECT_EQ(read["nbands"], 2);
        EXPECT_EQ(read["dtype"], numpy_dtype(type));
        EXPECT_EQ(read["interleave"], "bip");
        EXPECT_EQ(read["byte_order"], static_cast<int>(native_byte_order()));
        EXPECT_EQ(read["offset"], 0);
        EXPECT_EQ(read["centers"].get<std::vector<double>>(), image.header.wavelength);
        EXPECT_EQ(read["bandwidths"].get<std::vector<double>>(), image.header.fwhm);
        EXPECT_EQ(read["band_unit"], "Microns");
        EXPECT_EQ(read["band_names"].get<std::vector<std::string>>(), expected_names(2));
        EXPECT_EQ(read["description"],
                  std::string("glint oracle test image, ") + envi_type_name(type));
        EXPECT_EQ(read["data_units"], "Watts/(cm2 sr um)");
        EXPECT_EQ(read["glint_version"], "0.1.0");
        EXPECT_EQ(read["glint_seed"], "42");
        EXPECT_EQ(read["values"], image.values);
        EXPECT_EQ(read["pixel_1_2"], image.values[1][2]);
    }
}

TEST(SpectralOracle, ReadsTwoThousandFiveHundredBands) {
    SKIP_WITHOUT_SPECTRAL();
    TempDir dir;
    const TestImage image = write_test_image(dir, "wide", EnviDataType::float32, 4, 3, 2500);
    const json read = spectral_read(dir, image, false);
    EXPECT_EQ(read["nbands"], 2500);
    EXPECT_EQ(read["centers"].get<std::vector<double>>(), image.header.wavelength);
    EXPECT_EQ(read["band_names"].get<std::vector<std::string>>(), expected_names(2500));
}

/// Writes an ENVI pair with Spectral (`<name>.hdr` + `<name>.img`) in the given interleave and
/// byte order, and prints the values it wrote, [line][sample][band].
constexpr const char* kSpectralWrite = R"(
import json, sys
import numpy as np
import spectral
hdr, interleave, byteorder, dtype = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
lines, samples, bands = 4, 5, 3
cube = ((np.arange(lines * samples * bands).reshape(lines, samples, bands) * 13) % 240)
cube = cube.astype(dtype)
if cube.dtype.kind == "f":
    cube = cube * np.asarray(0.5, dtype=dtype) - np.asarray(7, dtype=dtype)
if cube.dtype.kind == "i":
    cube = cube - 100
metadata = {"wavelength": [0.45, 0.55, 0.65], "band names": ["b one", "b two", "b three"],
            "wavelength units": "Microns", "description": "written by spectral"}
spectral.envi.save_image(hdr, cube, interleave=interleave, byteorder=byteorder,
                         metadata=metadata, force=True)
print(json.dumps(cube.tolist()))
)";

TEST(SpectralOracle, GlintReadsWhatSpectralWrites) {
    SKIP_WITHOUT_SPECTRAL();
    TempDir dir;
    for (const std::string interleave : {"bsq", "bil", "bip"}) {
        for (const int order : {0, 1}) {
            for (const std::string dtype : {"int16", "uint16", "float32", "float64", "int64"}) {
                const std::string name = "sp_" + interleave + std::to_string(order) + dtype;
                SCOPED_TRACE(name);
                const auto hdr = dir.path() / (name + ".hdr");
                const CommandResult result = run_command(python_command(
                    dir, kSpectralWrite, {hdr.string(), interleave, std::to_string(order), dtype}));
                ASSERT_EQ(result.exit_status, 0) << result.err;
                const json expected = json::parse(result.out);
                EnviReader reader(hdr);  // finds <name>.img beside <name>.hdr
                EXPECT_EQ(reader.data_path(), dir.path() / (name + ".img"));
                const EnviHeader& header = reader.header();
                EXPECT_EQ(interleave_name(header.interleave), interleave);
                EXPECT_EQ(static_cast<int>(header.byte_order), order);
                EXPECT_EQ(header.description, "written by spectral");
                EXPECT_EQ(header.wavelength, (std::vector<double>{0.45, 0.55, 0.65}));
                EXPECT_EQ(header.band_names,
                          (std::vector<std::string>{"b one", "b two", "b three"}));
                ASSERT_EQ(header.bands, 3u);
                std::vector<double> line(header.samples * header.bands);
                for (std::size_t y = 0; y < header.lines; ++y) {
                    reader.read_line(y, line);
                    for (std::size_t x = 0; x < header.samples; ++x) {
                        for (std::size_t b = 0; b < header.bands; ++b) {
                            EXPECT_EQ(line[x * header.bands + b], expected[y][x][b].get<double>())
                                << "x=" << x << " y=" << y << " b=" << b;
                        }
                    }
                }
            }
        }
    }
}

}  // namespace envi_spectral_test
}  // namespace glint::io::oracle
