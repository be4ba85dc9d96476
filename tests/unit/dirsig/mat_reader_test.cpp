// SPDX-License-Identifier: Apache-2.0
// Tests of the `.mat` reader on materials as real DIRSIG databases write them (the
// tests/data/materials fixture): emissivity-only entries (ρ = 1 − ε), `RAD_SOLVER_NAME =
// Null`, `#` inside a value, classic `.ems` curve files in both curve layouts and with
// several texture classes, ε + ρ just above 1 (rounding) and well above it, and each bad
// `.ems` with its one message at file:line; a file's diagnostics are capped.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <string_view>

#include "glint/dirsig/scene_reader.h"
#include "glint/test/diagnostics.h"
#include "glint/test/temp_dir.h"

namespace glint::dirsig {
namespace mat_reader_test {

using glint::test::diagnostics_text;
using glint::test::only_error;
using glint::test::TempDir;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

const std::filesystem::path kData = std::filesystem::path(GLINT_TEST_DATA_DIR) / "materials";

/// The warnings of `diagnostics`, one "file:line: element: message" per line.
std::string warnings_text(const Diagnostics& diagnostics) {
    std::string out;
    for (const Diagnostic& d : diagnostics.items()) {
        if (d.severity == Diagnostic::Severity::warning) out += d.text() + "\n";
    }
    return out;
}

/// Writes `text` to the new file `path` in a TempDir.
void write_file(const std::filesystem::path& path, std::string_view text) {
    std::ofstream out(path, std::ios::binary);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

void expect_values(const std::vector<double>& actual, const std::vector<double>& expected) {
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < actual.size(); ++i) {
        EXPECT_NEAR(actual[i], expected[i], 1e-12) << "sample " << i;
    }
}

TEST(MatReader, ReadsRealDirsigMaterials) {
    Diagnostics diagnostics;
    const auto materials = read_dirsig_materials(kData / "real.mat", {}, diagnostics);
    const std::string all = warnings_text(diagnostics);
    EXPECT_FALSE(diagnostics.has_errors()) << diagnostics_text(diagnostics);
    ASSERT_EQ(materials.size(), 4u) << all;

    // Emissivity only, from a classic .ems in the CURVE_BEGIN layout: ρ = 1 − ε.
    const model::Material& paint = materials[0];
    EXPECT_EQ(paint.name, "Class #2");
    EXPECT_FALSE(paint.emissivity_is_default);
    EXPECT_THAT(paint.emissivity.wavelengths_um, ElementsAre(0.4, 0.7, 14.0));
    expect_values(paint.emissivity.values, {0.90, 0.60, 0.95});
    EXPECT_THAT(paint.reflectance.wavelengths_um, ElementsAre(0.4, 0.7, 14.0));
    expect_values(paint.reflectance.values, {0.10, 0.40, 0.05});

    // Null solver: black, no emission, one warning naming the material at its file:line.
    const model::Material& void_material = materials[1];
    expect_values(void_material.reflectance.values, {0.0, 0.0});
    expect_values(void_material.emissivity.values, {0.0, 0.0});
    EXPECT_THAT(all, HasSubstr((kData / "real.mat").string() +
                               ":18: MATERIAL_ENTRY[11]/RAD_SOLVER_NAME: radiometry solver "
                               "\"Null\" of material \"Void\": glint renders it black and "
                               "non-emitting"));

    // Three texture classes in descending wavenumber: the first, converted to µm.
    const model::Material& soil = materials[2];
    ASSERT_EQ(soil.emissivity.wavelengths_um.size(), 3u);
    expect_values(soil.emissivity.wavelengths_um, {4.0, 10.0, 14.0});
    expect_values(soil.emissivity.values, {0.80, 0.90, 0.95});
    expect_values(soil.reflectance.values, {0.20, 0.10, 0.05});
    const std::string soil_ems = (kData / "emissivity/soil.ems").string();
    EXPECT_THAT(
        all,
        HasSubstr(soil_ems + ":1: MATERIAL_ENTRY[12]/SURFACE_PROPERTIES/EMISSIVITY_PROP/FILENAME: "
                             "classic .ems with 3 curves (texture classes): glint uses the first "
                             "(line 94) unless an enabled <texturemap> covers the material"));
    EXPECT_THAT(
        all,
        HasSubstr(soil_ems + ":2: MATERIAL_ENTRY[12]/SURFACE_PROPERTIES/EMISSIVITY_PROP/FILENAME: "
                             "the angular emissivity table (lines 2-92) is read, not applied"));

    // 0.1 + 0.9000004: 4e-7 above 1 is rounding, accepted silently and left as written.
    const model::Material& rounded = materials[3];
    expect_values(rounded.reflectance.values, {0.10, 0.10});
    expect_values(rounded.emissivity.values, {0.9000004, 0.9000004});

    EXPECT_EQ(diagnostics.warning_count(), 3u) << all;
}

TEST(MatReader, HashIsACommentOnlyAtTheStartOfALine) {
    TempDir dir;
    write_file(dir / "r.txt", "0.4 0.1\n");
    write_file(dir / "m.mat",
               "# a comment\n  # an indented comment { not a block\nMATERIAL_ENTRY {\n  ID = #7\n"
               "  NAME = Class #2 # not a comment either\n"
               "  SURFACE_PROPERTIES { REFLECTANCE_PROP { TXT_FILENAME = r.txt } }\n}\n");
    Diagnostics diagnostics;
    const auto materials = read_dirsig_materials(dir / "m.mat", {}, diagnostics);
    EXPECT_TRUE(diagnostics.items().empty()) << diagnostics_text(diagnostics);
    ASSERT_EQ(materials.size(), 1u);
    EXPECT_EQ(materials[0].id, "#7");
    EXPECT_EQ(materials[0].name, "Class #2 # not a comment either");
}

TEST(MatReader, DoubleSidedFalseMakesTheBackFaceBlack) {
    // TRUE and FALSE are applied; anything else is one warning at the key, and two-sided.
    TempDir dir;
    write_file(dir / "r.txt", "0.4 0.1\n");
    write_file(dir / "m.mat",
               "MATERIAL_ENTRY {\n  ID = 1\n  DOUBLE_SIDED = FALSE\n"
               "  SURFACE_PROPERTIES { REFLECTANCE_PROP { TXT_FILENAME = r.txt } }\n}\n"
               "MATERIAL_ENTRY {\n  ID = 2\n  DOUBLE_SIDED = TRUE\n"
               "  SURFACE_PROPERTIES { REFLECTANCE_PROP { TXT_FILENAME = r.txt } }\n}\n"
               "MATERIAL_ENTRY {\n  ID = 3\n  DOUBLE_SIDED = SOMETIMES\n"
               "  SURFACE_PROPERTIES { REFLECTANCE_PROP { TXT_FILENAME = r.txt } }\n}\n");
    Diagnostics diagnostics;
    const auto materials = read_dirsig_materials(dir / "m.mat", {}, diagnostics);
    ASSERT_EQ(materials.size(), 3u);
    EXPECT_FALSE(materials[0].double_sided);
    EXPECT_TRUE(materials[1].double_sided);
    EXPECT_TRUE(materials[2].double_sided);
    EXPECT_EQ(warnings_text(diagnostics),
              (dir / "m.mat").string() +
                  ":13: MATERIAL_ENTRY[3]/DOUBLE_SIDED: DOUBLE_SIDED \"SOMETIMES\" is neither "
                  "TRUE nor FALSE; the material is two-sided\n");
}

TEST(MatReader, SurfaceModelsAsDirsigWritesThem) {
    // SimpleReflectance + SimpleTransmittance (a leaf: Kirchhoff ε = 1 − ρ − τ), WardBRDF
    // (DS_WEIGHTS, XY_SIGMAS: spectrally constant ρd + ρs) and ClassicEmissivity with a
    // SPECULAR_FRACTION (a mirror share); each guessed reading is said once per file.
    TempDir dir;
    write_file(dir / "r.txt", "0.4 0.1\n0.8 0.5\n");
    write_file(dir / "t.txt", "0.4 0.05\n0.8 0.4\n");
    write_file(dir / "w.ems", "0.4 0.98\n1.0 0.98\n");
    write_file(dir / "m.mat",
               "MATERIAL_ENTRY {\n  ID = leaf\n  DOUBLE_SIDED = TRUE\n"
               "  SURFACE_PROPERTIES {\n"
               "    REFLECTANCE_PROP_NAME = SimpleReflectance\n"
               "    REFLECTANCE_PROP { TXT_FILENAME = r.txt }\n"
               "    TRANSMITTANCE_PROP_NAME = SimpleTransmittance\n"
               "    TRANSMITTANCE_PROP { TXT_FILENAME = t.txt }\n  }\n}\n"
               "MATERIAL_ENTRY {\n  ID = metal\n  SURFACE_PROPERTIES {\n"
               "    REFLECTANCE_PROP_NAME = WardBRDF\n"
               "    REFLECTANCE_PROP {\n      DS_WEIGHTS = 0.2, 0.5\n      XY_SIGMAS = 0.1 0.3\n"
               "    }\n  }\n}\n"
               "MATERIAL_ENTRY {\n  ID = water\n  SURFACE_PROPERTIES {\n"
               "    EMISSIVITY_PROP_NAME = ClassicEmissivity\n"
               "    EMISSIVITY_PROP {\n      FILENAME = w.ems\n      SPECULAR_FRACTION = 1\n"
               "    }\n  }\n}\n"
               "MATERIAL_ENTRY {\n  ID = wet\n  SURFACE_PROPERTIES {\n"
               "    EMISSIVITY_PROP { FILENAME = w.ems\n SPECULAR_FRACTION = 0.25 }\n  }\n}\n");
    Diagnostics diagnostics;
    const auto materials = read_dirsig_materials(dir / "m.mat", {}, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors()) << diagnostics_text(diagnostics);
    ASSERT_EQ(materials.size(), 4u);
    const model::Material& leaf = materials[0];
    expect_values(leaf.transmittance.values, {0.05, 0.4});
    EXPECT_TRUE(leaf.emissivity_is_default);
    expect_values(leaf.emissivity.values, {0.85, 0.1});
    const model::Material& metal = materials[1];
    EXPECT_EQ(metal.model, model::ReflectionModel::ward);
    EXPECT_DOUBLE_EQ(metal.ward.diffuse, 0.2);
    EXPECT_DOUBLE_EQ(metal.ward.specular, 0.5);
    EXPECT_DOUBLE_EQ(metal.ward.alpha_x, 0.1);
    EXPECT_DOUBLE_EQ(metal.ward.alpha_y, 0.3);
    expect_values(metal.reflectance.values, {0.7, 0.7});
    expect_values(metal.emissivity.values, {0.3, 0.3});
    EXPECT_DOUBLE_EQ(materials[2].specular.fraction, 1.0);
    EXPECT_DOUBLE_EQ(materials[2].specular.roughness, 0.0);
    expect_values(materials[2].reflectance.values, {0.02, 0.02});
    EXPECT_DOUBLE_EQ(materials[3].specular.fraction, 0.25);
    const std::string m = (dir / "m.mat").string();
    EXPECT_EQ(warnings_text(diagnostics),
              m +
                  ":8: MATERIAL_ENTRY[leaf]/SURFACE_PROPERTIES/TRANSMITTANCE_PROP: "
                  "TRANSMITTANCE_PROP read as SimpleTransmittance: a diffuse transmittance curve "
                  "(TXT_FILENAME) of a thin two-sided sheet (glint's reading; "
                  "docs/materials.md); said once per file\n" +
                  m +
                  ":16: MATERIAL_ENTRY[metal]/SURFACE_PROPERTIES/REFLECTANCE_PROP/"
                  "DS_WEIGHTS: WardBRDF read as DS_WEIGHTS = diffuse, specular and "
                  "XY_SIGMAS = sigma_x, sigma_y of Ward's 1992 model (glint's reading of "
                  "DIRSIG's keys; docs/materials.md); said once per file\n" +
                  m +
                  ":27: MATERIAL_ENTRY[water]/SURFACE_PROPERTIES/EMISSIVITY_PROP/"
                  "SPECULAR_FRACTION: SPECULAR_FRACTION read as the share of the "
                  "reflectance in a mirror lobe, the rest Lambertian (glint's reading of "
                  "DIRSIG's specularity; docs/materials.md); said once per file\n");
}

struct RefusedModel {
    const char* name;
    const char* surface;  ///< the SURFACE_PROPERTIES body
    const char* message;
};

class RefusedSurfaceModels : public ::testing::TestWithParam<RefusedModel> {};

TEST_P(RefusedSurfaceModels, OneErrorNamingTheModel) {
    TempDir dir;
    write_file(dir / "r.txt", "0.4 0.1\n0.8 0.5\n");
    write_file(dir / "m.mat", std::string("MATERIAL_ENTRY {\n  ID = 1\n  SURFACE_PROPERTIES {\n") +
                                  GetParam().surface + "\n  }\n}\n");
    Diagnostics diagnostics;
    read_dirsig_materials(dir / "m.mat", {}, diagnostics);
    EXPECT_EQ(only_error(diagnostics).text(), (dir / "m.mat").string() + GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    MatReader, RefusedSurfaceModels,
    ::testing::Values(
        RefusedModel{"RossLi",
                     "REFLECTANCE_PROP_NAME = RossLiBRDF\nREFLECTANCE_PROP { F_ISO = 0.1 }",
                     ":4: MATERIAL_ENTRY[1]/SURFACE_PROPERTIES/REFLECTANCE_PROP_NAME: surface "
                     "model \"RossLiBRDF\" is not supported: its .mat parameter keys are not "
                     "documented publicly; glint's YAML scene format has the Ross-Li model "
                     "(ross_li: {volumetric, geometric})"},
        RefusedModel{"PriestGermer",
                     "REFLECTANCE_PROP_NAME = PriestGermerBRDF\nREFLECTANCE_PROP { }",
                     ":4: MATERIAL_ENTRY[1]/SURFACE_PROPERTIES/REFLECTANCE_PROP_NAME: surface "
                     "model \"PriestGermerBRDF\" is not supported: its parameter files (.brdf) "
                     "are not documented publicly"},
        RefusedModel{"DeltaTransmittance",
                     "REFLECTANCE_PROP { TXT_FILENAME = r.txt }\n"
                     "TRANSMITTANCE_PROP_NAME = DeltaTransmittance\nTRANSMITTANCE_PROP { }",
                     ":5: MATERIAL_ENTRY[1]/SURFACE_PROPERTIES/TRANSMITTANCE_PROP_NAME: surface "
                     "model \"DeltaTransmittance\" is not supported: its keys are not "
                     "documented publicly; glint's YAML scene format has straight-through "
                     "transmission (transmission: straight)"},
        RefusedModel{"Unknown", "REFLECTANCE_PROP_NAME = Shiny\nREFLECTANCE_PROP { }",
                     ":4: MATERIAL_ENTRY[1]/SURFACE_PROPERTIES/REFLECTANCE_PROP_NAME: unknown "
                     "REFLECTANCE model \"Shiny\" (and no curve file to read as "
                     "SimpleReflectance)"},
        RefusedModel{"Extinction",
                     "REFLECTANCE_PROP { TXT_FILENAME = r.txt }\nEXTINCTION_PROP { FILENAME = "
                     "leaf.ext }",
                     ":5: MATERIAL_ENTRY[1]/SURFACE_PROPERTIES/EXTINCTION_PROP: EXTINCTION_PROP "
                     "is not supported: extinction (.ext) slabs are not modelled; give a "
                     "SimpleTransmittance"},
        RefusedModel{"WardWithoutSigmas",
                     "REFLECTANCE_PROP_NAME = WardBRDF\nREFLECTANCE_PROP { DS_WEIGHTS = 0.1, 0.2 }",
                     ":5: MATERIAL_ENTRY[1]/SURFACE_PROPERTIES/REFLECTANCE_PROP: WardBRDF needs "
                     "DS_WEIGHTS (diffuse, specular) and XY_SIGMAS (x, y)"},
        RefusedModel{"ExtinctionName",
                     "REFLECTANCE_PROP { TXT_FILENAME = r.txt }\nEXTINCTION_PROP_NAME = LeafSlab",
                     ":5: MATERIAL_ENTRY[1]/SURFACE_PROPERTIES/EXTINCTION_PROP_NAME: extinction "
                     "model \"LeafSlab\" is not supported: extinction slabs are not modelled; "
                     "give a SimpleTransmittance"},
        RefusedModel{"BadSpecularFraction",
                     "EMISSIVITY_PROP { FILENAME = r.txt\nSPECULAR_FRACTION = 2 }",
                     ":5: MATERIAL_ENTRY[1]/SURFACE_PROPERTIES/EMISSIVITY_PROP/SPECULAR_FRACTION: "
                     "SPECULAR_FRACTION \"2\" is not a number in [0, 1]"}),
    [](const ::testing::TestParamInfo<RefusedModel>& param) { return param.param.name; });

TEST(MatReader, AModelWithoutItsBlockAndASpecularFractionOfATransmittanceAreWarned) {
    // SimpleTransmittance named with no TRANSMITTANCE_PROP: the material stays opaque, said at
    // the name. SPECULAR_FRACTION inside TRANSMITTANCE_PROP is no transmittance key: an
    // unknown key, not a mirror share.
    TempDir dir;
    write_file(dir / "r.txt", "0.4 0.1\n0.8 0.5\n");
    write_file(dir / "m.mat",
               "MATERIAL_ENTRY {\n  ID = 1\n  SURFACE_PROPERTIES {\n"
               "    REFLECTANCE_PROP { TXT_FILENAME = r.txt }\n"
               "    TRANSMITTANCE_PROP_NAME = SimpleTransmittance\n  }\n}\n"
               "MATERIAL_ENTRY {\n  ID = 2\n  SURFACE_PROPERTIES {\n"
               "    REFLECTANCE_PROP { TXT_FILENAME = r.txt }\n"
               "    TRANSMITTANCE_PROP { TXT_FILENAME = r.txt\n SPECULAR_FRACTION = 1 }\n  }\n}\n");
    Diagnostics diagnostics;
    const auto materials = read_dirsig_materials(dir / "m.mat", {}, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors()) << diagnostics_text(diagnostics);
    ASSERT_EQ(materials.size(), 2u);
    EXPECT_TRUE(materials[0].transmittance.empty());
    EXPECT_DOUBLE_EQ(materials[1].specular.fraction, 0.0);
    const std::string text = warnings_text(diagnostics);
    const std::string m = (dir / "m.mat").string();
    EXPECT_THAT(text, HasSubstr(m + ":5: MATERIAL_ENTRY[1]/SURFACE_PROPERTIES/"
                                    "TRANSMITTANCE_PROP_NAME: TRANSMITTANCE_PROP_NAME "
                                    "\"SimpleTransmittance\" has no TRANSMITTANCE_PROP block: "
                                    "ignored\n"));
    EXPECT_THAT(text, HasSubstr("unknown key SPECULAR_FRACTION ignored"));
}

TEST(MatReader, AnUnknownModelWithACurveFileIsReadAsTheSimpleOneWithAWarning) {
    TempDir dir;
    write_file(dir / "r.txt", "0.4 0.1\n0.8 0.5\n");
    write_file(dir / "m.mat",
               "MATERIAL_ENTRY {\n  ID = 1\n  SURFACE_PROPERTIES {\n"
               "    REFLECTANCE_PROP_NAME = ExtendedReflectanceProp\n"
               "    REFLECTANCE_PROP { TXT_FILENAME = r.txt }\n  }\n}\n");
    Diagnostics diagnostics;
    const auto materials = read_dirsig_materials(dir / "m.mat", {}, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors()) << diagnostics_text(diagnostics);
    ASSERT_EQ(materials.size(), 1u);
    expect_values(materials[0].reflectance.values, {0.1, 0.5});
    EXPECT_EQ(warnings_text(diagnostics),
              (dir / "m.mat").string() +
                  ":4: MATERIAL_ENTRY[1]/SURFACE_PROPERTIES/REFLECTANCE_PROP_NAME: unknown "
                  "REFLECTANCE model \"ExtendedReflectanceProp\": its curve file is read as "
                  "SimpleReflectance's\n");
}

TEST(MatReader, EmissivityPlusReflectanceAboveOneLowersTheReflectanceWithOneWarning) {
    TempDir dir;
    write_file(dir / "r.txt", "0.4 0.2\n10.0 0.2\n");
    write_file(dir / "e.txt", "0.4 0.9\n5.0 0.9\n10.0 0.7\n");
    write_file(dir / "m.mat",
               "MATERIAL_ENTRY {\n  ID = 4\n  SURFACE_PROPERTIES {\n"
               "    REFLECTANCE_PROP { TXT_FILENAME = r.txt }\n"
               "    EMISSIVITY_PROP { FILENAME = e.txt }\n  }\n}\n");
    Diagnostics diagnostics;
    const auto materials = read_dirsig_materials(dir / "m.mat", {}, diagnostics);
    ASSERT_EQ(diagnostics.items().size(), 1u) << diagnostics_text(diagnostics);
    const Diagnostic& w = diagnostics.items()[0];
    EXPECT_EQ(w.severity, Diagnostic::Severity::warning);
    EXPECT_EQ(w.text(), (dir / "m.mat").string() +
                            ":1: MATERIAL_ENTRY[4]: material '4': emissivity + reflectance "
                            "exceed 1 by up to 0.1 (at 0.4 um); the reflectance is lowered to 1 - "
                            "emissivity there");
    ASSERT_EQ(materials.size(), 1u);
    // On the union of both curves' wavelengths: ρ = min(0.2, 1 − ε).
    EXPECT_THAT(materials[0].reflectance.wavelengths_um, ElementsAre(0.4, 5.0, 10.0));
    expect_values(materials[0].reflectance.values, {0.1, 0.1, 0.2});
}

TEST(MatReader, SurfaceWithNeitherCurveIsAnError) {
    TempDir dir;
    write_file(dir / "m.mat",
               "MATERIAL_ENTRY {\n  ID = 1\n  SURFACE_PROPERTIES {\n"
               "    EMISSIVITY_PROP_NAME = ClassicEmissivity\n  }\n}\n");
    Diagnostics diagnostics;
    read_dirsig_materials(dir / "m.mat", {}, diagnostics);
    const Diagnostic e = only_error(diagnostics);
    EXPECT_EQ(e.text(), (dir / "m.mat").string() +
                            ":3: MATERIAL_ENTRY[1]/SURFACE_PROPERTIES: missing REFLECTANCE_PROP "
                            "and EMISSIVITY_PROP");
}

// ---- a bad classic .ems: one error at its line ---------------------------------------------

/// A .mat whose one material takes its emissivity from x.ems beside it.
constexpr std::string_view kEmsMaterial =
    "MATERIAL_ENTRY {\n  ID = 1\n  SURFACE_PROPERTIES {\n"
    "    EMISSIVITY_PROP { FILENAME = x.ems }\n  }\n}\n";

struct EmsCase {
    const char* name;
    std::string_view text;
    int line;
    const char* message;
};

class ClassicEmsErrors : public ::testing::TestWithParam<EmsCase> {};

TEST_P(ClassicEmsErrors, OneErrorAtItsLine) {
    const EmsCase& c = GetParam();
    TempDir dir;
    write_file(dir / "x.ems", c.text);
    write_file(dir / "m.mat", kEmsMaterial);
    Diagnostics diagnostics;
    read_dirsig_materials(dir / "m.mat", {}, diagnostics);
    const Diagnostic e = only_error(diagnostics);
    EXPECT_EQ(e.where.file, (dir / "x.ems").string());
    EXPECT_EQ(e.where.line, c.line);
    EXPECT_EQ(e.where.element, "MATERIAL_ENTRY[1]/SURFACE_PROPERTIES/EMISSIVITY_PROP/FILENAME");
    EXPECT_THAT(e.message, HasSubstr(c.message));
}

const EmsCase kEmsErrors[] = {
    {"FewerCurvesThanCounted", "2\n1.0\nCURVE_BEGIN\n0.4 0.9\n1.0 0.9\n", 1,
     "classic .ems: the first line gives 2 curve(s), the file holds 1"},
    {"AscendingWavenumbers", "1\n1.0\n700 0.9\n1000 0.9\n", 1,
     "the first line gives 1 curve(s), the file holds 2 (without CURVE_BEGIN the rows are read "
     "as wavenumbers in cm-1"},
    {"EmissivityAboveOne", "1\nCURVE_BEGIN\n0.4 0.9\n0.5 1.5\n", 4,
     "emissivity 1.5 is outside [0, 1]"},
    {"DecreasingWavelength", "1\nCURVE_BEGIN\n0.5 0.9\n0.4 0.9\n", 4,
     "wavelength 0.4 um is not positive and strictly increasing"},
    {"TextBeforeCurveBegin", "1\nCURVE_BEGIN\n0.4 0.9\nCURVE_END\nfoo\n", 5,
     "expected CURVE_BEGIN, got \"foo\""},
    {"NeitherLayout", "# header\nEMISSIVITY\n0.4 0.9\n", 2,
     "\"EMISSIVITY\" is not a curve file's first line: expected \"wavelength_um value\" (a "
     "two-column curve) or a curve count (a classic DIRSIG .ems)"},
    {"Binary", std::string_view("1\n\0\x01\x02", 5), 0, "binary data (a NUL byte)"},
};

INSTANTIATE_TEST_SUITE_P(MatReader, ClassicEmsErrors, ::testing::ValuesIn(kEmsErrors),
                         [](const ::testing::TestParamInfo<EmsCase>& test_case) {
                             return std::string(test_case.param.name);
                         });

TEST(MatReader, OldEmsFormatNumbersItsCurves) {
    // DIRSIG's "old" .ems: the count, 91 angular rows, then each curve after a line holding
    // its number (0, 1, …), in descending wavenumber (real anadirsig.mat bundles).
    TempDir dir;
    std::string ems = "2\n";
    for (int angle = 0; angle <= 90; ++angle) ems += "1.0\n";
    ems += "0\n1000 0.90\n500 0.95\n1\n1000 0.80\n500 0.85\n";
    write_file(dir / "x.ems", ems);
    write_file(dir / "m.mat", kEmsMaterial);
    Diagnostics diagnostics;
    const auto materials = read_dirsig_materials(dir / "m.mat", {}, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors()) << diagnostics_text(diagnostics);
    ASSERT_EQ(materials.size(), 1u);
    // The first curve, λ = 10⁴ / ν: 10 and 20 µm.
    EXPECT_THAT(materials[0].emissivity.wavelengths_um, ElementsAre(10.0, 20.0));
    expect_values(materials[0].emissivity.values, {0.90, 0.95});
    EXPECT_THAT(warnings_text(diagnostics), HasSubstr("classic .ems with 2 curves (texture "
                                                      "classes): glint uses the first (line 93)"));

    // A curve number out of sequence is an error at its line.
    std::string wrong_ems = "2\n";
    for (int angle = 0; angle <= 90; ++angle) wrong_ems += "1.0\n";
    write_file(dir / "x.ems", wrong_ems + "0\n1000 0.9\n500 0.95\n2\n1000 0.8\n500 0.85\n");
    Diagnostics wrong;
    read_dirsig_materials(dir / "m.mat", {}, wrong);
    ASSERT_TRUE(wrong.has_errors());
    ASSERT_EQ(wrong.error_count(), 1u) << diagnostics_text(wrong);
    const Diagnostic& error = wrong.items().back();
    EXPECT_EQ(error.where.line, 96);
    EXPECT_EQ(error.message,
              "expected curve number 1 or a row \"wavenumber_cm-1 value\", got \"2\"");
}

TEST(MatReader, AnIgnoredKeyIsSaidOncePerFileWithItsCountAndPlaces) {
    // Six materials with SPECIFIC_HEAT (DIRSIG's thermal keys: a real database has it in
    // every entry), two with DENSITY, one with an unknown block: three warnings, not nine.
    TempDir dir;
    std::string mat;
    for (int id = 1; id <= 6; ++id) {
        mat += "MATERIAL_ENTRY {\n  ID = " + std::to_string(id) + "\n  SPECIFIC_HEAT = 0.2\n" +
               (id <= 2 ? "  DENSITY = 1.5\n" : "") + (id == 3 ? "  GLOW { A = 1 }\n" : "") +
               "  SURFACE_PROPERTIES {\n    EMISSIVITY_PROP { FILENAME = x.ems }\n  }\n}\n";
    }
    write_file(dir / "x.ems", "0.4 0.9\n0.7 0.9\n");
    write_file(dir / "m.mat", mat);
    Diagnostics diagnostics;
    read_dirsig_materials(dir / "m.mat", {}, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors()) << diagnostics_text(diagnostics);
    const std::string file = (dir / "m.mat").string();
    EXPECT_EQ(warnings_text(diagnostics),
              file +
                  ":3: MATERIAL_ENTRY[1]/SPECIFIC_HEAT: unknown key SPECIFIC_HEAT ignored (6 "
                  "times: also lines 11, 19, 27 and 2 more)\n" +
                  file +
                  ":4: MATERIAL_ENTRY[1]/DENSITY: unknown key DENSITY ignored (2 times: "
                  "also line 12)\n" +
                  file + ":20: MATERIAL_ENTRY[3]/GLOW: unsupported block GLOW ignored\n");
    EXPECT_EQ(diagnostics.warning_count(), 3u);
}

TEST(MatReader, AMissingCurveFileIsSaidAtTheKeyThatNamesIt) {
    TempDir dir;
    write_file(dir / "m.mat",
               "MATERIAL_ENTRY {\n  ID = 1\n  SURFACE_PROPERTIES {\n"
               "    EMISSIVITY_PROP { FILENAME = gone.ems }\n  }\n}\n");
    Diagnostics diagnostics;
    read_dirsig_materials(dir / "m.mat", {}, diagnostics);
    ASSERT_EQ(diagnostics.error_count(), 1u) << diagnostics_text(diagnostics);
    EXPECT_EQ(diagnostics.items().at(0).text(),
              (dir / "m.mat").string() +
                  ":4: MATERIAL_ENTRY[1]/SURFACE_PROPERTIES/EMISSIVITY_PROP/FILENAME: emissivity "
                  "file " +
                  (dir / "gone.ems").string() + ": cannot open file: No such file or directory");
}

TEST(MatReader, AFilesDiagnosticsAreCappedAtTwenty) {
    TempDir dir;
    std::string rows = "1\nCURVE_BEGIN\n";
    for (int i = 0; i < 50; ++i) rows += "0.4 x\n";
    write_file(dir / "x.ems", rows);
    write_file(dir / "m.mat", kEmsMaterial);
    Diagnostics diagnostics;
    read_dirsig_materials(dir / "m.mat", {}, diagnostics);
    ASSERT_EQ(diagnostics.items().size(), 21u) << diagnostics_text(diagnostics);
    EXPECT_EQ(diagnostics.items()[19].where.line, 22);
    EXPECT_EQ(diagnostics.items()[20].text(),
              (dir / "x.ems").string() + ": … and 30 more (30 errors, 0 warnings) not shown");
    EXPECT_EQ(diagnostics.error_count(), 50u);  // every error found, those not shown included
}

}  // namespace mat_reader_test
}  // namespace glint::dirsig
