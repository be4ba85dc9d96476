// SPDX-License-Identifier: Apache-2.0
// The render's inputs: the loaded simulation (scene, atmosphere, platforms) taken over, the
// schedule, the scene's motion and the light (radiometry::Illumination).
#include <array>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include "glint/atmosphere/gas_absorption.h"
#include "glint/core/diagnostics.h"
#include "glint/core/error.h"
#include "glint/core/text.h"
#include "render_parts.h"

namespace glint::render::detail {

namespace {

/// One warning per focal plane whose bandpass reaches beyond the gas absorption table: its
/// bands there take the nearest row's transmittance.
void warn_beyond_gas_table(const RenderInputs& in, const RenderOptions& options,
                           Diagnostics& diagnostics) {
    const std::optional<std::array<double, 2>> range = in.light->gas_table_range_um();
    if (!range) return;
    const double first_um = (*range)[0];
    const double last_um = (*range)[1];
    std::set<const model::FocalPlane*> said;
    for (const schedule::ClockedFocalPlane& source : in.schedule->sources()) {
        const model::FocalPlane& fp = *source.focal_plane;
        const model::Bandpass& band = fp.capture_method.spectral_response.bandpass;
        if (!(band.min_um < first_um || band.max_um > last_um) || !said.insert(&fp).second) {
            continue;
        }
        diagnostics.warning(
            band.where,
            "focal plane " + quote(fp.name) + "'s bandpass " + format_shortest(band.min_um) + "-" +
                format_shortest(band.max_um) + " um reaches beyond the gas absorption table (" +
                format_shortest(first_um) + "-" + format_shortest(last_um) + " um, " +
                (options.data_dir / glint::atmosphere::GasBandModel::kRelativePath).string() +
                "): its bands there take the transmittance of the table's "
                "nearest wavelength");
    }
}

void build_all(RenderInputs& in, model::SimulationInputs loaded, const RenderOptions& options,
               const Context& context, Diagnostics& diagnostics) {
    in.schedule.emplace(
        schedule::Schedule::build(loaded, options.schedule, context.log, diagnostics));
    in.simulation = std::move(loaded.simulation);
    in.scene = std::move(loaded.scene);
    in.atmosphere = std::move(loaded.atmosphere);
    in.weather = std::move(loaded.weather);
    in.frame = in.schedule->frame();
    const DateTime reference = in.schedule->plugins().empty()
                                   ? DateTime{}
                                   : in.schedule->plugins().front().tasks.reference;
    in.scene_motion.emplace(scene::SceneMotion::make(in.scene, in.frame, reference, context.log));
    in.light.emplace(radiometry::Illumination::make(in.atmosphere, options.data, in.scene, in.frame,
                                                    reference, context.log));
    if (const std::size_t n = in.scene.point_sources.size(); n > 0) {
        context.log.info("Point sources = " + std::to_string(n) +
                         " (lit by next-event estimation, at mid-window in each capture)");
    }
    warn_beyond_gas_table(in, options, diagnostics);
    // A BasicPlatform entry's split_channels takes precedence over the option (as the DIRSIG5
    // BasicPlatform manual says): the option overruled by an entry's false is said once.
    if (options.split_channels) {
        for (const model::Plugin& plugin : in.simulation.plugins) {
            if (plugin.basic_platform && plugin.basic_platform->split_channels == false) {
                diagnostics.warning(plugin.where,
                                    "split_channels false takes precedence over "
                                    "--split-channels: this plugin's channels are not split");
            }
        }
    }
}

}  // namespace

RenderInputs make_render_inputs(model::SimulationInputs loaded, const RenderOptions& options,
                                const Context& context) {
    RenderInputs in;
    Diagnostics diagnostics;
    try {
        build_all(in, std::move(loaded), options, context, diagnostics);
    } catch (const Error& error) {
        diagnostics.log_and_rethrow(error, context.log);  // every problem, each once
    }
    diagnostics.log_to(context.log);  // the warnings
    return in;
}

}  // namespace glint::render::detail
