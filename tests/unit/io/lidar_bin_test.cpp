// SPDX-License-Identifier: Apache-2.0
// DIRSIG lidar BIN files (glint/io/lidar_bin.h): what write_bin writes read_bin reads back
// field by field; a pulse whose data does not match the counts is refused on writing; a file
// that is not BIN, or is cut short, is refused naming the file and the byte offset. The
// independent reader and writer of tests/data/lidar_bin/bin_tool.py check the layout itself
// (tests/cli/envi/bin-*.toml).
#include "glint/io/lidar_bin.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <vector>

#include "glint/core/error.h"
#include "glint/test/temp_dir.h"

namespace glint::io {
namespace lidar_bin_test {

BinFile sample() {
    BinFile f;
    f.header.created = "20201231T235959";
    f.header.dirsig_version = "glint test";
    f.header.description = "two pulses";
    f.header.origin_latitude_deg = 43.0;
    f.header.origin_longitude_deg = -77.6;
    f.header.origin_height_m = 150.0;
    f.header.transmitter_mount = "fixed";
    f.header.receiver_mount = "scanning";
    f.header.x_count = 2;
    f.header.y_count = 3;
    f.header.x_pitch_m = 2e-5;
    f.header.y_pitch_m = 3e-5;
    f.header.x_offset_m = 1e-6;
    f.header.k1 = 0.5;
    f.header.focal_plane_id = 4;
    BinTask task;
    task.header.description = "task";
    task.header.start = "20201231T235959";
    task.header.stop = "20210101T000000";
    task.header.focal_length_mm = 100;
    task.header.pulse_rate_hz = 5000;
    task.header.pulse_duration_s = 4e-9;
    task.header.pulse_energy_j = 2e-3;
    task.header.laser_center_um = 1.064;
    task.header.laser_width_um = 2e-4;
    for (std::uint32_t k = 0; k < 2; ++k) {
        BinPulse p;
        p.time_s = 2e-4 * k;
        p.gate_start_s = 6e-6;
        p.gate_stop_s = 8e-6;
        p.bin_count = 5;
        p.samples_per_bin = 1 + k;
        p.platform_location = {1.0, 2.0, 3.0 + k};
        p.platform_rotation = {0.1, 0.2, 0.3};
        p.transmitter_to_mount[3] = 0.25;
        p.receiver_mount_pointing = {0.0, 0.01 * k, 0.0};
        p.pulse_index = k;
        p.receive_mueller[1] = 0.5;
        p.data.resize(6 * p.values_per_pixel());
        for (std::size_t i = 0; i < p.data.size(); ++i) p.data[i] = 0.5 * i + k;
        task.pulses.push_back(p);
    }
    f.tasks.push_back(task);
    return f;
}

TEST(LidarBin, WhatIsWrittenReadsBackFieldByField) {
    test::TempDir dir;
    const BinFile f = sample();
    write_bin(dir / "a.bin", f);
    const BinFile r = read_bin(dir / "a.bin");
    EXPECT_EQ(r.header.version, 2);
    EXPECT_TRUE(r.header.little_endian);
    EXPECT_EQ(r.header.created, f.header.created);
    EXPECT_EQ(r.header.dirsig_version, f.header.dirsig_version);
    EXPECT_EQ(r.header.description, f.header.description);
    EXPECT_EQ(r.header.origin_longitude_deg, -77.6);
    EXPECT_EQ(r.header.receiver_mount, "scanning");
    EXPECT_EQ(r.header.x_count, 2u);
    EXPECT_EQ(r.header.y_count, 3u);
    EXPECT_EQ(r.header.y_pitch_m, 3e-5);
    EXPECT_EQ(r.header.x_offset_m, 1e-6);
    EXPECT_EQ(r.header.k1, 0.5);
    EXPECT_EQ(r.header.task_count, 1u);
    EXPECT_EQ(r.header.focal_plane_id, 4);
    ASSERT_EQ(r.tasks.size(), 1u);
    const BinTaskHeader& t = r.tasks[0].header;
    EXPECT_EQ(t.stop, "20210101T000000");
    EXPECT_EQ(t.pulse_energy_j, 2e-3);
    EXPECT_EQ(t.laser_width_um, 2e-4);
    EXPECT_EQ(t.pulse_count, 2u);
    ASSERT_EQ(r.tasks[0].pulses.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
        const BinPulse& a = f.tasks[0].pulses[k];
        const BinPulse& b = r.tasks[0].pulses[k];
        EXPECT_EQ(b.time_s, a.time_s);
        EXPECT_EQ(b.gate_stop_s, a.gate_stop_s);
        EXPECT_EQ(b.bin_count, a.bin_count);
        EXPECT_EQ(b.samples_per_bin, a.samples_per_bin);
        EXPECT_EQ(b.platform_location, a.platform_location);
        EXPECT_EQ(b.transmitter_to_mount, a.transmitter_to_mount);
        EXPECT_EQ(b.receiver_mount_pointing, a.receiver_mount_pointing);
        EXPECT_EQ(b.receive_mueller, a.receive_mueller);
        EXPECT_EQ(b.pulse_index, a.pulse_index);
        EXPECT_EQ(b.compression, 1);
        EXPECT_EQ(b.data, a.data);
    }
}

TEST(LidarBin, PulseDataOfTheWrongSizeIsRefusedAndNothingWritten) {
    test::TempDir dir;
    BinFile f = sample();
    f.tasks[0].pulses[1].data.pop_back();
    try {
        write_bin(dir / "a.bin", f);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::usage);
        // 2 x 3 pixels of 1 + 5 bins x 2 samples values.
        EXPECT_EQ(e.message(), "BIN pulse 1 holds 65 values, expected 66");
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "a.bin"));
}

TEST(LidarBin, NotABinFileAndACutFileAreInputErrorsAtTheByte) {
    test::TempDir dir;
    std::ofstream(dir / "x.bin") << "ENVI\nsamples = 1\n";
    try {
        (void)read_bin(dir / "x.bin");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_EQ(e.context().file, (dir / "x.bin").string());
        EXPECT_EQ(e.message(),
                  "not a DIRSIG BIN file (it does not start with DIRSIGPROTO) (at byte 0)");
    }
    write_bin(dir / "a.bin", sample());
    std::filesystem::resize_file(dir / "a.bin", std::filesystem::file_size(dir / "a.bin") - 3);
    try {
        (void)read_bin(dir / "a.bin");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        // The pulse's data size is checked against what is left of the file before any of it is
        // read (a header may claim any size).
        EXPECT_NE(e.message().find(" bytes runs past the end of the file ("), std::string::npos)
            << e.message();
    }
}

/// Reads every value of a BIN file held in memory, in pieces of 7 values.
std::size_t read_bin_values(std::string bytes) {
    BinReader reader(std::move(bytes), "m.bin");
    std::size_t count = 0;
    std::vector<double> piece;
    while (reader.next_task()) {
        while (reader.next_pulse()) {
            while (reader.values_left() > 0) {
                piece.resize(std::min<std::size_t>(7, reader.values_left()));
                reader.read_values(piece);
                count += piece.size();
            }
        }
    }
    return count;
}

std::string file_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

TEST(BinReader, PiecesOfAnySizeGiveTheValuesReadBinGives) {
    test::TempDir dir;
    write_bin(dir / "a.bin", sample());
    const BinFile whole = read_bin(dir / "a.bin");
    for (const std::size_t piece : {std::size_t{1}, std::size_t{5}, std::size_t{1000}}) {
        BinReader reader(file_bytes(dir / "a.bin"), "a.bin");
        std::size_t task = 0;
        while (reader.next_task()) {
            std::size_t pulse = 0;
            while (const std::optional<BinPulse> p = reader.next_pulse()) {
                EXPECT_TRUE(p->data.empty());
                std::vector<double> values;
                std::vector<double> buffer;
                while (reader.values_left() > 0) {
                    buffer.resize(std::min<std::size_t>(piece, reader.values_left()));
                    reader.read_values(buffer);
                    values.insert(values.end(), buffer.begin(), buffer.end());
                }
                EXPECT_EQ(values, whole.tasks.at(task).pulses.at(pulse).data) << piece;
                ++pulse;
            }
            ++task;
        }
        EXPECT_EQ(task, 1u);
    }
    // Pulses whose values are not read are skipped, unread.
    BinReader skipping(file_bytes(dir / "a.bin"), "a.bin");
    ASSERT_TRUE(skipping.next_task());
    ASSERT_TRUE(skipping.next_pulse());
    ASSERT_TRUE(skipping.next_pulse());
    EXPECT_FALSE(skipping.next_pulse());
    EXPECT_FALSE(skipping.next_task());
}

TEST(BinReader, APulseWithoutValuesIsRead) {
    // 0 x 3 pixels: no values (a memcpy of nothing from nowhere was undefined behaviour).
    BinFile f = sample();
    f.header.x_count = 0;
    for (BinPulse& p : f.tasks[0].pulses) p.data.clear();
    test::TempDir dir;
    write_bin(dir / "empty.bin", f);
    const BinFile read = read_bin(dir / "empty.bin");
    ASSERT_EQ(read.tasks.at(0).pulses.size(), 2u);
    EXPECT_TRUE(read.tasks[0].pulses[0].data.empty());
}

TEST(BinReader, DataThatDoesNotInflateToItsValuesIsRefused) {
    test::TempDir dir;
    write_bin(dir / "a.bin", sample());
    const std::string bytes = file_bytes(dir / "a.bin");
    const auto message_of = [](std::string data) {
        try {
            (void)read_bin_values(std::move(data));
        } catch (const Error& e) {
            return e.message();
        }
        return std::string("(no error)");
    };
    // The first pulse's data: its size field lies 8 + 128 bytes before its data, whose zlib
    // stream is what follows. Corrupt a byte in the middle of the stream.
    std::string corrupt = bytes;
    corrupt[corrupt.size() - 40] = static_cast<char>(corrupt[corrupt.size() - 40] ^ 0x5A);
    EXPECT_NE(message_of(corrupt).find("pulse data"), std::string::npos) << message_of(corrupt);
    // Bytes after the last pulse.
    EXPECT_NE(message_of(bytes + "xyz").find("3 bytes follow the last pulse"), std::string::npos)
        << message_of(bytes + "xyz");
}

}  // namespace lidar_bin_test
}  // namespace glint::io
