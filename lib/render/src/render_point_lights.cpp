// SPDX-License-Identifier: Apache-2.0
// The scene's point sources for one capture (render_parts.h, point_lights_at): each source's
// material intensity I(λ) resampled on the focal plane's grid (0 outside the curve), its
// position at the capture's mid-window time. docs/physics.md ("Point sources") states why
// the mid-window position is used.
#include <string>
#include <vector>

#include "glint/core/error.h"
#include "glint/motion/scene_instances.h"
#include "render_parts.h"

namespace glint::render::detail {

radiometry::PointLights point_lights_at(const RenderInputs& inputs, const SpectralGrid& grid,
                                        double t_s) {
    const model::Scene& scene = inputs.scene;
    radiometry::PointLights lights(grid.size());
    std::vector<std::vector<double>> intensity_by_material(scene.materials.size());
    for (std::size_t i = 0; i < scene.point_sources.size(); ++i) {
        const model::PointSource& source = scene.point_sources[i];
        if (source.material >= scene.materials.size() ||
            !scene.materials[source.material].point_source) {
            throw internal_error("point source \"" + source.name +
                                 "\" does not name a point-source material");
        }
        std::vector<double>& intensity = intensity_by_material[source.material];
        if (intensity.empty()) {
            const model::SpectralTable& table = scene.materials[source.material].intensity_w_per_sr_um;
            intensity = SpectralCurve(table.wavelengths_um, table.values, table.where).resample(grid);
        }
        const motion::Trajectory* trajectory =
            i < inputs.source_trajectories.size() ? inputs.source_trajectories[i].get() : nullptr;
        try {
            lights.add(source.name, motion::point_source_position_m(source, trajectory, t_s),
                       intensity);
        } catch (const Error& e) {
            if (!e.context().file.empty()) throw;
            throw input_error(e.message(), source.where);
        }
    }
    return lights;
}

}  // namespace glint::render::detail
