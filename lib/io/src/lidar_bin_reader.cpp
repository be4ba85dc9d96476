// SPDX-License-Identifier: Apache-2.0
// DIRSIG BIN reading (glint/io/lidar_bin.h): a cursor over the file's bytes in its declared
// byte order, the version-dependent pulse header, zlib's inflate for the pulse data, fed from
// the file in pieces.
#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>

#include "glint/core/error.h"
#include "glint/io/lidar_bin.h"
#include "glint/io/regular_file.h"
#include "lidar_bin_magic.h"

namespace glint::io {
namespace {

namespace fs = std::filesystem;

using bin_detail::kMagic;
using bin_detail::kMagicSize;
/// The largest pulse read (values per pulse × 8 bytes): 4 GiB, four times a 256 × 256 receiver
/// with 2,000 time samples. read_bin also holds at most this much of all pulses together.
constexpr std::uint64_t kMaxPulseBytes = std::uint64_t{1} << 32;
/// Compressed bytes read from the file at a time.
constexpr std::size_t kReadChunkBytes = std::size_t{1} << 20;

}  // namespace

/// zlib's inflate over a pulse's data, fed from the file in pieces.
struct BinReader::Inflater {
    z_stream stream{};
    bool open = false;
    bool ended = false;  ///< the zlib stream reached its end
    std::vector<unsigned char> input;

    Inflater() : input(kReadChunkBytes) {}
    ~Inflater() { close(); }
    Inflater(const Inflater&) = delete;
    Inflater& operator=(const Inflater&) = delete;
    void reset() {
        close();
        stream = z_stream{};
        if (::inflateInit(&stream) != Z_OK) throw runtime_error("zlib could not start inflating");
        open = true;
        ended = false;
    }
    void close() {
        if (open) ::inflateEnd(&stream);
        open = false;
    }
};

BinReader::BinReader(const fs::path& path)
    : m_name(path.string()), m_stream(std::make_unique<std::ifstream>()), m_in(*m_stream) {
    require_regular_file(path, m_name, "BIN file");
    static_cast<std::ifstream&>(m_in).open(path, std::ios::binary);
    if (!m_in) throw io_error("cannot open the BIN file", m_name);
    std::error_code ec;
    m_size = fs::file_size(path, ec);
    if (ec) throw io_error("cannot read the BIN file: " + ec.message(), m_name);
    read_file_header();
}

BinReader::BinReader(std::string bytes, std::string name)
    : m_name(std::move(name)),
      m_stream(std::make_unique<std::istringstream>(std::move(bytes), std::ios::binary)),
      m_in(*m_stream) {
    m_in.seekg(0, std::ios::end);
    m_size = static_cast<std::uint64_t>(m_in.tellg());
    m_in.seekg(0);
    read_file_header();
}

void BinReader::read_file_header() {
    if (m_size < kMagicSize || take(kMagicSize, "magic") != std::string(kMagic, kMagicSize)) {
        m_at = 0;
        fail("not a DIRSIG BIN file (it does not start with DIRSIGPROTO)");
    }
    BinFileHeader& h = m_header;
    h.version = value<std::uint8_t>("file header");
    if (h.version > 2) {
        fail("BIN format version " + std::to_string(h.version) +
             " is not read, expected 0, 1 or 2");
    }
    const std::uint8_t order = value<std::uint8_t>("file header");
    if (order > 1) {
        fail("byte order flag " + std::to_string(order) +
             ", expected 1 (little endian) or 0 (big endian)");
    }
    h.little_endian = order == 1;
    m_swap = h.little_endian != (std::endian::native == std::endian::little);
    h.created = text(15, "file header");
    h.dirsig_version = text(32, "file header");
    h.description = text(256, "file header");
    h.origin_latitude_deg = value<double>("file header");
    h.origin_longitude_deg = value<double>("file header");
    h.origin_height_m = value<double>("file header");
    h.transmitter_mount = text(16, "file header");
    h.receiver_mount = text(16, "file header");
    h.x_count = value<std::uint32_t>("file header");
    h.y_count = value<std::uint32_t>("file header");
    h.x_pitch_m = value<double>("file header");
    h.y_pitch_m = value<double>("file header");
    if (h.version >= 1) {
        h.x_offset_m = value<double>("file header");
        h.y_offset_m = value<double>("file header");
        h.k1 = value<double>("file header");
        h.k2 = value<double>("file header");
    }
    h.task_count = value<std::uint32_t>("file header");
    if (h.version >= 2) h.focal_plane_id = value<std::uint16_t>("file header");
    m_tasks_left = h.task_count;
}

BinReader::~BinReader() = default;

void BinReader::fail(const std::string& what) const {
    throw input_error(what + " (at byte " + std::to_string(m_at) + ")",
                      ErrorContext{m_name, 0, {}});
}

std::string BinReader::take(std::size_t n, const char* what) {
    if (m_size - m_at < n) fail("file ends inside the " + std::string(what));
    std::string bytes(n, '\0');
    m_in.read(bytes.data(), static_cast<std::streamsize>(n));
    if (!m_in) throw io_error("cannot read the BIN file", m_name);
    m_at += n;
    return bytes;
}

template <class T>
T BinReader::value(const char* what) {
    T v;
    if (m_size - m_at < sizeof(T)) fail("file ends inside the " + std::string(what));
    m_in.read(reinterpret_cast<char*>(&v), sizeof(T));
    if (!m_in) throw io_error("cannot read the BIN file", m_name);
    m_at += sizeof(T);
    if (m_swap && sizeof(T) > 1) {
        auto* b = reinterpret_cast<unsigned char*>(&v);
        std::reverse(b, b + sizeof(T));
    }
    return v;
}

std::string BinReader::text(std::size_t n, const char* what) {
    std::string s = take(n, what);
    s.resize(std::min(s.find('\0'), s.size()));
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
}

template <std::size_t N>
std::array<double, N> BinReader::doubles(const char* what) {
    std::array<double, N> a{};
    for (double& v : a) v = value<double>(what);
    return a;
}

void BinReader::skip_data() {
    if (m_data_left > 0) {
        m_in.seekg(static_cast<std::streamoff>(m_data_left), std::ios::cur);
        if (!m_in) throw io_error("cannot read the BIN file", m_name);
        m_at += m_data_left;
    }
    m_data_left = 0;
    m_values_left = 0;
    if (m_inflater) m_inflater->close();
}

std::optional<BinTaskHeader> BinReader::next_task() {
    while (next_pulse()) {
    }
    if (m_tasks_left == 0) {
        if (m_at != m_size) fail(std::to_string(m_size - m_at) + " bytes follow the last pulse");
        return std::nullopt;
    }
    --m_tasks_left;
    BinTaskHeader th;
    th.description = text(64, "task header");
    th.start = text(15, "task header");
    th.stop = text(15, "task header");
    th.focal_length_mm = value<double>("task header");
    th.pulse_rate_hz = value<double>("task header");
    th.pulse_duration_s = value<double>("task header");
    th.pulse_energy_j = value<double>("task header");
    th.laser_center_um = value<double>("task header");
    th.laser_width_um = value<double>("task header");
    th.pulse_count = value<std::uint32_t>("task header");
    m_pulses_left = th.pulse_count;
    return th;
}

std::optional<BinPulse> BinReader::next_pulse() {
    skip_data();
    if (m_pulses_left == 0) return std::nullopt;
    --m_pulses_left;
    BinPulse p;
    const int v = m_header.version;
    p.time_s = value<double>("pulse time");
    p.gate_start_s = value<double>("pulse gate");
    p.gate_stop_s = value<double>("pulse gate");
    p.bin_count = value<std::uint32_t>("bin count");
    p.samples_per_bin = v >= 1 ? value<std::uint32_t>("samples per bin") : 1;
    p.platform_location = doubles<3>("platform location");
    if (v < 2) p.angle_order = text(3, "angle order");
    p.platform_rotation = doubles<3>("platform rotation");
    // Versions 0 and 1 store a mount's pointing offset (3 × float64, then a 3-character angle
    // order): kept as the translation of its affine.
    const auto legacy_offset = [this](Affine16& affine, const char* what) {
        const auto offset = doubles<3>(what);
        affine[3] = offset[0];
        affine[7] = offset[1];
        affine[11] = offset[2];
        (void)text(3, what);
    };
    if (v >= 2) {
        p.transmitter_to_mount = doubles<16>("transmitter affine");
    } else {
        legacy_offset(p.transmitter_to_mount, "transmitter mount offset");
    }
    p.transmitter_mount_pointing = doubles<3>("transmitter pointing");
    if (v >= 2) {
        p.transmitter_mount_to_platform = doubles<16>("transmitter mount affine");
        p.receiver_to_mount = doubles<16>("receiver affine");
    } else {
        legacy_offset(p.receiver_to_mount, "receiver mount offset");
    }
    p.receiver_mount_pointing = doubles<3>("receiver pointing");
    if (v >= 2) p.receiver_mount_to_platform = doubles<16>("receiver mount affine");
    p.data_type = value<std::int32_t>("pulse data type");
    p.compression = value<std::uint8_t>("compression type");
    if (v >= 2) {
        p.pulse_index = value<std::uint32_t>("pulse index");
    } else {
        (void)value<std::uint8_t>("delta histogram flag");
        p.pulse_index = m_pulse_number;
    }
    ++m_pulse_number;
    p.data_bytes = value<std::uint64_t>("pulse data size");
    if (v >= 2) {
        p.transmit_mueller = doubles<16>("transmit Mueller matrix");
        p.receive_mueller = doubles<16>("receive Mueller matrix");
    }
    if (p.data_type != 5) {
        fail("pulse data type " + std::to_string(p.data_type) +
             " is not read, expected 5 (float64)");
    }
    if (p.samples_per_bin == 0) fail("samples per bin is 0");
    if (p.compression > 1) {
        fail("unknown pulse data compression " + std::to_string(p.compression) +
             ", expected 0 (none) or 1 (zlib)");
    }
    // Overflow-checked: x · y · (1 + bins · samples) values of 8 bytes.
    std::uint64_t per_pixel = 0;
    std::uint64_t values = 0;
    std::uint64_t bytes = 0;
    if (__builtin_mul_overflow(std::uint64_t{p.bin_count}, std::uint64_t{p.samples_per_bin},
                               &per_pixel) ||
        __builtin_add_overflow(per_pixel, 1, &per_pixel) ||
        __builtin_mul_overflow(std::uint64_t{m_header.x_count} * m_header.y_count, per_pixel,
                               &values) ||
        __builtin_mul_overflow(values, sizeof(double), &bytes) || bytes > kMaxPulseBytes) {
        fail("a pulse of " + std::to_string(m_header.x_count) + " x " +
             std::to_string(m_header.y_count) + " pixels of 1 + " + std::to_string(p.bin_count) +
             " x " + std::to_string(p.samples_per_bin) +
             " values is larger than glint reads (4 GiB)");
    }
    if (p.data_bytes > m_size - m_at) {
        fail("pulse data of " + std::to_string(p.data_bytes) + " bytes runs past the end of the " +
             "file (" + std::to_string(m_size - m_at) + " bytes left)");
    }
    if (p.compression == 0 && p.data_bytes != bytes) {
        fail("pulse data holds " + std::to_string(p.data_bytes) + " bytes, expected " +
             std::to_string(bytes));
    }
    m_compression = p.compression;
    m_data_left = p.data_bytes;
    m_values_left = values;
    if (m_compression == 1) {
        if (!m_inflater) m_inflater = std::make_unique<Inflater>();
        m_inflater->reset();
    }
    return p;
}

void BinReader::refill() {
    Inflater& z = *m_inflater;
    if (z.stream.avail_in != 0 || m_data_left == 0) return;
    const std::size_t n =
        static_cast<std::size_t>(std::min<std::uint64_t>(m_data_left, z.input.size()));
    m_in.read(reinterpret_cast<char*>(z.input.data()), static_cast<std::streamsize>(n));
    if (!m_in) throw io_error("cannot read the BIN file", m_name);
    m_at += n;
    m_data_left -= n;
    z.stream.next_in = z.input.data();
    z.stream.avail_in = static_cast<uInt>(n);
}

std::size_t BinReader::inflate_step(unsigned char* out, std::size_t room, const char* ends_early) {
    Inflater& z = *m_inflater;
    refill();
    z.stream.next_out = out;
    z.stream.avail_out = static_cast<uInt>(room);
    const int rc = ::inflate(&z.stream, Z_NO_FLUSH);
    if (rc == Z_STREAM_END) {
        z.ended = true;
    } else if (rc == Z_BUF_ERROR && z.stream.avail_in == 0 && m_data_left == 0) {
        fail(ends_early);
    } else if (rc != Z_OK && rc != Z_BUF_ERROR) {
        fail(std::string("pulse data does not inflate (zlib: ") +
             (z.stream.msg != nullptr ? z.stream.msg : zError(rc)) + ")");
    }
    return room - z.stream.avail_out;
}

void BinReader::inflate_into(unsigned char* bytes, std::size_t want) {
    std::size_t done = 0;
    while (done < want) {
        if (m_inflater->ended) fail("pulse data inflates to fewer bytes than its values need");
        const std::size_t room = std::min<std::size_t>(want - done, std::size_t{1} << 30);
        done +=
            inflate_step(bytes + done, room, "pulse data ends before it inflates to its values");
    }
}

void BinReader::finish_inflating() {
    Inflater& z = *m_inflater;
    while (!z.ended) {
        unsigned char extra = 0;
        if (inflate_step(&extra, 1, "pulse data ends inside its zlib stream") != 0) {
            fail("pulse data inflates to more bytes than its values");
        }
    }
    if (z.stream.avail_in != 0 || m_data_left != 0) {
        fail("pulse data holds bytes after its zlib stream");
    }
}

void BinReader::read_values(std::span<double> out) {
    if (out.size() > m_values_left) {
        throw usage_error("BinReader: " + std::to_string(out.size()) + " values asked, " +
                          std::to_string(m_values_left) + " left in the pulse");
    }
    if (out.empty()) return;  // (no memcpy from a null pointer for a pulse without values)
    auto* bytes = reinterpret_cast<unsigned char*>(out.data());
    const std::size_t want = out.size() * sizeof(double);
    if (m_compression == 0) {
        m_in.read(reinterpret_cast<char*>(bytes), static_cast<std::streamsize>(want));
        if (!m_in) throw io_error("cannot read the BIN file", m_name);
        m_at += want;
        m_data_left -= want;
    } else {
        inflate_into(bytes, want);
    }
    m_values_left -= out.size();
    if (m_swap) {
        for (double& v : out) {
            auto* b = reinterpret_cast<unsigned char*>(&v);
            std::reverse(b, b + sizeof(double));
        }
    }
    // After the last value the zlib stream must end, with nothing after it.
    if (m_values_left == 0 && m_compression == 1) finish_inflating();
}

BinFile read_bin(const fs::path& path) {
    BinReader reader(path);
    BinFile file;
    file.header = reader.header();
    std::uint64_t held_bytes = 0;
    while (std::optional<BinTaskHeader> task_header = reader.next_task()) {
        BinTask task;
        task.header = *task_header;
        while (std::optional<BinPulse> pulse = reader.next_pulse()) {
            const std::uint64_t values = reader.values_left();
            held_bytes += values * sizeof(double);
            if (held_bytes > kMaxPulseBytes) {
                throw input_error("the pulses' values take more than 4 GiB: read it pulse by pulse",
                                  ErrorContext{path.string(), 0, {}});
            }
            pulse->data.resize(static_cast<std::size_t>(values));
            reader.read_values(pulse->data);
            task.pulses.push_back(std::move(*pulse));
        }
        file.tasks.push_back(std::move(task));
    }
    return file;
}
}  // namespace glint::io
