// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the DIRSIG `.atm` reader (dirsig::parse_atm) on the input text.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "glint/dirsig/atm_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glint;
    const std::string text = fuzz::as_text(data, size);
    return fuzz::run(
        [&](Diagnostics& diagnostics) { (void)dirsig::parse_atm(text, "input.atm", diagnostics); });
}
