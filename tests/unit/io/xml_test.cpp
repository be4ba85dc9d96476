// SPDX-License-Identifier: Apache-2.0
// Unit tests of the XML layer: parsing without a prolog, CDATA, empty elements, malformed XML
// and deep nesting refused with their line, element paths with [name] labels, the whole-string
// number/integer/boolean parsers, and every value reader's diagnostic (message, line, path).
#include "glint/io/xml.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "glint/core/diagnostics.h"
#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/test/temp_dir.h"

namespace glint::io {
namespace xml_test {

using glint::test::TempDir;
using ::testing::HasSubstr;

/// The glint::Error that parsing `text` throws (fails the test when none).
Error parse_failure(const std::string& text, const std::string& name = "bad.xml") {
    try {
        XmlDocument::parse(text, name);
    } catch (const Error& error) {
        return error;
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return internal_error("no error");
}

constexpr const char* kPlatform = R"(<platform>
  <attachment>
    <mount name="Belly" type="static">
      <attachment>
        <instrument name="Cam">
          <focalplane name="RGB">
            <capturemethod>
              <imagefile areaunits="cm2" fluxunits="kilowatts"/>
            </capturemethod>
            <detectorarray>
              <xelementcount>64x</xelementcount>
              <yelementcount>+48</yelementcount>
              <xelementsize> 5.5 </xelementsize>
              <yelementsize>-5</yelementsize>
              <note><![CDATA[  <raw> & text  ]]></note>
              <empty/>
              <bogus>1</bogus>
            </detectorarray>
          </focalplane>
        </instrument>
      </attachment>
    </mount>
  </attachment>
</platform>
)";

/// The detectorarray element of kPlatform.
XmlNode detector_array(const XmlDocument& document) {
    const XmlNode root = document.root("platform");
    return root.child("attachment")
        ->child("mount")
        ->child("attachment")
        ->child("instrument")
        ->child("focalplane")
        ->child("detectorarray")
        .value();
}

constexpr const char* kDetectorPath =
    "platform/attachment/mount[Belly]/attachment/instrument[Cam]/focalplane[RGB]/detectorarray";

TEST(XmlDocument, ParsesWithoutPrologWithCdataAndEmptyElements) {
    const XmlDocument document = XmlDocument::parse(kPlatform, "cam.platform");
    const XmlNode array = detector_array(document);
    EXPECT_EQ(array.path(), kDetectorPath);
    EXPECT_EQ(array.line(), 10);
    EXPECT_EQ(array.file(), "cam.platform");
    EXPECT_EQ(array.child("note")->text(), "<raw> & text");
    EXPECT_EQ(array.child("empty")->text(), "");
    EXPECT_EQ(array.child("empty")->children().size(), 0u);
    EXPECT_FALSE(array.child("missing").has_value());
    EXPECT_EQ(array.children().size(), 7u);
    EXPECT_EQ(array.optional_text("xelementsize"), "5.5");
    EXPECT_EQ(array.optional_text("missing"), std::nullopt);
}

TEST(XmlDocument, AcceptsAPrologAndComments) {
    const XmlDocument document = XmlDocument::parse(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!-- c -->\n<a><b>1<!-- x -->2</b></a>",
        "a.xml");
    EXPECT_EQ(document.root("a").child("b")->text(), "12");
    EXPECT_EQ(document.display_name(), "a.xml");
}

TEST(XmlDocument, LoadsAFileAndNamesItInErrors) {
    TempDir dir;
    const auto path = dir / "t.xml";
    std::ofstream(path) << "<tasklist>\n  <task/>\n</tasklist>\n";
    const XmlDocument document = XmlDocument::load(path);
    EXPECT_EQ(document.display_name(), path.string());
    EXPECT_EQ(document.root().children("task").at(0).line(), 2);
    EXPECT_EQ(XmlDocument::load(path, "shown.tasks").root().file(), "shown.tasks");
}

TEST(XmlDocument, MissingFileIsAnIoError) {
    TempDir dir;
    try {
        XmlDocument::load(dir / "nope.xml", "nope.xml");
        FAIL() << "expected an error";
    } catch (const Error& error) {
        EXPECT_EQ(error.category(), ErrorCategory::io);
        EXPECT_THAT(error.what(), HasSubstr("nope.xml: cannot open file"));
    }
    try {
        XmlDocument::load(dir.path());
        FAIL() << "expected an error";
    } catch (const Error& error) {
        EXPECT_THAT(error.what(), HasSubstr("is a folder, expected a file"));
    }
}

TEST(XmlDocument, MalformedXmlNamesTheLine) {
    const Error error = parse_failure("<a>\n  <b>\n</a>\n", "cam.platform");
    EXPECT_EQ(error.category(), ErrorCategory::input);
    EXPECT_EQ(error.context().line, 2);
    EXPECT_THAT(error.what(), HasSubstr("cam.platform:2: malformed XML: mismatched element"));

    const Error attribute = parse_failure("<a>\n\n<b x=1/></a>");
    EXPECT_EQ(attribute.context().line, 3);
    EXPECT_THAT(attribute.what(), HasSubstr("bad.xml:3: malformed XML: parsing attribute"));

    const Error empty = parse_failure("  \n");
    EXPECT_THAT(empty.what(), HasSubstr("bad.xml:1: malformed XML: empty document"));

    const Error two_roots = parse_failure("<a/>\n<b/>");
    EXPECT_EQ(two_roots.context().line, 2);
    EXPECT_THAT(two_roots.what(), HasSubstr("malformed XML: a second root element <b>"));
}

TEST(XmlDocument, RefusesDeepNestingWithItsLine) {
    for (const int depth : {kMaxXmlDepth + 1, 100, 300}) {
        std::string text;
        for (int i = 0; i < depth; ++i) text += "<e>\n";
        for (int i = 0; i < depth; ++i) text += "</e>";
        const Error error = parse_failure(text, "deep.xml");
        EXPECT_THAT(error.what(), HasSubstr("elements nested deeper than 64 levels")) << depth;
        EXPECT_GT(error.context().line, kMaxXmlDepth) << depth;
        EXPECT_LE(error.context().line, depth) << depth;
    }
    std::string ok;
    for (int i = 0; i < kMaxXmlDepth; ++i) ok += "<e>";
    for (int i = 0; i < kMaxXmlDepth; ++i) ok += "</e>";
    EXPECT_NO_THROW(XmlDocument::parse(ok, "ok.xml"));
}

TEST(XmlDocument, RootNameIsChecked) {
    const XmlDocument document = XmlDocument::parse("\n<simulation/>", "a.sim");
    EXPECT_EQ(document.root("simulation").path(), "simulation");
    try {
        document.root("tasklist");
        FAIL() << "expected an error";
    } catch (const Error& error) {
        EXPECT_STREQ(error.what(), "a.sim:2: expected root element <tasklist>, got <simulation>");
    }
}

TEST(XmlNode, WhereAndAttributes) {
    const XmlDocument document = XmlDocument::parse(kPlatform, "cam.platform");
    const XmlNode array = detector_array(document);
    const ErrorContext where = array.child("xelementcount")->where();
    EXPECT_EQ(where.file, "cam.platform");
    EXPECT_EQ(where.line, 11);
    EXPECT_EQ(where.element, std::string(kDetectorPath) + "/xelementcount");
    const XmlNode mount = *document.root().child("attachment")->child("mount");
    EXPECT_EQ(mount.attribute("type"), "static");
    EXPECT_EQ(mount.attribute("nope"), std::nullopt);
    EXPECT_EQ(mount.where_attribute("type").element, "platform/attachment/mount[Belly]@type");
}

TEST(XmlNode, WarnsAboutUnknownChildren) {
    const XmlDocument document = XmlDocument::parse(kPlatform, "cam.platform");
    Diagnostics diagnostics;
    detector_array(document).warn_unknown_children(
        {"xelementcount", "yelementcount", "xelementsize", "yelementsize", "note", "empty"},
        diagnostics);
    ASSERT_EQ(diagnostics.items().size(), 1u);
    EXPECT_EQ(diagnostics.error_count(), 0u);
    EXPECT_EQ(diagnostics.items()[0].text(), "cam.platform:17: " + std::string(kDetectorPath) +
                                                 "/bogus: unknown element <bogus> ignored");
}

TEST(XmlNode, IntegerReaderReportsTrailingJunk) {
    const XmlDocument document = XmlDocument::parse(kPlatform, "cam.platform");
    const XmlNode array = detector_array(document);
    Diagnostics diagnostics;
    EXPECT_EQ(array.required_int("xelementcount", diagnostics, 1, 1000000), std::nullopt);
    EXPECT_EQ(array.required_int("yelementcount", diagnostics, 1, 1000000), 48);
    ASSERT_EQ(diagnostics.error_count(), 1u);
    EXPECT_EQ(diagnostics.items()[0].text(),
              "cam.platform:11: " + std::string(kDetectorPath) +
                  "/xelementcount: expected an integer in [1, 1000000], got \"64x\"");
}

TEST(XmlNode, MissingRequiredElement) {
    const XmlDocument document = XmlDocument::parse(kPlatform, "cam.platform");
    const XmlNode array = detector_array(document);
    Diagnostics diagnostics;
    EXPECT_EQ(array.required_double("rate", diagnostics), std::nullopt);
    EXPECT_EQ(array.required_int("count", diagnostics, 0, 10), std::nullopt);
    EXPECT_EQ(array.required_text("label", diagnostics), "");
    EXPECT_EQ(array.optional_double("rate", diagnostics), std::nullopt);
    ASSERT_EQ(diagnostics.error_count(), 3u);
    EXPECT_EQ(diagnostics.items()[0].text(), "cam.platform:10: " + std::string(kDetectorPath) +
                                                 ": missing required element <rate>");
    EXPECT_THAT(diagnostics.items()[2].message, HasSubstr("missing required element <label>"));
}

TEST(XmlNode, NegativeValueAgainstAPositiveRule) {
    const XmlDocument document = XmlDocument::parse(kPlatform, "cam.platform");
    const XmlNode array = detector_array(document);
    Diagnostics diagnostics;
    EXPECT_EQ(array.required_double("xelementsize", diagnostics, NumberRule::positive()), 5.5);
    EXPECT_EQ(array.required_double("yelementsize", diagnostics, NumberRule::positive()),
              std::nullopt);
    EXPECT_EQ(array.optional_double("yelementsize", diagnostics), -5.0);
    ASSERT_EQ(diagnostics.error_count(), 1u);
    EXPECT_EQ(diagnostics.items()[0].where.line, 14);
    EXPECT_EQ(diagnostics.items()[0].where.element, std::string(kDetectorPath) + "/yelementsize");
    EXPECT_EQ(diagnostics.items()[0].message, "expected a number > 0, got \"-5\"");
}

TEST(XmlNode, NonNumericAndNonFiniteValues) {
    const XmlDocument document = XmlDocument::parse(
        "<a>\n<x>abc</x>\n<y>NaN</y>\n<z>inf</z>\n<w>0x10</w>\n<v>1e999</v>\n<u>0.5</u>\n</a>",
        "v.xml");
    const XmlNode root = document.root();
    Diagnostics diagnostics;
    for (const char* name : {"x", "y", "z", "w", "v"}) {
        EXPECT_EQ(root.optional_double(name, diagnostics), std::nullopt) << name;
    }
    EXPECT_EQ(root.optional_double("u", diagnostics, NumberRule::fraction()), 0.5);
    ASSERT_EQ(diagnostics.error_count(), 5u);
    EXPECT_EQ(diagnostics.items()[0].text(), "v.xml:2: a/x: expected a number, got \"abc\"");
    EXPECT_EQ(diagnostics.items()[1].text(), "v.xml:3: a/y: expected a number, got \"NaN\"");
    EXPECT_EQ(diagnostics.items()[2].text(), "v.xml:4: a/z: expected a number, got \"inf\"");
    EXPECT_EQ(diagnostics.items()[3].text(), "v.xml:5: a/w: expected a number, got \"0x10\"");
    EXPECT_EQ(diagnostics.items()[4].text(), "v.xml:6: a/v: expected a number, got \"1e999\"");
}

TEST(XmlNode, UnknownEnumOnAnAttribute) {
    const XmlDocument document = XmlDocument::parse(kPlatform, "cam.platform");
    const XmlNode image = document.root()
                              .child("attachment")
                              ->child("mount")
                              ->child("attachment")
                              ->child("instrument")
                              ->child("focalplane")
                              ->child("capturemethod")
                              ->child("imagefile")
                              .value();
    Diagnostics diagnostics;
    EXPECT_EQ(image.attribute_enum("areaunits", {"cm2", "m2"}, diagnostics), "cm2");
    EXPECT_EQ(image.attribute_enum(
                  "fluxunits",
                  {"watts", "milliwatts", "microwatts", "photonspersecond", "electronspersecond"},
                  diagnostics),
              std::nullopt);
    EXPECT_EQ(image.attribute_enum("absent", {"a"}, diagnostics), std::nullopt);
    ASSERT_EQ(diagnostics.error_count(), 1u);
    EXPECT_EQ(diagnostics.items()[0].text(),
              "cam.platform:8: platform/attachment/mount[Belly]/attachment/instrument[Cam]/"
              "focalplane[RGB]/capturemethod/imagefile@fluxunits: expected one of watts, "
              "milliwatts, microwatts, photonspersecond, electronspersecond, got \"kilowatts\"");
}

TEST(XmlNode, EnumsAndBooleansIgnoreCase) {
    const XmlDocument document = XmlDocument::parse(
        "<a on=\"YES\" off=\"0\" odd=\"maybe\" k=\" 2.5 \">\n<mode> Simple </mode>\n"
        "<flag>False</flag>\n<bad>2</bad>\n<n>+3</n></a>",
        "e.xml");
    const XmlNode root = document.root();
    Diagnostics diagnostics;
    EXPECT_EQ(root.optional_enum("mode", {"simple", "raw"}, diagnostics), "simple");
    EXPECT_EQ(root.optional_bool("flag", diagnostics), false);
    EXPECT_EQ(root.optional_bool("bad", diagnostics), std::nullopt);
    EXPECT_EQ(root.attribute_bool("on", diagnostics), true);
    EXPECT_EQ(root.attribute_bool("off", diagnostics), false);
    EXPECT_EQ(root.attribute_bool("odd", diagnostics), std::nullopt);
    EXPECT_EQ(root.attribute_double("k", diagnostics, NumberRule::range(0, 10)), 2.5);
    EXPECT_EQ(root.attribute_double("k", diagnostics, NumberRule::range(3, 10)), std::nullopt);
    EXPECT_EQ(root.child("n")->own_double(diagnostics, NumberRule::non_negative()), 3.0);
    ASSERT_EQ(diagnostics.error_count(), 3u);
    EXPECT_EQ(diagnostics.items()[0].text(),
              "e.xml:4: a/bad: expected a boolean (true, false, yes, no, 1 or 0), got \"2\"");
    EXPECT_EQ(diagnostics.items()[1].text(),
              "e.xml:1: a@odd: expected a boolean (true, false, yes, no, 1 or 0), got \"maybe\"");
    EXPECT_EQ(diagnostics.items()[2].text(),
              "e.xml:1: a@k: expected a number in [3, 10], got \"2.5\"");
}

TEST(XmlNode, IntegerOverflowAndRangeDescriptions) {
    const XmlDocument document = XmlDocument::parse(
        "<a><big>99999999999999999999</big><neg>-1</neg><f>1.0</f><ok> 7 </ok></a>", "i.xml");
    const XmlNode root = document.root();
    Diagnostics diagnostics;
    constexpr auto kMax = std::numeric_limits<std::int64_t>::max();
    constexpr auto kMin = std::numeric_limits<std::int64_t>::min();
    EXPECT_EQ(root.optional_int("big", diagnostics, kMin, kMax), std::nullopt);
    EXPECT_EQ(root.optional_int("neg", diagnostics, 0, kMax), std::nullopt);
    EXPECT_EQ(root.optional_int("f", diagnostics, kMin, 5), std::nullopt);
    EXPECT_EQ(root.optional_int("ok", diagnostics, 0, 10), 7);
    ASSERT_EQ(diagnostics.error_count(), 3u);
    EXPECT_EQ(diagnostics.items()[0].message, "expected an integer, got \"99999999999999999999\"");
    EXPECT_EQ(diagnostics.items()[1].message, "expected an integer >= 0, got \"-1\"");
    EXPECT_EQ(diagnostics.items()[2].message, "expected an integer <= 5, got \"1.0\"");
}

TEST(XmlParsers, Doubles) {
    EXPECT_EQ(parse_double("1.5"), 1.5);
    EXPECT_EQ(parse_double("  +2e3\t\n"), 2000.0);
    EXPECT_EQ(parse_double("-0.25"), -0.25);
    EXPECT_EQ(parse_double(".5"), 0.5);
    for (const char* bad : {"", " ", "+", "++1", "+-1", "1.5m", "1,5", "nan", "NaN", "inf",
                            "-infinity", "0x1p3", "1e400", "1 2", "abc"}) {
        EXPECT_EQ(parse_double(bad), std::nullopt) << bad;
    }
}

TEST(XmlParsers, Integers) {
    EXPECT_EQ(parse_int("42"), 42);
    EXPECT_EQ(parse_int(" +7 "), 7);
    EXPECT_EQ(parse_int("-9223372036854775808"), std::numeric_limits<std::int64_t>::min());
    for (const char* bad :
         {"", "9223372036854775808", "1.0", "1e3", "0x10", "64x", "+-1", "--1", "1 2"}) {
        EXPECT_EQ(parse_int(bad), std::nullopt) << bad;
    }
}

TEST(XmlParsers, BooleansAndLists) {
    EXPECT_EQ(parse_bool("TRUE"), true);
    EXPECT_EQ(parse_bool(" yes "), true);
    EXPECT_EQ(parse_bool("1"), true);
    EXPECT_EQ(parse_bool("No"), false);
    EXPECT_EQ(parse_bool("0"), false);
    EXPECT_EQ(parse_bool("on"), std::nullopt);
    EXPECT_EQ(split_list("vis, nir ,,swir,"), (std::vector<std::string>{"vis", "nir", "swir"}));
    EXPECT_EQ(split_list("1 2  3", ' '), (std::vector<std::string>{"1", "2", "3"}));
    EXPECT_TRUE(split_list("  ").empty());
}

TEST(XmlParsers, NumberRules) {
    EXPECT_EQ(NumberRule::any().describe(), "a number");
    EXPECT_EQ(NumberRule::positive().describe(), "a number > 0");
    EXPECT_EQ(NumberRule::non_negative().describe(), "a number >= 0");
    EXPECT_EQ(NumberRule::fraction().describe(), "a number in [0, 1]");
    EXPECT_EQ((NumberRule{0.5, 1e20, true, true}.describe()), "a number in (0.5, 1e+20)");
    EXPECT_TRUE(NumberRule::fraction().accepts(1.0));
    EXPECT_FALSE(NumberRule::fraction().accepts(1.0001));
    EXPECT_FALSE(NumberRule::positive().accepts(0.0));
    EXPECT_TRUE(NumberRule::non_negative().accepts(0.0));
    EXPECT_FALSE(NumberRule::any().accepts(std::nan("")));
}

TEST(XmlDocument, UnreadAttributesOfElementsAReaderLookedIntoAreWarnedOnce) {
    // A reader reads <camera rate> and <lens>'s text; "colour" on <camera>, "units" on
    // <lens> (asked for by name) and the misspelt "rolingreadout" are never read: one warning
    // each at the attribute. "name" labels paths and the namespace attributes are XML's own;
    // <notes> was never looked into (unknown elements have their own warning).
    const XmlDocument doc = XmlDocument::parse(
        "<camera name=\"C\" rate=\"10\" colour=\"red\" rolingreadout=\"true\"\n"
        "        xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" xsi:type=\"x\">\n"
        "  <lens units=\"mm\">50</lens>\n"
        "  <notes author=\"me\"/>\n"
        "</camera>\n",
        "cam.xml");
    Diagnostics diagnostics;
    const XmlNode root = doc.root("camera");
    EXPECT_EQ(root.attribute_double("rate", diagnostics), 10.0);
    EXPECT_EQ(root.optional_double("lens", diagnostics), 50.0);
    doc.warn_unread(diagnostics);
    std::vector<std::string> warned;
    for (const Diagnostic& item : diagnostics.items()) {
        EXPECT_EQ(item.severity, Diagnostic::Severity::warning);
        EXPECT_THAT(item.message, HasSubstr("is not read by glint here (ignored)"));
        warned.push_back(item.where.file + ":" + std::to_string(item.where.line) + ": " +
                         item.where.element);
    }
    EXPECT_EQ(warned, (std::vector<std::string>{"cam.xml:1: camera[C]@colour",
                                                "cam.xml:1: camera[C]@rolingreadout",
                                                "cam.xml:3: camera[C]/lens@units"}));
    // Reading an attribute, or reporting a problem at it, counts as reading it.
    Diagnostics again;
    (void)root.attribute("colour");
    (void)root.where_attribute("rolingreadout");
    (void)root.child("lens")->attribute("units");
    doc.warn_unread(again);
    EXPECT_TRUE(again.items().empty()) << again.items().front().text();
}

TEST(XmlDocument, ASingularElementGivenAgainIsWarnedAtTheRepeat) {
    // The reader takes the first <rate> (child()) and every <entry> (children()); the second
    // <rate> is never looked into: one warning there naming the first's line. The two
    // <notes>, never looked into, and the entries, all read, give none.
    const XmlDocument doc = XmlDocument::parse(
        "<clock>\n  <rate>10</rate>\n  <notes/>\n  <rate>20</rate>\n  <notes/>\n"
        "  <entry>1</entry>\n  <entry>2</entry>\n</clock>\n",
        "clock.xml");
    Diagnostics diagnostics;
    const XmlNode root = doc.root("clock");
    EXPECT_EQ(root.optional_double("rate", diagnostics), 10.0);
    EXPECT_EQ(root.children("entry").size(), 2u);
    doc.warn_unread(diagnostics);
    ASSERT_EQ(diagnostics.items().size(), 1u);
    const Diagnostic& item = diagnostics.items().front();
    EXPECT_EQ(item.severity, Diagnostic::Severity::warning);
    EXPECT_EQ(item.where.line, 4);
    EXPECT_EQ(item.where.element, "clock/rate");
    EXPECT_EQ(item.message, "<rate> given again (first at line 2): this one is ignored");
}

}  // namespace xml_test
}  // namespace glint::io
