// SPDX-License-Identifier: Apache-2.0
// The text table of glint-schedule: one line per capture with what DIRSIG prints when it
// starts a capture ("Task #1, Capture #1, Event #1 of 21", date/time, relative time,
// instrument -> focal plane, bandpass, array size), plus the global index and the plugin. Column
// widths come from the sources, which are known before the first capture, so the table streams.
#include <algorithm>
#include <cstdio>

#include "writers.h"

namespace glint::app_schedule::internal {
namespace {

std::string fixed6(double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.6f", value);
    return buffer;
}

std::string scientific6(double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.6e", value);
    return buffer;
}

std::string pad(std::string text, std::size_t width, bool right) {
    if (text.size() >= width) return text;
    const std::string fill(width - text.size(), ' ');
    return right ? fill + text : text + fill;
}

/// What the table shows of one source, formatted once.
struct SourceColumns {
    std::string name;      ///< "Instrument -> FocalPlane"
    std::string bandpass;  ///< "0.400000 - 0.800000 @ 0.010000 microns (41 samples)"
    std::string array;     ///< "320 x 240"
};

SourceColumns columns_of(const schedule::ClockedFocalPlane& source) {
    SourceColumns c;
    const std::string instrument = source.instrument ? source.instrument->name : "";
    const model::Bandpass& band = source.focal_plane->capture_method.spectral_response.bandpass;
    c.name = instrument + " -> " + source.focal_plane->name;
    c.bandpass = fixed6(band.min_um) + " - " + fixed6(band.max_um) + " @ " + fixed6(band.delta_um) +
                 " microns (" + std::to_string(band.count) + " samples)";
    c.array = std::to_string(source.x_count) + " x " + std::to_string(source.y_count);
    return c;
}

class TextWriter final : public CaptureWriter {
public:
    TextWriter(const RunInfo& info, std::ostream& out) : m_out(out) {
        const schedule::Schedule& schedule = *info.schedule;
        for (const schedule::ClockedFocalPlane& source : schedule.sources()) {
            m_sources.push_back(columns_of(source));
        }
        m_name_width = kNameHeader.size();
        m_bandpass_width = kBandpassHeader.size();
        for (const SourceColumns& c : m_sources) {
            m_name_width = std::max(m_name_width, c.name.size());
            m_bandpass_width = std::max(m_bandpass_width, c.bandpass.size());
        }
        // "N of M" as wide as the largest event count of any task allows.
        std::uint64_t most = 0;
        for (std::size_t p = 0; p < schedule.plugins().size(); ++p) {
            for (std::size_t t = 0; t < schedule.plugins()[p].tasks.tasks.size(); ++t) {
                std::uint64_t n = 0;
                for (std::size_t s = 0; s < schedule.sources().size(); ++s) {
                    if (schedule.sources()[s].plugin == p) n += schedule.count(s, t);
                }
                most = std::max(most, n);
            }
        }
        const std::size_t digits = std::to_string(most).size();
        m_event_width = std::max<std::size_t>(5, 2 * digits + 4);
        m_index_width = std::max<std::size_t>(5, std::to_string(schedule.total_captures()).size());
    }

    void begin() override {
        m_out << pad("index", m_index_width, true) << "  plugin  task  capture  "
              << pad("event", m_event_width, true) << "  " << pad("date/time", kDateWidth, false)
              << "  " << pad("relative time", kRelativeWidth, true) << "  "
              << pad(std::string(kNameHeader), m_name_width, false) << "  "
              << pad(std::string(kBandpassHeader), m_bandpass_width, false) << "  array\n";
    }

    void capture(const CaptureRecord& record) override {
        const schedule::Capture& c = record.capture;
        const SourceColumns& columns = m_sources[c.source];
        const DateTime start = add_seconds(record.plugin->tasks.reference, c.t0_s);
        m_out << pad(std::to_string(c.index), m_index_width, true) << "  "
              << pad(std::to_string(record.plugin->plugin_index), 6, true) << "  "
              << pad(std::to_string(c.task_index), 4, true) << "  "
              << pad(std::to_string(c.capture_index), 7, true) << "  "
              << pad(std::to_string(record.event_number) + " of " +
                         std::to_string(record.event_count),
                     m_event_width, true)
              << "  " << pad(format_iso8601_local(start, 6), kDateWidth, false) << "  "
              << pad(scientific6(c.t0_s), kRelativeWidth, true) << "  "
              << pad(columns.name, m_name_width, false) << "  "
              << pad(columns.bandpass, m_bandpass_width, false) << "  " << columns.array << '\n';
    }

    void end(const WrittenTotals& /*totals*/) override {}

private:
    static constexpr std::string_view kNameHeader = "instrument -> focal plane";
    static constexpr std::string_view kBandpassHeader = "bandpass";
    static constexpr std::size_t kDateWidth = 32;      ///< 2008-12-30T12:00:00.000000-05:00
    static constexpr std::size_t kRelativeWidth = 13;  ///< -1.000000e+00

    std::ostream& m_out;
    std::vector<SourceColumns> m_sources;
    std::size_t m_name_width = 0;
    std::size_t m_bandpass_width = 0;
    std::size_t m_event_width = 0;
    std::size_t m_index_width = 0;
};

}  // namespace

std::unique_ptr<CaptureWriter> make_text_writer(const RunInfo& info, std::ostream& out) {
    return std::make_unique<TextWriter>(info, out);
}

}  // namespace glint::app_schedule::internal
