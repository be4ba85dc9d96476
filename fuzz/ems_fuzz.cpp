// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the curve files of a DIRSIG `.mat` (`.ems` emissivity and `.txt` reflectance
// tables, read by dirsig::read_dirsig_materials): a fixed `.mat` names the input as both
// curves of one material.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "glint/dirsig/scene_reader.h"

namespace {

constexpr const char* kMat =
    "MATERIAL_ENTRY {\n"
    "    ID = 1\n"
    "    NAME = fuzzed\n"
    "    SURFACE_PROPERTIES {\n"
    "        REFLECTANCE_PROP {\n"
    "            TXT_FILENAME = input.ems\n"
    "        }\n"
    "        EMISSIVITY_PROP {\n"
    "            FILENAME = input.ems\n"
    "        }\n"
    "    }\n"
    "}\n";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glint;
    const dirsig::ReadOptions options = fuzz::memory_options("input.ems", fuzz::as_text(data, size),
                                                             {{fuzz::kFolder / "fuzz.mat", kMat}});
    return fuzz::run([&](Diagnostics& diagnostics) {
        (void)dirsig::read_dirsig_materials(fuzz::kFolder / "fuzz.mat", options, diagnostics);
    });
}
