// SPDX-License-Identifier: Apache-2.0
// DIRSIG BIN reading and writing (glint/io/lidar_bin.h): a cursor over the file's bytes in
// its declared byte order, the version-dependent pulse header, zlib for the pulse data.
#include "glint/io/lidar_bin.h"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>

#include "glint/core/atomic_file.h"
#include "glint/core/error.h"
#include "glint/io/regular_file.h"

namespace glint::io {
namespace {

namespace fs = std::filesystem;

constexpr char kMagic[] = "DIRSIGPROTO";  // 11 characters, no NUL in the file
constexpr std::size_t kMagicSize = 11;
/// The largest pulse data block read (values per pulse × 8 bytes): 4 GiB.
constexpr std::uint64_t kMaxPulseBytes = std::uint64_t{1} << 32;

/// Reads values from the file's bytes in its byte order.
class Cursor {
public:
    Cursor(const std::string& bytes, std::string name) : m_bytes(bytes), m_name(std::move(name)) {}

    void set_little_endian(bool little) {
        m_swap = little != (std::endian::native == std::endian::little);
    }
    std::size_t offset() const { return m_at; }
    bool at_end() const { return m_at == m_bytes.size(); }

    [[noreturn]] void fail(const std::string& what) const {
        throw input_error(what + " (at byte " + std::to_string(m_at) + ")",
                          ErrorContext{m_name, 0, {}});
    }
    const char* take(std::size_t n, const char* what) {
        if (m_bytes.size() - m_at < n) fail("file ends inside the " + std::string(what));
        const char* p = m_bytes.data() + m_at;
        m_at += n;
        return p;
    }
    template <class T>
    T value(const char* what) {
        T v;
        std::memcpy(&v, take(sizeof(T), what), sizeof(T));
        if (m_swap && sizeof(T) > 1) {
            auto* b = reinterpret_cast<unsigned char*>(&v);
            std::reverse(b, b + sizeof(T));
        }
        return v;
    }
    std::string text(std::size_t n, const char* what) {
        const char* p = take(n, what);
        std::string s(p, n);
        s.resize(std::min(s.find('\0'), s.size()));
        while (!s.empty() && s.back() == ' ') s.pop_back();
        return s;
    }
    template <std::size_t N>
    std::array<double, N> doubles(const char* what) {
        std::array<double, N> a{};
        for (double& v : a) v = value<double>(what);
        return a;
    }

private:
    const std::string& m_bytes;
    std::string m_name;
    std::size_t m_at = 0;
    bool m_swap = false;
};

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

std::vector<double> inflate_doubles(const char* data, std::uint64_t size, std::uint64_t values,
                                    std::uint8_t compression, bool swap, const Cursor& at) {
    std::vector<double> out(values);
    const std::uint64_t want = values * sizeof(double);
    if (compression == 0) {
        if (size != want)
            at.fail("pulse data holds " + std::to_string(size) + " bytes, expected " +
                    std::to_string(want));
        std::memcpy(out.data(), data, want);
    } else if (compression == 1) {
        uLongf got = static_cast<uLongf>(want);
        const int rc = ::uncompress(reinterpret_cast<Bytef*>(out.data()), &got,
                                    reinterpret_cast<const Bytef*>(data), static_cast<uLong>(size));
        if (rc != Z_OK || got != want) {
            at.fail("pulse data does not inflate to " + std::to_string(want) + " bytes (zlib: " +
                    (rc == Z_OK ? std::to_string(got) + " bytes" : std::string(zError(rc))) + ")");
        }
    } else {
        at.fail("unknown pulse data compression " + std::to_string(compression) +
                ", expected 0 (none) or 1 (zlib)");
    }
    if (swap) {
        for (double& v : out) {
            auto* b = reinterpret_cast<unsigned char*>(&v);
            std::reverse(b, b + sizeof(double));
        }
    }
    return out;
}

/// A version 0/1 mount pointing offset (3 × float64, then a 3-character angle order): kept as
/// the translation of `affine`.
void read_legacy_offset(Cursor& c, Affine16& affine, const char* what) {
    const auto offset = c.doubles<3>(what);
    affine[3] = offset[0];
    affine[7] = offset[1];
    affine[11] = offset[2];
    (void)c.text(3, what);
}

BinPulse read_pulse(Cursor& c, const BinFileHeader& h, bool swap) {
    BinPulse p;
    const int v = h.version;
    p.time_s = c.value<double>("pulse time");
    p.gate_start_s = c.value<double>("pulse gate");
    p.gate_stop_s = c.value<double>("pulse gate");
    p.bin_count = c.value<std::uint32_t>("bin count");
    p.samples_per_bin = v >= 1 ? c.value<std::uint32_t>("samples per bin") : 1;
    p.platform_location = c.doubles<3>("platform location");
    if (v < 2) p.angle_order = c.text(3, "angle order");
    p.platform_rotation = c.doubles<3>("platform rotation");
    if (v >= 2) {
        p.transmitter_to_mount = c.doubles<16>("transmitter affine");
    } else {
        read_legacy_offset(c, p.transmitter_to_mount, "transmitter mount offset");
    }
    p.transmitter_mount_pointing = c.doubles<3>("transmitter pointing");
    if (v >= 2) {
        p.transmitter_mount_to_platform = c.doubles<16>("transmitter mount affine");
        p.receiver_to_mount = c.doubles<16>("receiver affine");
    } else {
        read_legacy_offset(c, p.receiver_to_mount, "receiver mount offset");
    }
    p.receiver_mount_pointing = c.doubles<3>("receiver pointing");
    if (v >= 2) p.receiver_mount_to_platform = c.doubles<16>("receiver mount affine");
    p.data_type = c.value<std::int32_t>("pulse data type");
    p.compression = c.value<std::uint8_t>("compression type");
    if (v >= 2) {
        p.pulse_index = c.value<std::uint32_t>("pulse index");
    } else {
        (void)c.value<std::uint8_t>("delta histogram flag");
    }
    p.data_bytes = c.value<std::uint64_t>("pulse data size");
    if (v >= 2) {
        p.transmit_mueller = c.doubles<16>("transmit Mueller matrix");
        p.receive_mueller = c.doubles<16>("receive Mueller matrix");
    }
    if (p.data_type != 5) {
        c.fail("pulse data type " + std::to_string(p.data_type) +
               " is not read, expected 5 (float64)");
    }
    if (p.samples_per_bin == 0) c.fail("samples per bin is 0");
    const std::uint64_t values = static_cast<std::uint64_t>(h.x_count) * h.y_count *
                                 (1 + static_cast<std::uint64_t>(p.bin_count) * p.samples_per_bin);
    if (values * sizeof(double) > kMaxPulseBytes || p.data_bytes > kMaxPulseBytes) {
        c.fail("a pulse of " + std::to_string(values) +
               " values is larger than glint reads (4 GiB)");
    }
    const Cursor at = c;
    const char* data = c.take(p.data_bytes, "pulse data");
    p.data = inflate_doubles(data, p.data_bytes, values, p.compression, swap, at);
    return p;
}

}  // namespace

BinFile read_bin(const fs::path& path) {
    require_regular_file(path, path.string(), "BIN file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw io_error("cannot open the BIN file", path.string());
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw io_error("cannot read the BIN file", path.string());
    Cursor c(bytes, path.string());
    if (bytes.size() < kMagicSize || bytes.compare(0, kMagicSize, kMagic) != 0) {
        c.fail("not a DIRSIG BIN file (it does not start with DIRSIGPROTO)");
    }
    (void)c.take(kMagicSize, "magic");
    BinFile file;
    BinFileHeader& h = file.header;
    h.version = c.value<std::uint8_t>("file header");
    if (h.version > 2)
        c.fail("BIN format version " + std::to_string(h.version) +
               " is not read, expected 0, 1 or 2");
    const std::uint8_t order = c.value<std::uint8_t>("file header");
    if (order > 1)
        c.fail("byte order flag " + std::to_string(order) +
               ", expected 1 (little endian) or 0 (big endian)");
    h.little_endian = order == 1;
    c.set_little_endian(h.little_endian);
    const bool swap = h.little_endian != (std::endian::native == std::endian::little);
    h.created = c.text(15, "file header");
    h.dirsig_version = c.text(32, "file header");
    h.description = c.text(256, "file header");
    h.origin_latitude_deg = c.value<double>("file header");
    h.origin_longitude_deg = c.value<double>("file header");
    h.origin_height_m = c.value<double>("file header");
    h.transmitter_mount = c.text(16, "file header");
    h.receiver_mount = c.text(16, "file header");
    h.x_count = c.value<std::uint32_t>("file header");
    h.y_count = c.value<std::uint32_t>("file header");
    h.x_pitch_m = c.value<double>("file header");
    h.y_pitch_m = c.value<double>("file header");
    if (h.version >= 1) {
        h.x_offset_m = c.value<double>("file header");
        h.y_offset_m = c.value<double>("file header");
        h.k1 = c.value<double>("file header");
        h.k2 = c.value<double>("file header");
    }
    h.task_count = c.value<std::uint32_t>("file header");
    if (h.version >= 2) h.focal_plane_id = c.value<std::uint16_t>("file header");
    std::uint32_t pulse_number = 0;
    for (std::uint32_t t = 0; t < h.task_count; ++t) {
        BinTask task;
        BinTaskHeader& th = task.header;
        th.description = c.text(64, "task header");
        th.start = c.text(15, "task header");
        th.stop = c.text(15, "task header");
        th.focal_length_mm = c.value<double>("task header");
        th.pulse_rate_hz = c.value<double>("task header");
        th.pulse_duration_s = c.value<double>("task header");
        th.pulse_energy_j = c.value<double>("task header");
        th.laser_center_um = c.value<double>("task header");
        th.laser_width_um = c.value<double>("task header");
        th.pulse_count = c.value<std::uint32_t>("task header");
        for (std::uint32_t p = 0; p < th.pulse_count; ++p) {
            task.pulses.push_back(read_pulse(c, h, swap));
            // Versions 0 and 1 store no pulse index: the pulses are numbered in file order.
            if (h.version < 2) task.pulses.back().pulse_index = pulse_number;
            ++pulse_number;
        }
        file.tasks.push_back(std::move(task));
    }
    if (!c.at_end())
        c.fail(std::to_string(bytes.size() - c.offset()) + " bytes follow the last pulse");
    return file;
}

namespace {

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
