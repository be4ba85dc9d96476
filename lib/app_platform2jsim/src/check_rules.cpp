// SPDX-License-Identifier: Apache-2.0
// The checks glint-platform2jsim --check makes over a whole simulation once its files are
// read: two BasicPlatform entries writing one output name, truth collectors naming materials
// or tags no scene has; and its summary line.
#include <string>
#include <vector>

#include "glint/app_platform2jsim/inputs.h"
#include "glint/core/text.h"
#include "glint/inputs/scene_atmosphere.h"
#include "glint/model/derived.h"
#include "glint/model/truth.h"

namespace glint::app_platform2jsim {

std::string describe_output_name(const model::BasicPlatformInputs& entry) {
    return "output_folder '" + entry.output_folder.value_or("") + "' and output_prefix '" +
           entry.output_prefix.value_or("") + "'";
}

void check_output_names(const model::Simulation& simulation, Diagnostics& diagnostics) {
    const std::vector<std::size_t> indices = simulation.basic_platform_indices();
    for (std::size_t j = 0; j < indices.size(); ++j) {
        const model::Plugin& later = simulation.plugins[indices[j]];
        for (std::size_t i = 0; i < j; ++i) {
            const model::Plugin& earlier = simulation.plugins[indices[i]];
            const model::BasicPlatformInputs& a = *earlier.basic_platform;
            const model::BasicPlatformInputs& b = *later.basic_platform;
            if (a.output_folder.value_or("") != b.output_folder.value_or("") ||
                a.output_prefix.value_or("") != b.output_prefix.value_or("")) {
                continue;
            }
            diagnostics.warning(later.where, "plugin_list[" + std::to_string(indices[j]) +
                                                 "] (BasicPlatform) has the same " +
                                                 describe_output_name(b) + " as plugin_list[" +
                                                 std::to_string(indices[i]) +
                                                 "]: their output files may overwrite each other");
            break;
        }
    }
}

std::string summary_text(std::size_t errors, std::size_t warnings, std::size_t files) {
    return plural(errors, "error") + ", " + plural(warnings, "warning") + " in " +
           plural(files, "file");
}

void check_truth_targets(LoadedInputs& inputs) {
    for (const model::Simulation& simulation : inputs.simulations) {
        std::vector<const model::TruthCollector*> abundance;
        for (std::size_t index : simulation.basic_platform_indices()) {
            const model::Platform* platform =
                inputs.platform_of(*simulation.plugins[index].basic_platform);
            if (platform == nullptr) continue;
            for (const model::InstrumentPath& path : model::list_instruments(*platform)) {
                for (const model::FocalPlane& fp : path.instrument->focal_planes) {
                    for (const model::TruthCollection& truth : fp.truth_collections) {
                        if (!model::writes_truth(truth)) continue;
                        for (const model::TruthCollector& collector : truth.collectors) {
                            if (!collector.materials.empty() || !collector.tags.empty()) {
                                abundance.push_back(&collector);
                            }
                        }
                    }
                }
            }
        }
        if (abundance.empty() || simulation.scenes.empty()) continue;
        // The simulation's scene as the render sees it (several merge into one; load_scenes
        // reported what merging finds).
        model::Scene scene;
        Diagnostics merge_problems;
        bool complete = true;
        for (const model::SceneEntry& entry : simulation.scenes) {
            const auto it = inputs.scenes.find(LoadedInputs::key_of(entry.file.resolved));
            if (it == inputs.scenes.end()) {
                complete = false;
                break;
            }
            ::glint::inputs::merge_scene(scene, it->second, merge_problems);
        }
        if (!complete) continue;
        for (const model::TruthCollector* collector : abundance) {
            std::vector<std::string> warnings;
            try {
                model::resolve_abundance(*collector, scene, warnings);
            } catch (const Error& error) {
                inputs.diagnostics.add(error);
            }
            for (const std::string& warning : warnings) {
                inputs.diagnostics.warning(collector->where, warning);
            }
        }
    }
}

}  // namespace glint::app_platform2jsim
