// SPDX-License-Identifier: Apache-2.0
// One pass of glint-demosaic: a DemosaicStream over a fresh reader of the mosaic, its output
// lines handed on one at a time.
#include <vector>

#include "glint/core/error.h"
#include "stages.h"

namespace glint::app_demosaic::internal {

void demosaic_pass(const MosaicSource& source, const demosaic::DemosaicOptions& used,
                   const std::string& stage, Context& ctx,
                   const std::function<void(std::size_t y, std::span<const double> rgb)>& use) {
    std::optional<demosaic::DemosaicStream> stream;
    try {
        stream.emplace(source.width, source.height, used, line_reader(source));
    } catch (const Error& e) {
        if (e.category() != ErrorCategory::input) throw;
        throw e.with_file(source.path.string());
    }
    std::vector<double> line(source.width * 3);
    for (std::size_t y = 0; y < source.height; ++y) {
        ctx.cancel.throw_if_cancelled();
        stream->next_line(line);
        use(y, line);
        ctx.progress.update(stage, y + 1, source.height);
    }
    ctx.progress.finish(stage, source.height);
}

}  // namespace glint::app_demosaic::internal
