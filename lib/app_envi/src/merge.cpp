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

#include "glint/app_envi/bin_commands.h"
#include "glint/core/atomic_file.h"
#include "glint/core/error.h"
#include "glint/core/folder_lock.h"
#include "glint/core/text.h"
#include "glint/inputs/schedule_file.h"
#include "glint/io/envi.h"
#include "glint/io/envi_part.h"
#include "glint/io/input_files.h"
#include "merge_pieces.h"

namespace glint::app_envi {
namespace {

namespace fs = std::filesystem;

using merge_detail::kCommandLineKey;
using merge_detail::Piece;
using merge_detail::Problems;
using merge_detail::Segment;
using merge_detail::WholeFile;

/// Bytes copied at a time.
constexpr std::size_t kCopyChunkBytes = std::size_t{16} << 20;

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
            if (!header.find_extra(io::kCapturesKey)) continue;  // not a glint-render image
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
            if (!merge_detail::read_piece(piece, shown, problems)) continue;
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
    for (auto& [rel, file] : images) merge_detail::resolve(file, out / rel, problems);
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
