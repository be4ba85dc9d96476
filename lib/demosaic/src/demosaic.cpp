// SPDX-License-Identifier: Apache-2.0
// Method names, the checks every method makes on its input, DemosaicStream's dispatch to the
// Bayer and TrueSense line demosaicers, and the whole-image functions over a stream.
#include "glint/demosaic/demosaic.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "glint/core/error.h"
#include "line_demosaicker.h"

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

void check_method(const DemosaicOptions& options) {
    if (method_supports(options.method, options.pattern)) return;
    throw usage_error("method " + std::string(demosaic_method_name(options.method)) +
                      " does not apply to the " + cfa_pattern_name(options.pattern) +
                      " pattern (expected " +
                      (options.pattern == CfaPattern::bayer ? "bilinear or mhc" : "pan-guided") +
                      ")");
}

DemosaicStream::DemosaicStream(std::size_t width, std::size_t height,
                               const DemosaicOptions& options, MosaicLineReader read)
    : m_width(width), m_height(height) {
    check_method(options);
    const std::size_t period = cfa_period(options.pattern);
    if (width < period || height < period) {
        throw input_error("a " + std::string(cfa_pattern_name(options.pattern)) +
                          " mosaic needs at least " + std::to_string(period) + " x " +
                          std::to_string(period) + " pixels (one block of the pattern), got " +
                          std::to_string(width) + " x " + std::to_string(height));
    }
    m_lines = options.pattern == CfaPattern::bayer
                  ? internal::make_bayer(width, height, options.phase, options.method,
                                         std::move(read))
                  : internal::make_truesense(width, height, std::move(read));
}

DemosaicStream::~DemosaicStream() = default;

void DemosaicStream::next_line(std::span<double> rgb) {
    if (m_next >= m_height || rgb.size() != m_width * 3) {
        throw internal_error("DemosaicStream::next_line: line " + std::to_string(m_next) +
                             " of " + std::to_string(m_height) + ", buffer of " +
                             std::to_string(rgb.size()) + " values for width " +
                             std::to_string(m_width));
    }
    m_lines->line(m_next, rgb);
    ++m_next;
}

std::size_t DemosaicStream::bytes_held(std::size_t width, DemosaicMethod method) {
    const std::size_t values = method == DemosaicMethod::pan_guided
                                   ? internal::truesense_values_held(width)
                                   : internal::bayer_values_held(width);
    return values * sizeof(double);
}

RgbImage demosaic(const Plane& mosaic, const DemosaicOptions& options, const CancelToken* cancel) {
    if (mosaic.values.size() != mosaic.width * mosaic.height) {
        throw internal_error("mosaic plane holds " + std::to_string(mosaic.values.size()) +
                             " values, expected " + std::to_string(mosaic.width) + " x " +
                             std::to_string(mosaic.height));
    }
    DemosaicStream stream(mosaic.width, mosaic.height, options,
                          [&mosaic](std::size_t y, std::span<double> out) {
                              const auto first = mosaic.values.begin() +
                                                 static_cast<std::ptrdiff_t>(y * mosaic.width);
                              std::copy(first, first + static_cast<std::ptrdiff_t>(out.size()),
                                        out.begin());
                          });
    RgbImage out{mosaic.width, mosaic.height, std::vector<double>(mosaic.values.size() * 3)};
    const std::size_t line_values = mosaic.width * 3;
    for (std::size_t y = 0; y < mosaic.height; ++y) {
        if (cancel != nullptr) cancel->throw_if_cancelled();
        stream.next_line(std::span<double>(out.rgb).subspan(y * line_values, line_values));
    }
    return out;
}

RgbImage demosaic_bayer_bilinear(const Plane& mosaic, BayerPhase phase, const CancelToken* cancel) {
    return demosaic(mosaic, {CfaPattern::bayer, phase, DemosaicMethod::bilinear}, cancel);
}

RgbImage demosaic_bayer_mhc(const Plane& mosaic, BayerPhase phase, const CancelToken* cancel) {
    return demosaic(mosaic, {CfaPattern::bayer, phase, DemosaicMethod::mhc}, cancel);
}

RgbImage demosaic_truesense(const Plane& mosaic, const CancelToken* cancel) {
    return demosaic(mosaic, {CfaPattern::truesense, BayerPhase::rggb, DemosaicMethod::pan_guided},
                    cancel);
}

}  // namespace glint::demosaic
