// SPDX-License-Identifier: Apache-2.0
// Method names, the checks every method makes on its input, and the dispatch from
// DemosaicOptions to the Bayer and TrueSense implementations.
#include "glint/demosaic/demosaic.h"

#include <cctype>
#include <string>

#include "glint/core/error.h"
#include "validate.h"

namespace glint::demosaic {

const char* demosaic_method_name(DemosaicMethod method) {
    switch (method) {
        case DemosaicMethod::bilinear:
            return "bilinear";
        case DemosaicMethod::mhc:
            return "mhc";
        case DemosaicMethod::pan_guided:
            return "pan-guided";
    }
    return "?";
}

std::optional<DemosaicMethod> demosaic_method_from_name(std::string_view name) {
    std::string n(name);
    for (char& c : n) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (DemosaicMethod method :
         {DemosaicMethod::bilinear, DemosaicMethod::mhc, DemosaicMethod::pan_guided}) {
        if (n == demosaic_method_name(method)) return method;
    }
    return std::nullopt;
}

bool method_supports(DemosaicMethod method, CfaPattern pattern) {
    return (pattern == CfaPattern::truesense) == (method == DemosaicMethod::pan_guided);
}

DemosaicMethod default_method(CfaPattern pattern) {
    return pattern == CfaPattern::bayer ? DemosaicMethod::bilinear : DemosaicMethod::pan_guided;
}

namespace internal {

void check_plane(const Plane& plane, CfaPattern pattern) {
    if (plane.values.size() != plane.width * plane.height) {
        throw internal_error("mosaic plane holds " + std::to_string(plane.values.size()) +
                             " values, expected " + std::to_string(plane.width) + " x " +
                             std::to_string(plane.height));
    }
    const std::size_t period = cfa_period(pattern);
    if (plane.width < period || plane.height < period) {
        throw input_error("a " + std::string(cfa_pattern_name(pattern)) +
                          " mosaic needs at least " + std::to_string(period) + " x " +
                          std::to_string(period) + " pixels (one block of the pattern), got " +
                          std::to_string(plane.width) + " x " + std::to_string(plane.height));
    }
}

}  // namespace internal

RgbImage demosaic(const Plane& mosaic, const DemosaicOptions& options, const CancelToken* cancel) {
    if (!method_supports(options.method, options.pattern)) {
        throw usage_error(
            "method " + std::string(demosaic_method_name(options.method)) +
            " does not apply to the " + cfa_pattern_name(options.pattern) + " pattern (expected " +
            (options.pattern == CfaPattern::bayer ? "bilinear or mhc" : "pan-guided") + ")");
    }
    switch (options.method) {
        case DemosaicMethod::bilinear:
            return demosaic_bayer_bilinear(mosaic, options.phase, cancel);
        case DemosaicMethod::mhc:
            return demosaic_bayer_mhc(mosaic, options.phase, cancel);
        case DemosaicMethod::pan_guided:
            return demosaic_truesense(mosaic, cancel);
    }
    throw internal_error("unknown demosaic method");
}

}  // namespace glint::demosaic
