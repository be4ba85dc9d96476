// SPDX-License-Identifier: Apache-2.0
// Fuzz target: glint's YAML scene reader (yaml::read_yaml_scene), the input served from
// memory; every `.obj` it names is a one-triangle mesh, other files are missing.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "glint/yaml/scene_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glint;
    const dirsig::ReadOptions options =
        fuzz::memory_options("input.yaml", fuzz::as_text(data, size));
    return fuzz::run([&](Diagnostics& diagnostics) {
        (void)yaml::read_yaml_scene(fuzz::kFolder / "input.yaml", options, diagnostics);
    });
}
