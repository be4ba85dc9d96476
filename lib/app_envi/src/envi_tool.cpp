// SPDX-License-Identifier: Apache-2.0
// glint-envi's entry point (glint/app_envi/envi_tool.h): the chosen subcommand.
#include "glint/app_envi/envi_tool.h"

#include "glint/core/error.h"
#include "glint/core/runner.h"
#include "glint/core/stdio_name.h"
#include "glint/core/text.h"

namespace glint::app_envi {

namespace {

/// `-` where a file is needed: a usage error before anything is read or written.
void refuse_stdio_names(const Options& options) {
    switch (options.subcommand) {
        case Subcommand::info:  // "-" is a header on standard input
            return;
        case Subcommand::stats:
            refuse_stdio_name(options.stats.file, StdioRole::input, "the input of glint-envi stats",
                              kImageInputNeedsFile);
            return;
        case Subcommand::convert:
            refuse_stdio_image_files(options.convert.input, options.convert.output,
                                     "glint-envi convert");
            return;
        case Subcommand::encode:
            for (const auto& frame : options.encode.frames) {
                refuse_stdio_name(frame, StdioRole::input, "an input of glint-envi encode",
                                  kImageInputNeedsFile);
            }
            refuse_stdio_name(options.encode.output, StdioRole::output,
                              "the output of glint-envi encode", kOutputNeedsFile);
            return;
        case Subcommand::merge:
            for (const auto& part : options.merge.parts) {
                refuse_stdio_name(part, StdioRole::input, "a part folder of glint-envi merge",
                                  kImageInputNeedsFile);
            }
            refuse_stdio_name(options.merge.output_folder, StdioRole::output,
                              "the output folder of glint-envi merge", kOutputNeedsFile);
            if (!options.merge.expect.empty()) {
                refuse_stdio_name(options.merge.expect, StdioRole::input,
                                  "the --expect schedule of glint-envi merge",
                                  kImageInputNeedsFile);
            }
            return;
    }
}

}  // namespace

int run(const Options& options, Context& ctx, std::ostream& out) {
    refuse_stdio_names(options);
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
        case Subcommand::merge:
            for (const auto& file : merge_parts(options.merge, ctx)) {
                out << terminal_safe_line(file.string()) << "\n";
            }
            return kExitSuccess;
    }
    throw internal_error("unknown glint-envi subcommand");
}

}  // namespace glint::app_envi
