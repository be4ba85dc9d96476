// SPDX-License-Identifier: Apache-2.0
// DIRSIG BIN writing (glint/io/lidar_bin.h): the file header, task headers and pulses in
// little-endian order, each pulse's data zlib compressed, published atomically on commit.
#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>

#include "glint/core/atomic_file.h"
#include "glint/core/error.h"
#include "glint/io/lidar_bin.h"
#include "lidar_bin_magic.h"

namespace glint::io {
namespace {

namespace fs = std::filesystem;

using bin_detail::kMagic;
using bin_detail::kMagicSize;

/// Appends values in little-endian order.
class Out {
public:
    template <class T>
    void value(T v) {
        if constexpr (std::endian::native != std::endian::little && sizeof(T) > 1) {
            auto* b = reinterpret_cast<unsigned char*>(&v);
            std::reverse(b, b + sizeof(T));
        }
        bytes.append(reinterpret_cast<const char*>(&v), sizeof(T));
    }
    void text(const std::string& s, std::size_t n) {
        std::string padded = s.substr(0, n);
        padded.resize(n, '\0');
        bytes += padded;
    }
    template <std::size_t N>
    void doubles(const std::array<double, N>& a) {
        for (const double v : a) value(v);
    }
    std::string bytes;
};

/// The pulse data of `p`, little-endian float64 values, zlib compressed.
std::string compress_pulse(const BinPulse& p) {
    std::string raw(p.data.size() * sizeof(double), '\0');
    for (std::size_t i = 0; i < p.data.size(); ++i) {
        Out one;
        one.value(p.data[i]);
        std::memcpy(raw.data() + i * sizeof(double), one.bytes.data(), sizeof(double));
    }
    uLongf packed_size = ::compressBound(static_cast<uLong>(raw.size()));
    std::string packed(packed_size, '\0');
    if (::compress2(reinterpret_cast<Bytef*>(packed.data()), &packed_size,
                    reinterpret_cast<const Bytef*>(raw.data()), static_cast<uLong>(raw.size()),
                    Z_BEST_SPEED) != Z_OK) {
        throw runtime_error("zlib could not compress a BIN pulse");
    }
    packed.resize(packed_size);
    return packed;
}

}  // namespace

BinWriter::BinWriter(const fs::path& path, const BinFileHeader& h, std::uint32_t task_count)
    : m_path(path),
      m_file(path),
      m_pixels(static_cast<std::size_t>(h.x_count) * h.y_count),
      m_tasks_left(task_count) {
    Out o;
    o.bytes.append(kMagic, kMagicSize);
    o.value<std::uint8_t>(2);
    o.value<std::uint8_t>(1);  // little endian
    o.text(h.created, 15);
    o.text(h.dirsig_version, 32);
    o.text(h.description, 256);
    o.value(h.origin_latitude_deg);
    o.value(h.origin_longitude_deg);
    o.value(h.origin_height_m);
    o.text(h.transmitter_mount, 16);
    o.text(h.receiver_mount, 16);
    o.value(h.x_count);
    o.value(h.y_count);
    o.value(h.x_pitch_m);
    o.value(h.y_pitch_m);
    o.value(h.x_offset_m);
    o.value(h.y_offset_m);
    o.value(h.k1);
    o.value(h.k2);
    o.value(task_count);
    o.value(h.focal_plane_id);
    m_file.write(o.bytes);
}

BinWriter::~BinWriter() = default;

void BinWriter::begin_task(const BinTaskHeader& th, std::uint32_t pulse_count) {
    if (m_pulses_left != 0 || m_tasks_left == 0) {
        throw usage_error("BIN task begun with " + std::to_string(m_pulses_left) +
                          " pulses of the previous one missing and " +
                          std::to_string(m_tasks_left) + " tasks left");
    }
    Out o;
    o.text(th.description, 64);
    o.text(th.start, 15);
    o.text(th.stop, 15);
    for (const double v : {th.focal_length_mm, th.pulse_rate_hz, th.pulse_duration_s,
                           th.pulse_energy_j, th.laser_center_um, th.laser_width_um}) {
        o.value(v);
    }
    o.value(pulse_count);
    m_file.write(o.bytes);
    --m_tasks_left;
    m_pulses_left = pulse_count;
    m_task_open = true;
}

void BinWriter::add_pulse(const BinPulse& p) {
    if (!m_task_open || m_pulses_left == 0) {
        throw usage_error("BIN pulse " + std::to_string(p.pulse_index) +
                          " written outside a task's pulses");
    }
    const std::size_t values = m_pixels * p.values_per_pixel();
    if (p.data.size() != values) {
        throw usage_error("BIN pulse " + std::to_string(p.pulse_index) + " holds " +
                          std::to_string(p.data.size()) + " values, expected " +
                          std::to_string(values));
    }
    const std::string packed = compress_pulse(p);
    Out o;
    o.value(p.time_s);
    o.value(p.gate_start_s);
    o.value(p.gate_stop_s);
    o.value(p.bin_count);
    o.value(p.samples_per_bin);
    o.doubles(p.platform_location);
    o.doubles(p.platform_rotation);
    o.doubles(p.transmitter_to_mount);
    o.doubles(p.transmitter_mount_pointing);
    o.doubles(p.transmitter_mount_to_platform);
    o.doubles(p.receiver_to_mount);
    o.doubles(p.receiver_mount_pointing);
    o.doubles(p.receiver_mount_to_platform);
    o.value<std::int32_t>(5);
    o.value<std::uint8_t>(1);
    o.value(p.pulse_index);
    o.value(static_cast<std::uint64_t>(packed.size()));
    o.doubles(p.transmit_mueller);
    o.doubles(p.receive_mueller);
    m_file.write(o.bytes);
    m_file.write(packed);
    --m_pulses_left;
}

void BinWriter::commit() {
    if (m_tasks_left != 0 || m_pulses_left != 0) {
        throw usage_error("BIN file " + m_path.string() + " closed with " +
                          std::to_string(m_tasks_left) + " tasks and " +
                          std::to_string(m_pulses_left) + " pulses missing");
    }
    m_file.commit();
}

void write_bin(const fs::path& path, const BinFile& file) {
    BinWriter writer(path, file.header, static_cast<std::uint32_t>(file.tasks.size()));
    for (const BinTask& task : file.tasks) {
        writer.begin_task(task.header, static_cast<std::uint32_t>(task.pulses.size()));
        for (const BinPulse& p : task.pulses) writer.add_pulse(p);
    }
    writer.commit();
}

}  // namespace glint::io
