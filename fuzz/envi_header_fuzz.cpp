// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the ENVI header parser (io::parse_envi_header) on the input text; a header it
// accepts is formatted again (io::format_envi_header), which may refuse it only by
// glint::Error.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "glint/io/envi.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glint;
    const std::string text = fuzz::as_text(data, size);
    return fuzz::run([&](Diagnostics&) {
        const io::EnviHeader header = io::parse_envi_header(text, "input.hdr");
        (void)io::format_envi_header(header);
    });
}
