// SPDX-License-Identifier: Apache-2.0
// Reader of DIRSIG `.tasks` files: the reference date-time (ISO-8601 with UTC offset) and the
// collection windows, whose start and stop are seconds after the reference ("relative") or
// ISO-8601 date-times ("absolute") converted to seconds after the reference.
#include <charconv>
#include <optional>

#include "glint/core/datetime.h"
#include "glint/core/text.h"
#include "glint/dirsig/readers.h"
#include "glint/io/xml.h"

namespace glint::dirsig {
namespace {

/// A number of seconds for messages, in shortest round-trip form.
std::string seconds_text(double seconds) { return format_shortest(seconds) + " s"; }

/// A `<datetime>` as read: seconds after the reference and, when written absolute, the instant.
struct TimeValue {
    std::optional<double> seconds;    ///< relative to the reference
    std::optional<DateTime> instant;  ///< when written as an absolute date-time
};

/// Reads `<datetime>` under `parent`: relative seconds as written, absolute ISO-8601 as
/// seconds after `reference` (unknown when the reference could not be read). `absolute_only`
/// is for the reference itself, which must be absolute.
TimeValue read_datetime(const io::XmlNode& parent, bool absolute_only,
                        const std::optional<DateTime>& reference, Diagnostics& diagnostics) {
    TimeValue out;
    const auto node = parent.child("datetime");
    if (!node) {
        diagnostics.error(parent.where(), "missing required element <datetime>");
        return out;
    }
    node->warn_unknown_children({}, diagnostics);
    std::optional<std::string> type;
    if (node->attribute("type")) {
        type = absolute_only ? node->attribute_enum("type", {"absolute"}, diagnostics)
                             : node->attribute_enum("type", {"relative", "absolute"}, diagnostics);
        if (!type) return out;
    } else if (!absolute_only) {
        // No type: a plain number is relative, anything else must be a date-time.
        type = parse_double(node->text()) ? "relative" : "absolute";
    } else {
        type = "absolute";
    }

    if (*type == "relative") {
        out.seconds = node->own_double(diagnostics);
        return out;
    }
    try {
        out.instant = parse_iso8601(node->text(), node->where());
    } catch (const Error& error) {
        diagnostics.add(error);
        return out;
    }
    if (reference) out.seconds = seconds_between(*reference, *out.instant);
    return out;
}

model::Task read_task(const io::XmlNode& node, const std::optional<DateTime>& reference,
                      Diagnostics& diagnostics) {
    model::Task task;
    task.where = node.where();
    node.warn_unknown_children({"metadata", "start", "stop"}, diagnostics);

    if (const auto metadata = node.child("metadata")) {
        metadata->warn_unknown_children({"entry"}, diagnostics);
        model::Metadata entries;
        for (const io::XmlNode& entry : metadata->children("entry")) {
            entry.warn_unknown_children({"name", "value"}, diagnostics);
            const std::string name = entry.required_text("name", diagnostics);
            entries.entries.emplace_back(name, entry.optional_text("value").value_or(""));
        }
        task.name = entries.find("Name").value_or("");
        task.description = entries.find("Description").value_or("");
    }

    std::optional<double> start;
    std::optional<double> stop;
    const auto start_node = node.child("start");
    const auto stop_node = node.child("stop");
    if (start_node) {
        start_node->warn_unknown_children({"datetime"}, diagnostics);
        start = read_datetime(*start_node, false, reference, diagnostics).seconds;
    } else {
        diagnostics.error(node.where(), "missing required element <start>");
    }
    if (stop_node) {
        stop_node->warn_unknown_children({"datetime"}, diagnostics);
        stop = read_datetime(*stop_node, false, reference, diagnostics).seconds;
    } else {
        diagnostics.error(node.where(), "missing required element <stop>");
    }
    if (start && stop && *stop < *start) {
        diagnostics.error(stop_node->where(), "stop time " + seconds_text(*stop) +
                                                  " is before start time " + seconds_text(*start) +
                                                  ": expected stop >= start");
    }
    task.start_s = start.value_or(0.0);
    task.stop_s = stop.value_or(task.start_s);
    return task;
}

}  // namespace

model::TaskList read_tasks(const std::filesystem::path& file, const ReadOptions& options,
                           Diagnostics& diagnostics) {
    model::TaskList list;
    list.file = file.string();
    try {
        const io::XmlDocument document =
            io::XmlDocument::parse(options.read_text(file, list.file), list.file);
        const io::XmlNode root = document.root("tasklist");
        root.warn_unknown_children({"reference", "task"}, diagnostics);

        std::optional<DateTime> reference;
        if (const auto node = root.child("reference")) {
            node->warn_unknown_children({"datetime"}, diagnostics);
            reference = read_datetime(*node, true, std::nullopt, diagnostics).instant;
        } else {
            diagnostics.error(root.where(), "missing required element <reference>");
        }
        if (reference) list.reference = *reference;

        const std::vector<io::XmlNode> tasks = root.children("task");
        if (tasks.empty()) {
            diagnostics.error(root.where(), "no <task> element: expected at least one task");
        }
        for (const io::XmlNode& node : tasks) {
            list.tasks.push_back(read_task(node, reference, diagnostics));
        }
        document.warn_unread(diagnostics);
    } catch (const Error& error) {
        diagnostics.add(error);
    }
    return list;
}

}  // namespace glint::dirsig
