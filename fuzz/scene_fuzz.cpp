// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the DIRSIG `.scene` reader (dirsig::read_dirsig_scene), the input served from
// memory (the .glist and .mat files it names are missing).
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "glint/dirsig/scene_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glint;
    const dirsig::ReadOptions options =
        fuzz::memory_options("input.scene", fuzz::as_text(data, size));
    return fuzz::run([&](Diagnostics& diagnostics) {
        (void)dirsig::read_dirsig_scene(fuzz::kFolder / "input.scene", options, diagnostics);
    });
}
