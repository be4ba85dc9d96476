// SPDX-License-Identifier: Apache-2.0
// glint-envi on DIRSIG lidar BIN files (glint/app_envi/lidar_bin.h).
#include "glint/app_envi/lidar_bin.h"

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

namespace fs = std::filesystem;

std::string num(double v) { return format_shortest(v); }

/// Start time (s after the pulse) of value i of a pixel's bins × samples of `p`: the gate is
/// split evenly among them.
double bin_start_s(const io::BinPulse& p, std::size_t i) {
    const double bins = static_cast<double>(p.bin_count) * p.samples_per_bin;
    return p.gate_start_s + static_cast<double>(i) * (p.gate_stop_s - p.gate_start_s) / bins;
}

nlohmann::ordered_json pulse_json(const io::BinPulse& p) {
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
    double passive = 0.0;
    double active = 0.0;
    const std::size_t per_pixel = p.values_per_pixel();
    for (std::size_t i = 0; i < p.data.size(); ++i) {
        (i % per_pixel == 0 ? passive : active) += p.data[i];
    }
    j["total_passive_photons_per_s"] = passive;
    j["total_active_photons"] = active;
    return j;
}

nlohmann::ordered_json bin_json(const fs::path& path, const io::BinFile& file) {
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
    j["pitch_m"] = {h.x_pitch_m, h.y_pitch_m};
    j["array_offset_m"] = {h.x_offset_m, h.y_offset_m};
    j["distortion"] = {{"k1", h.k1}, {"k2", h.k2}};
    j["focal_plane_id"] = h.focal_plane_id;
    nlohmann::ordered_json tasks = nlohmann::ordered_json::array();
    for (const io::BinTask& task : file.tasks) {
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
        for (const io::BinPulse& p : task.pulses) pulses.push_back(pulse_json(p));
        tj["pulses"] = std::move(pulses);
        tasks.push_back(std::move(tj));
    }
    j["tasks"] = std::move(tasks);
    return j;
}

/// The ENVI cube of one pulse.
void write_pulse_cube(const fs::path& out, const fs::path& input, const io::BinFile& file,
                      std::size_t task, const io::BinPulse& p, const Context& ctx) {
    const io::BinFileHeader& h = file.header;
    io::EnviHeader header;
    header.description = "DIRSIG BIN pulse " + std::to_string(p.pulse_index) + " of task " +
                         std::to_string(task) + " of " + input.filename().string();
    header.samples = h.x_count;
    header.lines = h.y_count;
    header.bands = p.values_per_pixel();
    header.data_type = io::EnviDataType::float64;
    header.interleave = io::Interleave::bip;
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
    io::EnviWriter writer(out, header);
    const std::size_t line_values = static_cast<std::size_t>(h.x_count) * header.bands;
    for (std::size_t y = 0; y < h.y_count; ++y) {
        writer.write_line(std::span<const double>(p.data).subspan(y * line_values, line_values));
    }
    writer.commit();
}

/// Half the speed of light, m/s: range per second of round trip.
constexpr double kHalfLightSpeedMPerS = 0.5 * kSpeedOfLightMPerS;

/// The range image of one pulse: per pixel the range (m) and photons of its strongest time
/// sample.
void write_range_image(const fs::path& out, const fs::path& input, const io::BinFile& file,
                       std::size_t task, const io::BinPulse& p, const Context& ctx) {
    const io::BinFileHeader& h = file.header;
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
    io::EnviWriter writer(out, header);
    std::vector<double> line(static_cast<std::size_t>(h.x_count) * 2);
    for (std::size_t y = 0; y < h.y_count; ++y) {
        for (std::size_t x = 0; x < h.x_count; ++x) {
            const double* v = p.data.data() + (y * h.x_count + x) * values + 1;
            const double* peak = std::max_element(v, v + values - 1);
            const bool returned = values > 1 && *peak > 0.0;
            const double t = bin_start_s(p, static_cast<std::size_t>(peak - v)) + 0.5 * sample_s;
            line[2 * x] = returned ? kHalfLightSpeedMPerS * t : 0.0;
            line[2 * x + 1] = returned ? *peak : 0.0;
        }
        writer.write_line(line);
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

std::string format_bin_json(const fs::path& path, const io::BinFile& file) {
    return json_text(bin_json(path, file), 2);
}

std::string format_bin_text(const fs::path& path, const io::BinFile& file) {
    const io::BinFileHeader& h = file.header;
    std::ostringstream out;
    std::size_t pulses = 0;
    for (const io::BinTask& t : file.tasks) pulses += t.pulses.size();
    out << path.string() << ": DIRSIG BIN version " << int(h.version) << ", "
        << (h.little_endian ? "little" : "big") << " endian, " << h.x_count << " x " << h.y_count
        << " pixels, " << file.tasks.size() << " task(s), " << pulses << " pulse(s)\n";
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
        for (const io::BinPulse& p : file.tasks[t].pulses) {
            const nlohmann::ordered_json j = pulse_json(p);
            out << "    pulse " << p.pulse_index << ": t = " << num(p.time_s) << " s, gate "
                << num(p.gate_start_s) << " to " << num(p.gate_stop_s) << " s, " << p.bin_count
                << " bins x " << p.samples_per_bin << " samples; active "
                << num(j["total_active_photons"].get<double>()) << " photons, passive "
                << num(j["total_passive_photons_per_s"].get<double>()) << " photons/s\n";
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
    const io::BinFile file = io::read_bin(input);
    std::vector<std::pair<std::size_t, const io::BinPulse*>> all;
    for (std::size_t t = 0; t < file.tasks.size(); ++t) {
        for (const io::BinPulse& p : file.tasks[t].pulses) all.emplace_back(t, &p);
    }
    std::vector<fs::path> written;
    if (pulse) {
        if (*pulse >= all.size()) {
            throw usage_error("--pulse " + std::to_string(*pulse) + ": " + input.string() +
                              " holds " + std::to_string(all.size()) + " pulses (0-based)");
        }
        write(output, input, file, all[*pulse].first, *all[*pulse].second, ctx);
        written.push_back(output);
        return written;
    }
    for (std::size_t i = 0; i < all.size(); ++i) {
        char suffix[32];
        std::snprintf(suffix, sizeof suffix, "-p%04zu", i);
        fs::path out =
            output.parent_path() / (output.stem().string() + suffix + output.extension().string());
        ctx.cancel.throw_if_cancelled();
        write(out, input, file, all[i].first, *all[i].second, ctx);
        written.push_back(out);
    }
    return written;
}

}  // namespace glint::app_envi
