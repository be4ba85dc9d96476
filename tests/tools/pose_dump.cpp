// SPDX-License-Identifier: Apache-2.0
// pose_dump: a debug harness over the pose service (glint/motion/pose_service.h) until
// glint-schedule (issue [D]) prints poses. For one BasicPlatform of a .jsim/.sim it prints, at
// times T0, T0 + DT, … ≤ T1, one CSV row per instrument:
//   t,instrument,x,y,z,qw,qx,qy,qz,boresight_e,boresight_n,boresight_u
// (instrument origin in scene ENU m; instrument → scene quaternion; boresight −Z in ENU).
// Usage: pose_dump --poses SIM [--plugin N] [--instrument I] --from T0 --to T1 --step DT
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/error.h"
#include "glint/core/runner.h"
#include "glint/dirsig/readers.h"
#include "glint/inputs/load.h"
#include "glint/motion/frames.h"
#include "glint/motion/pose_service.h"

namespace {

using glint::motion::PoseService;

struct Options {
    std::string simulation;
    std::optional<std::size_t> plugin;
    std::optional<std::size_t> instrument;
    double from_s = 0.0;
    double to_s = 0.0;
    double step_s = 0.0;
};

/// Upper bound on printed times, so a typo in --step cannot fill the disk.
constexpr double kMaxSteps = 1e6;

/// `value` with `decimals` decimals; a value that rounds to zero prints without a sign.
std::string fixed(double value, int decimals) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    std::string text = buffer;
    if (text.front() == '-' && text.find_first_not_of("-0.") == std::string::npos) {
        text.erase(0, 1);
    }
    return text;
}

int dump(const Options& o, glint::Context& ctx, std::ostream& stream) {
    if (!(o.step_s > 0.0) || !std::isfinite(o.step_s)) {
        throw glint::usage_error("--step must be a positive number of seconds");
    }
    if (!std::isfinite(o.from_s) || !std::isfinite(o.to_s) || o.to_s < o.from_s) {
        throw glint::usage_error("--to must not be before --from");
    }
    const double steps = std::floor((o.to_s - o.from_s) / o.step_s * (1.0 + 1e-12));
    if (steps > kMaxSteps) throw glint::usage_error("more than 1000000 steps; raise --step");

    glint::Diagnostics diagnostics;
    const std::vector<glint::model::Simulation> simulations =
        glint::dirsig::read_simulation(o.simulation, {}, diagnostics);
    diagnostics.log_to(ctx.log);
    diagnostics.throw_if_errors();
    if (simulations.empty()) throw glint::input_error("no simulation", {o.simulation, 0, ""});
    const glint::model::Simulation& simulation = simulations.front();
    std::size_t plugin = 0;
    if (o.plugin) {
        plugin = *o.plugin;
    } else {
        const std::vector<std::size_t> platforms = simulation.basic_platform_indices();
        if (platforms.empty()) {
            throw glint::input_error("no BasicPlatform plugin", {o.simulation, 0, ""});
        }
        plugin = platforms.front();
    }
    glint::Diagnostics read_diagnostics;
    const auto entry = glint::inputs::read_platform_entry(simulation, plugin, {}, read_diagnostics);
    read_diagnostics.log_to(ctx.log);
    read_diagnostics.throw_if_errors();
    const PoseService service = glint::motion::make_pose_service(*entry, ctx.seed, ctx.log);
    if (o.instrument && *o.instrument >= service.instrument_count()) {
        throw glint::usage_error("--instrument " + std::to_string(*o.instrument) +
                                 " out of range (the platform has " +
                                 std::to_string(service.instrument_count()) + " instruments)");
    }

    std::string out = "t,instrument,x,y,z,qw,qx,qy,qz,boresight_e,boresight_n,boresight_u\n";
    const auto total = static_cast<long long>(steps);
    for (long long n = 0; n <= total; ++n) {
        const double t = o.from_s + static_cast<double>(n) * o.step_s;
        for (std::size_t k = 0; k < service.instrument_count(); ++k) {
            if (o.instrument && k != *o.instrument) continue;
            const glint::motion::Rigid r = service.instrument_to_scene(k, t);
            // Same sign for q and −q: print the one with w ≥ 0.
            glint::motion::Quaternion q = r.rotation;
            if (q.w < 0.0) q = {-q.w, -q.x, -q.y, -q.z};
            const glint::motion::Vec3 b =
                glint::motion::apply_direction(r, glint::motion::kInstrumentBoresight);
            out += fixed(t, 6) + ',' + std::to_string(k) + ',' + fixed(r.translation_m.x, 6) + ',' +
                   fixed(r.translation_m.y, 6) + ',' + fixed(r.translation_m.z, 6) + ',' +
                   fixed(q.w, 9) + ',' + fixed(q.x, 9) + ',' + fixed(q.y, 9) + ',' + fixed(q.z, 9) +
                   ',' + fixed(b.x, 9) + ',' + fixed(b.y, 9) + ',' + fixed(b.z, 9) + '\n';
        }
        ctx.cancel.throw_if_cancelled();
    }
    stream << out << std::flush;
    if (!stream) throw glint::io_error("cannot write to stdout");
    return glint::kExitSuccess;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    const glint::ToolSpec spec{"pose_dump",
                               "Print instrument poses of one BasicPlatform as CSV (debug harness "
                               "of the pose service)",
                               glint::kCommonSeed};
    const glint::ToolStreams streams{std::cout, std::cerr, ::isatty(STDERR_FILENO) != 0};
    return glint::run_tool(
        spec, argc, argv, streams,
        [&](CLI::App& app) {
            app.add_option("--poses", options.simulation, "The .jsim (or .sim) to read")
                ->type_name("SIM")
                ->required();
            app.add_option("--plugin", options.plugin,
                           "Index in plugin_list of the BasicPlatform (default: the first)")
                ->type_name("N");
            app.add_option("--instrument", options.instrument,
                           "Only this instrument (list_instruments order; default: all)")
                ->type_name("I");
            app.add_option("--from", options.from_s, "First time (s after the tasks reference)")
                ->type_name("T0")
                ->required();
            app.add_option("--to", options.to_s, "Last time (s)")->type_name("T1")->required();
            app.add_option("--step", options.step_s, "Time step (s)")->type_name("DT")->required();
        },
        [&](glint::Context& ctx) { return dump(options, ctx, streams.out); });
}
