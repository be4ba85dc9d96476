// SPDX-License-Identifier: Apache-2.0
// read_schedule_selection: the capture indices of a glint-schedule JSON file (--schedule).
#include <string>

#include <nlohmann/json.hpp>

#include "glint/core/error.h"
#include "glint/core/stdio_name.h"
#include "glint/core/text.h"
#include "glint/io/input_files.h"
#include "glint/sensor/render.h"

namespace glint::sensor {

namespace {

/// The largest schedule file read (2 GiB): a glint-schedule JSON of the 10⁶ captures one
/// render plans is about 1 GB; anything larger is not one.
constexpr std::size_t kMaxScheduleBytes = std::size_t{2} << 30;

}  // namespace

std::set<std::uint64_t> read_schedule_selection(const std::filesystem::path& file) {
    // "-": the schedule piped in (glint-schedule ... --format json | jq ... | glint-render
    // --schedule - ...).
    const bool piped = is_stdio_name(file);
    const std::string text =
        piped ? io::read_standard_input(kMaxScheduleBytes, "schedule")
              : io::read_input_file(file, file.string(), kMaxScheduleBytes, "schedule file");
    const ErrorContext where{piped ? io::kStandardInputName : file.string(), 0, {}};
    nlohmann::json json;
    try {
        json = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {  // parse_error, or out_of_range (1e999)
        throw input_error("not JSON: " + quote(e.what()), where);
    }
    if (!json.is_object() || json.value("format", "") != "glint-schedule") {
        throw input_error("not a glint-schedule file (expected \"format\": \"glint-schedule\"; "
                          "write one with glint-schedule --format json)",
                          where);
    }
    const auto captures = json.find("captures");
    if (captures == json.end() || !captures->is_array()) {
        throw input_error("the schedule has no \"captures\" array", where);
    }
    std::set<std::uint64_t> indices;
    for (std::size_t i = 0; i < captures->size(); ++i) {
        const nlohmann::json& capture = (*captures)[i];
        if (!capture.is_object() || !capture.contains("index") ||
            !capture["index"].is_number_unsigned()) {
            throw input_error("captures[" + std::to_string(i) +
                                  "] has no non-negative integer \"index\"",
                              where);
        }
        indices.insert(capture["index"].get<std::uint64_t>());
    }
    if (indices.empty()) throw input_error("the schedule selects no capture", where);
    return indices;
}

}  // namespace glint::sensor
