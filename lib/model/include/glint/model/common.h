// SPDX-License-Identifier: Apache-2.0
// Small pieces shared by every model struct: references to other files, metadata entries.
// The model is plain data in SI units (lengths m, times s, angles rad, rates Hz), except
// wavelengths, which are µm like the rest of glint's radiometry (`_um` names say so). Each
// struct keeps where it came from (`where`) so later stages can point at the input.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "glint/core/error.h"

namespace glint::model {

/// A path named in an input: as written, and resolved (variables expanded, made absolute
/// against the folder of the file that named it, lexically normalised).
struct FileRef {
    std::string text;                ///< as written in the input, e.g. "$SCENE_DIR/a.png"
    std::filesystem::path resolved;  ///< absolute; empty when `text` is empty
    ErrorContext where;              ///< where it was named

    bool empty() const { return text.empty(); }
};

/// Name/value metadata entries (`<metadata><entry><name>…<value>…`), in file order.
struct Metadata {
    std::vector<std::pair<std::string, std::string>> entries;

    /// Value of the first entry named `name` (case-insensitive), if any.
    std::optional<std::string> find(const std::string& name) const;
};

}  // namespace glint::model
