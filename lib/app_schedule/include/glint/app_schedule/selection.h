// SPDX-License-Identifier: Apache-2.0
// Which captures of a schedule glint-schedule writes: the filters --task N, --captures A:B,
// --focal-plane NAME and the shard --shard K/N. Everything works on the stream of captures
// in schedule order; nothing is held per capture.
//
// Shards (--shard K/N, K in 1..N): the selected captures (after the other filters), in
// schedule order, are split into N contiguous runs by cumulative problem count. With P the
// problems of a capture, C the problems of the selected captures before it and T the total
// of the selection, the capture belongs to shard
//     k = floor(N · (C + P/2) / T) + 1     (clamped to N)
// i.e. to the shard whose slice [(k−1)·T/N, k·T/N) of the problem axis holds the capture's
// midpoint. Every capture lands in exactly one shard, shards are contiguous in schedule
// order, and each shard's total differs from T/N by at most the largest problem count of
// one capture. When T is 0 (data recorders only) every capture weighs 1 instead.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "glint/core/cancel.h"
#include "glint/schedule/schedule.h"

namespace glint::app_schedule {

/// --captures A:B: global capture indices in [first, end) (Python slice rules; "N" alone is
/// N:N+1, "A:" runs to the end, ":B" starts at 0).
struct CaptureRange {
    std::uint64_t first = 0;
    std::optional<std::uint64_t> end;  ///< one past the last; none = to the end

    bool contains(std::uint64_t index) const { return index >= first && (!end || index < *end); }
};

/// --shard K/N: the K-th (1-based) of N shards.
struct ShardSpec {
    std::uint64_t index = 1;  ///< K, 1..count
    std::uint64_t count = 1;  ///< N >= 1
    /// --by rows: every selected capture, lines ⌊(K−1)·L/N⌋ … ⌊K·L/N⌋ − 1 of each
    /// (glint/schedule/row_band.h), instead of whole captures.
    bool by_rows = false;
};

/// Parses "A:B", "A:", ":B" or "N". Throws glint::Error (usage) naming --captures otherwise
/// (negative numbers, B < A, junk).
CaptureRange parse_capture_range(std::string_view text);
/// Parses "K/N" with 1 <= K <= N. Throws glint::Error (usage) naming --shard otherwise.
ShardSpec parse_shard(std::string_view text);

/// Problems (pixel problems handed to the radiometry) of one capture of `source`
/// (ClockedFocalPlane::problems_per_capture: x × y elements after scale_resolution, x for a TDI
/// focal plane).
std::uint64_t problems_per_capture(const schedule::ClockedFocalPlane& source);

/// The lines [a, b) of a capture of `source` that a --by rows shard holds; nullopt without
/// one (whole captures).
std::optional<std::pair<std::uint64_t, std::uint64_t>> shard_rows(
    const schedule::ClockedFocalPlane& source, const std::optional<ShardSpec>& shard);
/// Problems of one capture of `source` in the selection: problems_per_capture, or those of
/// the --by rows shard's lines.
std::uint64_t selected_problems(const schedule::ClockedFocalPlane& source,
                                const std::optional<ShardSpec>& shard);

/// The filters, resolved against one schedule.
struct Filters {
    std::optional<std::size_t> task;         ///< --task N (task index within each plugin)
    std::optional<CaptureRange> captures;    ///< --captures A:B (global indices)
    std::optional<std::string> focal_plane;  ///< --focal-plane NAME or INSTRUMENT/NAME
    std::optional<ShardSpec> shard;          ///< --shard K/N
};

/// Decides, capture by capture in schedule order, whether a capture is selected.
class Selection {
public:
    /// Resolves `filters` against `schedule`. Throws glint::Error (input) for a focal-plane
    /// name that no capturing focal plane has, or a task index that no plugin has (the
    /// message lists what there is). The shard is applied by ShardSplitter, not here.
    Selection(const schedule::Schedule& schedule, const Filters& filters);

    /// True when `source` may produce selected captures (focal-plane filter only).
    bool source_selected(std::size_t source) const { return m_source_selected[source]; }
    /// True when the task/focal-plane filters keep a capture of `source` in `task`.
    bool keeps(std::size_t source, std::size_t task) const {
        return m_source_selected[source] && (!m_filters.task || *m_filters.task == task);
    }
    /// True when the filters other than the shard keep `capture`.
    bool matches(const schedule::Capture& capture) const {
        return keeps(capture.source, capture.task_index) &&
               (!m_filters.captures || m_filters.captures->contains(capture.index));
    }
    /// True once no later capture can match (past the end of --captures).
    bool exhausted(const schedule::Capture& capture) const {
        return m_filters.captures && m_filters.captures->end &&
               capture.index + 1 >= *m_filters.captures->end;
    }
    /// True when the filters other than the shard can be counted without enumerating the
    /// captures (no --captures).
    bool analytic() const { return !m_filters.captures; }

    const Filters& filters() const { return m_filters; }

private:
    Filters m_filters;
    std::vector<bool> m_source_selected;
};

/// Problems and captures of the captures a Selection's filters keep (shard ignored).
struct SelectionTotals {
    std::uint64_t captures = 0;
    std::uint64_t problems = 0;
};

/// Totals of what `selection` keeps (shard ignored): analytic (Schedule::count per source
/// and task) unless --captures is given, then by enumerating the captures (no poses).
/// Polls `cancel` while enumerating.
SelectionTotals selection_totals(const schedule::Schedule& schedule, const Selection& selection,
                                 const CancelToken& cancel);

/// Assigns the captures a Selection keeps, in schedule order, to shards (rule at the top of
/// this file). Feed every kept capture, in order, to shard_of.
class ShardSplitter {
public:
    /// `totals`: the selection's totals (selection_totals); `shards`: N.
    ShardSplitter(const SelectionTotals& totals, std::uint64_t shards);
    /// The shard (1-based) of the next kept capture, whose problem count is `problems`.
    std::uint64_t shard_of(std::uint64_t problems);

private:
    std::uint64_t m_shards;
    bool m_by_count;  ///< total problems 0: every capture weighs 1
    std::uint64_t m_total;
    std::uint64_t m_before = 0;
};

}  // namespace glint::app_schedule
