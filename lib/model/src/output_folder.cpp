// SPDX-License-Identifier: Apache-2.0
// Where a simulation writes (glint/model/output_folder.h).
#include "glint/model/output_folder.h"

#include <system_error>

namespace glint::model {
namespace {

namespace fs = std::filesystem;

fs::path absolute_normal(const fs::path& path, const fs::path& base) {
    return (path.is_absolute() ? path : base / path).lexically_normal();
}

/// `path` without a trailing separator ("/a/b/" -> "/a/b"), so "/a/b" lies inside "/a/b/".
fs::path without_trailing_separator(fs::path path) {
    if (!path.has_filename() && path.has_parent_path() && path != path.root_path()) {
        path = path.parent_path();
    }
    return path;
}

}  // namespace

std::vector<OutputFolder> output_folders(const Simulation& simulation,
                                         const std::optional<std::string>& command_line,
                                         const fs::path& working_folder) {
    std::vector<OutputFolder> folders;
    for (std::size_t index : simulation.basic_platform_indices()) {
        const Plugin& plugin = simulation.plugins[index];
        const BasicPlatformInputs& inputs = *plugin.basic_platform;
        OutputFolder out;
        out.plugin_index = index;
        out.where = plugin.where;
        out.from_simulation = inputs.output_folder.has_value();
        const std::string folder =
            inputs.output_folder.value_or(command_line.value_or(std::string()));
        out.folder = without_trailing_separator(
            absolute_normal(folder.empty() ? fs::path(".") : fs::path(folder), working_folder));
        folders.push_back(std::move(out));
    }
    return folders;
}

bool lies_inside(const fs::path& path, const fs::path& folder) {
    const fs::path inside = without_trailing_separator(path);
    const fs::path outer = without_trailing_separator(folder);
    auto p = inside.begin();
    for (auto f = outer.begin(); f != outer.end(); ++f, ++p) {
        if (p == inside.end() || *p != *f) return false;
    }
    return true;
}

std::optional<std::string> unexpected_output_folder(const OutputFolder& output,
                                                    const Simulation& simulation,
                                                    const fs::path& working_folder) {
    if (!output.from_simulation) return std::nullopt;
    const fs::path working = without_trailing_separator(working_folder.lexically_normal());
    const fs::path simulation_folder = without_trailing_separator(
        absolute_normal(fs::path(simulation.file).parent_path(), working_folder));
    if (lies_inside(output.folder, simulation_folder) || lies_inside(output.folder, working)) {
        return std::nullopt;
    }
    return "output_folder " + output.folder.string() + " lies outside both the simulation's folder (" +
           simulation_folder.string() + ") and the working folder (" + working.string() +
           "): this run writes there because the simulation says so; check that you meant it "
           "(--output-folder applies only to entries without their own)";
}

}  // namespace glint::model
