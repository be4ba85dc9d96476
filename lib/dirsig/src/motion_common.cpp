// SPDX-License-Identifier: Apache-2.0
// The motion file entry point (read_motion: `.ppd` or `.motion` by root element) and the
// parts the GenericMotion and FlexMotion readers share: unit attributes, locations, direction
// hints, CDATA data tables reported row by row at their own file lines, the time-order
// check. The platform jitter elements are read in jitter_reader.cpp.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "glint/core/text.h"
#include "glint/core/units.h"
#include "motion_parts.h"
#include "platform_tree.h"

namespace glint::dirsig::detail {

namespace {

constexpr double kMetresPerFoot = 0.3048;

/// The 1-based file line on which the text content of `element` starts (after blanks,
/// a CDATA opener and comments), found by scanning `source` from the element's start tag;
/// 0 when it cannot be told (no source, or the tag is not where the parser said).
int first_text_line(std::string_view source, const io::XmlNode& element) {
    if (source.empty() || element.line() <= 0) return 0;
    std::size_t pos = 0;
    int line = 1;
    while (line < element.line()) {
        pos = source.find('\n', pos);
        if (pos == std::string_view::npos) return 0;
        ++pos;
        ++line;
    }
    const std::string tag = "<" + element.name();
    const std::size_t start = source.find(tag, pos);
    if (start == std::string_view::npos) return 0;
    line += static_cast<int>(std::count(source.begin() + static_cast<std::ptrdiff_t>(pos),
                                        source.begin() + static_cast<std::ptrdiff_t>(start), '\n'));
    char quote = 0;
    for (pos = start + tag.size(); pos < source.size(); ++pos) {
        const char c = source[pos];
        if (c == '\n') ++line;
        if (quote != 0) {
            if (c == quote) quote = 0;
        } else if (c == '"' || c == '\'') {
            quote = c;
        } else if (c == '>') {
            break;
        }
    }
    if (pos >= source.size() || source[pos - 1] == '/') return 0;
    ++pos;
    while (pos < source.size()) {
        const char c = source[pos];
        if (c == '\n') {
            ++line;
            ++pos;
        } else if (is_blank(c)) {
            ++pos;
        } else if (source.substr(pos, 9) == "<![CDATA[") {
            pos += 9;
        } else if (source.substr(pos, 4) == "<!--") {
            const std::size_t end = source.find("-->", pos);
            if (end == std::string_view::npos) return 0;
            line += static_cast<int>(std::count(source.begin() + static_cast<std::ptrdiff_t>(pos),
                                                source.begin() + static_cast<std::ptrdiff_t>(end),
                                                '\n'));
            pos = end + 3;
        } else {
            break;
        }
    }
    return line;
}

/// Splits one table line on `delimiter` (blank delimiters: on runs of blanks), trimming items.
std::vector<std::string> split_fields(std::string_view line, char delimiter) {
    std::vector<std::string> out;
    if (delimiter == ' ' || delimiter == '\t') {
        std::size_t pos = 0;
        while (pos < line.size()) {
            while (pos < line.size() && is_blank(line[pos])) ++pos;
            std::size_t end = pos;
            while (end < line.size() && !is_blank(line[end])) ++end;
            if (end > pos) out.emplace_back(line.substr(pos, end - pos));
            pos = end;
        }
        return out;
    }
    std::size_t pos = 0;
    while (true) {
        const std::size_t end = line.find(delimiter, pos);
        out.push_back(trimmed(line.substr(pos, end == std::string_view::npos ? end : end - pos)));
        if (end == std::string_view::npos) break;
        pos = end + 1;
    }
    return out;
}

/// "\",\"" or "a blank" for messages about the delimiter.
std::string delimiter_text(char delimiter) {
    if (delimiter == ' ') return "blanks";
    if (delimiter == '\t') return "tabs";
    return "\"" + std::string(1, delimiter) + "\"";
}

/// The table delimiter of `data` (default ','); an invalid one is an error (nullopt).
std::optional<char> read_delimiter(const io::XmlNode& data, Diagnostics& diagnostics) {
    const std::optional<std::string> raw = data.attribute("delimiter");
    if (!raw) return ',';
    const std::string& d = *raw;
    const bool single = d.size() == 1;
    const unsigned char c = single ? static_cast<unsigned char>(d[0]) : 0;
    if (single && c >= 0x20 && c < 0x7f && !std::isalnum(c) && c != '.' && c != '+' && c != '-') {
        return static_cast<char>(c);
    }
    if (single && c == '\t') return '\t';
    diagnostics.error(data.where_attribute("delimiter"),
                      "delimiter \"" + d +
                          "\" is not one character other than a digit, letter, '.', '+' or '-', "
                          "expected e.g. \",\"");
    return std::nullopt;
}

}  // namespace

double length_unit_factor(const io::XmlNode& node, std::string_view attribute, double fallback,
                          Diagnostics& diagnostics) {
    const std::optional<std::string> raw = node.attribute(attribute);
    if (!raw) return fallback;
    const std::string units = lower_trimmed(*raw);
    if (units == "meters" || units == "metres" || units == "meter" || units == "m") return 1.0;
    if (units == "kilometers" || units == "kilometres" || units == "km") return 1000.0;
    if (units == "feet" || units == "foot" || units == "ft") return kMetresPerFoot;
    diagnostics.error(node.where_attribute(attribute),
                      "unknown " + std::string(attribute) + " \"" + *raw +
                          "\", expected meters, kilometers or feet");
    return fallback;
}

double angle_unit_factor(const io::XmlNode& node, std::string_view attribute, double fallback,
                         Diagnostics& diagnostics) {
    const std::optional<std::string> raw = node.attribute(attribute);
    if (!raw) return fallback;
    const std::string units = lower_trimmed(*raw);
    if (units == "degrees" || units == "degree" || units == "deg") return deg_to_rad(1.0);
    if (units == "radians" || units == "radian" || units == "rad") return 1.0;
    diagnostics.error(
        node.where_attribute(attribute),
        "unknown " + std::string(attribute) + " \"" + *raw + "\", expected degrees or radians");
    return fallback;
}

std::optional<std::vector<double>> parse_number_list(std::string_view text) {
    std::string copy(text);
    std::replace(copy.begin(), copy.end(), ',', ' ');
    std::vector<double> values;
    for (const std::string& item : split_fields(copy, ' ')) {
        const std::optional<double> value = parse_double(item);
        if (!value) return std::nullopt;
        values.push_back(*value);
    }
    return values;
}

std::optional<model::Location> read_location(const io::XmlNode& node, double length_factor,
                                             Diagnostics& diagnostics) {
    model::Location location;
    location.where = node.where();
    const std::optional<std::string> frame_attr = node.attribute("frame");
    const std::optional<std::string> type_attr = node.attribute("type");
    if (frame_attr && type_attr && lower_trimmed(*frame_attr) != lower_trimmed(*type_attr)) {
        diagnostics.error(node.where_attribute("type"), "@frame \"" + *frame_attr +
                                                            "\" and @type \"" + *type_attr +
                                                            "\" disagree, expected one frame");
        return std::nullopt;
    }
    const std::string attribute = frame_attr ? "frame" : "type";
    if (frame_attr || type_attr) {
        const std::string raw = frame_attr ? *frame_attr : *type_attr;
        const std::string frame = lower_trimmed(raw);
        if (frame == "scene") {
            location.frame = model::LocationFrame::scene;
        } else if (frame == "ecef") {
            location.frame = model::LocationFrame::ecef;
        } else if (frame == "geodetic") {
            location.frame = model::LocationFrame::geodetic;
        } else {
            diagnostics.error(
                node.where_attribute(attribute),
                "unknown location frame \"" + raw + "\", expected scene, ecef or geodetic");
            return std::nullopt;
        }
    }

    const bool geodetic = location.frame == model::LocationFrame::geodetic;
    const std::array<std::string_view, 3> names =
        geodetic ? std::array<std::string_view, 3>{"latitude", "longitude", "altitude"}
                 : std::array<std::string_view, 3>{"x", "y", "z"};
    const std::optional<io::XmlNode> point = geodetic ? std::nullopt : node.child("point");
    const io::XmlNode& source = point ? *point : node;
    std::array<std::optional<double>, 3> values;
    const bool has_children =
        source.child(names[0]) || source.child(names[1]) || source.child(names[2]);
    const std::string expected =
        geodetic ? "<latitude>, <longitude>, <altitude> children or the text \"lat, lon, alt\""
                 : "<point> with <x>, <y>, <z> children, or the text \"x, y, z\"";
    if (has_children) {
        source.warn_unknown_children({names[0], names[1], names[2]}, diagnostics);
        const std::array<io::NumberRule, 3> rules = {
            geodetic ? io::NumberRule::range(-90.0, 90.0) : io::NumberRule::any(),
            geodetic ? io::NumberRule::range(-360.0, 360.0) : io::NumberRule::any(),
            io::NumberRule::any()};
        for (std::size_t i = 0; i < 3; ++i) {
            values[i] = source.required_double(names[i], diagnostics, rules[i]);
        }
    } else if (!source.text().empty()) {
        const std::optional<std::vector<double>> list = parse_number_list(source.text());
        if (!list || list->size() != 3) {
            diagnostics.error(source.where(),
                              "\"" + source.text() + "\" is not a location, expected " + expected);
            return std::nullopt;
        }
        for (std::size_t i = 0; i < 3; ++i) values[i] = (*list)[i];
        if (geodetic && std::abs((*list)[0]) > 90.0) {
            diagnostics.error(source.where(), "latitude " + number_text((*list)[0]) +
                                                  " is out of range, expected a number in [-90, "
                                                  "90] degrees");
            return std::nullopt;
        }
        if (geodetic && std::abs((*list)[1]) > 360.0) {
            diagnostics.error(source.where(), "longitude " + number_text((*list)[1]) +
                                                  " is out of range, expected a number in "
                                                  "[-360, 360] degrees");
            return std::nullopt;
        }
    } else {
        diagnostics.error(source.where(), "missing location, expected " + expected);
        return std::nullopt;
    }
    if (!values[0] || !values[1] || !values[2]) return std::nullopt;
    if (geodetic) {
        location.latitude_deg = *values[0];
        location.longitude_deg = *values[1];
        location.altitude_m = *values[2] * length_factor;
    } else {
        location.xyz_m = {*values[0] * length_factor, *values[1] * length_factor,
                          *values[2] * length_factor};
    }
    return location;
}

model::DirectionHint read_direction_hint(const io::XmlNode& node, bool allow_velocity,
                                         Diagnostics& diagnostics) {
    model::DirectionHint hint;
    hint.where = node.where();
    if (const std::optional<std::string> raw = node.attribute("type")) {
        const std::string type = lower_trimmed(*raw);
        if (type == "constant") {
            hint.type = model::DirectionType::constant;
        } else if (type == "velocity" && allow_velocity) {
            hint.type = model::DirectionType::velocity;
        } else {
            diagnostics.error(node.where_attribute("type"),
                              "unknown <" + node.name() + "> type \"" + *raw + "\", expected " +
                                  (allow_velocity ? "constant or velocity" : "constant"));
        }
    }
    if (const std::optional<std::string> raw = node.attribute("frame")) {
        const std::string frame = lower_trimmed(*raw);
        if (frame == "scene") {
            hint.frame = model::LocationFrame::scene;
        } else if (frame == "ecef") {
            hint.frame = model::LocationFrame::ecef;
        } else {
            diagnostics.error(node.where_attribute("frame"),
                              "unknown direction frame \"" + *raw + "\", expected scene or ecef");
        }
    }
    const std::optional<std::string> attribute = node.attribute("vector");
    const std::string text = attribute ? *attribute : node.text();
    if (hint.type == model::DirectionType::velocity) {
        if (!text.empty()) {
            diagnostics.warning(attribute ? node.where_attribute("vector") : node.where(),
                                "a vector is ignored for type=\"velocity\"");
        }
        return hint;
    }
    if (text.empty()) return hint;  // default 0,0,1
    const ErrorContext where = attribute ? node.where_attribute("vector") : node.where();
    const std::optional<std::vector<double>> list = parse_number_list(text);
    if (!list || list->size() != 3) {
        diagnostics.error(where, "\"" + text + "\" is not a vector, expected \"x, y, z\"");
        return hint;
    }
    if ((*list)[0] == 0.0 && (*list)[1] == 0.0 && (*list)[2] == 0.0) {
        diagnostics.error(where, "the vector is zero, expected a direction");
        return hint;
    }
    hint.vector = {(*list)[0], (*list)[1], (*list)[2]};
    return hint;
}

std::optional<std::string> time_order_problem(std::string_view label, std::size_t index,
                                              double previous_s, double time_s) {
    const std::string name = std::string(label) + " " + std::to_string(index);
    const std::string before = std::string(label) + " " + std::to_string(index - 1);
    if (time_s == previous_s) {
        return name + " has the same time (" + number_text(time_s) + " s) as " + before +
               ": duplicate times, expected strictly increasing times";
    }
    if (time_s < previous_s) {
        return name + " time " + number_text(time_s) + " s is before " + before + "'s " +
               number_text(previous_s) + " s, expected strictly increasing times";
    }
    return std::nullopt;
}

std::vector<model::MotionTableRow> read_table(const io::XmlNode& data, std::size_t value_count,
                                              std::string_view columns,
                                              const MotionReadContext& context,
                                              Diagnostics& diagnostics) {
    std::vector<model::MotionTableRow> rows;
    if (const std::optional<std::string> raw = data.attribute("source")) {
        if (lower_trimmed(*raw) != "internal") {
            diagnostics.error(data.where_attribute("source"),
                              "data source \"" + *raw +
                                  "\" is not supported yet, expected internal (rows in the "
                                  "element's text)");
            return rows;
        }
    }
    if (const std::optional<std::string> raw = data.attribute("datetime")) {
        const std::string type = lower_trimmed(*raw);
        if (type == "absolute") {
            diagnostics.error(data.where_attribute("datetime"),
                              "absolute motion times need the tasks file's reference date and are "
                              "not supported yet, expected datetime=\"relative\" (seconds after "
                              "the reference time)");
            return rows;
        }
        if (type != "relative") {
            diagnostics.error(data.where_attribute("datetime"),
                              "unknown datetime type \"" + *raw + "\", expected relative");
            return rows;
        }
    }
    const std::optional<char> delimiter = read_delimiter(data, diagnostics);
    if (!delimiter) return rows;
    data.warn_unknown_children({}, diagnostics);

    const std::string text = data.text();
    const int first_line = first_text_line(context.source_text, data);
    std::size_t pos = 0;
    int line_index = 0;
    std::optional<double> previous;
    std::size_t row_number = 0;
    while (pos <= text.size() && !text.empty()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string::npos) end = text.size();
        const std::string line = trimmed(std::string_view(text).substr(pos, end - pos));
        const int file_line = first_line > 0 ? first_line + line_index : data.line();
        pos = end + 1;
        ++line_index;
        if (line.empty() || line[0] == '#') continue;
        ++row_number;
        const ErrorContext where{data.file(), file_line, data.path()};
        const std::string row = "row " + std::to_string(row_number);
        const std::vector<std::string> fields = split_fields(line, *delimiter);
        if (fields.size() != value_count + 1) {
            diagnostics.error(where, row + " has " + std::to_string(fields.size()) +
                                         " fields, expected " + std::to_string(value_count + 1) +
                                         " (" + std::string(columns) + ") separated by " +
                                         delimiter_text(*delimiter));
            continue;
        }
        model::MotionTableRow out;
        out.line = file_line;
        bool ok = true;
        for (std::size_t i = 0; i < fields.size(); ++i) {
            const std::optional<double> value = parse_double(fields[i]);
            if (!value) {
                diagnostics.error(where, row + " field " + std::to_string(i + 1) + " \"" +
                                             fields[i] + "\" is not a number, expected " +
                                             std::string(columns) + " separated by " +
                                             delimiter_text(*delimiter));
                ok = false;
                break;
            }
            if (i == 0) {
                out.time_s = *value;
            } else {
                out.values[i - 1] = *value;
            }
        }
        if (!ok) continue;
        if (previous) {
            if (auto problem = time_order_problem("row", row_number, *previous, out.time_s)) {
                diagnostics.error(where, *problem);
            }
        }
        previous = out.time_s;
        rows.push_back(out);
    }
    if (row_number == 0) {
        diagnostics.error(data.where(), "no rows in <" + data.name() + ">, expected lines of " +
                                            std::string(columns));
    }
    return rows;
}

}  // namespace glint::dirsig::detail

namespace glint::dirsig {

model::PlatformMotion read_motion(const std::filesystem::path& file, const ReadOptions& options,
                                  Diagnostics& diagnostics) {
    model::PlatformMotion motion;
    motion.file = file.string();
    try {
        const std::string text = options.read_text(file, motion.file);
        const io::XmlDocument document = io::XmlDocument::parse(text, motion.file);
        const io::XmlNode root = document.root();
        const MotionReadContext context{options, file.parent_path(), text};
        const std::optional<std::string> type = root.attribute("type");
        const std::string kind = type ? detail::lower_trimmed(*type) : std::string();
        if (root.name() == "platformmotion") {
            if (type && kind != "generic") {
                diagnostics.error(root.where_attribute("type"),
                                  "platformmotion type \"" + *type +
                                      "\" is not supported, expected generic (a .ppd)");
            } else {
                motion.generic = read_generic_motion(root, context, diagnostics);
            }
        } else if (root.name() == "motion") {
            if (kind != "flexible") {
                diagnostics.error(type ? root.where_attribute("type") : root.where(),
                                  type ? "motion type \"" + *type +
                                             "\" is not supported in a motion file, expected "
                                             "flexible (a FlexMotion .motion)"
                                       : "missing required attribute type, expected "
                                         "type=\"flexible\" (a FlexMotion .motion)");
            } else {
                motion.flexible = read_flex_motion(root, context, diagnostics);
            }
        } else {
            diagnostics.error(root.where(),
                              "expected root element <platformmotion> (GenericMotion "
                              ".ppd) or <motion> (FlexMotion .motion), got <" +
                                  root.name() + ">");
        }
        document.warn_unread(diagnostics);
    } catch (const Error& error) {
        diagnostics.add(error);
    }
    return motion;
}

}  // namespace glint::dirsig
