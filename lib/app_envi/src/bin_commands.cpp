// SPDX-License-Identifier: Apache-2.0
// glint-envi on DIRSIG lidar BIN files (glint/app_envi/bin_commands.h).
#include "glint/app_envi/bin_commands.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "glint/core/error.h"
#include "glint/core/json_text.h"
#include "glint/core/text.h"
#include "glint/core/units.h"
#include "glint/io/envi.h"
#include "glint/io/output_kind.h"
#include "glint/io/regular_file.h"

namespace glint::app_envi {
namespace {

/// The order glint reads a pulse's pixels in (docs/lidar-bin.md, "Pixel order"): the
/// published readers disagree, so every report says which one glint assumed.
constexpr const char* kPixelOrder =
    "x slowest, then y ([x][y][value]); each pixel's values together";

namespace fs = std::filesystem;

std::string num(double v) { return format_shortest(v); }

/// Start time (s after the pulse) of value i of a pixel's bins × samples of `p`: the gate is
/// split evenly among them.
double bin_start_s(const io::BinPulse& p, std::size_t i) {
    const double bins = static_cast<double>(p.bin_count) * p.samples_per_bin;
    return p.gate_start_s + static_cast<double>(i) * (p.gate_stop_s - p.gate_start_s) / bins;
}

nlohmann::ordered_json pulse_json(const BinSummary::Pulse& pulse) {
    const io::BinPulse& p = pulse.header;
    nlohmann::ordered_json j;
    j["index"] = p.pulse_index;
    j["time_s"] = p.time_s;
    j["gate_s"] = {p.gate_start_s, p.gate_stop_s};
    j["bin_count"] = p.bin_count;
    j["samples_per_bin"] = p.samples_per_bin;
    j["platform_location"] = p.platform_location;
    j["platform_rotation"] = p.platform_rotation;
    j["transmitter_to_mount"] = p.transmitter_to_mount;
    j["transmitter_mount_pointing"] = p.transmitter_mount_pointing;
    j["transmitter_mount_to_platform"] = p.transmitter_mount_to_platform;
    j["receiver_to_mount"] = p.receiver_to_mount;
    j["receiver_mount_pointing"] = p.receiver_mount_pointing;
    j["receiver_mount_to_platform"] = p.receiver_mount_to_platform;
    j["data_type"] = p.data_type;
    j["compression"] = p.compression;
    j["data_bytes"] = p.data_bytes;
    j["total_passive_photons_per_s"] = pulse.passive_photons_per_s;
    j["total_active_photons"] = pulse.active_photons;
    return j;
}

nlohmann::ordered_json bin_json(const fs::path& path, const BinSummary& file) {
    const io::BinFileHeader& h = file.header;
    nlohmann::ordered_json j;
    j["file"] = path.string();
    j["format"] = "DIRSIG BIN";
    j["version"] = h.version;
    j["byte_order"] = h.little_endian ? "little" : "big";
    j["created"] = h.created;
    j["dirsig_version"] = h.dirsig_version;
    j["description"] = h.description;
    j["scene_origin"] = {{"latitude_deg", h.origin_latitude_deg},
                         {"longitude_deg", h.origin_longitude_deg},
                         {"height_m", h.origin_height_m}};
    j["transmitter_mount"] = h.transmitter_mount;
    j["receiver_mount"] = h.receiver_mount;
    j["x_count"] = h.x_count;
    j["y_count"] = h.y_count;
    j["pixel_order"] = kPixelOrder;
    j["pitch_m"] = {h.x_pitch_m, h.y_pitch_m};
    j["array_offset_m"] = {h.x_offset_m, h.y_offset_m};
    j["distortion"] = {{"k1", h.k1}, {"k2", h.k2}};
    j["focal_plane_id"] = h.focal_plane_id;
    nlohmann::ordered_json tasks = nlohmann::ordered_json::array();
    for (const BinSummary::Task& task : file.tasks) {
        const io::BinTaskHeader& t = task.header;
        nlohmann::ordered_json tj;
        tj["description"] = t.description;
        tj["start"] = t.start;
        tj["stop"] = t.stop;
        tj["focal_length_mm"] = t.focal_length_mm;
        tj["pulse_rate_hz"] = t.pulse_rate_hz;
        tj["pulse_duration_s"] = t.pulse_duration_s;
        tj["pulse_energy_j"] = t.pulse_energy_j;
        tj["laser_center_um"] = t.laser_center_um;
        tj["laser_width_um"] = t.laser_width_um;
        tj["pulse_count"] = task.pulses.size();
        nlohmann::ordered_json pulses = nlohmann::ordered_json::array();
        for (const BinSummary::Pulse& p : task.pulses) pulses.push_back(pulse_json(p));
        tj["pulses"] = std::move(pulses);
        tasks.push_back(std::move(tj));
    }
    j["tasks"] = std::move(tasks);
    return j;
}

/// A buffer of `pixels` pixels of `per_pixel` values each for `what` of pulse `p`, refused
/// beyond `max_memory_bytes`.
std::vector<double> pixel_buffer(const io::BinPulse& p, std::uint64_t pixels,
                                 std::uint64_t per_pixel, const char* what,
                                 std::size_t max_memory_bytes) {
    const std::uint64_t values = pixels * per_pixel;  // the reader bounds a pulse to 4 GiB
    if (values * sizeof(double) > max_memory_bytes) {
        throw usage_error(
            std::string(what) + " of BIN pulse " + std::to_string(p.pulse_index) + " (" +
            std::to_string(pixels) + " pixels of " + std::to_string(per_pixel) + " values) needs " +
            format_byte_size(static_cast<double>(values * sizeof(double))) +
            ", more than --max-memory " + format_byte_size(static_cast<double>(max_memory_bytes)));
    }
    return std::vector<double>(static_cast<std::size_t>(values));
}

/// The ENVI cube of one pulse (y lines of x samples of its values per pixel, BIP).
void write_pulse_cube(const fs::path& out, const fs::path& input, io::BinReader& reader,
                      std::size_t task, const io::BinPulse& p, const Context& ctx) {
    const io::BinFileHeader& h = reader.header();
    io::EnviHeader header;
    header.description = "DIRSIG BIN pulse " + std::to_string(p.pulse_index) + " of task " +
                         std::to_string(task) + " of " + input.filename().string();
    header.samples = h.x_count;
    header.lines = h.y_count;
    header.bands = p.values_per_pixel();
    header.data_type = io::EnviDataType::float64;
    header.interleave = io::Interleave::bip;
    header.set_extra("glint bin pixel order", kPixelOrder);
    header.data_units = "photons";
    header.band_names.push_back("passive (photons/s)");
    for (std::size_t b = 0; b + 1 < header.bands; ++b) {
        char name[80];
        if (p.samples_per_bin > 1) {
            std::snprintf(name, sizeof name, "bin %zu sample %zu (t = %.6g s)",
                          b / p.samples_per_bin, b % p.samples_per_bin, bin_start_s(p, b));
        } else {
            std::snprintf(name, sizeof name, "bin %zu (t = %.6g s)", b, bin_start_s(p, b));
        }
        header.band_names.push_back(name);
    }
    header.set_extra("glint tool", "glint-envi convert");
    header.set_extra("glint source", input.string());
    header.set_extra("glint command line", ctx.command_line());
    header.set_extra("glint bin pulse", std::to_string(p.pulse_index));
    header.set_extra("glint bin pulse time", num(p.time_s));
    header.set_extra("glint bin gate", "{" + num(p.gate_start_s) + ", " + num(p.gate_stop_s) + "}");
    header.set_extra("glint bin samples per bin", std::to_string(p.samples_per_bin));
    // The file holds x slowest and an ENVI cube y slowest: the whole pulse is read, then
    // written line by line.
    const std::size_t values = p.values_per_pixel();
    std::vector<double> pulse = pixel_buffer(p, std::uint64_t{h.x_count} * h.y_count, values,
                                             "the cube", ctx.max_memory_bytes);
    reader.read_values(pulse);
    std::vector<double> line(static_cast<std::size_t>(h.x_count) * values);
    io::EnviWriter writer(out, header);
    for (std::size_t y = 0; y < h.y_count; ++y) {
        ctx.cancel.throw_if_cancelled();
        for (std::size_t x = 0; x < h.x_count; ++x) {
            const double* from = pulse.data() + io::bin_pixel_index(x, y, h.y_count) * values;
            std::copy(from, from + values, line.begin() + static_cast<std::ptrdiff_t>(x * values));
        }
        writer.write_line(line);
    }
    writer.commit();
}

/// Half the speed of light, m/s: range per second of round trip.
constexpr double kHalfLightSpeedMPerS = 0.5 * kSpeedOfLightMPerS;

/// The range image of one pulse: per pixel the range (m) and photons of its strongest time
/// sample.
void write_range_image(const fs::path& out, const fs::path& input, io::BinReader& reader,
                       std::size_t task, const io::BinPulse& p, const Context& ctx) {
    const io::BinFileHeader& h = reader.header();
    io::EnviHeader header;
    header.description = "range image of DIRSIG BIN pulse " + std::to_string(p.pulse_index) +
                         " of task " + std::to_string(task) + " of " + input.filename().string();
    header.samples = h.x_count;
    header.lines = h.y_count;
    header.bands = 2;
    header.data_type = io::EnviDataType::float64;
    header.interleave = io::Interleave::bip;
    header.band_names = {"range of the strongest return (m)", "its photons"};
    header.set_extra("glint tool", "glint-envi convert --range");
    header.set_extra("glint source", input.string());
    header.set_extra("glint command line", ctx.command_line());
    header.set_extra("glint bin pulse", std::to_string(p.pulse_index));
    const std::size_t values = p.values_per_pixel();
    const double sample_s =
        (p.gate_stop_s - p.gate_start_s) / (static_cast<double>(p.bin_count) * p.samples_per_bin);
    // The file holds x slowest: each column of y pixels is read in turn and reduced into the
    // image (2 values per pixel), which is then written line by line.
    std::vector<double> column =
        pixel_buffer(p, h.y_count, values, "a column", ctx.max_memory_bytes);
    std::vector<double> image = pixel_buffer(p, std::uint64_t{h.x_count} * h.y_count, 2,
                                             "the range image", ctx.max_memory_bytes);
    for (std::size_t x = 0; x < h.x_count; ++x) {
        ctx.cancel.throw_if_cancelled();
        reader.read_values(column);
        for (std::size_t y = 0; y < h.y_count; ++y) {
            const double* v = column.data() + y * values + 1;
            const double* peak = std::max_element(v, v + values - 1);
            const bool returned = values > 1 && *peak > 0.0;
            const double t = bin_start_s(p, static_cast<std::size_t>(peak - v)) + 0.5 * sample_s;
            double* pixel = image.data() + 2 * (y * h.x_count + x);
            pixel[0] = returned ? kHalfLightSpeedMPerS * t : 0.0;
            pixel[1] = returned ? *peak : 0.0;
        }
    }
    io::EnviWriter writer(out, header);
    const std::size_t line_values = static_cast<std::size_t>(h.x_count) * 2;
    for (std::size_t y = 0; y < h.y_count; ++y) {
        writer.write_line(std::span<const double>(image.data() + y * line_values, line_values));
    }
    writer.commit();
}

}  // namespace

bool is_lidar_bin(const fs::path& path) {
    if (io::not_a_regular_file(path)) return false;  // opening a FIFO would block
    std::ifstream in(path, std::ios::binary);
    char magic[11] = {};
    return in.read(magic, sizeof magic) && std::string(magic, sizeof magic) == "DIRSIGPROTO";
}

std::uint64_t BinSummary::pulse_count() const {
    std::uint64_t count = 0;
    for (const Task& t : tasks) count += t.pulses.size();
    return count;
}

BinSummary summarize_bin(const fs::path& path, const CancelToken& cancel) {
    constexpr std::size_t kChunkValues = std::size_t{1} << 16;
    io::BinReader reader(path);
    BinSummary summary;
    summary.header = reader.header();
    std::vector<double> chunk;
    while (std::optional<io::BinTaskHeader> task = reader.next_task()) {
        summary.tasks.push_back({*task, {}});
        while (std::optional<io::BinPulse> pulse = reader.next_pulse()) {
            cancel.throw_if_cancelled();
            BinSummary::Pulse totals{*pulse, 0.0, 0.0};
            const std::uint64_t per_pixel = pulse->values_per_pixel();
            std::uint64_t index = 0;  // of the next value within the pulse
            while (reader.values_left() > 0) {
                chunk.resize(static_cast<std::size_t>(
                    std::min<std::uint64_t>(reader.values_left(), kChunkValues)));
                reader.read_values(chunk);
                for (const double v : chunk) {
                    (index % per_pixel == 0 ? totals.passive_photons_per_s
                                            : totals.active_photons) += v;
                    ++index;
                }
            }
            summary.tasks.back().pulses.push_back(std::move(totals));
        }
    }
    return summary;
}

std::string format_bin_json(const fs::path& path, const BinSummary& file) {
    return json_text(bin_json(path, file), 2);
}

std::string format_bin_text(const fs::path& path, const BinSummary& file) {
    const io::BinFileHeader& h = file.header;
    std::ostringstream out;
    out << path.string() << ": DIRSIG BIN version " << int(h.version) << ", "
        << (h.little_endian ? "little" : "big") << " endian, " << h.x_count << " x " << h.y_count
        << " pixels, " << file.tasks.size() << " task(s), " << file.pulse_count() << " pulse(s)\n";
    out << "  pixel order (assumed): " << kPixelOrder << "\n";
    out << "  created: " << h.created << "; written by: " << h.dirsig_version << "\n";
    if (!h.description.empty()) out << "  description: " << h.description << "\n";
    out << "  scene origin: " << num(h.origin_latitude_deg) << " deg, "
        << num(h.origin_longitude_deg) << " deg, " << num(h.origin_height_m) << " m\n";
    out << "  pitch: " << num(h.x_pitch_m) << " x " << num(h.y_pitch_m) << " m; array offset "
        << num(h.x_offset_m) << ", " << num(h.y_offset_m) << " m; k1 " << num(h.k1) << ", k2 "
        << num(h.k2) << "; mounts: transmitter " << quote(h.transmitter_mount) << ", receiver "
        << quote(h.receiver_mount) << "; focal plane " << h.focal_plane_id << "\n";
    for (std::size_t t = 0; t < file.tasks.size(); ++t) {
        const io::BinTaskHeader& th = file.tasks[t].header;
        out << "  task " << t << ": " << quote(th.description) << " " << th.start << " to "
            << th.stop << "; focal length " << num(th.focal_length_mm) << " mm; pulses "
            << file.tasks[t].pulses.size() << " at " << num(th.pulse_rate_hz) << " Hz, "
            << num(th.pulse_energy_j) << " J, " << num(th.pulse_duration_s) << " s; laser "
            << num(th.laser_center_um) << " um, width " << num(th.laser_width_um) << " um\n";
        for (const BinSummary::Pulse& pulse : file.tasks[t].pulses) {
            const io::BinPulse& p = pulse.header;
            out << "    pulse " << p.pulse_index << ": t = " << num(p.time_s) << " s, gate "
                << num(p.gate_start_s) << " to " << num(p.gate_stop_s) << " s, " << p.bin_count
                << " bins x " << p.samples_per_bin << " samples; active "
                << num(pulse.active_photons) << " photons, passive "
                << num(pulse.passive_photons_per_s) << " photons/s\n";
        }
    }
    return out.str();
}

std::vector<fs::path> convert_bin(const fs::path& input, const fs::path& output,
                                  std::optional<std::uint64_t> pulse, bool range,
                                  const Context& ctx) {
    const auto write = range ? write_range_image : write_pulse_cube;
    if (io::output_kind_of(output, "") != io::OutputKind::envi) {
        throw usage_error(
            "a BIN file converts to ENVI cubes (an output ending in .img, .dat, "
            ".bip, …): convert the cube to an image afterwards");
    }
    // The whole file is checked before anything is written.
    const std::uint64_t count = summarize_bin(input, ctx.cancel).pulse_count();
    if (pulse && *pulse >= count) {
        throw usage_error("--pulse " + std::to_string(*pulse) + ": " + input.string() + " holds " +
                          std::to_string(count) + " pulses (0-based)");
    }
    io::BinReader reader(input);
    std::vector<fs::path> written;
    std::uint64_t i = 0;
    for (std::size_t t = 0; std::optional<io::BinTaskHeader> task = reader.next_task(); ++t) {
        while (std::optional<io::BinPulse> p = reader.next_pulse()) {
            const std::uint64_t number = i++;
            if (pulse && number != *pulse) continue;
            ctx.cancel.throw_if_cancelled();
            fs::path out = output;
            if (!pulse) {
                char suffix[32];
                std::snprintf(suffix, sizeof suffix, "-p%04llu",
                              static_cast<unsigned long long>(number));
                out = output.parent_path() /
                      (output.stem().string() + suffix + output.extension().string());
            }
            write(out, input, reader, t, *p, ctx);
            written.push_back(out);
        }
    }
    return written;
}

}  // namespace glint::app_envi
