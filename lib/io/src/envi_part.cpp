// SPDX-License-Identifier: Apache-2.0
// Index runs of the part keys (glint/io/envi_part.h).
#include "glint/io/envi_part.h"

#include <charconv>

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
    std::vector<std::uint64_t> out;
    for (const std::string& item : envi_list_items(value)) {
        const std::size_t colon = item.find(':');
        std::optional<std::uint64_t> a = parse_index(std::string_view(item).substr(0, colon));
        std::optional<std::uint64_t> b =
            colon == std::string::npos ? (a ? std::optional(*a + 1) : std::nullopt)
                                       : parse_index(std::string_view(item).substr(colon + 1));
        if (!a || !b || *b <= *a || (!out.empty() && *a <= out.back())) return std::nullopt;
        if (*b - *a > (std::uint64_t{1} << 32)) return std::nullopt;  // not a glint file
        for (std::uint64_t i = *a; i < *b; ++i) out.push_back(i);
    }
    return out;
}

}  // namespace glint::io
