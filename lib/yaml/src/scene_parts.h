// SPDX-License-Identifier: Apache-2.0
// Internal to the glint YAML scene reader: the shared key-reading helper (file line and key
// path of every node, typed values reported to Diagnostics) and the per-section readers.
#pragma once

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include "glint/core/text.h"
#include "glint/dirsig/motion_reader.h"
#include "glint/dirsig/scene_reader.h"
#include "glint/io/xml.h"
#include "glint/mesh/mesh.h"
#include "glint/yaml/scene_reader.h"

namespace glint::yaml {

// The DIRSIG readers a YAML scene builds on: its `glists`, DIRSIG `.mat` materials and
// FlexMotion files of dynamic instances.
using dirsig::MotionReadContext;
using dirsig::read_dirsig_materials;
using dirsig::read_flex_motion;
using dirsig::read_glist;
using dirsig::read_motion;
using dirsig::ReadOptions;

}  // namespace glint::yaml

namespace glint::yaml::yaml_scene {

inline constexpr double kDegToRad = std::numbers::pi / 180.0;

/// Everything the key readers share.
struct Reader {
    std::string file;  ///< display name of the YAML file
    std::filesystem::path base_dir;
    ReadOptions options;
    Diagnostics& diagnostics;

    ErrorContext where(const YAML::Node& node, const std::string& path) const {
        return {file, node.Mark().line >= 0 ? node.Mark().line + 1 : 0, path};
    }
    void error(const YAML::Node& node, const std::string& path, const std::string& message) {
        diagnostics.error(where(node, path), message);
    }

    /// True when `node` is a mapping; otherwise an error.
    bool expect_map(const YAML::Node& node, const std::string& path) {
        if (node.IsMap()) return true;
        error(node, path, "expected a mapping");
        return false;
    }
    /// Warns about each key of `node` not in `known`.
    void warn_unknown(const YAML::Node& node, const std::string& path,
                      std::initializer_list<std::string_view> known) {
        for (const auto& entry : node) {
            const std::string key = entry.first.Scalar();
            bool found = false;
            for (const std::string_view k : known) found = found || k == key;
            if (!found) {
                diagnostics.warning(where(entry.first, join(path, key)),
                                    "unknown key \"" + key + "\" (ignored)");
            }
        }
    }
    static std::string join(const std::string& path, const std::string& key) {
        return path.empty() ? key : path + "." + key;
    }

    std::optional<double> number(const YAML::Node& node, const std::string& path) {
        if (node.IsScalar()) {
            if (auto value = parse_double(node.Scalar())) return value;
            error(node, path, "expected a finite number, got \"" + node.Scalar() + "\"");
        } else {
            error(node, path, "expected a finite number");
        }
        return std::nullopt;
    }
    std::optional<double> number_key(const YAML::Node& parent, const std::string& path,
                                     const std::string& key, bool required) {
        const YAML::Node node = parent[key];
        if (!node) {
            if (required) error(parent, path, "missing required key \"" + key + "\"");
            return std::nullopt;
        }
        return number(node, join(path, key));
    }
    std::optional<long long> integer_key(const YAML::Node& parent, const std::string& path,
                                         const std::string& key) {
        const YAML::Node node = parent[key];
        if (!node) return std::nullopt;
        if (node.IsScalar()) {
            if (auto value = parse_int(node.Scalar())) return *value;
        }
        error(node, join(path, key), "expected an integer");
        return std::nullopt;
    }
    /// An optional true/false key (also yes/no, 1/0).
    std::optional<bool> bool_key(const YAML::Node& parent, const std::string& path,
                                 const std::string& key) {
        const YAML::Node node = parent[key];
        if (!node) return std::nullopt;
        if (node.IsScalar()) {
            if (auto value = parse_bool(node.Scalar())) return *value;
        }
        error(node, join(path, key), "expected true or false");
        return std::nullopt;
    }
    std::optional<std::string> text_key(const YAML::Node& parent, const std::string& path,
                                        const std::string& key, bool required) {
        const YAML::Node node = parent[key];
        if (!node) {
            if (required) error(parent, path, "missing required key \"" + key + "\"");
            return std::nullopt;
        }
        if (!node.IsScalar() || node.Scalar().empty()) {
            error(node, join(path, key), "expected non-empty text");
            return std::nullopt;
        }
        return node.Scalar();
    }
    std::vector<double> numbers(const YAML::Node& node, const std::string& path) {
        std::vector<double> out;
        if (!node.IsSequence()) {
            error(node, path, "expected a list of numbers");
            return out;
        }
        for (std::size_t i = 0; i < node.size(); ++i) {
            const auto value = number(node[i], path + "[" + std::to_string(i) + "]");
            out.push_back(value.value_or(std::nan("")));
        }
        return out;
    }
    std::optional<std::array<double, 3>> triple_key(const YAML::Node& parent,
                                                    const std::string& path,
                                                    const std::string& key) {
        const YAML::Node node = parent[key];
        if (!node) return std::nullopt;
        const std::size_t errors = diagnostics.error_count();
        const std::vector<double> values = numbers(node, join(path, key));
        if (diagnostics.error_count() != errors) return std::nullopt;
        if (values.size() != 3) {
            error(node, join(path, key),
                  "expected 3 numbers [x, y, z], got " + std::to_string(values.size()));
            return std::nullopt;
        }
        return std::array<double, 3>{values[0], values[1], values[2]};
    }
};

/// Reads one `materials[i]` entry.
model::Material read_material(Reader& r, const YAML::Node& node, const std::string& path);
/// Reads one `objects[i]` entry (its geometry and instances) into `scene`.
void read_object(Reader& r, const YAML::Node& node, const std::string& path, model::Scene& scene);

}  // namespace glint::yaml::yaml_scene
