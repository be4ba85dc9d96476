// SPDX-License-Identifier: Apache-2.0
// read_schedule_file: a glint-schedule JSON file read by a SAX handler that keeps only what
// ScheduleFile holds (glint/inputs/schedule_file.h).
#include "glint/inputs/schedule_file.h"

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "glint/core/error.h"
#include "glint/core/stdio_name.h"
#include "glint/core/text.h"
#include "glint/io/input_files.h"

namespace glint::inputs {

namespace {

using Json = nlohmann::json;

/// Reads what ScheduleFile holds — the top-level "format", each captures[].index (and, when
/// asked, its files.image and files.truth[]), selection.shard and provenance.working_folder —
/// as the parser goes (SAX), without building the document: a glint-schedule JSON holds some
/// 2 kB per capture, and its document tree would take several times the text.
class ScheduleReader final : public nlohmann::json_sax<Json> {
public:
    explicit ScheduleReader(bool with_files) : m_with_files(with_files) {}

    std::optional<std::string> format;
    bool has_captures = false;
    bool captures_is_array = false;
    std::optional<std::size_t> bad_capture;  ///< the first capture without a valid index
    std::optional<std::string> parse_problem;
    std::vector<ScheduleFile::Capture> captures;
    std::optional<std::string> working_folder;
    /// selection.shard's index, count and by (a "rows" shard renders a band of lines).
    std::optional<std::uint64_t> shard_index;
    std::optional<std::uint64_t> shard_count;
    std::optional<std::string> shard_by;

    bool null() override { return scalar(); }
    bool boolean(bool) override { return scalar(); }
    bool number_integer(number_integer_t) override { return scalar(); }
    bool number_unsigned(number_unsigned_t value) override {
        if (in_capture() && m_key == "index") {
            captures.back().index = value;
            m_capture_has_index = true;
            return true;
        }
        if (m_depth == 3 && m_in_shard && m_key == "index") shard_index = value;
        if (m_depth == 3 && m_in_shard && m_key == "count") shard_count = value;
        return scalar();
    }
    bool number_float(number_float_t, const string_t&) override { return scalar(); }
    bool string(string_t& value) override {
        if (m_depth == 1 && m_key == "format") format = value;
        if (m_depth == 2 && m_in_provenance && m_key == "working_folder") working_folder = value;
        if (m_with_files && m_depth == 4 && m_in_files && m_key == "image") {
            captures.back().image = value;
        }
        if (m_with_files && m_depth == 5 && m_in_truth) captures.back().truth.push_back(value);
        if (m_depth == 3 && m_in_shard && m_key == "by") shard_by = value;
        return scalar();
    }
    bool binary(binary_t&) override { return scalar(); }
    bool key(string_t& value) override {
        m_key = value;
        return true;
    }
    bool start_object(std::size_t) override { return open(true); }
    bool end_object() override {
        if (in_capture() && !m_capture_has_index) note_bad_capture();
        return close();
    }
    bool start_array(std::size_t) override { return open(false); }
    bool end_array() override { return close(); }
    bool parse_error(std::size_t, const std::string&,
                     const nlohmann::detail::exception& error) override {
        parse_problem = error.what();
        return false;
    }

private:
    /// Inside a captures[] element (an object directly in the top-level "captures" array).
    bool in_capture() const { return m_depth == 3 && m_in_captures; }
    /// A direct element of the top-level "captures" array.
    bool at_capture_element() const { return m_depth == 2 && m_in_captures; }

    bool scalar() {
        if (m_depth == 1 && m_key == "captures") has_captures = true;
        if (at_capture_element()) {
            note_bad_capture();
            ++m_capture;
        }
        return true;
    }
    bool open(bool object) {
        if (m_depth == 1 && m_key == "captures") {
            has_captures = true;
            captures_is_array = !object;
            m_in_captures = !object;
        } else if (at_capture_element()) {
            if (!object) note_bad_capture();
            captures.emplace_back();
            m_capture_has_index = false;
        } else if (in_capture() && m_key == "files" && object) {
            m_in_files = true;
        } else if (m_depth == 4 && m_in_files && m_key == "truth" && !object) {
            m_in_truth = true;
        } else if (m_depth == 1 && m_key == "provenance" && object) {
            m_in_provenance = true;
        } else if (m_depth == 1 && m_key == "selection" && object) {
            m_in_selection = true;
        } else if (m_depth == 2 && m_in_selection && m_key == "shard" && object) {
            m_in_shard = true;
        }
        ++m_depth;
        m_key.clear();
        return true;
    }
    bool close() {
        --m_depth;
        if (at_capture_element()) ++m_capture;
        if (m_depth == 1) m_in_captures = false;
        if (m_depth == 1) m_in_selection = false;
        if (m_depth == 1) m_in_provenance = false;
        if (m_depth == 2) m_in_shard = false;
        if (m_depth == 3) m_in_files = false;
        if (m_depth == 4) m_in_truth = false;
        m_key.clear();
        return true;
    }
    void note_bad_capture() {
        if (!bad_capture) bad_capture = m_capture;
    }

    std::size_t m_depth = 0;  ///< containers open around the current value
    std::string m_key;        ///< the current object key at this depth
    bool m_in_captures = false;
    bool m_in_selection = false;   ///< inside the top-level "selection" object
    bool m_in_shard = false;       ///< inside selection.shard
    bool m_in_provenance = false;  ///< inside the top-level "provenance" object
    bool m_in_files = false;       ///< inside a capture's "files" object
    bool m_in_truth = false;       ///< inside its "truth" array
    bool m_with_files = false;     ///< keep the captures' files
    std::size_t m_capture = 0;     ///< index of the current captures[] element
    bool m_capture_has_index = false;
};

}  // namespace

ScheduleFile read_schedule_file(const std::filesystem::path& file, bool with_files) {
    // "-": the schedule piped in (glint-schedule ... --format json | jq ... | glint-render
    // --schedule - ...).
    const bool piped = is_stdio_name(file);
    const std::string text =
        piped ? io::read_standard_input(kMaxScheduleFileBytes, "schedule")
              : io::read_input_file(file, file.string(), kMaxScheduleFileBytes, "schedule file");
    const ErrorContext where{piped ? io::kStandardInputName : file.string(), 0, {}};
    ScheduleReader reader(with_files);
    if (!Json::sax_parse(text, &reader) || reader.parse_problem) {
        throw input_error("not JSON: " + quote(reader.parse_problem.value_or("parse error")),
                          where);
    }
    if (reader.format != "glint-schedule") {
        throw input_error(
            "not a glint-schedule file (expected \"format\": \"glint-schedule\"; "
            "write one with glint-schedule --format json)",
            where);
    }
    if (!reader.captures_is_array) {
        throw input_error("the schedule has no \"captures\" array", where);
    }
    if (reader.bad_capture) {
        throw input_error("captures[" + std::to_string(*reader.bad_capture) +
                              "] has no non-negative integer \"index\"",
                          where);
    }
    if (reader.captures.empty()) throw input_error("the schedule selects no capture", where);
    ScheduleFile schedule;
    schedule.captures = std::move(reader.captures);
    schedule.working_folder = std::move(reader.working_folder);
    if (reader.shard_by && *reader.shard_by != "captures") {
        if (*reader.shard_by != "rows") {
            throw input_error("selection.shard.by is " + quote(*reader.shard_by) +
                                  ", expected \"captures\" or \"rows\"",
                              where);
        }
        if (!reader.shard_index || !reader.shard_count || *reader.shard_index < 1 ||
            *reader.shard_index > *reader.shard_count) {
            throw input_error(
                "selection.shard of a row shard needs \"index\" K and \"count\" N with 1 <= K "
                "<= N",
                where);
        }
        schedule.row_shard = {*reader.shard_index, *reader.shard_count};
    }
    return schedule;
}

}  // namespace glint::inputs
