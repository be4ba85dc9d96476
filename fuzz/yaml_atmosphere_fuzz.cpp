// SPDX-License-Identifier: Apache-2.0
// Fuzz target: glint's YAML atmosphere reader (yaml::parse_yaml_atmosphere) on the input
// text; a table file it names is missing.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "glint/yaml/atmosphere_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glint;
    const std::string text = fuzz::as_text(data, size);
    const dirsig::ReadOptions options = fuzz::memory_options("input.yaml", text);
    return fuzz::run([&](Diagnostics& diagnostics) {
        (void)yaml::parse_yaml_atmosphere(text, fuzz::kFolder / "input.yaml", "input.yaml", options,
                                          diagnostics);
    });
}
