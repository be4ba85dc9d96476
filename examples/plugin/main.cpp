// SPDX-License-Identifier: Apache-2.0
// glint-radiometer: a single-pixel radiometer looking straight down from a fixed altitude,
// swept along a line across a glint scene; one CSV row of at-aperture radiance per position.
// A custom sensor written against the installed glint package (README.md).
// Usage: glint-radiometer SIM [SAMPLES [X0 Y0 X1 Y1 [ALTITUDE_M]]]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "glint/atmosphere/atmosphere.h"
#include "glint/atmosphere/solar.h"
#include "glint/core/context.h"
#include "glint/core/spectral.h"
#include "glint/inputs/data_tables.h"
#include "glint/inputs/load.h"
#include "glint/motion/frames.h"
#include "glint/motion/scene_instances.h"
#include "glint/motion/sun.h"
#include "glint/radiometry/environment.h"
#include "glint/radiometry/materials.h"
#include "glint/radiometry/path_tracer.h"
#include "glint/radiometry/problem.h"
#include "glint/scene/geometry_scene.h"

namespace {

constexpr double kPi = 3.14159265358979323846;

// The radiometer's sample rays: problem i is position i of the sweep; each sample looks down
// through a circular field of view of half-angle `half_angle_rad` around nadir.
class SweepRays final : public glint::radiometry::RaySource {
public:
    SweepRays(glint::radiometry::Vec3 from, glint::radiometry::Vec3 to, std::uint64_t count,
              double half_angle_rad)
        : m_from(from), m_to(to), m_count(count), m_half_angle(half_angle_rad) {}

    glint::radiometry::Vec3 position(std::uint64_t i) const {
        const double t =
            m_count > 1 ? static_cast<double>(i) / static_cast<double>(m_count - 1) : 0.0;
        return {m_from.x + t * (m_to.x - m_from.x), m_from.y + t * (m_to.y - m_from.y),
                m_from.z + t * (m_to.z - m_from.z)};
    }

    glint::radiometry::SampleRay generate(std::uint64_t problem, std::uint64_t,
                                          glint::RandomStream& rng) const override {
        // Uniform over the cone's solid angle (small: uniform in the disk of tan θ).
        const double r = m_half_angle * std::sqrt(rng.uniform());
        const double phi = 2.0 * kPi * rng.uniform();
        glint::radiometry::Vec3 d{r * std::cos(phi), r * std::sin(phi), -1.0};
        const double norm = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        d = {d.x / norm, d.y / norm, d.z / norm};
        return {position(problem), d, 0.0, 1.0};
    }

private:
    glint::radiometry::Vec3 m_from;
    glint::radiometry::Vec3 m_to;
    std::uint64_t m_count;
    double m_half_angle;
};

double arg_or(int argc, char** argv, int i, double fallback) {
    return i < argc ? std::stod(argv[i]) : fallback;
}

}  // namespace

int main(int argc, char** argv) try {
    if (argc < 2 || std::string(argv[1]) == "--help") {
        std::cerr << "usage: glint-radiometer SIM [SAMPLES [X0 Y0 X1 Y1 [ALTITUDE_M]]]\n"
                     "  data folder: $GLINT_DATA_DIR, else " GLINT_DATA_DIR_DEFAULT "\n";
        return argc < 2 ? 2 : 0;
    }
    const std::uint64_t count = static_cast<std::uint64_t>(arg_or(argc, argv, 2, 29));
    // Default sweep: west to east across the demo's five calibration panels (y = -23 m).
    const double x0 = arg_or(argc, argv, 3, -14.0), y0 = arg_or(argc, argv, 4, -23.0);
    const double x1 = arg_or(argc, argv, 5, 14.0), y1 = arg_or(argc, argv, 6, -23.0);
    const double altitude_m = arg_or(argc, argv, 7, 800.0);
    const char* env_data = std::getenv("GLINT_DATA_DIR");
    const std::filesystem::path data_dir =
        env_data != nullptr && *env_data != '\0' ? env_data : GLINT_DATA_DIR_DEFAULT;

    // 1. The simulation: scene, atmosphere, platforms (only the tasks' date is used here).
    const glint::Log log(
        [](glint::LogLevel level, const std::string& message) {
            std::cerr << "glint-radiometer: " << glint::log_level_name(level) << ": " << message
                      << "\n";
        },
        glint::LogLevel::warning);
    const glint::model::SimulationInputs sim =
        glint::inputs::load_logged(argv[1], glint::inputs::LoadOptions{}, log);
    const glint::DateTime when =
        sim.platforms.empty() ? glint::DateTime{} : sim.platforms.front().tasks.reference;
    const glint::motion::SceneFrame frame =
        sim.scene.origin ? glint::motion::SceneFrame(sim.scene.origin->latitude_deg,
                                                     sim.scene.origin->longitude_deg,
                                                     sim.scene.origin->altitude_m)
                         : glint::motion::SceneFrame();

    // 2. The Embree scene at the reference time (t = 0: moving instances frozen there).
    const auto trajectories =
        glint::motion::make_instance_trajectories(sim.scene, frame, when, log);
    const glint::scene::GeometryScene geometry =
        glint::scene::GeometryScene::build(sim.scene, trajectories, {}, log);

    // 3. Spectral grid, materials, atmosphere, sun, and this capture's environment.
    const glint::SpectralGrid grid = glint::SpectralGrid::regular(0.40, 0.90, 0.01);
    const glint::radiometry::MaterialTable materials(sim.scene.materials, grid, log);
    const glint::atmosphere::DataTables tables = glint::inputs::read_data_tables(
        data_dir, glint::atmosphere::needs_gas_table(sim.atmosphere));
    const auto atmosphere = glint::atmosphere::make_atmosphere_model(sim.atmosphere, tables.gases);
    const glint::atmosphere::SolarSpectrum& sun = *tables.sun;
    const glint::motion::SunPosition sun_at = glint::motion::sun_position(when, frame);
    glint::radiometry::EnvironmentInputs env;
    env.sun_direction_begin = env.sun_direction_end = sun_at.direction_enu;
    env.sun_distance_au = sun_at.distance_au;
    env.surface_altitude_m = frame.origin().altitude_m;
    env.sensor_altitude_m = frame.origin().altitude_m + altitude_m;
    const auto environment = glint::radiometry::Environment::make(grid, *atmosphere, sun, env);
    const glint::radiometry::PathTracer tracer(geometry, materials, environment);

    // 4. One pixel problem per position: 0.5 mrad field of view, 32 to 256 samples.
    const SweepRays rays({x0, y0, altitude_m}, {x1, y1, altitude_m}, count, 0.5e-3);
    glint::radiometry::ProblemBatch batch;
    batch.source = &rays;
    batch.convergence = {32, 256, 1e-5};
    batch.reference_band = glint::radiometry::nearest_band(grid, 0.65);
    batch.count = count;
    const glint::radiometry::Solutions solutions =
        glint::radiometry::solve(tracer, batch, glint::Context{});

    // 5. CSV: position, band-integrated radiance over the grid (trapezoid), and three bands.
    const std::size_t blue = glint::radiometry::nearest_band(grid, 0.45);
    const std::size_t red = glint::radiometry::nearest_band(grid, 0.65);
    const std::size_t nir = glint::radiometry::nearest_band(grid, 0.85);
    std::printf(
        "sample,x_m,y_m,samples,radiance_0.40-0.90um_W_per_cm2_sr,"
        "L_450nm,L_650nm,L_850nm\n");
    for (std::uint64_t i = 0; i < count; ++i) {
        const auto radiance = solutions.radiance(i);
        double integrated = 0.0;
        for (std::size_t b = 1; b < grid.size(); ++b) {
            integrated += 0.5 * (radiance[b] + radiance[b - 1]) *
                          (grid.wavelength_um(b) - grid.wavelength_um(b - 1));
        }
        const auto p = rays.position(i);
        std::printf("%llu,%.3f,%.3f,%llu,%.6e,%.6e,%.6e,%.6e\n", static_cast<unsigned long long>(i),
                    p.x, p.y, static_cast<unsigned long long>(solutions.samples[i]), integrated,
                    radiance[blue], radiance[red], radiance[nir]);
    }
    return 0;
} catch (const std::exception& e) {
    std::cerr << "glint-radiometer: error: " << e.what() << "\n";
    return 1;
}
