// SPDX-License-Identifier: Apache-2.0
// Fuzz target: two-line element sets (motion::Tle::parse, the TLE of a FlexMotion `.motion`)
// on the input's first two lines; an accepted TLE is propagated by SGP4 at its epoch, a day
// on and a year back, which may fail only by its status code.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_support.h"
#include "glint/motion/sgp4.h"
#include "glint/motion/tle.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glint;
    const std::string text = fuzz::as_text(data, size);
    const std::size_t newline = text.find('\n');
    const std::string_view all(text);
    const std::string_view line1 = all.substr(0, newline);
    const std::string_view line2 =
        newline == std::string_view::npos ? std::string_view{} : all.substr(newline + 1);
    return fuzz::run([&](Diagnostics&) {
        const motion::Tle tle =
            motion::Tle::parse(line1, line2.substr(0, line2.find('\n')), {"input.tle", 1, {}});
        (void)tle.epoch();
        const motion::Sgp4 sgp4(tle);
        for (const double minutes : {0.0, 1440.0, -525960.0}) (void)sgp4.propagate_minutes(minutes);
    });
}
