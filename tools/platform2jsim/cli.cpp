// SPDX-License-Identifier: Apache-2.0
// glint-platform2jsim's options (CLI11; DIRSIG5's `--output_folder`, `--output_prefix` and
// `--split_channels` spellings accepted too) and the mode they select: convert INPUT, build
// from --platform/--motion/--tasks, --append, --check, --dump-platform.
#include "cli.h"

#include "../read_options_cli.h"
#include "glint/core/error.h"
#include "glint/core/runner.h"

namespace glint::tools::platform2jsim {
namespace {

using app_platform2jsim::Mode;

/// Throws a usage error naming the first of `flags` that was given (for `mode`).
void forbid(const CLI::App& app, std::initializer_list<const char*> flags, const char* mode) {
    for (const char* flag : flags) {
        if (app.count(flag) == 0) continue;
        const std::string what = std::string(flag) == "input" ? "an input file (SIM)" : flag;
        throw usage_error(what + " cannot be combined with " + mode);
    }
}

}  // namespace

void Platform2JsimCli::configure(CLI::App& app) {
    m_app = &app;
    app.add_option("input", m_input, "DIRSIG4 .sim (or .jsim) to convert into a .jsim")
        ->type_name("SIM");
    app.add_option("-o,--output", m_options.output,
                   "Output file (- for stdout); with --append, the existing .jsim")
        ->type_name("FILE");
    app.add_option("--platform", m_platform, "Build a .jsim: the .platform file")
        ->type_name("FILE");
    app.add_option("--motion", m_motion, "Build a .jsim: the .ppd or .motion file")
        ->type_name("FILE");
    app.add_option("--tasks", m_tasks, "Build a .jsim: the .tasks file")->type_name("FILE");
    app.add_option("--scene", m_scene, "Build a .jsim: the .scene file (scene_list)")
        ->type_name("FILE");
    app.add_option("--atmosphere", m_atmosphere, "Build a .jsim: the .atm file (BasicAtmosphere)")
        ->type_name("FILE");
    app.add_option("--output-folder,--output_folder", m_output_folder,
                   "BasicPlatform output_folder, written as given")
        ->type_name("DIR");
    add_read_options(app, m_options.read_options);
    app.add_option("--output-prefix,--output_prefix", m_output_prefix,
                   "BasicPlatform output_prefix (tells constellation members apart)")
        ->type_name("PREFIX");
    app.add_flag("--split-channels,--split_channels", m_options.split_channels,
                 "BasicPlatform split_channels: true");
    app.add_flag("--append", m_append,
                 "Add the --platform/--motion/--tasks entry to the existing .jsim named by -o");
    app.add_option("--check", m_check,
                   "Check FILE(s) (.sim, .jsim, .platform, .tasks) and every file they "
                   "reference; print a summary")
        ->type_name("FILE")
        ->expected(1, -1);
    app.add_flag("--allow-processing", m_options.allow_processing,
                 "With --check: count every program a <processing> task names as allowed, as "
                 "glint-render --allow-processing does");
    app.add_option("--dump-platform", m_dump,
                   "Print a .platform (or each platform of a .sim/.jsim) as normalized JSON")
        ->type_name("FILE");
}

void Platform2JsimCli::choose_mode() {
    const CLI::App& app = *m_app;
    app_platform2jsim::Options& o = m_options;
    const bool parts = app.count("--platform") + app.count("--motion") + app.count("--tasks") > 0;
    if (app.count("--check") > 0) {
        forbid(app,
               {"input", "--output", "--platform", "--motion", "--tasks", "--scene", "--atmosphere",
                "--output-folder", "--output-prefix", "--split-channels", "--append",
                "--dump-platform"},
               "--check");
        o.mode = Mode::check;
        o.check_files.assign(m_check.begin(), m_check.end());
        return;
    }
    if (m_options.allow_processing) {
        throw usage_error("--allow-processing goes with --check (glint-render takes it for a run)");
    }
    if (app.count("--dump-platform") > 0) {
        forbid(app,
               {"input", "--platform", "--motion", "--tasks", "--scene", "--atmosphere",
                "--output-folder", "--output-prefix", "--split-channels", "--append"},
               "--dump-platform");
        o.mode = Mode::dump_platform;
        o.input = m_dump;
        return;
    }
    if (app.count("--output-folder") > 0) o.output_folder = m_output_folder;
    if (app.count("--output-prefix") > 0) o.output_prefix = m_output_prefix;
    if (m_append || parts) {
        forbid(app, {"input"}, m_append ? "--append" : "--platform/--motion/--tasks");
        o.mode = m_append ? Mode::append : Mode::parts;
        o.platform = m_platform;
        o.motion = m_motion;
        o.tasks = m_tasks;
        if (app.count("--scene") > 0) o.scene = m_scene;
        if (app.count("--atmosphere") > 0) o.atmosphere = m_atmosphere;
        return;
    }
    if (m_input.empty()) {
        throw usage_error(
            "nothing to do: give a .sim to convert, --platform/--motion/--tasks, --check FILE "
            "or --dump-platform FILE");
    }
    forbid(app, {"--scene", "--atmosphere"}, "a .sim input (it names its own)");
    o.mode = Mode::convert;
    o.input = m_input;
}

int Platform2JsimCli::execute(Context& ctx, std::ostream& out) {
    choose_mode();
    return app_platform2jsim::run(m_options, ctx, out);
}

}  // namespace glint::tools::platform2jsim
