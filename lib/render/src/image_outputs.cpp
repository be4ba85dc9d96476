// SPDX-License-Identifier: Apache-2.0
// ImageOutputs: planned ENVI files filled capture by capture (glint/render/image_outputs.h).
#include "glint/render/image_outputs.h"

#include <optional>
#include <string>
#include <utility>

#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/io/envi_part.h"

namespace glint::render {

struct ImageOutputs::File {
    io::EnviHeader header;
    std::uint64_t lines_per_capture = 0;
    std::uint64_t captures = 0;
    std::uint64_t written = 0;           ///< captures ended
    std::uint64_t lines_in_capture = 0;  ///< lines of the current capture written
    std::vector<CaptureStamp> stamps;
    std::optional<io::EnviWriter> writer;
    std::optional<PartOf> part;
};

struct ImageOutputs::BinFile {
    io::BinFileHeader header;
    std::vector<std::pair<io::BinTaskHeader, std::uint32_t>> tasks;
    std::size_t task = 0;           ///< the task being written
    std::uint32_t task_pulses = 0;  ///< pulses of it written
    std::optional<io::BinWriter> writer;
};

ImageOutputs::ImageOutputs() = default;
ImageOutputs::~ImageOutputs() = default;
ImageOutputs::ImageOutputs(ImageOutputs&&) noexcept = default;
ImageOutputs& ImageOutputs::operator=(ImageOutputs&&) noexcept = default;

void ImageOutputs::plan(const std::filesystem::path& path, io::EnviHeader header,
                        std::uint64_t lines_per_capture, std::uint64_t captures,
                        std::optional<PartOf> part) {
    header.lines = static_cast<std::size_t>(lines_per_capture * captures);
    auto it = m_files.find(path);
    if (it != m_files.end()) {
        const File& f = *it->second;
        if (f.header.samples != header.samples || f.header.bands != header.bands ||
            f.lines_per_capture != lines_per_capture) {
            throw usage_error("output " + path.string() +
                              " is written by two focal planes of different shapes");
        }
        it->second->captures += captures;
        it->second->header.lines =
            static_cast<std::size_t>(it->second->lines_per_capture * it->second->captures);
        return;
    }
    auto file = std::make_unique<File>();
    file->header = std::move(header);
    file->lines_per_capture = lines_per_capture;
    file->captures = captures;
    file->part = std::move(part);
    m_files.emplace(path, std::move(file));
    m_order.push_back(path);
}

void ImageOutputs::write_capture(const std::filesystem::path& path, std::span<const double> image,
                                 const CaptureStamp& stamp) {
    auto it = m_files.find(path);
    if (it == m_files.end()) throw internal_error("write to unplanned output " + path.string());
    const File& f = *it->second;
    const std::size_t line_values = f.header.samples * f.header.bands;
    if (image.size() != line_values * f.lines_per_capture) {
        throw internal_error("capture image of " + std::to_string(image.size()) + " values for " +
                             path.string() + ", expected " +
                             std::to_string(line_values * f.lines_per_capture));
    }
    write_lines(path, image);
    end_capture(path, stamp);
}

void ImageOutputs::write_lines(const std::filesystem::path& path, std::span<const double> lines) {
    auto it = m_files.find(path);
    if (it == m_files.end()) throw internal_error("write to unplanned output " + path.string());
    File& f = *it->second;
    const std::size_t line_values = f.header.samples * f.header.bands;
    if (line_values == 0 || lines.size() % line_values != 0 ||
        f.lines_in_capture + lines.size() / line_values > f.lines_per_capture) {
        throw internal_error(std::to_string(lines.size()) + " values for " + path.string() +
                             ": not whole lines of its current capture");
    }
    if (f.written >= f.captures) {
        throw internal_error("more captures than planned for " + path.string());
    }
    if (!f.writer) {
        open_folder(path);
        f.writer.emplace(path, f.header);
    }
    for (std::size_t at = 0; at < lines.size(); at += line_values) {
        f.writer->write_line(lines.subspan(at, line_values));
    }
    f.lines_in_capture += lines.size() / line_values;
}

void ImageOutputs::end_capture(const std::filesystem::path& path, const CaptureStamp& stamp) {
    auto it = m_files.find(path);
    if (it == m_files.end()) throw internal_error("write to unplanned output " + path.string());
    File& f = *it->second;
    if (f.lines_in_capture != f.lines_per_capture) {
        throw internal_error("capture of " + std::to_string(f.lines_in_capture) + " lines for " +
                             path.string() + ", expected " + std::to_string(f.lines_per_capture));
    }
    f.lines_in_capture = 0;
    f.stamps.push_back(stamp);
    ++f.written;
    if (f.written < f.captures) return;

    std::vector<std::string> times;
    std::vector<std::string> ids;
    std::vector<std::string> datetimes;
    std::vector<std::string> indices;
    for (const CaptureStamp& s : f.stamps) {
        times.push_back(format_shortest(s.t0_s) + " " + format_shortest(s.t1_s));
        ids.push_back("t" + std::to_string(s.task) + "c" + std::to_string(s.capture));
        datetimes.push_back(s.datetime_utc);
        indices.push_back(std::to_string(s.index));
    }
    f.writer->set_extra(io::kCapturesKey, std::to_string(f.stamps.size()));
    f.writer->set_extra(io::kLinesPerCaptureKey, std::to_string(f.lines_per_capture));
    f.writer->set_extra(io::kIdsKey, io::envi_brace_list(ids));
    f.writer->set_extra(io::kIndicesKey, io::envi_brace_list(indices));
    f.writer->set_extra(io::kWindowsKey, io::envi_brace_list(times));
    f.writer->set_extra(io::kDatetimesKey, io::envi_brace_list(datetimes));
    if (f.part) {
        f.writer->set_extra(io::kPartRowsKey, "{" + std::to_string(f.part->first_line) + ", " +
                                                  std::to_string(f.part->end_line) + "}");
        f.writer->set_extra(io::kPartLinesPerCaptureKey,
                            std::to_string(f.part->whole_lines_per_capture));
        f.writer->set_extra(io::kPartCapturesKey, io::format_index_runs(f.part->whole_captures));
    }
    f.writer->commit();
    f.writer.reset();
    m_published.push_back(path);
}

void ImageOutputs::open_folder(const std::filesystem::path& path) {
    // The output folder is created as DIRSIG does; an existing file in its place, or a
    // folder that cannot be created, is an io error naming it.
    const std::filesystem::path folder = path.parent_path();
    if (!folder.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(folder, ec);
        if (ec) {
            throw io_error("cannot create the output folder: " + ec.message(), folder.string());
        }
    }
    if (!m_locks.contains(folder))
        m_locks.emplace(folder, FolderLock(folder.empty() ? "." : folder));
}

void ImageOutputs::plan_bin(const std::filesystem::path& path, const io::BinFileHeader& header,
                            std::vector<std::pair<io::BinTaskHeader, std::uint32_t>> tasks) {
    if (m_bins.contains(path) || m_files.contains(path)) {
        throw usage_error("output " + path.string() + " is planned twice");
    }
    auto file = std::make_unique<BinFile>();
    file->header = header;
    file->tasks = std::move(tasks);
    m_bins.emplace(path, std::move(file));
    m_order.push_back(path);
}

void ImageOutputs::write_pulse(const std::filesystem::path& path, const io::BinPulse& pulse) {
    auto it = m_bins.find(path);
    if (it == m_bins.end()) throw internal_error("pulse for unplanned output " + path.string());
    BinFile& f = *it->second;
    if (f.task >= f.tasks.size())
        throw internal_error("more pulses than planned for " + path.string());
    if (!f.writer) {
        open_folder(path);
        f.writer.emplace(path, f.header, static_cast<std::uint32_t>(f.tasks.size()));
    }
    if (f.task_pulses == 0) f.writer->begin_task(f.tasks[f.task].first, f.tasks[f.task].second);
    f.writer->add_pulse(pulse);
    if (++f.task_pulses < f.tasks[f.task].second) return;
    f.task_pulses = 0;
    if (++f.task < f.tasks.size()) return;
    f.writer->commit();
    f.writer.reset();
    m_published.push_back(path);
}

void ImageOutputs::lock_folders() {
    for (const std::filesystem::path& path : m_order) {
        const std::filesystem::path folder = path.parent_path();
        if (m_locks.contains(folder)) continue;
        std::error_code ec;
        if (!std::filesystem::is_directory(folder.empty() ? "." : folder, ec)) continue;
        m_locks.emplace(folder, FolderLock(folder.empty() ? "." : folder));
    }
}

std::vector<std::filesystem::path> ImageOutputs::planned() const { return m_order; }

std::vector<std::pair<std::filesystem::path, std::string>> ImageOutputs::written() const {
    std::vector<std::pair<std::filesystem::path, std::string>> files;
    for (const std::filesystem::path& path : m_order) {
        const std::string name = path.filename().string();
        if (m_bins.count(path) > 0) {
            files.emplace_back(path, "lidar file " + name);
            continue;
        }
        files.emplace_back(path, "image " + name);
        files.emplace_back(std::filesystem::path(path.string() + ".hdr"),
                           "header of image " + name);
    }
    return files;
}

}  // namespace glint::render
