// SPDX-License-Identifier: Apache-2.0
// GDAL as an oracle for glint's ENVI files: `gdalinfo -json` must see the size, band count,
// data type, pixel interleave, byte order, wavelengths and band names we wrote, and GDAL's
// Python bindings the same pixel values; in the other direction, ENVI files that GDAL writes
// (BSQ/BIL/BIP, `<name>.hdr` naming) must read back in glint as GDAL reads them.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>

#include "glint/io/envi.h"
#include "oracle_support.h"

namespace glint::io::oracle {
namespace envi_gdal_test {

using nlohmann::json;
using ::testing::HasSubstr;

#define SKIP_WITHOUT_GDALINFO()                                                             \
    do {                                                                                    \
        if (!program_exists("gdalinfo")) {                                                  \
            GTEST_SKIP() << "gdalinfo not found (install gdal-bin to run the GDAL oracle)"; \
        }                                                                                   \
    } while (0)

#define SKIP_WITHOUT_OSGEO()                                                                   \
    do {                                                                                       \
        if (!python_has("numpy; from osgeo import gdal")) {                                    \
            GTEST_SKIP() << GLINT_ORACLE_PYTHON                                                \
                         << " cannot import osgeo.gdal (install python3-gdal for the oracle)"; \
        }                                                                                      \
    } while (0)

/// GDAL's version as major * 100 + minor, from `gdalinfo --version`.
int gdal_version() {
    const CommandResult result = run_command({"gdalinfo", "--version"});
    int major = 0;
    int minor = 0;
    std::sscanf(result.out.c_str(), "GDAL %d.%d", &major, &minor);
    return major * 100 + minor;
}

json gdalinfo(const std::filesystem::path& path) {
    const CommandResult result = run_command({"gdalinfo", "-json", "-mdd", "all", path.string()});
    EXPECT_EQ(result.exit_status, 0) << result.err;
    return json::parse(result.out);
}

/// Pixel values as GDAL's Python bindings read them: [line][sample][band].
constexpr const char* kGdalPixels = R"(
import json, sys
import numpy as np
from osgeo import gdal
gdal.UseExceptions()
ds = gdal.Open(sys.argv[1])
bands = [ds.GetRasterBand(b + 1).ReadAsArray() for b in range(ds.RasterCount)]
cube = np.stack(bands, axis=2)
print(json.dumps({"dtype": cube.dtype.name, "values": cube.tolist()}))
)";

TEST(GdalOracle, ReadsEveryWritableType) {
    SKIP_WITHOUT_GDALINFO();
    TempDir dir;
    const int version = gdal_version();
    const bool osgeo = python_has("numpy; from osgeo import gdal");
    for (const EnviDataType type : kWritableTypes) {
        SCOPED_TRACE(envi_type_name(type));
        const std::string name = std::string("cube_") + envi_type_name(type);
        const TestImage image = write_test_image(dir, name, type, 4, 3, 2);
        const bool is_64bit_integer = type == EnviDataType::int64 || type == EnviDataType::uint64;
        if (is_64bit_integer && version < 308) {
            // ENVI Int64/UInt64 came with GDAL 3.8 (OSGeo/gdal#8529); older GDAL refuses them.
            const CommandResult result = run_command({"gdalinfo", "-json", image.data.string()});
            EXPECT_NE(result.exit_status, 0);
            EXPECT_THAT(result.err, HasSubstr("data_type"));
            continue;
        }
        const json info = gdalinfo(image.data);
        EXPECT_EQ(info["driverShortName"], "ENVI");
        EXPECT_EQ(info["size"], json::array({4, 3}));
        EXPECT_EQ(info["files"], json::array({image.data.string(), image.header_path.string()}));
        EXPECT_EQ(info["metadata"]["IMAGE_STRUCTURE"]["INTERLEAVE"], "PIXEL");
        const json& envi = info["metadata"]["ENVI"];
        EXPECT_EQ(envi["byte_order"], std::to_string(static_cast<int>(native_byte_order())));
        EXPECT_EQ(envi["interleave"], "bip");
        EXPECT_EQ(envi["header_offset"], "0");
        EXPECT_EQ(envi["data_units"], "Watts/(cm2 sr um)");
        EXPECT_EQ(envi["glint_version"], "0.1.0");
        EXPECT_EQ(envi["glint_seed"], "42");
        EXPECT_EQ(envi["description"],
                  std::string("{glint oracle test image, ") + envi_type_name(type) + "}")
            << "GDAL keeps the braces of the description";
        const json& bands = info["bands"];
        ASSERT_EQ(bands.size(), 2u);
        for (std::size_t b = 0; b < 2; ++b) {
            const json& band = bands[b];
            EXPECT_EQ(band["type"], gdal_type_name(type));
            // GDAL describes a band as "<band name> (<wavelength> <units>)" and keeps the
            // wavelength text of the header in the band metadata.
            const std::string wavelength = band["metadata"][""]["wavelength"];
            EXPECT_EQ(std::stod(wavelength), image.header.wavelength[b]);
            EXPECT_EQ(band["metadata"][""]["wavelength_units"], "Microns");
            EXPECT_EQ(band["description"],
                      "Band " + std::to_string(b + 1) + "; (total) (" + wavelength + " Microns)");
        }
        if (!osgeo) continue;
        const CommandResult pixels =
            run_command(python_command(dir, kGdalPixels, {image.data.string()}));
        ASSERT_EQ(pixels.exit_status, 0) << pixels.err;
        const json read = json::parse(pixels.out);
        EXPECT_EQ(read["values"], image.values);
    }
    if (!osgeo) GTEST_SKIP() << "pixel values not compared: osgeo.gdal cannot be imported";
}

TEST(GdalOracle, FindsTheHeaderOfACaptureName) {
    SKIP_WITHOUT_GDALINFO();
    TempDir dir;
    // The header sits beside the data as <name>.img.hdr; GDAL finds it from the data path.
    const TestImage image =
        write_test_image(dir, "radiance-t0000-c0000", EnviDataType::float64, 2, 2, 1);
    const json info = gdalinfo(image.data);
    EXPECT_EQ(info["bands"].size(), 1u);
    EXPECT_EQ(info["bands"][0]["type"], "Float64");
}

TEST(GdalOracle, ReadsTwoThousandFiveHundredBands) {
    SKIP_WITHOUT_GDALINFO();
    TempDir dir;
    const TestImage image = write_test_image(dir, "wide", EnviDataType::float32, 4, 3, 2500);
    // Our own promise first: no header line is longer than 200 characters.
    std::istringstream header(read_text(image.header_path));
    for (std::string line; std::getline(header, line);) ASSERT_LE(line.size(), 200u) << line;
    const json info = gdalinfo(image.data);
    EXPECT_EQ(info["size"], json::array({4, 3}));
    const json& bands = info["bands"];
    ASSERT_EQ(bands.size(), 2500u);
    for (const std::size_t b : {0u, 1u, 1249u, 2498u, 2499u}) {
        const std::string wavelength = bands[b]["metadata"][""]["wavelength"];
        EXPECT_EQ(std::stod(wavelength), image.header.wavelength[b]) << b;
        EXPECT_EQ(bands[b]["description"],
                  "Band " + std::to_string(b + 1) + "; (total) (" + wavelength + " Microns)");
        EXPECT_EQ(bands[b]["type"], "Float32");
    }
}

/// Writes an ENVI file with GDAL (`<name>.hdr` naming, the given interleave) and prints the
/// values GDAL wrote, [line][sample][band].
constexpr const char* kGdalWrite = R"(
import json, sys
import numpy as np
from osgeo import gdal
gdal.UseExceptions()
path, interleave, type_name = sys.argv[1], sys.argv[2], sys.argv[3]
samples, lines, bands = 5, 4, 3
gdt = {"Int16": gdal.GDT_Int16, "UInt16": gdal.GDT_UInt16, "Float32": gdal.GDT_Float32,
       "Float64": gdal.GDT_Float64, "Byte": gdal.GDT_Byte, "Int32": gdal.GDT_Int32}[type_name]
ds = gdal.GetDriverByName("ENVI").Create(path, samples, lines, bands, gdt,
                                         options=["INTERLEAVE=" + interleave])
cube = np.zeros((lines, samples, bands))
for b in range(bands):
    values = (np.arange(lines * samples).reshape(lines, samples) * 7 + b * 50) % 250
    if type_name.startswith("Float"):
        values = values * 0.25 - 3.0
    band = ds.GetRasterBand(b + 1)
    band.WriteArray(values)
    band.SetDescription("gdal band %d" % (b + 1))
    cube[:, :, b] = band.ReadAsArray()
ds = None
print(json.dumps(cube.tolist()))
)";

TEST(GdalOracle, GlintReadsWhatGdalWrites) {
    SKIP_WITHOUT_OSGEO();
    TempDir dir;
    for (const std::string interleave : {"BSQ", "BIL", "BIP"}) {
        for (const std::string type : {"Int16", "Float32", "Float64", "UInt16"}) {
            SCOPED_TRACE(interleave + " " + type);
            const auto path = dir.path() / ("gdal_" + interleave + "_" + type + ".img");
            const CommandResult result =
                run_command(python_command(dir, kGdalWrite, {path.string(), interleave, type}));
            ASSERT_EQ(result.exit_status, 0) << result.err;
            const json expected = json::parse(result.out);
            // GDAL names the header gdal_*.hdr, not gdal_*.img.hdr.
            ASSERT_TRUE(
                std::filesystem::exists(dir.path() / ("gdal_" + interleave + "_" + type + ".hdr")));
            EnviHeader header;
            const std::vector<double> values = read_envi_bip(path, &header);
            EXPECT_EQ(interleave_name(header.interleave),
                      std::string(interleave == "BSQ"   ? "bsq"
                                  : interleave == "BIL" ? "bil"
                                                        : "bip"));
            ASSERT_EQ(header.bands, 3u);
            EXPECT_EQ(header.band_names,
                      (std::vector<std::string>{"gdal band 1", "gdal band 2", "gdal band 3"}));
            std::size_t i = 0;
            for (std::size_t y = 0; y < header.lines; ++y) {
                for (std::size_t x = 0; x < header.samples; ++x) {
                    for (std::size_t b = 0; b < header.bands; ++b, ++i) {
                        EXPECT_EQ(values[i], expected[y][x][b].get<double>())
                            << "x=" << x << " y=" << y << " b=" << b;
                    }
                }
            }
        }
    }
}

}  // namespace envi_gdal_test
}  // namespace glint::io::oracle
