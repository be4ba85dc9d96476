// SPDX-License-Identifier: Apache-2.0
// glint-envi merge (glint/app_envi/merge.h): find the parts, check that they make whole
// files, then write each whole file.
#include "glint/app_envi/merge.h"

#include <stdlib.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include "glint/app_envi/lidar_bin.h"
#include "glint/core/atomic_file.h"
#include "glint/core/error.h"
#include "glint/core/folder_lock.h"
#include "glint/core/text.h"
#include "glint/inputs/schedule_file.h"
#include "glint/io/envi.h"
#include "glint/io/envi_part.h"
#include "glint/io/input_files.h"

namespace glint::app_envi {
namespace {

namespace fs = std::filesystem;

using io::kCapturesKey;
using io::kDatetimesKey;
using io::kIdsKey;
using io::kIndicesKey;
using io::kLinesPerCaptureKey;
using io::kWindowsKey;
constexpr const char* kCommandLineKey = "glint command line";

/// The most captures a whole file may have: what its merged header can list within the ENVI
/// header limit, at 32 bytes a capture at the least (524,288).
constexpr std::uint64_t kMaxWholeCaptures = io::kMaxEnviHeaderBytes / 32;
/// Bytes copied at a time.
constexpr std::size_t kCopyChunkBytes = std::size_t{16} << 20;

/// One glint-render image found in a part folder.
struct Piece {
    fs::path part;  ///< the part folder
    fs::path header_path;
    fs::path data_path;
    io::EnviHeader header;
    std::vector<std::uint64_t> captures;  ///< its captures' global indices, in file order
    std::vector<std::string> ids, windows, datetimes;  ///< per capture
    std::uint64_t first_line = 0;  ///< lines first_line … end_line − 1 of each capture
    std::uint64_t end_line = 0;
    std::uint64_t whole_lines = 0;  ///< lines per capture of the whole file
    /// The whole file's captures as index runs ("{0:4, 7}"), compared between parts and
    /// expanded once per file (WholeFile::captures), never per part.
    std::string whole_captures;
    std::uint64_t whole_capture_count = 0;
};

/// One band of lines of one capture, from a piece.
struct Segment {
    const Piece* piece = nullptr;
    std::size_t position = 0;  ///< the capture's position in the piece
    std::uint64_t first_line = 0;
    std::uint64_t end_line = 0;
};

/// A whole file and its pieces.
struct WholeFile {
    fs::path relative;
    std::vector<Piece> pieces;
    io::EnviHeader header;                       ///< of the merged file
    std::vector<std::uint64_t> captures;         ///< the whole file's captures, sorted
    std::vector<std::vector<Segment>> segments;  ///< per whole capture, in line order
};

/// Collects the problems of every file; merge writes nothing unless there is none.
class Problems {
public:
    void add(const fs::path& file, const std::string& message) {
        m_list.push_back(file.string() + ": " + message);
    }
    bool empty() const { return m_list.empty(); }
    /// Logs every problem and throws one input error counting them.
    [[noreturn]] void raise(Context& ctx) const {
        for (const std::string& p : m_list) ctx.log.error(p);
        throw input_error(std::to_string(m_list.size()) +
                          (m_list.size() == 1 ? " problem" : " problems") +
                          " in the parts (above): nothing was written");
    }

private:
    std::vector<std::string> m_list;
};

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

/// Every file under `part`, relative to it, in path order.
std::vector<fs::path> files_under(const fs::path& part) {
    std::vector<fs::path> files;
    std::error_code ec;
    fs::recursive_directory_iterator it(part, ec);
    if (ec) throw io_error("cannot read the part folder: " + ec.message(), part.string());
    for (; it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (ec) throw io_error("cannot read the part folder: " + ec.message(), part.string());
        if (it->is_regular_file(ec)) files.push_back(it->path().lexically_relative(part));
    }
    std::sort(files.begin(), files.end());
    return files;
}

/// "5 (t0c2)": a capture's global index and id.
std::string capture_name(const WholeFile& file, std::size_t position) {
    const Segment& s = file.segments[position].front();
    return std::to_string(file.captures[position]) + " (" + s.piece->ids[s.position] + ")";
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

/// `path` as merge compares output paths: absolute (a relative one counts from `base`), then
/// with every symbolic link of its existing part resolved (a cluster's /home -> /gpfs), so
/// the --expect list and the output folder name the same file the same way.
fs::path comparable(const fs::path& path, const fs::path& base) {
    const fs::path absolute = (path.is_absolute() ? path : base / path).lexically_normal();
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(absolute, ec);
    return ec ? absolute : canonical;
}

/// Every image and truth file a glint-schedule JSON lists, as comparable() paths: relative
/// ones count from the folder glint-schedule ran in (provenance.working_folder), else, for a
/// JSON without it, from the JSON's own folder.
std::set<fs::path> expected_files(const fs::path& schedule) {
    const inputs::ScheduleFile listed = inputs::read_schedule_file(schedule, true);
    fs::path base = fs::absolute(schedule).parent_path();
    if (listed.working_folder && fs::path(*listed.working_folder).is_absolute()) {
        base = *listed.working_folder;
    }
    std::set<fs::path> files;
    for (const inputs::ScheduleFile::Capture& capture : listed.captures) {
        if (!capture.image.empty()) files.insert(comparable(capture.image, base));
        for (const std::string& t : capture.truth) files.insert(comparable(t, base));
    }
    return files;
}

/// Writes one whole file from its pieces' lines.
void write_whole(const WholeFile& file, const fs::path& target, Context& ctx) {
    io::EnviWriter writer(target, file.header);
    const std::size_t line_bytes =
        file.header.samples * file.header.bands * file.header.value_bytes();
    std::map<const Piece*, std::ifstream> streams;
    std::vector<std::byte> buffer;
    for (const std::vector<Segment>& segments : file.segments) {
        ctx.cancel.throw_if_cancelled();
        for (const Segment& s : segments) {
            const Piece& p = *s.piece;
            std::ifstream& in = streams[&p];
            if (!in.is_open()) {
                in.open(p.data_path, std::ios::binary);
                if (!in) throw io_error("cannot open the part", p.data_path.string());
            }
            const std::uint64_t piece_lines = p.end_line - p.first_line;
            std::uint64_t line = static_cast<std::uint64_t>(s.position) * piece_lines;
            std::uint64_t left = s.end_line - s.first_line;
            const std::uint64_t chunk_lines =
                std::max<std::uint64_t>(1, kCopyChunkBytes / std::max<std::size_t>(line_bytes, 1));
            while (left > 0) {
                ctx.cancel.throw_if_cancelled();  // a one-capture file is all one segment
                const std::uint64_t n = std::min(left, chunk_lines);
                buffer.resize(static_cast<std::size_t>(n) * line_bytes);
                in.seekg(static_cast<std::streamoff>(p.header.header_offset + line * line_bytes));
                in.read(reinterpret_cast<char*>(buffer.data()),
                        static_cast<std::streamsize>(buffer.size()));
                if (!in) throw io_error("cannot read the part's lines", p.data_path.string());
                for (std::uint64_t i = 0; i < n; ++i) {
                    writer.write_line_raw(std::span<const std::byte>(buffer).subspan(
                        static_cast<std::size_t>(i) * line_bytes, line_bytes));
                }
                line += n;
                left -= n;
            }
        }
    }
    writer.set_extra(kCommandLineKey, ctx.command_line());
    ctx.cancel.throw_if_cancelled();
    writer.commit();
}

void copy_file(const fs::path& from, const fs::path& to, Context& ctx) {
    std::ifstream in(from, std::ios::binary);
    if (!in) throw io_error("cannot open the part", from.string());
    AtomicFile out(to);
    std::vector<char> buffer(kCopyChunkBytes);
    while (in) {
        ctx.cancel.throw_if_cancelled();
        in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
        out.write(buffer.data(), static_cast<std::size_t>(in.gcount()));
    }
    if (in.bad()) throw io_error("cannot read the part", from.string());
    out.commit();
}

/// A folder `.merge.tmp-XXXXXX` inside `parent`, removed with what it holds when it goes.
class StagingFolder {
public:
    explicit StagingFolder(const fs::path& parent) {
        std::string name = (parent / ".merge.tmp-XXXXXX").string();
        if (::mkdtemp(name.data()) == nullptr) {
            throw io_error("cannot create a staging folder: " + errno_text(errno), parent.string());
        }
        m_path = name;
    }
    ~StagingFolder() {
        std::error_code ec;
        fs::remove_all(m_path, ec);
    }
    StagingFolder(const StagingFolder&) = delete;
    StagingFolder& operator=(const StagingFolder&) = delete;
    const fs::path& path() const { return m_path; }

private:
    fs::path m_path;
};

bool inside(const fs::path& path, const fs::path& folder) {
    const fs::path rel = path.lexically_relative(folder);
    return !rel.empty() && *rel.begin() != "..";
}

}  // namespace

std::vector<fs::path> merge_parts(const MergeOptions& options, Context& ctx) {
    if (options.parts.empty()) throw usage_error("merge needs at least one part folder");
    if (options.output_folder.empty()) throw usage_error("merge needs -o OUTPUT_FOLDER");
    const fs::path out = fs::weakly_canonical(fs::absolute(options.output_folder));
    std::vector<fs::path> parts;
    for (const fs::path& part : options.parts) {
        std::error_code ec;
        if (!fs::is_directory(part, ec)) {
            throw input_error(
                "not a folder: merge joins the folders sharded glint-render runs "
                "wrote (one --output-folder per shard)",
                ErrorContext{part.string(), 0, {}});
        }
        const fs::path canonical = fs::weakly_canonical(fs::absolute(part));
        if (std::find(parts.begin(), parts.end(), canonical) != parts.end()) {
            throw usage_error("the part folder " + part.string() + " is given twice");
        }
        if (canonical == out || inside(out, canonical)) {
            throw usage_error("the output folder " + options.output_folder.string() +
                              " is (inside) the part folder " + part.string() +
                              ": merge into a folder of its own");
        }
        parts.push_back(canonical);
    }

    // Find the parts: glint-render images by their headers, lidar BIN files, and the rest.
    Problems problems;
    std::map<fs::path, WholeFile> images;  // by relative data path
    std::map<fs::path, std::vector<fs::path>> bins;
    std::vector<fs::path> others;
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const fs::path& part = options.parts[k];
        const std::vector<fs::path> files = files_under(part);
        std::set<fs::path> claimed;
        for (const fs::path& rel : files) {
            if (rel.extension() != ".hdr") continue;
            const fs::path shown = part / rel;
            io::EnviHeader header;
            fs::path data;
            try {
                io::EnviReader reader(shown, io::EnviReader::LineUse::describe_only);
                header = reader.header();
                data = reader.data_path();
            } catch (const Error& e) {
                problems.add(shown, std::string("cannot be read as an ENVI image: ") + e.what());
                continue;
            }
            if (!header.find_extra(kCapturesKey)) continue;  // not a glint-render image
            const fs::path data_rel = data.lexically_relative(part);
            claimed.insert(rel);
            claimed.insert(data_rel);
            if (header.interleave != io::Interleave::bip || header.header_offset != 0 ||
                header.byte_order != io::native_byte_order()) {
                problems.add(shown,
                             "not written by glint-render here (it writes BIP in this "
                             "machine's byte order, no header offset)");
                continue;
            }
            Piece piece;
            piece.part = part;
            piece.header_path = shown;
            piece.data_path = data;
            piece.header = std::move(header);
            if (!read_piece(piece, shown, problems)) continue;
            WholeFile& whole = images[data_rel];
            whole.relative = data_rel;
            whole.pieces.push_back(std::move(piece));
        }
        for (const fs::path& rel : files) {
            if (claimed.contains(rel)) continue;
            if (rel.extension() == ".hdr") {
                others.push_back(part / rel);
            } else if (rel.extension() == ".bin" && is_lidar_bin(part / rel)) {
                bins[rel].push_back(part / rel);
            } else {
                others.push_back(part / rel);
            }
        }
    }
    for (auto& [rel, file] : images) resolve(file, out / rel, problems);
    for (const auto& [rel, copies] : bins) {
        if (images.contains(rel)) {
            problems.add(out / rel, "is both an ENVI image and a BIN file in the parts");
        } else if (copies.size() > 1) {
            problems.add(out / rel, "is in two parts: " + copies[0].string() + " and " +
                                        copies[1].string() +
                                        " (glint-render writes a lidar receiver's BIN file whole, "
                                        "in one shard)");
        }
    }
    if (!options.expect.empty()) {
        const std::set<fs::path> expected = expected_files(options.expect);
        std::set<fs::path> produced;
        for (const auto& [rel, file] : images) produced.insert(comparable(out / rel, out));
        for (const auto& [rel, copies] : bins) produced.insert(comparable(out / rel, out));
        for (const fs::path& f : expected) {
            if (!produced.contains(f)) {
                problems.add(f, "listed in " + options.expect.string() + " but in no part");
            }
        }
        for (const fs::path& f : produced) {
            if (!expected.contains(f)) {
                problems.add(f, "in the parts but not listed in " + options.expect.string() +
                                    " (was it made with glint-schedule --output-folder " +
                                    options.output_folder.string() + "?)");
            }
        }
    }
    if (images.empty() && bins.empty()) {
        problems.add(options.parts.front(), "no glint-render image in the part folders");
    }
    if (!problems.empty()) problems.raise(ctx);
    if (!others.empty()) {
        std::string list;
        for (std::size_t i = 0; i < others.size() && i < 3; ++i) {
            list += (i > 0 ? ", " : "") + others[i].string();
        }
        if (others.size() > 3) list += " and " + std::to_string(others.size() - 3) + " more";
        ctx.log.warning(std::to_string(others.size()) +
                        " files in the part folders are not glint-render images and were not "
                        "merged: " +
                        list);
    }

    // Write every file into a staging folder inside the locked output folder, then publish
    // them all by renames: an interrupt or a full disk leaves none of them under its name.
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec) throw io_error("cannot create the output folder: " + ec.message(), out.string());
    const FolderLock lock(out);
    const StagingFolder staging(out);
    struct Staged {
        fs::path from, to;
        bool listed = true;  ///< a data file (listed on stdout), not a header
    };
    std::vector<Staged> staged;  // data before its header, as glint-render publishes
    const auto stage = [&](const fs::path& rel) {
        const fs::path path = staging.path() / rel;
        fs::create_directories(path.parent_path(), ec);
        if (ec)
            throw io_error("cannot create a folder: " + ec.message(), path.parent_path().string());
        staged.push_back({path, options.output_folder / rel});
        return path;
    };
    for (const auto& [rel, file] : images) {
        const fs::path path = stage(rel);
        write_whole(file, path, ctx);
        staged.push_back({fs::path(path.string() + ".hdr"),
                          fs::path((options.output_folder / rel).string() + ".hdr"), false});
    }
    for (const auto& [rel, copies] : bins) copy_file(copies.front(), stage(rel), ctx);
    ctx.cancel.throw_if_cancelled();
    std::vector<fs::path> written;
    for (const Staged& file : staged) {
        fs::create_directories(file.to.parent_path(), ec);
        fs::rename(file.from, file.to, ec);
        if (ec) throw io_error("cannot publish the merged file: " + ec.message(), file.to.string());
        if (file.listed) written.push_back(file.to);
    }
    std::sort(written.begin(), written.end());
    return written;
}

}  // namespace glint::app_envi
