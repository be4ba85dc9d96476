// SPDX-License-Identifier: Apache-2.0
// Helpers for the `.platform` reader tests: read a fixture from tests/data/platform or a
// platform written from a string into a temporary folder, build small platforms around an
// instrument or detector-array fragment, and find the diagnostic carrying a message so a
// test can assert its line and element path.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>

#include "glint/core/diagnostics.h"
#include "glint/dirsig/readers.h"
#include "glint/model/platform.h"
#include "glint/test/temp_dir.h"

namespace glint::test::plat {

/// The folder of the platform fixtures.
inline std::filesystem::path fixture_dir() {
    return std::filesystem::path(GLINT_TEST_DATA_DIR) / "platform";
}

/// Options whose path resolver sees only $GLINT_TEST_VAR (= "/opt/glint-test").
inline dirsig::ReadOptions options() {
    dirsig::ReadOptions o;
    o.paths.environment = [](const std::string& name) -> std::optional<std::string> {
        if (name == "GLINT_TEST_VAR") return std::string("/opt/glint-test");
        return std::nullopt;
    };
    return o;
}

/// A platform and what reading it reported.
struct Read {
    std::string file;
    model::Platform platform;
    Diagnostics diagnostics;
};

/// Every diagnostic, one per line, for failure messages.
inline std::string dump(const Diagnostics& diagnostics) {
    std::string out;
    for (const Diagnostic& d : diagnostics.items()) {
        out +=
            (d.severity == Diagnostic::Severity::error ? "error: " : "warning: ") + d.text() + "\n";
    }
    return out;
}

/// Reads a fixture of tests/data/platform.
inline Read read_fixture(const std::string& name) {
    Read read;
    read.file = (fixture_dir() / name).string();
    read.platform = dirsig::read_platform(read.file, options(), read.diagnostics);
    return read;
}

/// Writes `text` as `name` into `dir` and reads it.
inline Read read_text(const TempDir& dir, const std::string& text,
                      const std::string& name = "test.platform") {
    Read read;
    read.file = (dir / name).string();
    {
        std::ofstream out(read.file, std::ios::binary);
        out << text;
    }
    read.platform = dirsig::read_platform(read.file, options(), read.diagnostics);
    return read;
}

/// 1-based line of the first occurrence of `needle` in `text` (0 when absent).
inline int line_of(std::string_view text, std::string_view needle) {
    const std::size_t pos = text.find(needle);
    if (pos == std::string_view::npos) return 0;
    int line = 1;
    for (std::size_t i = 0; i < pos; ++i) {
        if (text[i] == '\n') ++line;
    }
    return line;
}

/// The first diagnostic of `severity` whose message contains `part`, or nullptr.
inline const Diagnostic* find(const Diagnostics& diagnostics, std::string_view part,
                              Diagnostic::Severity severity = Diagnostic::Severity::error) {
    for (const Diagnostic& d : diagnostics.items()) {
        if (d.severity == severity && d.message.find(part) != std::string::npos) return &d;
    }
    return nullptr;
}

/// Number of diagnostics of `severity` whose message contains `part`.
inline std::size_t count(const Diagnostics& diagnostics, std::string_view part,
                         Diagnostic::Severity severity = Diagnostic::Severity::error) {
    std::size_t n = 0;
    for (const Diagnostic& d : diagnostics.items()) {
        if (d.severity == severity && d.message.find(part) != std::string::npos) ++n;
    }
    return n;
}

/// Asserts that an error (or warning) containing `part` exists, at `line` with element
/// path `element`, in `file`.
inline void expect_diagnostic(const Read& read, std::string_view part, int line,
                              std::string_view element,
                              Diagnostic::Severity severity = Diagnostic::Severity::error) {
    const Diagnostic* d = find(read.diagnostics, part, severity);
    ASSERT_NE(d, nullptr) << "no diagnostic containing \"" << part << "\" in:\n"
                          << dump(read.diagnostics);
    EXPECT_EQ(d->where.file, read.file);
    EXPECT_EQ(d->where.line, line) << d->text();
    EXPECT_EQ(d->where.element, element) << d->text();
}

/// A valid capture method (one Gaussian channel), on lines of its own.
inline constexpr const char* kCapture = R"(<capturemethod type="simple" name="Simple">
<imagefile areaunits="cm2" fluxunits="watts"><basename>out</basename><extension>img</extension><schedule>capture</schedule></imagefile>
<spectralresponse>
<bandpass spectralunits="microns"><minimum>0.4</minimum><maximum>0.7</maximum><delta>0.01</delta></bandpass>
<channellist><channel name="Green" shape="gaussian"><center>0.55</center><width>0.04</width></channel></channellist>
</spectralresponse>
<temporalintegration tdi="false"><time>0.001</time><samples>1</samples></temporalintegration>
</capturemethod>
)";

/// A valid detector array of 4 x 3 elements of 10 µm on a 10 Hz independent clock.
inline constexpr const char* kDetector = R"(<detectorarray spatialunits="microns">
<clock type="independent" temporalunits="hertz"><rate>10</rate><offset>0</offset></clock>
<xelementcount>4</xelementcount>
<yelementcount>3</yelementcount>
<xelementspacing>10</xelementspacing>
<yelementspacing>10</yelementspacing>
</detectorarray>
)";

/// A platform with one attachment holding `instrument` directly, after `clocktable`.
inline std::string with_instrument(const std::string& instrument,
                                   const std::string& clocktable = "<clocktable/>") {
    return "<platform>\n" + clocktable + "\n<attachment>\n<affinetransform/>\n" + instrument +
           "\n</attachment>\n</platform>\n";
}

/// A generic instrument "Cam" (focal length 50 mm) with one focal plane "FP" built from
/// `body` (defaults: the valid capture method and detector array).
inline std::string with_focal_plane(const std::string& body,
                                    const std::string& clocktable = "<clocktable/>") {
    return with_instrument(
        "<instrument name=\"Cam\" type=\"generic\">\n"
        "<properties><focallength>50</focallength></properties>\n"
        "<focalplane name=\"FP\">\n" +
            body + "\n</focalplane>\n</instrument>",
        clocktable);
}

/// A focal plane with the valid capture method and `detector` as its array.
inline std::string with_detector(const std::string& detector,
                                 const std::string& clocktable = "<clocktable/>") {
    return with_focal_plane(std::string(kCapture) + detector, clocktable);
}

/// A platform with one attachment holding `mount` (and nothing else).
inline std::string with_mount(const std::string& mount) {
    return "<platform>\n<clocktable/>\n<attachment>\n<affinetransform/>\n" + mount +
           "\n</attachment>\n</platform>\n";
}

/// Element path prefixes of the fragments above.
inline constexpr const char* kInstrumentPath = "platform/attachment/instrument[Cam]";
inline constexpr const char* kFocalPlanePath = "platform/attachment/instrument[Cam]/focalplane[FP]";
inline constexpr const char* kDetectorPath =
    "platform/attachment/instrument[Cam]/focalplane[FP]/detectorarray";

}  // namespace glint::test::plat
