// SPDX-License-Identifier: Apache-2.0
// Writes the figure of docs/physics.md, "The sky in the renderer" (scripts/make-sky-fisheye.sh):
// the sky the renderer's escaping rays read (Environment::sky_radiance), in an equidistant
// fisheye looking up (zenith at the centre, the horizon at the rim, north up, east left), at
// 0.65, 0.55 and 0.45 µm as red, green and blue, for a rural haze of 23 km and of 5 km
// visibility side by side, the sun 60° from the zenith in the south-east. One scale for both
// panels (the 99th percentile of their values; the aureole's core saturates), gamma 2.2.
// Usage: sky_fisheye <glint data folder> <out.png>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <numbers>
#include <vector>

#include "glint/atmosphere/aerosol_table.h"
#include "glint/atmosphere/atmosphere.h"
#include "glint/atmosphere/solar.h"
#include "glint/io/image.h"
#include "glint/io/input_files.h"
#include "glint/radiometry/environment.h"

namespace {

using glint::radiometry::Vec3;

constexpr double kPi = std::numbers::pi;
constexpr std::size_t kPanel = 400;  // pixels across one fisheye
constexpr double kSunZenithDeg = 60.0;
constexpr double kSunAzimuthDeg = 135.0;

Vec3 direction(double zenith_deg, double azimuth_deg) {
    const double t = zenith_deg * kPi / 180.0;
    const double p = azimuth_deg * kPi / 180.0;
    return {std::sin(t) * std::sin(p), std::sin(t) * std::cos(p), std::cos(t)};
}

/// One panel's RGB radiances (W/(cm² sr µm)), row-major, negative outside the circle.
std::vector<double> panel(const glint::radiometry::Environment& env) {
    std::vector<double> rgb(kPanel * kPanel * 3, -1.0);
    const double radius = 0.5 * static_cast<double>(kPanel);
    for (std::size_t y = 0; y < kPanel; ++y) {
        for (std::size_t x = 0; x < kPanel; ++x) {
            const double dx = (static_cast<double>(x) + 0.5 - radius) / radius;
            const double dy = (static_cast<double>(y) + 0.5 - radius) / radius;
            const double r = std::hypot(dx, dy);
            if (r >= 1.0) continue;
            // Looking up with north at the top: east is on the left.
            const double azimuth = std::atan2(-dx, -dy) * 180.0 / kPi;
            const std::vector<double> l = env.sky_radiance(direction(90.0 * r, azimuth), 0.0, 0.0);
            for (std::size_t c = 0; c < 3; ++c) rgb[(y * kPanel + x) * 3 + c] = l[2 - c];
        }
    }
    return rgb;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: sky_fisheye <glint data folder> <out.png>\n");
        return 2;
    }
    try {
        const std::filesystem::path data = argv[1];
        const auto aerosols = std::make_shared<const glint::atmosphere::AerosolTable>(
            glint::atmosphere::AerosolTable::from_csv(
                glint::io::read_input_file(data / glint::atmosphere::AerosolTable::kRelativePath),
                glint::atmosphere::AerosolTable::kRelativePath));
        const auto sun = glint::atmosphere::SolarSpectrum::from_astm_g173(
            glint::io::read_input_file(data / glint::atmosphere::SolarSpectrum::kAstmRelativePath),
            glint::atmosphere::SolarSpectrum::kAstmRelativePath);
        const glint::SpectralGrid grid({0.45, 0.55, 0.65});
        std::vector<std::vector<double>> panels;
        for (const double visibility_km : {23.0, 5.0}) {
            glint::model::ParametricAtmosphere p;
            p.gas_absorption = false;
            p.aerosol_model = "rural";
            p.visibility_km = visibility_km;
            const glint::atmosphere::ParametricAtmosphereModel model(p, nullptr, aerosols);
            glint::radiometry::EnvironmentInputs inputs;
            inputs.sun_direction_begin = inputs.sun_direction_end =
                direction(kSunZenithDeg, kSunAzimuthDeg);
            panels.push_back(panel(glint::radiometry::Environment::make(grid, model, sun, inputs)));
        }
        std::vector<double> values;
        for (const auto& p : panels) {
            for (const double v : p) {
                if (v >= 0.0) values.push_back(v);
            }
        }
        const auto at = values.begin() + static_cast<std::ptrdiff_t>(0.99 * values.size());
        std::nth_element(values.begin(), at, values.end());
        const double scale = *at;
        glint::io::ImageWriteOptions options;
        options.description = "glint's directional sky: rural haze 23 km | 5 km, sun at 60 deg";
        glint::io::ImageWriter writer(argv[2], 2 * kPanel, kPanel, 3, options);
        std::vector<double> line(2 * kPanel * 3);
        for (std::size_t y = 0; y < kPanel; ++y) {
            for (std::size_t side = 0; side < 2; ++side) {
                for (std::size_t x = 0; x < kPanel; ++x) {
                    for (std::size_t c = 0; c < 3; ++c) {
                        const double v = panels[side][(y * kPanel + x) * 3 + c];
                        line[((side * kPanel) + x) * 3 + c] =
                            v < 0.0
                                ? 255.0
                                : std::round(255.0 * std::pow(std::min(v / scale, 1.0), 1.0 / 2.2));
                    }
                }
            }
            writer.write_line(line);
        }
        writer.commit();
        std::printf("wrote %s (scale %.4g W/(cm2 sr um) at the 99th percentile)\n", argv[2], scale);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "sky_fisheye: %s\n", e.what());
        return 1;
    }
}
