// SPDX-License-Identifier: Apache-2.0
// Before the first capture: the selected captures, the focal planes' states, the output
// files planned with their headers, the memory estimate, and the run's capture list.
#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "glint/core/atomic_file.h"
#include "glint/core/error.h"
#include "glint/schedule/capture_list.h"
#include "render_parts.h"

namespace glint::render::detail {
namespace {

/// The selected captures in schedule order, skipping (with one info line each) the sources
/// glint-render does not render.
/// The captures a run renders and, when it renders only part of the schedule (--schedule,
/// --rows), every file's captures in the whole schedule (what its parts are parts of).
struct Selected {
    std::vector<PlannedCapture> captures;
    std::map<std::filesystem::path, std::vector<std::uint64_t>> whole;
};

Selected select_captures(const RenderInputs& in, const RenderOptions& options,
                         const Context& context) {
    const schedule::Schedule& schedule = *in.schedule;
    const auto& sources = schedule.sources();
    std::vector<bool> skip(sources.size(), false);
    for (std::size_t s = 0; s < sources.size(); ++s) {
        std::string why;
        if (!renders(sources[s], why)) {
            skip[s] = true;
            // A data recorder's focal plane (its imagefile, spectral response, ...) is said
            // here, once.
            const model::InstrumentType type = sources[s].instrument->type;
            if (type == model::InstrumentType::generic) {
                context.log.warning(
                    format_located(sources[s].focal_plane->where, why + ": not rendered"));
            } else if (type == model::InstrumentType::data_recorder) {
                context.log.warning(format_located(sources[s].focal_plane->where, why));
            }
        }
    }
    // The plan holds every selected capture: refuse a run too long to plan before building
    // it (a 1e9 Hz clock over 0.25 s would need 50 GB), from the analytic counts.
    std::uint64_t selected = 0;
    for (std::size_t s = 0; s < sources.size(); ++s) {
        if (skip[s]) continue;
        for (std::size_t t = 0; t < schedule.plugins()[sources[s].plugin].tasks.tasks.size(); ++t) {
            selected += schedule.count(s, t);
        }
    }
    if (!options.only_captures.empty()) {
        selected = std::min<std::uint64_t>(selected, options.only_captures.size());
    }
    if (selected > kMaxCapturesPerRender) {
        throw input_error(
            "the schedule has " + std::to_string(selected) +
                " captures to render, more than one glint-render run plans (" +
                std::to_string(kMaxCapturesPerRender) +
                "): check the clock rates and task windows (glint-schedule --summary shows them), "
                "or "
                "render it in shards (glint-schedule --shard K/N -o part.json, then glint-render "
                "--schedule part.json)",
            ErrorContext{schedule.simulation_file().string(), 0, {}});
    }
    std::map<std::pair<std::size_t, std::size_t>, std::uint64_t> events;  // (plugin, task)
    std::map<std::pair<std::size_t, std::size_t>, std::uint64_t> event_counts;
    for (std::size_t s = 0; s < sources.size(); ++s) {
        const std::size_t tasks = schedule.plugins()[sources[s].plugin].tasks.tasks.size();
        for (std::size_t t = 0; t < tasks; ++t) {
            event_counts[{sources[s].plugin, t}] += schedule.count(s, t);
        }
    }
    const bool partial = !options.only_captures.empty() || options.rows;
    Selected selected_captures;
    std::vector<PlannedCapture>& out = selected_captures.captures;
    schedule::Schedule::Generator generator = schedule.captures();
    while (const std::optional<schedule::Capture> capture = generator.next()) {
        if ((capture->index & 0x3FF) == 0) context.cancel.throw_if_cancelled();
        const std::pair key{sources[capture->source].plugin, capture->task_index};
        const std::uint64_t event = ++events[key];
        if (skip[capture->source]) continue;
        std::filesystem::path image = schedule.image_file(*capture);
        std::vector<std::filesystem::path> truth = schedule.truth_files(*capture);
        if (partial) {
            selected_captures.whole[image].push_back(capture->index);
            for (const auto& t : truth) selected_captures.whole[t].push_back(capture->index);
        }
        if (!options.only_captures.empty() && !options.only_captures.contains(capture->index)) {
            continue;
        }
        const std::uint64_t lines = sources[capture->source].lines_per_capture();
        out.push_back(
            {*capture, std::move(image), std::move(truth), event, event_counts[key], 0, lines});
    }
    if (!options.only_captures.empty()) {
        std::set<std::uint64_t> found;
        for (const PlannedCapture& p : out) found.insert(p.capture.index);
        for (std::uint64_t wanted : options.only_captures) {
            if (!found.contains(wanted)) {
                throw input_error("capture " + std::to_string(wanted) +
                                  " of the --schedule selection is not a rendered capture of " +
                                  schedule.simulation_file().string());
            }
        }
    }
    if (options.rows) {
        // A band of lines: a capture with none of its lines in it renders nothing here.
        std::erase_if(out, [&](PlannedCapture& p) {
            const auto [a, b] = options.rows->of(p.end_line);
            p.first_line = a;
            p.end_line = b;
            return a == b;
        });
        if (out.empty()) {
            context.log.warning("--rows " + options.rows->describe() +
                                " holds no line of any selected capture: nothing is rendered");
        }
    }
    return selected_captures;
}

/// A file the selected captures write: its focal plane, which of its truth files it is (none:
/// the radiometric image), how many captures it holds and which of their lines.
struct PlannedFile {
    std::size_t source = 0;
    std::optional<std::size_t> truth;
    std::uint64_t captures = 0;
    std::uint64_t first_line = 0;  ///< the lines of each capture it holds
    std::uint64_t end_line = 0;
};

/// The files `captures` write, by path.
std::map<std::filesystem::path, PlannedFile> files_of(const std::vector<PlannedCapture>& captures) {
    std::map<std::filesystem::path, PlannedFile> files;
    for (const PlannedCapture& p : captures) {
        PlannedFile& entry = files[p.file];
        entry.source = p.capture.source;
        ++entry.captures;
        entry.first_line = p.first_line;
        entry.end_line = p.end_line;
        for (std::size_t t = 0; t < p.truth_files.size(); ++t) {
            PlannedFile& truth = files[p.truth_files[t]];
            truth = {p.capture.source, t, truth.captures + 1, p.first_line, p.end_line};
        }
    }
    return files;
}

/// The state of every focal plane that writes one of `files`, built in the files' order.
std::map<std::size_t, FocalPlaneState> plan_focal_planes(
    const RenderInputs& in, const std::map<std::filesystem::path, PlannedFile>& files,
    const RenderOptions& options, const Context& context) {
    std::map<std::size_t, FocalPlaneState> states;
    for (const auto& [path, entry] : files) {
        if (!states.contains(entry.source)) {
            states.emplace(entry.source,
                           make_focal_plane_state(in, entry.source, options, context));
        }
    }
    return states;
}

/// Plans every output file with its header and capture count.
ImageOutputs plan_outputs(const RenderInputs& in, const Selected& selected,
                          const std::map<std::filesystem::path, PlannedFile>& files,
                          const std::map<std::size_t, FocalPlaneState>& states,
                          const RenderOptions& options) {
    const std::vector<PlannedCapture>& captures = selected.captures;
    ImageOutputs outputs;
    // A lidar receiver's BIN files, each with its pulses in schedule order.
    std::map<std::filesystem::path, std::vector<const PlannedCapture*>> pulses;
    for (const PlannedCapture& p : captures) {
        if (states.at(p.capture.source).lidar) pulses[p.file].push_back(&p);
    }
    for (const auto& [path, entry] : files) {
        const FocalPlaneState& state = states.at(entry.source);
        const schedule::ClockedFocalPlane& s = in.schedule->sources()[entry.source];
        // A part: some of the whole file's lines or captures (glint/io/envi_part.h).
        std::optional<PartOf> part;
        const auto whole = selected.whole.find(path);
        const std::uint64_t lines = entry.end_line - entry.first_line;
        if (lines != s.lines_per_capture() ||
            (whole != selected.whole.end() && whole->second.size() != entry.captures)) {
            part = PartOf{
                entry.first_line, entry.end_line, s.lines_per_capture(),
                whole != selected.whole.end() ? whole->second : std::vector<std::uint64_t>{}};
        }
        if (state.lidar) {
            if (part) {
                throw usage_error(
                    "lidar receiver \"" + s.focal_plane->name + "\"'s file " + path.string() +
                    " would hold " + std::to_string(entry.captures) + " of its " +
                    std::to_string(part->whole_captures.size()) + " pulses" +
                    (lines != s.lines_per_capture() ? std::string(" and some of their rows") : "") +
                    ": glint-envi merge joins ENVI parts, not BIN files; render all of a lidar "
                    "receiver's pulses in one run, without --rows (glint-schedule --focal-plane "
                    "selects them)");
            }
            plan_bin_file(in, state, entry.source, path, pulses.at(path), options, outputs);
            continue;
        }
        if (!entry.truth) {
            outputs.plan(path, state.header, lines, entry.captures, part);
            continue;
        }
        if (*entry.truth >= state.truth.files.size()) {
            throw internal_error("truth file " + path.string() + " has no collection");
        }
        outputs.plan(path,
                     sensor::truth_header(state.header, *s.focal_plane, state.truth,
                                          state.truth.files[*entry.truth], in.scene),
                     lines, entry.captures, std::move(part));
    }
    return outputs;
}

/// Refuses a run two of whose outputs are one file (a truth image named like the image's
/// header, an image named like a data recorder's file, --log-info-filename naming an image):
/// the second would overwrite the first. Throws glint::Error (input) naming both.
void refuse_colliding_outputs(const ImageOutputs& outputs,
                              const std::vector<PlannedTelemetry>& telemetry,
                              const RenderOptions& options) {
    std::vector<std::pair<std::filesystem::path, std::string>> written = outputs.written();
    for (const PlannedTelemetry& t : telemetry) {
        written.emplace_back(t.csv, "data recorder file " + t.csv.filename().string());
        written.emplace_back(t.jsonl, "data recorder file " + t.jsonl.filename().string());
    }
    if (!options.log_info_file.empty()) {
        written.emplace_back(options.log_info_file, "the --log-info-filename file");
    }
    std::map<std::filesystem::path, const std::string*> seen;
    for (const auto& [path, what] : written) {
        std::error_code ec;
        const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
        const auto [it, inserted] = seen.emplace((ec ? path : absolute).lexically_normal(), &what);
        if (inserted) continue;
        throw input_error("two outputs of this run are the same file, " + path.string() + ": " +
                          *it->second + " and " + what +
                          " (the second would overwrite the first); give them distinct "
                          "<basename> or <extension> values, or a distinct output_prefix");
    }
}

}  // namespace

PlannedRender plan_render(model::SimulationInputs loaded, const RenderOptions& options,
                          const Context& context) {
    auto p = std::make_unique<RenderPlan>();
    p->inputs = make_render_inputs(std::move(loaded), options, context);
    Selected selected = select_captures(p->inputs, options, context);
    const std::map<std::filesystem::path, PlannedFile> files = files_of(selected.captures);
    p->states = plan_focal_planes(p->inputs, files, options, context);
    ImageOutputs outputs = plan_outputs(p->inputs, selected, files, p->states, options);
    p->captures = std::move(selected.captures);
    p->telemetry = plan_telemetry(p->inputs, options, context);
    RenderReport& report = p->report;
    report.files = outputs.planned();
    for (const PlannedTelemetry& t : p->telemetry) {
        report.files.push_back(t.csv);
        report.files.push_back(t.jsonl);
    }
    refuse_colliding_outputs(outputs, p->telemetry, options);
    const RenderInputs& in = p->inputs;
    std::uint64_t triangles = 0;
    for (const model::Instance& instance : in.scene.instances) {
        triangles += in.scene.objects[instance.object_index].mesh.triangles.size();
    }
    std::uint64_t largest = 0;
    for (const PlannedCapture& planned : p->captures) {
        const schedule::ClockedFocalPlane& s = in.schedule->sources()[planned.capture.source];
        report.pixels += planned.problems(s);
        const FocalPlaneState& state = p->states.at(planned.capture.source);
        // A lidar pulse holds 1 + time samples values per pixel (and its returns as many); an
        // image capture a band of lines of channels and truth (block_lines) at a time.
        const std::uint64_t bytes =
            state.lidar ? s.problems_per_capture *
                              (2 * (1 + state.lidar->gate.samples) + state.grid.size()) * 8
                        : band_bytes(s, state);
        largest = std::max<std::uint64_t>(largest, bytes);
    }
    report.memory_estimate_bytes = triangles * 85 + largest;
    return {std::move(p), std::move(outputs)};
}

void write_log_info(const RenderPlan& plan, const RenderOptions& options, const Context& context) {
    if (options.log_info_file.empty()) return;
    const RenderInputs& in = plan.inputs;
    std::ostringstream text;
    schedule::CaptureListWriter list(
        text, *in.schedule,
        schedule::CaptureListProvenance{"glint-render", context.arguments, options.schedule.seed});
    list.begin();
    for (const PlannedCapture& p : plan.captures) {
        list.add(p.capture, p.file, in.schedule->truth_files(p.capture));
    }
    list.end();
    write_file_atomically(options.log_info_file, text.str());
}

scene::BuildOptions build_options(const RenderOptions& options, double t0_s, double t1_s) {
    scene::BuildOptions b;
    b.device = options.device;
    b.window = {t0_s, t1_s};
    return b;
}

}  // namespace glint::render::detail
