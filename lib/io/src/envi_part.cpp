// SPDX-License-Identifier: Apache-2.0
// Index runs of the part keys (glint/io/envi_part.h).
#include "glint/io/envi_part.h"

#include <charconv>
#include <cstdint>
#include <utility>

#include "glint/io/envi.h"

namespace glint::io {
namespace {

std::optional<std::uint64_t> parse_index(std::string_view text) {
    std::uint64_t value = 0;
    if (text.empty()) return std::nullopt;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc{} || end != text.data() + text.size()) return std::nullopt;
    return value;
}

/// The runs [a, b) of a brace list of indices and runs, each after the last; nullopt for
/// anything else.
std::optional<std::vector<std::pair<std::uint64_t, std::uint64_t>>> parse_runs(
    std::string_view value) {
    std::vector<std::pair<std::uint64_t, std::uint64_t>> runs;
    for (const std::string& item : envi_list_items(value)) {
        const std::size_t colon = item.find(':');
        std::optional<std::uint64_t> a = parse_index(std::string_view(item).substr(0, colon));
        std::optional<std::uint64_t> b =
            colon == std::string::npos
                ? (a && *a < UINT64_MAX ? std::optional(*a + 1) : std::nullopt)
                : parse_index(std::string_view(item).substr(colon + 1));
        if (!a || !b || *b <= *a || (!runs.empty() && *a < runs.back().second)) {
            return std::nullopt;
        }
        runs.emplace_back(*a, *b);
    }
    return runs;
}

/// How many indices `runs` hold; nullopt when the count overflows.
std::optional<std::uint64_t> count_of(
    const std::vector<std::pair<std::uint64_t, std::uint64_t>>& runs) {
    std::uint64_t count = 0;
    for (const auto& [a, b] : runs) {
        if (__builtin_add_overflow(count, b - a, &count)) return std::nullopt;
    }
    return count;
}

}  // namespace

std::string format_index_runs(const std::vector<std::uint64_t>& sorted) {
    std::vector<std::string> runs;
    for (std::size_t i = 0; i < sorted.size();) {
        std::size_t j = i + 1;
        while (j < sorted.size() && sorted[j] == sorted[j - 1] + 1) ++j;
        runs.push_back(j - i == 1
                           ? std::to_string(sorted[i])
                           : std::to_string(sorted[i]) + ":" + std::to_string(sorted[j - 1] + 1));
        i = j;
    }
    return envi_brace_list(runs);
}

std::optional<std::vector<std::uint64_t>> parse_index_runs(std::string_view value) {
    const auto runs = parse_runs(value);
    const std::optional<std::uint64_t> count = runs ? count_of(*runs) : std::nullopt;
    // More than 2^32 indices is no glint file (and would be 32 GiB listed): count_index_runs
    // says how many a list names without listing them.
    if (!count || *count > (std::uint64_t{1} << 32)) return std::nullopt;
    std::vector<std::uint64_t> out;
    out.reserve(static_cast<std::size_t>(*count));
    for (const auto& [a, b] : *runs) {
        for (std::uint64_t i = a; i < b; ++i) out.push_back(i);
    }
    return out;
}

std::optional<std::uint64_t> count_index_runs(std::string_view value) {
    const auto runs = parse_runs(value);
    return runs ? count_of(*runs) : std::nullopt;
}

}  // namespace glint::io
