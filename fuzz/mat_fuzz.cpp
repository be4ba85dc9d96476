// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the DIRSIG `.mat` reader (dirsig::read_dirsig_materials), the input served
// from memory; the curve files it names are served as one valid two-row curve
// (`refl.txt`, `emis.ems`), every other is missing.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "glint/dirsig/scene_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glint;
    const std::string curve = "0.4 0.1\n0.9 0.3\n";
    const dirsig::ReadOptions options = fuzz::memory_options(
        "input.mat", fuzz::as_text(data, size),
        {{fuzz::kFolder / "refl.txt", curve}, {fuzz::kFolder / "emis.ems", curve}});
    return fuzz::run([&](Diagnostics& diagnostics) {
        (void)dirsig::read_dirsig_materials(fuzz::kFolder / "input.mat", options, diagnostics);
    });
}
