// SPDX-License-Identifier: Apache-2.0
// The filters and shards of glint-schedule: parsing --captures and --shard, resolving
// --task and --focal-plane against a schedule, the selection's totals and the problem-count
// shard split (rule in selection.h).
#include "glint/app_schedule/selection.h"

#include <charconv>
#include <set>

#include "glint/core/error.h"
#include "glint/schedule/row_band.h"

namespace glint::app_schedule {
namespace {

__extension__ using Uint128 = unsigned __int128;

/// Parses a whole unsigned decimal number; nullopt for anything else (sign, blanks, junk).
std::optional<std::uint64_t> parse_count(std::string_view text) {
    std::uint64_t value = 0;
    if (text.empty()) return std::nullopt;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

/// "Instrument/FocalPlane" or "FocalPlane" of a source, for messages.
std::string source_name(const schedule::ClockedFocalPlane& source) {
    const std::string instrument = source.instrument ? source.instrument->name : "";
    const std::string focal_plane = source.focal_plane ? source.focal_plane->name : "";
    return instrument + "/" + focal_plane;
}

/// True when `pattern` (NAME or INSTRUMENT/NAME) names `source`.
bool names_source(const std::string& pattern, const schedule::ClockedFocalPlane& source) {
    const std::string focal_plane = source.focal_plane ? source.focal_plane->name : "";
    const std::size_t slash = pattern.find('/');
    if (slash == std::string::npos) return pattern == focal_plane;
    const std::string instrument = source.instrument ? source.instrument->name : "";
    return pattern.substr(0, slash) == instrument && pattern.substr(slash + 1) == focal_plane;
}

}  // namespace

CaptureRange parse_capture_range(std::string_view text) {
    const auto bad = [&]() {
        return usage_error(
            "--captures: expected A:B, A:, :B or N (global capture indices, "
            "B > A), got \"" +
            std::string(text) + "\"");
    };
    const std::size_t colon = text.find(':');
    CaptureRange range;
    if (colon == std::string_view::npos) {
        const auto index = parse_count(text);
        if (!index || *index == UINT64_MAX) throw bad();
        range.first = *index;
        range.end = *index + 1;
        return range;
    }
    const std::string_view first = text.substr(0, colon);
    const std::string_view end = text.substr(colon + 1);
    if (first.empty() && end.empty()) throw bad();
    if (!first.empty()) {
        const auto value = parse_count(first);
        if (!value) throw bad();
        range.first = *value;
    }
    if (!end.empty()) {
        const auto value = parse_count(end);
        if (!value || *value <= range.first) throw bad();
        range.end = *value;
    }
    return range;
}

ShardSpec parse_shard(std::string_view text) {
    const std::size_t slash = text.find('/');
    const auto index = parse_count(text.substr(0, slash));
    const auto count =
        slash == std::string_view::npos ? std::nullopt : parse_count(text.substr(slash + 1));
    if (!index || !count || *count == 0 || *index == 0 || *index > *count) {
        throw usage_error("--shard: expected K/N with 1 <= K <= N, got \"" + std::string(text) +
                          "\"");
    }
    return ShardSpec{*index, *count};
}

std::uint64_t problems_per_capture(const schedule::ClockedFocalPlane& source) {
    return source.problems_per_capture;
}

std::optional<std::pair<std::uint64_t, std::uint64_t>> shard_rows(
    const schedule::ClockedFocalPlane& source, const std::optional<ShardSpec>& shard) {
    if (!shard || !shard->by_rows) return std::nullopt;
    schedule::RowBand band;
    band.shard = {shard->index, shard->count};
    return band.of(source.lines_per_capture());
}

std::uint64_t selected_problems(const schedule::ClockedFocalPlane& source,
                                const std::optional<ShardSpec>& shard) {
    const std::uint64_t problems = problems_per_capture(source);
    const auto rows = shard_rows(source, shard);
    if (!rows || source.lines_per_capture() == 0) return problems;
    return problems / source.lines_per_capture() * (rows->second - rows->first);
}

Selection::Selection(const schedule::Schedule& schedule, const Filters& filters)
    : m_filters(filters), m_source_selected(schedule.sources().size(), true) {
    const auto& sources = schedule.sources();
    if (filters.focal_plane) {
        bool any = false;
        std::set<std::string> names;
        for (std::size_t i = 0; i < sources.size(); ++i) {
            m_source_selected[i] = names_source(*filters.focal_plane, sources[i]);
            any = any || m_source_selected[i];
            names.insert(source_name(sources[i]));
        }
        if (!any) {
            std::string have;
            for (const std::string& name : names) have += (have.empty() ? "" : ", ") + name;
            throw input_error("--focal-plane: no capturing focal plane is named \"" +
                              *filters.focal_plane +
                              "\" (there are: " + (have.empty() ? "none" : have) + ")");
        }
    }
    if (filters.task) {
        std::size_t most = 0;
        for (const schedule::PluginSchedule& plugin : schedule.plugins()) {
            most = std::max(most, plugin.tasks.tasks.size());
        }
        if (*filters.task >= most) {
            throw input_error(
                "--task: no task " + std::to_string(*filters.task) +
                (most == 0 ? std::string(" (the simulation has no tasks)")
                           : " (task indices run from 0 to " + std::to_string(most - 1) + ")"));
        }
    }
}

SelectionTotals selection_totals(const schedule::Schedule& schedule, const Selection& selection,
                                 const CancelToken& cancel) {
    SelectionTotals totals;
    const auto& sources = schedule.sources();
    if (selection.analytic()) {
        for (std::size_t s = 0; s < sources.size(); ++s) {
            const std::size_t tasks = schedule.plugins()[sources[s].plugin].tasks.tasks.size();
            const std::uint64_t per_capture = problems_per_capture(sources[s]);
            for (std::size_t t = 0; t < tasks; ++t) {
                if (!selection.keeps(s, t)) continue;
                const std::uint64_t n = schedule.count(s, t);
                totals.captures += n;
                totals.problems += n * per_capture;
            }
        }
        return totals;
    }
    schedule::Schedule::Generator generator = schedule.captures();
    std::uint64_t seen = 0;
    while (const std::optional<schedule::Capture> capture = generator.next()) {
        if ((++seen & 0xFFFF) == 0) cancel.throw_if_cancelled();
        if (selection.matches(*capture)) {
            ++totals.captures;
            totals.problems += problems_per_capture(sources[capture->source]);
        }
        if (selection.exhausted(*capture)) break;
    }
    return totals;
}

ShardSplitter::ShardSplitter(const SelectionTotals& totals, std::uint64_t shards)
    : m_shards(shards == 0 ? 1 : shards),
      m_by_count(totals.problems == 0),
      m_total(totals.problems == 0 ? totals.captures : totals.problems) {}

std::uint64_t ShardSplitter::shard_of(std::uint64_t problems) {
    const std::uint64_t weight = m_by_count ? 1 : problems;
    std::uint64_t shard = m_shards;
    if (m_total > 0) {
        // floor(N · (C + P/2) / T) in exact integer arithmetic: N · (2C + P) / (2T).
        const Uint128 numerator =
            static_cast<Uint128>(m_shards) * (2 * static_cast<Uint128>(m_before) + weight);
        const Uint128 k = numerator / (2 * static_cast<Uint128>(m_total));
        if (k < m_shards) shard = static_cast<std::uint64_t>(k) + 1;
    }
    m_before += weight;
    return shard;
}

}  // namespace glint::app_schedule
