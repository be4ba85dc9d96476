// SPDX-License-Identifier: Apache-2.0
// The options of the tools that read simulations (glint-render, glint-schedule,
// glint-platform2jsim) about how files are read: --max-instances and --path-map.
#pragma once

#include <string>

#include "glint/core/error.h"
#include "glint/core/runner.h"
#include "glint/dirsig/read_options.h"

namespace glint::tools {

/// Adds --max-instances and --path-map FROM=TO (repeatable) to `app`, both into `read`.
inline void add_read_options(CLI::App& app, dirsig::ReadOptions& read) {
    app.add_option("--max-instances", read.max_instances,
                   "Most scene instances nested glists may expand to (counted before building)")
        ->check(whole_number())
        ->type_name("N")
        ->capture_default_str();
    app.add_option_function<std::vector<std::string>>(
           "--path-map",
           [&read](const std::vector<std::string>& mappings) {
               for (const std::string& text : mappings) {
                   read.paths.path_map.push_back(dirsig::PathMapping::parse(text));
               }
           },
           "Read paths beginning FROM as beginning TO (repeatable; e.g. the Windows folder of "
           "a simulation written there: C:/DIRSIG=/data/dirsig)")
        ->check(CLI::Validator(
            [](const std::string& text) {
                try {
                    (void)dirsig::PathMapping::parse(text);
                    return std::string();
                } catch (const Error& error) {
                    return error.message();
                }
            },
            "FROM=TO"))
        ->type_name("FROM=TO");
}

}  // namespace glint::tools
