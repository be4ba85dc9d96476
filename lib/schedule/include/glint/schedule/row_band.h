// SPDX-License-Identifier: Apache-2.0
// A band of lines of every capture: what `glint-render --rows A:B` and a `glint-schedule
// --shard K/N --by rows` shard render (docs/scale.md). Lines are a capture's lines as its
// file stores them (a frame's y rows; one line for a TDI focal plane).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace glint::schedule {

struct RowBand {
    /// --rows A:B: lines first … end − 1 (end none: to the last), clipped to each capture.
    std::uint64_t first = 0;
    std::optional<std::uint64_t> end;
    /// --shard K/N --by rows: shard K (1-based) of N, lines ⌊(K−1)·L/N⌋ … ⌊K·L/N⌋ − 1 of a
    /// capture of L lines (set instead of first/end).
    std::optional<std::pair<std::uint64_t, std::uint64_t>> shard;

    /// The lines [a, b) of a capture of `lines` lines this band renders (a == b: none).
    std::pair<std::uint64_t, std::uint64_t> of(std::uint64_t lines) const;
    /// "A:B", "A:" or "shard K/N by rows", for messages.
    std::string describe() const;
};

/// Parses --rows "A:B", "A:", ":B" or "N" (line N alone). Throws glint::Error (usage) naming
/// --rows for anything else, negative numbers or B <= A.
RowBand parse_row_band(std::string_view text);

}  // namespace glint::schedule
