// SPDX-License-Identifier: Apache-2.0
// The pieces of glint-envi merge (merge_pieces.h): a part's header read into a Piece, and the
// pieces of one whole file checked against each other and laid out line by line.
#include "merge_pieces.h"

#include <algorithm>
#include <charconv>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include "glint/core/text.h"
#include "glint/io/envi_part.h"

namespace glint::app_envi::merge_detail {
namespace {

namespace fs = std::filesystem;

using io::kCapturesKey;
using io::kDatetimesKey;
using io::kIdsKey;
using io::kIndicesKey;
using io::kLinesPerCaptureKey;
using io::kWindowsKey;

/// The most captures a whole file may have: what its merged header can list within the ENVI
/// header limit, at 32 bytes a capture at the least (524,288).
constexpr std::uint64_t kMaxWholeCaptures = io::kMaxEnviHeaderBytes / 32;

/// A whole number written alone (blanks around it allowed); nullopt for anything else.
std::optional<std::uint64_t> whole_number(const std::optional<std::string>& text) {
    if (!text) return std::nullopt;
    const std::string_view digits = trim(*text);
    std::uint64_t value = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (digits.empty() || ec != std::errc{} || end != digits.data() + digits.size()) {
        return std::nullopt;
    }
    return value;
}

/// The header without what differs between the parts of one file, as text: what every part
/// must agree on.
std::string comparable_header(io::EnviHeader h) {
    h.lines = 0;
    std::erase_if(h.extra, [](const auto& kv) {
        const std::string& k = kv.first;
        return k == kCapturesKey || k == kLinesPerCaptureKey || k == kIdsKey || k == kIndicesKey ||
               k == kWindowsKey || k == kDatetimesKey || k == kCommandLineKey ||
               k == io::kPartRowsKey || k == io::kPartLinesPerCaptureKey ||
               k == io::kPartCapturesKey;
    });
    return io::format_envi_header(h);
}

/// The first line where two header texts differ, as "A" vs "B".
std::string first_difference(const std::string& a, const std::string& b) {
    const std::vector<std::string> la = split_list(a, '\n');
    const std::vector<std::string> lb = split_list(b, '\n');
    for (std::size_t i = 0; i < std::max(la.size(), lb.size()); ++i) {
        const std::string x = i < la.size() ? la[i] : "(nothing)";
        const std::string y = i < lb.size() ? lb[i] : "(nothing)";
        if (x != y) return quote(x) + " against " + quote(y);
    }
    return "(none)";
}

/// "5 (t0c2)": a capture's global index and id.
std::string capture_name(const WholeFile& file, std::size_t position) {
    const Segment& s = file.segments[position].front();
    return std::to_string(file.captures[position]) + " (" + s.piece->ids[s.position] + ")";
}

}  // namespace

/// Reads what a glint-render header says about its captures and part; a problem otherwise.
bool read_piece(Piece& piece, const fs::path& shown, Problems& problems) {
    const io::EnviHeader& h = piece.header;
    const std::optional<std::uint64_t> count = whole_number(h.find_extra(kCapturesKey));
    const std::optional<std::uint64_t> lines = whole_number(h.find_extra(kLinesPerCaptureKey));
    const std::optional<std::string> indices = h.find_extra(kIndicesKey);
    std::optional<std::vector<std::uint64_t>> captures;
    if (indices) {
        captures.emplace();
        for (const std::string& item : io::envi_list_items(*indices)) {
            const std::optional<std::uint64_t> index = whole_number(item);
            if (!index || (!captures->empty() && *index <= captures->back())) {
                captures.reset();
                break;
            }
            captures->push_back(*index);
        }
    }
    if (!count || !lines || *lines == 0 || !captures || captures->size() != *count ||
        h.lines != *count * *lines) {
        problems.add(shown,
                     "its glint capture keys (\"glint captures\", \"glint lines per "
                     "capture\", \"glint capture indices\") do not describe its " +
                         std::to_string(h.lines) + " lines: not a glint-render image");
        return false;
    }
    piece.captures = std::move(*captures);
    piece.ids = io::envi_list_items(h.find_extra(kIdsKey).value_or(""));
    piece.windows = io::envi_list_items(h.find_extra(kWindowsKey).value_or(""));
    piece.datetimes = io::envi_list_items(h.find_extra(kDatetimesKey).value_or(""));
    if (piece.ids.size() != *count || piece.windows.size() != *count ||
        piece.datetimes.size() != *count) {
        problems.add(shown, "its capture ids, windows and date-times do not list its " +
                                std::to_string(*count) + " captures");
        return false;
    }
    const std::optional<std::string> rows = h.find_extra(io::kPartRowsKey);
    const std::optional<std::string> whole_lines = h.find_extra(io::kPartLinesPerCaptureKey);
    const std::optional<std::string> whole_captures = h.find_extra(io::kPartCapturesKey);
    if (!rows && !whole_lines && !whole_captures) {  // a whole file
        piece.first_line = 0;
        piece.end_line = *lines;
        piece.whole_lines = *lines;
        piece.whole_captures = io::format_index_runs(piece.captures);
        piece.whole_capture_count = piece.captures.size();
        return true;
    }
    const std::vector<std::string> band = io::envi_list_items(rows.value_or(""));
    std::uint64_t a = 0;
    std::uint64_t b = 0;
    bool band_read = false;
    if (band.size() == 2) {
        const std::optional<std::uint64_t> first = whole_number(band[0]);
        const std::optional<std::uint64_t> end = whole_number(band[1]);
        band_read = first && end;
        a = first.value_or(0);
        b = end.value_or(0);
    }
    const std::optional<std::uint64_t> l = whole_number(whole_lines);
    // Counted, not expanded: "{0:4294967296}" is a few bytes of header.
    const std::optional<std::uint64_t> w =
        whole_captures ? io::count_index_runs(*whole_captures) : std::nullopt;
    if (!band_read || !l || !w || b <= a || b > *l || b - a != *lines) {
        problems.add(shown, std::string("its part keys (\"") + io::kPartRowsKey + "\", \"" +
                                io::kPartLinesPerCaptureKey + "\", \"" + io::kPartCapturesKey +
                                "\") are missing or do not fit its " + std::to_string(*lines) +
                                " lines per capture");
        return false;
    }
    piece.first_line = a;
    piece.end_line = b;
    piece.whole_lines = *l;
    piece.whole_captures = *whole_captures;
    piece.whole_capture_count = *w;
    return true;
}

/// Checks that the pieces of `file` cover every line of every capture once and agree; fills
/// its merged header and segments.
void resolve(WholeFile& file, const fs::path& shown, Problems& problems) {
    const Piece& first = file.pieces.front();
    const std::string reference = comparable_header(first.header);
    bool consistent = true;
    for (const Piece& piece : file.pieces) {
        if (piece.whole_captures != first.whole_captures ||
            piece.whole_lines != first.whole_lines) {
            problems.add(shown,
                         "the parts in " + first.part.string() + " and " + piece.part.string() +
                             " are parts of different files (their \"" + io::kPartCapturesKey +
                             "\" or \"" + io::kPartLinesPerCaptureKey + "\" differ)");
            consistent = false;
        }
        const std::string other = comparable_header(piece.header);
        if (other != reference) {
            problems.add(shown, "the parts in " + first.part.string() + " and " +
                                    piece.part.string() +
                                    " differ: " + first_difference(reference, other));
            consistent = false;
        }
    }
    if (!consistent) return;
    // The merged header lists every capture (index, id, window, date-time: 32 bytes at the
    // least), so a whole file of more captures than a header can hold is no glint-render
    // file: its list is refused before it is expanded.
    if (first.whole_capture_count > kMaxWholeCaptures) {
        problems.add(shown, "its parts' \"" + std::string(io::kPartCapturesKey) + "\" lists " +
                                std::to_string(first.whole_capture_count) +
                                " captures, more than the header of a merged file can list (" +
                                std::to_string(kMaxWholeCaptures) +
                                "): not parts glint-render "
                                "wrote");
        return;
    }
    file.captures =
        io::parse_index_runs(first.whole_captures).value_or(std::vector<std::uint64_t>{});
    const std::vector<std::uint64_t>& whole = file.captures;
    const std::uint64_t lines = first.whole_lines;
    file.segments.assign(whole.size(), {});
    for (const Piece& piece : file.pieces) {
        for (std::size_t k = 0; k < piece.captures.size(); ++k) {
            const auto at = std::lower_bound(whole.begin(), whole.end(), piece.captures[k]);
            if (at == whole.end() || *at != piece.captures[k]) {
                problems.add(shown, "the part in " + piece.part.string() + " holds capture " +
                                        std::to_string(piece.captures[k]) +
                                        ", which is not one of the file's captures");
                continue;
            }
            file.segments[static_cast<std::size_t>(at - whole.begin())].push_back(
                {&piece, k, piece.first_line, piece.end_line});
        }
    }
    // Gaps and overlaps, grouped by the lines they concern so that a missing shard is one line.
    std::map<std::pair<std::uint64_t, std::uint64_t>, std::vector<std::uint64_t>> gaps;
    for (std::size_t c = 0; c < whole.size(); ++c) {
        std::vector<Segment>& segments = file.segments[c];
        std::sort(segments.begin(), segments.end(),
                  [](const Segment& x, const Segment& y) { return x.first_line < y.first_line; });
        std::uint64_t covered = 0;
        const Segment* last = nullptr;
        for (const Segment& s : segments) {
            if (s.first_line > covered) gaps[{covered, s.first_line}].push_back(whole[c]);
            if (s.first_line < covered && last != nullptr) {
                problems.add(shown, "capture " + capture_name(file, c) + " lines " +
                                        std::to_string(s.first_line) + " to " +
                                        std::to_string(std::min(covered, s.end_line) - 1) +
                                        " are in two parts: " + last->piece->part.string() +
                                        " and " + s.piece->part.string());
            }
            if (s.end_line > covered) last = &s;
            covered = std::max(covered, s.end_line);
            const Piece& p = *s.piece;
            const Piece& q = *segments.front().piece;
            const std::size_t j = segments.front().position;
            if (p.ids[s.position] != q.ids[j] || p.windows[s.position] != q.windows[j] ||
                p.datetimes[s.position] != q.datetimes[j]) {
                problems.add(shown, "capture " + std::to_string(whole[c]) +
                                        " has another id, window or time in " + p.part.string() +
                                        " than in " + q.part.string());
            }
        }
        if (covered < lines) gaps[{covered, lines}].push_back(whole[c]);
    }
    for (const auto& [band, captures] : gaps) {
        const std::string list = io::format_index_runs(captures);
        problems.add(shown, (captures.size() == 1 ? "capture " : "captures ") +
                                list.substr(1, list.size() - 2) + " lines " +
                                std::to_string(band.first) + " to " +
                                std::to_string(band.second - 1) + " are in no part (of " +
                                std::to_string(lines) + " lines per capture)");
    }
    // The whole file's header: the first part's, with the whole file's lines and captures.
    io::EnviHeader& h = file.header;
    h = first.header;
    h.lines = static_cast<std::size_t>(lines * whole.size());
    std::erase_if(h.extra, [](const auto& kv) {
        return kv.first == io::kPartRowsKey || kv.first == io::kPartLinesPerCaptureKey ||
               kv.first == io::kPartCapturesKey;
    });
    std::vector<std::string> ids, indices, windows, datetimes;
    for (std::size_t c = 0; c < whole.size(); ++c) {
        indices.push_back(std::to_string(whole[c]));
        if (file.segments[c].empty()) continue;
        const Segment& s = file.segments[c].front();
        ids.push_back(s.piece->ids[s.position]);
        windows.push_back(s.piece->windows[s.position]);
        datetimes.push_back(s.piece->datetimes[s.position]);
    }
    h.set_extra(kCapturesKey, std::to_string(whole.size()));
    h.set_extra(kLinesPerCaptureKey, std::to_string(lines));
    h.set_extra(kIdsKey, io::envi_brace_list(ids));
    h.set_extra(kIndicesKey, io::envi_brace_list(indices));
    h.set_extra(kWindowsKey, io::envi_brace_list(windows));
    h.set_extra(kDatetimesKey, io::envi_brace_list(datetimes));
}
}  // namespace glint::app_envi::merge_detail
