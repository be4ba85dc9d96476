// SPDX-License-Identifier: Apache-2.0
// The colour map of index bands (`glint-envi convert --colormap`): a band that holds labels
// (material, instance or object indices of a truth cube) gets one colour per integer value
// instead of a grey stretch, so that neighbouring labels stay apart.
//
// Colour of a value v: k = v rounded to the nearest integer (ties to even); hue
// h = frac(k / phi), phi the golden ratio, so consecutive labels are 137.5 degrees apart
// (the golden angle); brightness 1 - 0.4 frac(k sqrt 2) and saturation 1 - 0.45 frac(k
// sqrt 3), so labels whose hues come close differ in shade. Each fraction is a 64-bit
// fixed-point Weyl sequence (k times the constant modulo 2^64): exact, so the colour depends
// on k alone. HSV to RGB in [0, 1]. Labels -1024..4095 get distinct 8-bit colours, 0..31 lie
// at least 0.15 apart in RGB, and the brightest channel of a label is at least 0.6 (153 of
// 255), so no label is black: black is kept for NaN, infinities, the file's
// `data ignore value` and values beyond ±2^53 (not labels).
//
// An index band is one whose `glint band units` entry is `index` (any case) when the header
// has that list with one unit per band; otherwise one whose name ends in `Index` (any case).
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace glint::app_envi {

/// `--colormap`: how one band reaches an image.
enum class Colormap {
    automatic,  ///< index for an index band written to an 8- or 16-bit image, else none
    index,      ///< one colour per integer value (three output channels)
    none,       ///< the band's values, stretched as the stretch options say
};

/// "auto", "index" or "none" → the colour map; nullopt otherwise.
std::optional<Colormap> colormap_from_name(std::string_view name);
/// The name colormap_from_name takes.
const char* colormap_name(Colormap colormap);

/// The RGB colour, each channel in [0, 1], of a label value (see the top of this file);
/// black for values that are not labels (NaN, infinite, beyond ±2^53).
std::array<double, 3> index_colour(double value);

/// Whether a band holds labels: `unit` (its `glint band units` entry; empty when the file
/// gives none) is `index`, or, without a unit, `name` ends in `Index` (any case).
bool is_index_band(std::string_view name, std::string_view unit);

}  // namespace glint::app_envi
