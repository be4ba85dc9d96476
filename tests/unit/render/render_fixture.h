// SPDX-License-Identifier: Apache-2.0
// What the in-process render tests share: the tests/data/render fixtures, reading a text
// file, loading a simulation and the render options writing into a folder.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "glint/inputs/data_tables.h"
#include "glint/inputs/load.h"
#include "glint/render/render.h"

namespace glint::render::test_render {

inline const std::filesystem::path kRenderData =
    std::filesystem::path(GLINT_TEST_DATA_DIR) / "render";

inline std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

inline model::SimulationInputs load(const std::filesystem::path& simulation) {
    return inputs::load_logged(simulation, inputs::LoadOptions{}, Log{});
}

/// Options writing into `out`, glint's data tables from the source tree's data folder.
inline RenderOptions options_into(const std::filesystem::path& out) {
    RenderOptions options;
    options.schedule.output_folder = out.string();
    options.data_dir = std::filesystem::path(GLINT_SOURCE_DIR) / "data";
    options.data = inputs::read_data_tables(options.data_dir, true);
    return options;
}

}  // namespace glint::render::test_render
