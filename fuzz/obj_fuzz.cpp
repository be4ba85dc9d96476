// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the Wavefront OBJ parser (mesh::parse_obj_mesh) on the input text, with two
// materials ("grass" = 0, "paint" = 1) and faces before any `usemtl` taking material 0.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "fuzz_support.h"
#include "glint/mesh/mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glint;
    const std::string text = fuzz::as_text(data, size);
    const mesh::MaterialLookup lookup =
        [](const std::string& name) -> std::optional<std::uint32_t> {
        if (name == "grass") return 0;
        if (name == "paint") return 1;
        return std::nullopt;
    };
    return fuzz::run([&](Diagnostics& diagnostics) {
        const model::Mesh mesh = mesh::parse_obj_mesh(text, "input.obj", lookup, 0, 2, diagnostics);
        // A mesh that passed must be what validate_mesh promises.
        for (const auto& triangle : mesh.triangles) {
            for (const std::uint32_t index : triangle) {
                if (index >= mesh.vertices_m.size()) __builtin_trap();
            }
        }
    });
}
