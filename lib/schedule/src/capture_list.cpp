// SPDX-License-Identifier: Apache-2.0
// The capture-list JSON stream (glint/schedule/capture_list.h).
#include "glint/schedule/capture_list.h"

#include <nlohmann/json.hpp>
#include <utility>

#include "glint/core/datetime.h"
#include "glint/core/json_text.h"
#include "glint/core/runner.h"

namespace glint::schedule {
namespace {

using Json = nlohmann::ordered_json;

Json path_json(const std::filesystem::path& path) {
    if (path.empty()) return nullptr;
    return path.generic_string();
}

}  // namespace

CaptureListWriter::CaptureListWriter(std::ostream& out, const Schedule& schedule,
                                     CaptureListProvenance provenance)
    : m_out(out), m_schedule(schedule), m_provenance(std::move(provenance)) {}

void CaptureListWriter::begin() {
    Json head;
    head["format"] = "glint-capture-list";
    head["version"] = 1;
    head["provenance"] = Json{{"tool", m_provenance.tool},
                              {"glint_version", version()},
                              {"arguments", m_provenance.arguments},
                              {"seed", m_provenance.seed}};
    head["run_info"] =
        Json{{"reference_date_time",
              m_schedule.plugins().empty()
                  ? Json(nullptr)
                  : Json(format_iso8601_utc(m_schedule.plugins()[0].tasks.reference, 6))},
             {"simulation_file", m_schedule.simulation_file().generic_string()}};
    std::string text = json_text(head, 2);
    text.resize(text.size() - 2);  // drop "\n}": more members follow
    m_out << text << ",\n  \"capture_list\": [";
}

void CaptureListWriter::add(const Capture& capture, const std::filesystem::path& image,
                            const std::vector<std::filesystem::path>& truth) {
    Json truth_json = Json::array();
    for (const auto& path : truth) truth_json.push_back(path.generic_string());
    Json j;
    j["task_index"] = capture.task_index;
    j["capture_index"] = capture.capture_index;
    j["relative_time_window"] = Json::array({capture.t0_s, capture.t1_s});
    j["plugin_data"] = Json{{"filename", path_json(image)}, {"truth_filenames", truth_json}};
    j["index"] = capture.index;
    j["plugin_index"] =
        m_schedule.plugins()[m_schedule.sources()[capture.source].plugin].plugin_index;
    m_out << (m_first ? "\n    " : ",\n    ") << json_text(j);
    m_first = false;
}

void CaptureListWriter::end() { m_out << "\n  ]\n}\n"; }

}  // namespace glint::schedule
