// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the DIRSIG `.glist` reader (dirsig::read_glist) into a scene that has two
// materials (ids "1" and "2", names "grass" and "paint"); the input is served from memory,
// every `.obj` it names is a one-triangle mesh, nested glists and motion files are missing.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "glint/dirsig/scene_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glint;
    const dirsig::ReadOptions options =
        fuzz::memory_options("input.glist", fuzz::as_text(data, size));
    return fuzz::run([&](Diagnostics& diagnostics) {
        model::Scene scene;
        scene.materials.resize(2);
        scene.materials[0].id = "1";
        scene.materials[0].name = "grass";
        scene.materials[1].id = "2";
        scene.materials[1].name = "paint";
        dirsig::read_glist(fuzz::kFolder / "input.glist", options, scene, diagnostics);
    });
}
