// SPDX-License-Identifier: Apache-2.0
// The light of a run (glint/radiometry/illumination.h): the sun or the moon through the
// atmosphere model, and the scene's point sources.
#include "glint/radiometry/illumination.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <utility>

#include "glint/atmosphere/gas_absorption.h"
#include "glint/atmosphere/lunar.h"
#include "glint/atmosphere/refraction.h"
#include "glint/core/text.h"
#include "glint/motion/scene_instances.h"

namespace glint::radiometry {
namespace {

/// The apparent direction of a source outside the atmosphere at `true_direction` (scene ENU),
/// seen from `observer_m` above sea level: raised by the refraction, its azimuth kept; the true
/// direction for a source below the apparent horizon or overhead.
Vec3 apparent_direction(const glint::atmosphere::RefractionTracer& tracer, double observer_m,
                        const Vec3& true_direction) {
    const double horizontal = std::hypot(true_direction.x, true_direction.y);
    if (!(horizontal > 0.0)) return true_direction;
    const double true_zenith_deg =
        std::atan2(horizontal, true_direction.z) * 180.0 / std::numbers::pi;
    const std::optional<double> apparent =
        tracer.apparent_zenith_for_true_deg(observer_m, true_zenith_deg);
    if (!apparent) return true_direction;
    const double z = *apparent * std::numbers::pi / 180.0;
    const double length = norm(true_direction);
    return Vec3{std::sin(z) * true_direction.x / horizontal,
                std::sin(z) * true_direction.y / horizontal, std::cos(z)} *
           length;
}

}  // namespace

Illumination::Illumination(Illumination&&) noexcept = default;
Illumination& Illumination::operator=(Illumination&&) noexcept = default;
Illumination::~Illumination() = default;

Illumination Illumination::make(const model::Atmosphere& atmosphere,
                                const glint::atmosphere::DataTables& data,
                                const model::Scene& scene, const motion::SceneFrame& frame,
                                const DateTime& reference_utc, Log log) {
    if (!data.sun || (glint::atmosphere::needs_gas_table(atmosphere) && !data.gases) ||
        (glint::atmosphere::needs_aerosol_table(atmosphere) && !data.aerosols)) {
        throw internal_error("glint's data tables were not read (inputs::read_data_tables)");
    }
    Illumination light;
    light.m_atmosphere_kind = atmosphere.kind;
    light.m_atmosphere_where = atmosphere.where;
    light.m_model = glint::atmosphere::make_atmosphere_model(atmosphere, data.gases, data.aerosols);
    light.m_sun = data.sun;
    const auto* parametric =
        dynamic_cast<const glint::atmosphere::ParametricAtmosphereModel*>(light.m_model.get());
    // The aerosol as the model resolved it (the layered one's humidity and season defaults).
    if (parametric != nullptr) log.info("Aerosol: " + parametric->aerosol().description());
    if (parametric != nullptr && atmosphere.parametric.refraction &&
        atmosphere.parametric.profile != model::StandardAtmosphere::isothermal) {
        // The profile's levels at the air's temperatures: shifted with air_temperature_k as
        // the model shifts them for the air's emission (the pressures and water kept).
        const model::StandardAtmosphereProfile& profile =
            model::standard_atmosphere(atmosphere.parametric.profile);
        light.m_refraction_levels.assign(profile.levels.begin(), profile.levels.end());
        for (model::AtmosphereLevel& level : light.m_refraction_levels) {
            level.temperature_k = parametric->air_temperature_k(level.altitude_km * 1000.0);
        }
        const double shift_k =
            light.m_refraction_levels.front().temperature_k - profile.levels.front().temperature_k;
        log.info(std::string("Refraction: view rays, the sun and the moon bent through the ") +
                 profile.name + " profile" +
                 (shift_k != 0.0 ? " (its temperatures shifted " + format_shortest(shift_k) +
                                       " K at sea level, to 0 at 11 km)"
                                 : std::string()) +
                 ", Ciddor's index at each spectral state's wavelength");
    }
    light.m_frame = frame;
    light.m_source_trajectories =
        motion::make_point_source_trajectories(scene, frame, reference_utc, log);
    return light;
}

Environment Illumination::environment(const SpectralGrid& grid, const CaptureWindow& window,
                                      double sensor_z_m, std::vector<double> levels_z_m,
                                      unsigned threads, SensorPathCache* cache) const {
    const DateTime begin = add_seconds(window.reference_utc, window.begin_s);
    const DateTime end = add_seconds(window.reference_utc, window.end_s);
    const motion::SunPosition sun0 = sun_at(begin);
    const motion::SunPosition sun1 = sun_at(end);
    EnvironmentInputs env;
    env.sun_direction_begin = sun0.direction_enu;
    env.sun_direction_end = sun1.direction_enu;
    env.window_begin_s = window.begin_s;
    env.window_end_s = window.end_s;
    env.sun_distance_au = sun0.distance_au;
    if (0.5 * (sun0.zenith_deg + sun1.zenith_deg) >= 90.0) {
        // Night: the moon is the directional source (docs/physics.md, "The moon").
        const motion::MoonPosition moon0 = moon_at(begin);
        const motion::MoonPosition moon1 = moon_at(end);
        env.sun_direction_begin = moon0.direction_enu;
        env.sun_direction_end = moon1.direction_enu;
        env.source_irradiance_scale =
            glint::atmosphere::lunar_irradiance_ratio(moon0.phase_angle_deg, moon0.distance_km);
        env.source_half_angle_rad = glint::atmosphere::lunar_angular_radius_rad(moon0.distance_km);
    }
    if (!m_refraction_levels.empty() && grid.size() > 0) {
        // The sun's or moon's apparent direction, at the grid's middle wavelength (refraction's
        // dispersion moves a source at 10° elevation by about 1″ across the visible).
        const glint::atmosphere::RefractionTracer tracer(glint::atmosphere::RefractiveProfile(
            m_refraction_levels, std::max(grid.wavelength_um(grid.size() / 2), 0.2)));
        const double observer_m = std::max(m_frame.origin().altitude_m, 0.0);
        const bool still = env.sun_direction_begin.x == env.sun_direction_end.x &&
                           env.sun_direction_begin.y == env.sun_direction_end.y &&
                           env.sun_direction_begin.z == env.sun_direction_end.z;
        env.sun_direction_begin = apparent_direction(tracer, observer_m, env.sun_direction_begin);
        env.sun_direction_end = still
                                    ? env.sun_direction_begin
                                    : apparent_direction(tracer, observer_m, env.sun_direction_end);
    }
    env.surface_altitude_m = m_frame.origin().altitude_m;
    env.sensor_altitude_m = m_frame.origin().altitude_m + sensor_z_m;
    env.levels_z_m = std::move(levels_z_m);
    env.threads = threads;
    return Environment::make(grid, *m_model, *m_sun, env, cache);
}

std::shared_ptr<const ViewRefraction> Illumination::view_refraction(double wavelength_um,
                                                                    double sensor_z_m,
                                                                    SensorPathCache* cache) const {
    if (m_refraction_levels.empty() || !(sensor_z_m >= kMinRefractionHeight_m)) return nullptr;
    const double ground_m = std::max(m_frame.origin().altitude_m, 0.0);
    const SensorPathCache::ViewKey key{std::llround(ground_m), std::llround(ground_m + sensor_z_m),
                                       std::llround(wavelength_um * 1e6)};
    if (cache != nullptr) {
        if (auto found = cache->find_view(key)) return found;
    }
    const glint::atmosphere::RefractionTracer tracer(glint::atmosphere::RefractiveProfile(
        m_refraction_levels, static_cast<double>(key[2]) * 1e-6));
    auto view = std::make_shared<const ViewRefraction>(tracer, static_cast<double>(key[0]),
                                                       static_cast<double>(key[1]));
    if (cache != nullptr) cache->insert_view(key, view);
    return view;
}

PointLights Illumination::point_lights_at(const model::Scene& scene, const SpectralGrid& grid,
                                          double t_s) const {
    PointLights lights(grid.size());
    std::vector<std::vector<double>> intensity_by_material(scene.materials.size());
    for (std::size_t i = 0; i < scene.point_sources.size(); ++i) {
        const model::PointSource& source = scene.point_sources[i];
        if (source.material >= scene.materials.size() ||
            !scene.materials[source.material].point_source) {
            throw internal_error("point source \"" + source.name +
                                 "\" does not name a point-source material");
        }
        std::vector<double>& intensity = intensity_by_material[source.material];
        if (intensity.empty()) {
            const model::SpectralTable& table =
                scene.materials[source.material].intensity_w_per_sr_um;
            intensity =
                SpectralCurve(table.wavelengths_um, table.values, table.where).resample(grid);
        }
        const motion::Trajectory* trajectory =
            i < m_source_trajectories.size() ? m_source_trajectories[i].get() : nullptr;
        try {
            lights.add(source.name, motion::point_source_position_m(source, trajectory, t_s),
                       intensity);
        } catch (const Error& e) {
            if (!e.context().file.empty()) throw;
            throw input_error(e.message(), source.where);
        }
    }
    return lights;
}

motion::SunPosition Illumination::sun_at(const DateTime& utc) const {
    return motion::sun_position(utc, m_frame);
}

motion::MoonPosition Illumination::moon_at(const DateTime& utc) const {
    return motion::moon_position(utc, m_frame);
}

std::optional<std::array<double, 2>> Illumination::gas_table_range_um() const {
    const auto* parametric =
        dynamic_cast<const glint::atmosphere::ParametricAtmosphereModel*>(m_model.get());
    const glint::atmosphere::GasBandModel* table =
        parametric != nullptr ? parametric->gas_table() : nullptr;
    if (table == nullptr || table->wavelengths_um().empty()) return std::nullopt;
    return std::array<double, 2>{table->wavelengths_um().front(), table->wavelengths_um().back()};
}

void Illumination::warn_if_one_geometry(const scene::GeometryScene& geometry,
                                        const Log& log) const {
    if (m_atmosphere_kind != model::AtmosphereKind::tabulated) return;
    const std::vector<double> levels = altitude_levels(geometry);
    if (levels.size() < 2) return;
    log.warning(format_located(
        m_atmosphere_where,
        "a tabulated atmosphere is one geometry: its sun, sky and path terms are applied at "
        "every height, but the scene has surfaces from " +
            format_shortest(levels.front()) + " m to " + format_shortest(levels.back()) +
            " m above its origin (docs/scene.md, \"At which altitude each light path sees the "
            "atmosphere\")"));
}

}  // namespace glint::radiometry
