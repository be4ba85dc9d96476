// SPDX-License-Identifier: Apache-2.0
// Tests of the truth-collection part of the `.platform` reader: the truth.platform fixture
// (several collections, an empty one, repeated names, Abundance with materials and tags)
// field by field, and the bad truth inputs with their message, line and element path.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "platform_test_util.h"

namespace glint::test::plat {
namespace truth_reader_test {

using Severity = Diagnostic::Severity;

constexpr const char* kTruthPath =
    "platform/attachment/instrument[Cam]/focalplane[FP]/truthcollection";

std::string with_truth(const std::string& truth) {
    return with_focal_plane(std::string(kCapture) + kDetector + truth);
}

TEST(TruthReader, TruthFixtureFieldByField) {
    const Read read = read_fixture("truth.platform");
    ASSERT_FALSE(read.diagnostics.has_errors()) << dump(read.diagnostics);
    // The empty <truthcollection/> and the disabled one are each worth a warning.
    ASSERT_EQ(read.diagnostics.warning_count(), 2u) << dump(read.diagnostics);
    const std::string plane =
        "platform/attachment/mount[Belly]/attachment/instrument[Cam]/focalplane[RGB]";
    expect_diagnostic(read, "empty <truthcollection>: nothing to collect", 88,
                      plane + "/truthcollection", Severity::warning);
    expect_diagnostic(read,
                      "truth collection \"Geometry\" is disabled: no truth image is written "
                      "for it",
                      90, plane + "/truthcollection/enabled", Severity::warning);
    EXPECT_EQ(read.platform.metadata.find("name").value_or(""), "Truth");

    const auto& truths = model::list_instruments(read.platform)
                             .at(0)
                             .instrument->focal_planes.at(0)
                             .truth_collections;
    ASSERT_EQ(truths.size(), 5u);
    const model::TruthCollection& geometry = truths[0];
    EXPECT_TRUE(geometry.enabled);
    EXPECT_EQ(geometry.name, "Geometry");
    EXPECT_EQ(geometry.image_file.basename, "geometry_truth");
    EXPECT_EQ(geometry.image_file.schedule, model::ImageSchedule::capture);
    ASSERT_EQ(geometry.collectors.size(), 3u);
    EXPECT_EQ(geometry.collectors[0].name, "Material");
    EXPECT_EQ(geometry.collectors[1].name, "GeoLocation");
    EXPECT_EQ(geometry.collectors[2].name, "Intersection");
    EXPECT_TRUE(geometry.collectors[0].materials.empty());
    EXPECT_EQ(geometry.where.line, 49);

    const model::TruthCollection& abundance = truths[1];
    EXPECT_EQ(abundance.name, "Abundances");
    EXPECT_EQ(abundance.image_file.schedule, model::ImageSchedule::task);
    ASSERT_EQ(abundance.collectors.size(), 2u);
    EXPECT_EQ(abundance.collectors[0].name, "Abundance");
    EXPECT_EQ(abundance.collectors[0].materials, (std::vector<std::string>{"10", "grass"}));
    EXPECT_TRUE(abundance.collectors[0].tags.empty());
    EXPECT_EQ(abundance.collectors[1].tags, (std::vector<std::string>{"truck", "car"}));
    EXPECT_TRUE(abundance.collectors[1].materials.empty());

    const model::TruthCollection& empty = truths[2];
    EXPECT_FALSE(empty.enabled);  // an empty element collects nothing
    EXPECT_TRUE(empty.collectors.empty());
    EXPECT_EQ(empty.where.line, 88);

    const model::TruthCollection& again = truths[3];
    EXPECT_FALSE(again.enabled);
    EXPECT_EQ(again.name, "Geometry");  // names may repeat
    EXPECT_EQ(again.image_file.basename, "geometry_truth_again");
    EXPECT_EQ(again.image_file.schedule, model::ImageSchedule::simulation);
    ASSERT_EQ(again.collectors.size(), 1u);
    EXPECT_EQ(again.collectors[0].name, "materialindex");

    const model::TruthCollection& unnamed = truths[4];
    EXPECT_TRUE(unnamed.enabled);
    EXPECT_EQ(unnamed.name, "");
    EXPECT_EQ(unnamed.collectors.at(0).name, "Shadow");
}

TEST(TruthReader, CollectorErrors) {
    TempDir dir;
    const std::string text = with_truth(
        "<truthcollection>\n<enabled>perhaps</enabled>\n"
        "<imagefile><basename>t</basename></imagefile>\n<collectorlist>\n"
        "<collector><materials>1</materials></collector>\n"
        "<collector><name>Abundance</name></collector>\n"
        "<collector><name>abundance</name><materials>1</materials><tags>car</tags></collector>\n"
        "<collector><name>Material</name><tags>car</tags></collector>\n"
        "<gadget/>\n</collectorlist>\n</truthcollection>");
    const Read read = read_text(dir, text);
    const std::string list = std::string(kTruthPath) + "/collectorlist";
    expect_diagnostic(read, "expected a boolean (true, false, yes, no, 1 or 0), got \"perhaps\"",
                      line_of(text, "<enabled>"), std::string(kTruthPath) + "/enabled");
    expect_diagnostic(read, "missing required element <name>",
                      line_of(text, "<collector><materials>"), list + "/collector");
    expect_diagnostic(read,
                      "the Abundance collector needs <materials> (comma-separated material ids) "
                      "or <tags> (comma-separated geometry tags)",
                      line_of(text, "<collector><name>Abundance"), list + "/collector");
    expect_diagnostic(read, "both <materials> and <tags> given, expected one of the two",
                      line_of(text, "<collector><name>abundance"), list + "/collector/tags");
    expect_diagnostic(read, "<tags> ignored: only the Abundance collector uses it",
                      line_of(text, "<collector><name>Material"), list + "/collector/tags",
                      Severity::warning);
    expect_diagnostic(read, "unknown element <gadget> ignored", line_of(text, "<gadget/>"),
                      list + "/gadget", Severity::warning);
}

TEST(TruthReader, ImageFileRequiredWhenEnabled) {
    TempDir dir;
    const std::string text = with_truth(
        "<truthcollection>\n<enabled>true</enabled>\n<collectorlist><collector><name>Material"
        "</name></collector></collectorlist>\n</truthcollection>\n"
        "<truthcollection>\n<enabled>false</enabled>\n</truthcollection>");
    const Read read = read_text(dir, text);
    expect_diagnostic(read, "missing required element <imagefile>",
                      line_of(text, "<truthcollection>"), kTruthPath);
    EXPECT_EQ(read.diagnostics.error_count(), 1u) << dump(read.diagnostics);
}

TEST(TruthReader, EnabledWithoutCollectorsWarns) {
    TempDir dir;
    const std::string text = with_truth(
        "<truthcollection>\n<imagefile><basename>t</basename></imagefile>\n"
        "<collectorlist/>\n</truthcollection>");
    const Read read = read_text(dir, text);
    EXPECT_FALSE(read.diagnostics.has_errors()) << dump(read.diagnostics);
    expect_diagnostic(read, "truth collection has no <collector>: nothing to collect",
                      line_of(text, "<truthcollection>"), kTruthPath, Severity::warning);
}

}  // namespace truth_reader_test
}  // namespace glint::test::plat
