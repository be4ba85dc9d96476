// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the tabulated atmosphere's table file (yaml::read_atmosphere_table), the input
// served from memory.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "glint/yaml/atmosphere_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glint;
    const dirsig::ReadOptions options =
        fuzz::memory_options("table.txt", fuzz::as_text(data, size));
    return fuzz::run([&](Diagnostics& diagnostics) {
        (void)yaml::read_atmosphere_table(fuzz::kFolder / "table.txt", options, diagnostics);
    });
}
