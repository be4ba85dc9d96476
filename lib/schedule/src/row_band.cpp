// SPDX-License-Identifier: Apache-2.0
// RowBand (glint/schedule/row_band.h).
#include "glint/schedule/row_band.h"

#include <algorithm>
#include <charconv>

#include "glint/core/error.h"

namespace glint::schedule {
namespace {

__extension__ using Uint128 = unsigned __int128;

std::optional<std::uint64_t> parse_line(std::string_view text) {
    std::uint64_t value = 0;
    if (text.empty() || text.size() > 19) return std::nullopt;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc{} || end != text.data() + text.size()) return std::nullopt;
    return value;
}

}  // namespace

std::pair<std::uint64_t, std::uint64_t> RowBand::of(std::uint64_t lines) const {
    if (shard) {
        const auto [k, n] = *shard;
        // ⌊(K−1)·L/N⌋ in 128 bits, so no product overflows.
        const auto at = [&](std::uint64_t i) {
            return static_cast<std::uint64_t>(static_cast<Uint128>(i) * lines / n);
        };
        return {at(k - 1), at(k)};
    }
    const std::uint64_t a = std::min(first, lines);
    const std::uint64_t b = std::min(end.value_or(lines), lines);
    return {a, std::max(a, b)};
}

std::string RowBand::describe() const {
    if (shard) {
        return "shard " + std::to_string(shard->first) + "/" + std::to_string(shard->second) +
               " by rows";
    }
    return std::to_string(first) + ":" + (end ? std::to_string(*end) : std::string());
}

RowBand parse_row_band(std::string_view text) {
    const auto bad = [&](const std::string& why) {
        return usage_error(
            "--rows: expected A:B (lines A to B-1 of every capture, 0-based), A:, "
            ":B or N, got \"" +
            std::string(text) + "\"" + why);
    };
    RowBand band;
    const std::size_t colon = text.find(':');
    if (colon == std::string_view::npos) {
        const std::optional<std::uint64_t> line = parse_line(text);
        if (!line || *line == UINT64_MAX) throw bad("");
        band.first = *line;
        band.end = *line + 1;
        return band;
    }
    const std::string_view a = text.substr(0, colon);
    const std::string_view b = text.substr(colon + 1);
    if (!a.empty()) {
        const std::optional<std::uint64_t> first = parse_line(a);
        if (!first) throw bad("");
        band.first = *first;
    }
    if (!b.empty()) {
        band.end = parse_line(b);
        if (!band.end) throw bad("");
        if (*band.end <= band.first) throw bad(": B must be greater than A");
    }
    return band;
}

}  // namespace glint::schedule
