// SPDX-License-Identifier: Apache-2.0
// glint-envi's entry point (glint/app_envi/envi_tool.h): the chosen subcommand.
#include "glint/app_envi/envi_tool.h"

#include "glint/core/error.h"
#include "glint/core/runner.h"

namespace glint::app_envi {

int run(const Options& options, Context& ctx, std::ostream& out) {
    switch (options.subcommand) {
        case Subcommand::info:
            return report_info(options.info, ctx, out);
        case Subcommand::stats:
            return report_stats(options.stats, ctx, out);
        case Subcommand::convert:
            convert_file(options.convert, ctx);
            return kExitSuccess;
        case Subcommand::encode:
            encode_frames(options.encode, ctx);
            return kExitSuccess;
    }
    throw internal_error("unknown glint-envi subcommand");
}

}  // namespace glint::app_envi
