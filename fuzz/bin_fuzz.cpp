// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the DIRSIG lidar BIN reader (io::BinReader) on the input bytes, read as
// glint-envi info and convert read it: every task, every pulse header, and every pulse's
// values in pieces. Besides crashes and sanitizer reports, the findings this target exists
// for are small inputs that make the reader allocate or hang (zip bombs, sizes whose product
// wraps, data claimed beyond the end of the file): the reader must hold one piece at a time.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fuzz_support.h"
#include "glint/io/lidar_bin.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glint;
    return fuzz::run([&](Diagnostics&) {
        io::BinReader reader(fuzz::as_text(data, size), "input.bin");
        std::vector<double> piece;
        while (reader.next_task()) {
            while (const std::optional<io::BinPulse> pulse = reader.next_pulse()) {
                while (reader.values_left() > 0) {
                    piece.resize(static_cast<std::size_t>(
                        std::min<std::uint64_t>(reader.values_left(), 4096)));
                    reader.read_values(piece);
                }
            }
        }
    });
}
