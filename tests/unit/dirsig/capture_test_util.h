// SPDX-License-Identifier: Apache-2.0
// Helpers for the capture-method reader tests: read a `<capturemethod>` (or a `<focalplane>`
// holding one) from an XML string through the detail:: functions, and assert that a
// diagnostic with a given message sits on the line of a given piece of the text and names
// the expected element path.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "../../../lib/dirsig/src/platform_parts.h"
#include "glint/core/diagnostics.h"
#include "glint/dirsig/readers.h"
#include "glint/io/xml.h"
#include "glint/model/platform.h"

namespace glint::test {

inline constexpr const char* kCaptureFile = "test.platform";
inline constexpr const char* kBaseDir = "/data/platforms";

/// A valid bandpass (0.4–0.7 µm at 0.01) and one Gaussian channel, to wrap a test around.
inline constexpr const char* kBandpass =
    "<bandpass><minimum>0.4</minimum><maximum>0.7</maximum><delta>0.01</delta></bandpass>";
inline constexpr const char* kOneChannel =
    "<channellist><channel name=\"G\"><center>0.55</center><width>0.04</width></channel>"
    "</channellist>";

/// A capture method with a valid image file and spectral response plus `extra` children.
/// Line 1 holds the opening tag; each piece starts on its own line.
inline std::string capture_xml(std::string_view extra,
                               std::string_view spectral = std::string_view(),
                               std::string_view attributes = "type=\"simple\" name=\"C\"") {
    std::string text = "<capturemethod " + std::string(attributes) + ">\n";
    text += "<imagefile><basename>out</basename></imagefile>\n";
    text += "<spectralresponse>\n";
    if (spectral.empty()) {
        text += std::string(kBandpass) + "\n" + kOneChannel + "\n";
    } else {
        text += std::string(spectral) + "\n";
    }
    text += "</spectralresponse>\n";
    text += std::string(extra) + "\n</capturemethod>\n";
    return text;
}

/// What a read produced.
struct CaptureRead {
    std::string xml;
    model::CaptureMethod capture;
    model::FocalPlane focal_plane;
    Diagnostics diagnostics;
};

/// Options whose path resolver sees no environment variables.
inline const dirsig::ReadOptions& test_read_options() {
    static const dirsig::ReadOptions options = [] {
        dirsig::ReadOptions o;
        o.paths.environment = [](const std::string&) -> std::optional<std::string> {
            return std::nullopt;
        };
        return o;
    }();
    return options;
}

/// Reads `xml` whose root is `<capturemethod>`.
inline CaptureRead read_capture(std::string xml) {
    CaptureRead result;
    result.xml = std::move(xml);
    const auto doc = io::XmlDocument::parse(result.xml, kCaptureFile);
    const dirsig::detail::ReadContext context{test_read_options(), kBaseDir};
    result.capture =
        dirsig::detail::read_capture_method(doc.root("capturemethod"), context, result.diagnostics);
    return result;
}

/// Reads `xml` whose root is `<focalplane>` holding a `<capturemethod>` (and maybe extras),
/// with a detector array of `rows` rows, and runs check_focal_plane.
inline CaptureRead read_focal_plane(std::string xml, std::size_t rows = 48) {
    CaptureRead result;
    result.xml = std::move(xml);
    const auto doc = io::XmlDocument::parse(result.xml, kCaptureFile);
    const dirsig::detail::ReadContext context{test_read_options(), kBaseDir};
    const auto root = doc.root("focalplane");
    auto& plane = result.focal_plane;
    plane.where = root.where();
    if (const auto capture = root.child("capturemethod")) {
        plane.capture_method =
            dirsig::detail::read_capture_method(*capture, context, result.diagnostics);
    }
    dirsig::detail::read_focal_plane_extras(root, plane.capture_method, context,
                                            result.diagnostics);
    plane.detector_array.x_count = 64;
    plane.detector_array.y_count = rows;
    dirsig::detail::check_focal_plane(plane, result.diagnostics);
    result.capture = plane.capture_method;
    return result;
}

/// 1-based line of the first occurrence of `needle` in `text` (0 when absent).
inline int line_of(std::string_view text, std::string_view needle) {
    const auto at = text.find(needle);
    if (at == std::string_view::npos) return 0;
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

inline std::string list_diagnostics(const Diagnostics& diagnostics) {
    std::string text;
    for (const auto& item : diagnostics.items()) {
        text += (item.severity == Diagnostic::Severity::error ? "  error: " : "  warning: ");
        text += item.text() + "\n";
    }
    return text.empty() ? "  (no diagnostics)\n" : text;
}

/// A diagnostic of `severity` whose message contains `message`, on the line where `at`
/// first occurs in the XML, naming `element` as its path.
inline ::testing::AssertionResult has_diagnostic(const CaptureRead& read,
                                                 Diagnostic::Severity severity,
                                                 std::string_view message, std::string_view at,
                                                 std::string_view element) {
    const int line = line_of(read.xml, at);
    for (const auto& item : read.diagnostics.items()) {
        if (item.severity != severity || item.message.find(message) == std::string::npos) {
            continue;
        }
        if (item.where.line == line && item.where.element == element &&
            item.where.file == kCaptureFile) {
            return ::testing::AssertionSuccess();
        }
    }
    return ::testing::AssertionFailure()
           << "no " << (severity == Diagnostic::Severity::error ? "error" : "warning")
           << " containing \"" << message << "\" at " << kCaptureFile << ":" << line << " "
           << element << "; got:\n"
           << list_diagnostics(read.diagnostics);
}

inline ::testing::AssertionResult has_error(const CaptureRead& read, std::string_view message,
                                            std::string_view at, std::string_view element) {
    return has_diagnostic(read, Diagnostic::Severity::error, message, at, element);
}

inline ::testing::AssertionResult has_warning(const CaptureRead& read, std::string_view message,
                                              std::string_view at, std::string_view element) {
    return has_diagnostic(read, Diagnostic::Severity::warning, message, at, element);
}

/// No diagnostics at all.
inline ::testing::AssertionResult clean(const CaptureRead& read) {
    if (read.diagnostics.items().empty()) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "unexpected diagnostics:\n"
                                         << list_diagnostics(read.diagnostics);
}

/// A platform fixture of tests/data/platform read with dirsig::read_platform.
struct PlatformRead {
    model::Platform platform;
    Diagnostics diagnostics;
};

inline PlatformRead read_platform_fixture(const std::string& name) {
    PlatformRead read;
    const auto file = std::filesystem::path(GLINT_TEST_DATA_DIR) / "platform" / name;
    read.platform = dirsig::read_platform(file, test_read_options(), read.diagnostics);
    return read;
}

/// Every focal plane of the platform, in document order.
inline std::vector<const model::FocalPlane*> focal_planes(const model::Platform& platform) {
    std::vector<const model::FocalPlane*> planes;
    for (const auto& path : model::list_instruments(platform)) {
        for (const auto& plane : path.instrument->focal_planes) planes.push_back(&plane);
    }
    return planes;
}

}  // namespace glint::test
