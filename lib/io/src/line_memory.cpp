// SPDX-License-Identifier: Apache-2.0
// The readers' line budget (line_memory.h).
#include "glint/io/line_memory.h"

#include <cmath>
#include <string>

#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::io {

void check_line_memory(std::size_t samples, std::size_t bands, std::size_t max_memory_bytes,
                       const std::filesystem::path& file) {
    // A line of 10⁹ samples (a sparse data file or an image header can claim one) would need
    // 8 GB as doubles.
    const double line_bytes =
        static_cast<double>(samples) * static_cast<double>(bands) * sizeof(double);
    const std::size_t max_line_bytes = max_memory_bytes / kLinesPerMaxMemory;
    if (line_bytes <= static_cast<double>(max_line_bytes)) return;
    // The --max-memory that would read the line, in whole GiB (or MiB below 1 GiB).
    const double needed_bytes = line_bytes * kLinesPerMaxMemory;
    const bool in_gib = needed_bytes > double{1 << 30};
    const auto needed = static_cast<long long>(std::ceil(needed_bytes / (in_gib ? 1 << 30 : 1 << 20)));
    throw input_error("one line holds " + std::to_string(samples) + " samples x " +
                          std::to_string(bands) + " bands, " + format_byte_size(line_bytes) +
                          " as doubles; glint reads images line by line and refuses lines "
                          "over " +
                          format_byte_size(static_cast<double>(max_line_bytes)) +
                          " (--max-memory " + format_byte_size(static_cast<double>(max_memory_bytes)) +
                          " / " + std::to_string(kLinesPerMaxMemory) + "; --max-memory " +
                          std::to_string(needed) + (in_gib ? "G" : "M") + " would read it)",
                      ErrorContext{file.string(), 0, {}});
}

}  // namespace glint::io
