// SPDX-License-Identifier: Apache-2.0
// The `.platform` reader's entry point: loads the XML, reads the metadata, the clock table
// and the attachment tree (affine transforms here; mounts, instruments, detector arrays and
// capture methods in their own files), then checks what needs the whole file (synchronous
// clocks naming a master of the clock table). Every problem goes to the Diagnostics.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "glint/core/text.h"
#include "glint/core/units.h"
#include "glint/dirsig/readers.h"
#include "motion_parts.h"
#include "platform_tree.h"

namespace glint::dirsig {

namespace detail {

std::string trimmed(std::string_view text) {
    std::size_t begin = 0;
    std::size_t end = text.size();
    while (begin < end && std::isspace(static_cast<unsigned char>(text[begin]))) ++begin;
    while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
    return std::string(text.substr(begin, end - begin));
}

std::string lower_trimmed(std::string_view text) {
    std::string out = trimmed(text);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::string number_text(double value) { return format_shortest(value); }

double angular_unit_factor(const io::XmlNode& node, Diagnostics& diagnostics) {
    return angle_unit_factor(node, "angularunits", deg_to_rad(1.0), diagnostics);
}

std::string read_rotation_order(const io::XmlNode& node, Diagnostics& diagnostics) {
    const std::optional<std::string> raw = node.attribute("rotationorder");
    if (!raw) return "xyz";
    std::string order = lower_trimmed(*raw);
    std::string sorted = order;
    std::sort(sorted.begin(), sorted.end());
    if (sorted == "xyz") return order;
    diagnostics.error(node.where_attribute("rotationorder"),
                      "rotationorder \"" + *raw +
                          "\" is not a permutation of xyz, expected xyz, xzy, yxz, yzx, zxy "
                          "or zyx");
    return "xyz";
}

std::array<double, 3> read_triplet(const io::XmlNode& node,
                                   const std::array<std::string_view, 3>& names, double factor,
                                   Diagnostics& diagnostics) {
    std::array<double, 3> out{0, 0, 0};
    for (std::size_t i = 0; i < 3; ++i) {
        out[i] = node.optional_double(names[i], diagnostics).value_or(0.0) * factor;
    }
    return out;
}

std::optional<double> read_either(const io::XmlNode& node, std::string_view first,
                                  std::string_view second, Diagnostics& diagnostics,
                                  io::NumberRule rule) {
    const std::optional<io::XmlNode> a = node.child(first);
    const std::optional<io::XmlNode> b = node.child(second);
    if (a && b) {
        diagnostics.error(b->where(), "both <" + std::string(first) + "> and <" +
                                          std::string(second) +
                                          "> given, expected only one of the two spellings");
    }
    if (a) return node.optional_double(first, diagnostics, rule);
    if (b) return node.optional_double(second, diagnostics, rule);
    return std::nullopt;
}

void warn_not_used(const io::XmlNode& node, Diagnostics& diagnostics) {
    diagnostics.warning(node.where(), "<" + node.name() + "> is parsed but not used yet");
}

namespace {

/// `<matrix>`: 16 numbers (blank or comma separated), row-major, last row 0 0 0 1.
std::optional<std::array<double, 16>> read_matrix(const io::XmlNode& node,
                                                  Diagnostics& diagnostics) {
    std::string text = node.text();
    std::replace(text.begin(), text.end(), ',', ' ');
    std::vector<double> values;
    std::size_t pos = 0;
    while (pos < text.size()) {
        while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
        std::size_t end = pos;
        while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end]))) ++end;
        if (end == pos) break;
        const std::string token = text.substr(pos, end - pos);
        const std::optional<double> value = parse_double(token);
        if (!value) {
            diagnostics.error(node.where(), "\"" + token +
                                                "\" is not a number, expected 16 numbers "
                                                "(a row-major 4x4 matrix)");
            return std::nullopt;
        }
        values.push_back(*value);
        pos = end;
    }
    if (values.size() != 16) {
        diagnostics.error(node.where(), "matrix has " + std::to_string(values.size()) +
                                            " values, expected 16 (a row-major 4x4 matrix)");
        return std::nullopt;
    }
    std::array<double, 16> matrix{};
    std::copy(values.begin(), values.end(), matrix.begin());
    if (matrix[12] != 0.0 || matrix[13] != 0.0 || matrix[14] != 0.0 || matrix[15] != 1.0) {
        diagnostics.error(node.where(),
                          "matrix last row is " + number_text(matrix[12]) + " " +
                              number_text(matrix[13]) + " " + number_text(matrix[14]) + " " +
                              number_text(matrix[15]) + ", expected 0 0 0 1 (an affine transform)");
        return std::nullopt;
    }
    return matrix;
}

/// `<affinetransform>`: empty = identity; x/y/z translate (m), x/y/z rotate (angularunits)
/// with @rotationorder, or a `<matrix>`.
model::AffineTransform read_affine_transform(const io::XmlNode& node, Diagnostics& diagnostics) {
    model::AffineTransform transform;
    transform.where = node.where();
    const double factor = angular_unit_factor(node, diagnostics);
    transform.rotation_order = read_rotation_order(node, diagnostics);
    static constexpr std::array<std::string_view, 3> kTranslate = {"xtranslate", "ytranslate",
                                                                   "ztranslate"};
    static constexpr std::array<std::string_view, 3> kTranslation = {"xtranslation", "ytranslation",
                                                                     "ztranslation"};
    static constexpr std::array<std::string_view, 3> kRotate = {"xrotate", "yrotate", "zrotate"};
    static constexpr std::array<std::string_view, 3> kRotation = {"xrotation", "yrotation",
                                                                  "zrotation"};
    bool has_parts = false;
    for (std::size_t i = 0; i < 3; ++i) {
        if (auto t = read_either(node, kTranslate[i], kTranslation[i], diagnostics)) {
            transform.translation_m[i] = *t;
        }
        if (auto r = read_either(node, kRotate[i], kRotation[i], diagnostics)) {
            transform.rotation_rad[i] = *r * factor;
        }
        has_parts = has_parts || node.child(kTranslate[i]) || node.child(kTranslation[i]) ||
                    node.child(kRotate[i]) || node.child(kRotation[i]);
    }
    if (const std::optional<io::XmlNode> matrix = node.child("matrix")) {
        if (has_parts) {
            diagnostics.error(matrix->where(),
                              "<matrix> given together with translations or rotations, expected "
                              "either a matrix or translations/rotations");
        }
        transform.matrix = read_matrix(*matrix, diagnostics);
    }
    node.warn_unknown_children(
        {"xtranslate", "ytranslate", "ztranslate", "xtranslation", "ytranslation", "ztranslation",
         "xrotate", "yrotate", "zrotate", "xrotation", "yrotation", "zrotation", "matrix"},
        diagnostics);
    return transform;
}

model::Metadata read_metadata(const io::XmlNode& node, Diagnostics& diagnostics) {
    model::Metadata metadata;
    for (const io::XmlNode& entry : node.children("entry")) {
        std::string name = entry.required_text("name", diagnostics);
        std::string value = entry.optional_text("value").value_or("");
        entry.warn_unknown_children({"name", "value"}, diagnostics);
        metadata.entries.emplace_back(std::move(name), std::move(value));
    }
    node.warn_unknown_children({"entry"}, diagnostics);
    return metadata;
}

std::vector<model::MasterClock> read_clock_table(const io::XmlNode& node,
                                                 Diagnostics& diagnostics) {
    std::vector<model::MasterClock> clocks;
    for (const io::XmlNode& child : node.children("clock")) {
        model::MasterClock clock = detail::read_master_clock(child, diagnostics);
        const auto same = std::find_if(clocks.begin(), clocks.end(), [&](const auto& other) {
            return !clock.name.empty() && other.name == clock.name;
        });
        if (same != clocks.end()) {
            diagnostics.error(clock.where, "clock \"" + clock.name +
                                               "\" is defined twice in the clocktable (first at "
                                               "line " +
                                               std::to_string(same->where.line) +
                                               "), expected unique names");
            continue;
        }
        clocks.push_back(std::move(clock));
    }
    node.warn_unknown_children({"clock"}, diagnostics);
    return clocks;
}

/// Synchronous focal-plane clocks must name a clock of the clock table.
void check_masters(const model::Platform& platform, Diagnostics& diagnostics) {
    std::string known;
    for (const model::MasterClock& clock : platform.clock_table) {
        known += (known.empty() ? "" : ", ") + clock.name;
    }
    for (const model::InstrumentPath& path : model::list_instruments(platform)) {
        for (const model::FocalPlane& plane : path.instrument->focal_planes) {
            const model::Clock& clock = plane.detector_array.clock;
            if (clock.type != model::ClockType::synchronous || clock.master.empty()) continue;
            const bool found =
                std::any_of(platform.clock_table.begin(), platform.clock_table.end(),
                            [&](const auto& master) { return master.name == clock.master; });
            if (found) continue;
            diagnostics.error(clock.where,
                              "synchronous clock names master \"" + clock.master +
                                  "\", which is not in the <clocktable> (" +
                                  (known.empty() ? "the clocktable is empty" : "it has " + known) +
                                  ")");
        }
    }
}

}  // namespace

model::Attachment read_attachment(const io::XmlNode& node, const ReadContext& context,
                                  Diagnostics& diagnostics) {
    model::Attachment attachment;
    attachment.where = node.where();
    attachment.transform.where = node.where();
    const std::vector<io::XmlNode> transforms = node.children("affinetransform");
    if (!transforms.empty())
        attachment.transform = read_affine_transform(transforms[0], diagnostics);
    if (transforms.size() > 1) {
        diagnostics.error(transforms[1].where(),
                          "more than one <affinetransform> in an <attachment>, expected at most "
                          "one");
    }
    for (const io::XmlNode& child : node.children()) {
        if (child.name() == "mount") {
            attachment.mounts.push_back(read_mount(child, context, diagnostics));
        } else if (child.name() == "instrument") {
            attachment.instruments.push_back(read_instrument(child, context, diagnostics));
        }
    }
    node.warn_unknown_children({"affinetransform", "mount", "instrument"}, diagnostics);
    if (attachment.mounts.empty() && attachment.instruments.empty()) {
        diagnostics.warning(node.where(), "attachment holds no mount and no instrument");
    }
    return attachment;
}

}  // namespace detail

model::Platform read_platform(const std::filesystem::path& file, const ReadOptions& options,
                              Diagnostics& diagnostics) {
    model::Platform platform;
    platform.file = file.string();
    std::error_code ec;
    const std::filesystem::path absolute = std::filesystem::absolute(file, ec);
    const detail::ReadContext context{options, (ec ? file : absolute).parent_path()};
    try {
        const io::XmlDocument document =
            io::XmlDocument::parse(options.read_text(file, file.string()), file.string());
        const io::XmlNode root = document.root("platform");
        if (const std::optional<io::XmlNode> metadata = root.child("metadata")) {
            platform.metadata = detail::read_metadata(*metadata, diagnostics);
        }
        if (const std::optional<io::XmlNode> table = root.child("clocktable")) {
            platform.clock_table = detail::read_clock_table(*table, diagnostics);
        }
        for (const io::XmlNode& child : root.children()) {
            if (child.name() == "attachment") {
                platform.attachments.push_back(
                    detail::read_attachment(child, context, diagnostics));
            } else if ((child.name() == "rotationdeviates" || child.name() == "locationdeviates" ||
                        child.name() == "uncertainty") &&
                       !child.children().empty()) {
                diagnostics.warning(child.where(), "platform-level <" + child.name() +
                                                       "> (vehicle jitter) is not supported yet; "
                                                       "ignored");
            }
        }
        root.warn_unknown_children({"metadata", "clocktable", "attachment", "rotationdeviates",
                                    "locationdeviates", "uncertainty"},
                                   diagnostics);
        if (platform.attachments.empty()) {
            diagnostics.warning(root.where(), "platform has no <attachment>: no instruments");
        }
        detail::check_masters(platform, diagnostics);
        document.warn_unread(diagnostics);
    } catch (const Error& error) {
        diagnostics.add(error);
    }
    return platform;
}

}  // namespace glint::dirsig
