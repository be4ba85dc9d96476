// SPDX-License-Identifier: Apache-2.0
// Readers of DIRSIG platform motion: GenericMotion `.ppd` (`<platformmotion type="generic">`)
// and FlexMotion `.motion` (`<motion type="flexible">`), told apart by their root element,
// and a FlexMotion reader for an inline `<motion>` element (a GLIST dynamic instance). Like
// every legacy reader they report each problem (file:line, element path) to `diagnostics`
// and carry on; the caller fails when diagnostics has errors. The elements read are listed
// in glint/model/motion.h.
#pragma once

#include <filesystem>
#include <string_view>

#include "glint/core/diagnostics.h"
#include "glint/dirsig/read_options.h"
#include "glint/io/xml.h"
#include "glint/model/motion.h"

namespace glint::dirsig {

/// Reads a platform motion file: a `.ppd` (GenericMotion) or a `.motion` (FlexMotion).
model::PlatformMotion read_motion(const std::filesystem::path& file, const ReadOptions& options,
                                  Diagnostics& diagnostics);

/// What the element readers need besides the element.
struct MotionReadContext {
    ReadOptions options;             ///< path resolution (PSD files of the jitter)
    std::filesystem::path base_dir;  ///< folder of the file holding the element
    /// The whole text of that file. With it, a bad row of a CDATA table is reported at its
    /// own file line; without it (empty), at the line of its `<data>` element.
    std::string_view source_text;
};

/// Reads a `<motion type="flexible">` element (a `.motion` root or inline in a GLIST).
model::FlexMotion read_flex_motion(const io::XmlNode& motion, const MotionReadContext& context,
                                   Diagnostics& diagnostics);

/// Reads a `<platformmotion type="generic">` element (a `.ppd` root).
model::GenericMotion read_generic_motion(const io::XmlNode& platform_motion,
                                         const MotionReadContext& context,
                                         Diagnostics& diagnostics);

}  // namespace glint::dirsig
