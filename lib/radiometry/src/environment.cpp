// SPDX-License-Identifier: Apache-2.0
// Environment: the per-capture illumination and sensor-path tables
// (glint/radiometry/environment.h).
#include "glint/radiometry/environment.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "environment_sky.h"
#include "glint/core/error.h"
#include "glint/radiometry/sampling.h"
#include "glint/radiometry/view_refraction.h"

namespace glint::radiometry {
namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

Vec3 checked_unit(const Vec3& v, const char* what) {
    const double n = norm(v);
    if (!std::isfinite(n) || !(n > 0.0)) {
        throw input_error(std::string(what) + " must be a finite non-zero vector");
    }
    return v / n;
}

void check_spectrum(const std::vector<double>& values, std::size_t bands, const char* what) {
    if (values.size() != bands) {
        throw input_error(std::string(what) + " has " + std::to_string(values.size()) +
                          " values for a grid of " + std::to_string(bands));
    }
    for (double v : values) {
        if (!std::isfinite(v) || v < 0.0) {
            throw input_error(std::string(what) + " values must be finite and >= 0");
        }
    }
}

bool any_positive(const std::vector<double>& values) {
    return std::any_of(values.begin(), values.end(), [](double v) { return v > 0.0; });
}

double zenith_deg(const Vec3& unit) { return std::acos(std::clamp(unit.z, -1.0, 1.0)) * kRadToDeg; }

/// Azimuth clockwise from north (+y) towards east (+x), degrees in [0, 360).
double azimuth_deg(const Vec3& unit) {
    const double a = std::atan2(unit.x, unit.y) * kRadToDeg;
    return a < 0.0 ? a + 360.0 : a;
}

/// Position of `value` on nodes 0, step, 2·step … (count nodes): lower index and fraction.
std::pair<std::size_t, double> locate(double value, double step, std::size_t count) {
    if (count < 2) return {0, 0.0};
    const double x = std::clamp(value / step, 0.0, static_cast<double>(count - 1));
    const auto lo = std::min(static_cast<std::size_t>(x), count - 2);
    return {lo, x - static_cast<double>(lo)};
}

/// T_v over the view-zenith nodes and L_p over the (zenith, relative azimuth) nodes.
std::shared_ptr<const SensorPathTables> sensor_path_tables(
    const SpectralGrid& grid, const glint::atmosphere::AtmosphereModel& atmosphere,
    const glint::atmosphere::AtmosphereGeometry& geometry, const std::vector<double>& toa,
    unsigned threads) {
    auto t = std::make_shared<SensorPathTables>();
    const std::size_t bands = grid.size();
    t->zenith_nodes = static_cast<std::size_t>(std::lround(Environment::kViewZenithMaxDeg /
                                                           Environment::kViewZenithStepDeg)) +
                      1;
    t->azimuth_nodes =
        static_cast<std::size_t>(std::lround(180.0 / Environment::kAzimuthStepDeg)) + 1;
    t->transmittance.resize(t->zenith_nodes * bands);
    t->path_radiance.resize(t->zenith_nodes * t->azimuth_nodes * bands);
    // One view zenith per task: each node's values depend on its geometry alone.
    const auto zenith_row = [&](std::size_t z) {
        glint::atmosphere::AtmosphereGeometry g = geometry;
        g.view_zenith_deg = static_cast<double>(z) * Environment::kViewZenithStepDeg;
        g.view_azimuth_deg = g.sun_azimuth_deg;
        const std::vector<double> t_view = atmosphere.sensor_transmittance(grid, g);
        std::copy(t_view.begin(), t_view.end(),
                  t->transmittance.begin() + static_cast<std::ptrdiff_t>(z * bands));
        std::vector<double> azimuths(t->azimuth_nodes);
        for (std::size_t a = 0; a < t->azimuth_nodes; ++a) {
            azimuths[a] = std::fmod(
                g.sun_azimuth_deg + static_cast<double>(a) * Environment::kAzimuthStepDeg, 360.0);
        }
        const std::vector<std::vector<double>> lp =
            atmosphere.path_radiance_at_azimuths(grid, g, toa, azimuths);
        for (std::size_t a = 0; a < t->azimuth_nodes; ++a) {
            std::copy(lp[a].begin(), lp[a].end(),
                      t->path_radiance.begin() +
                          static_cast<std::ptrdiff_t>((z * t->azimuth_nodes + a) * bands));
        }
    };
    tbb::task_arena arena(threads == 0 ? tbb::task_arena::automatic : static_cast<int>(threads));
    arena.execute([&] {
        tbb::parallel_for(std::size_t{0}, t->zenith_nodes, [&](std::size_t z) { zenith_row(z); });
    });
    t->effects = std::any_of(t->transmittance.begin(), t->transmittance.end(),
                             [](double v) { return v != 1.0; }) ||
                 any_positive(t->path_radiance);
    return t;
}

}  // namespace

std::shared_ptr<const SensorPathTables> SensorPathCache::find(const Key& key) const {
    const auto it = m_tables.find(key);
    return it == m_tables.end() ? nullptr : it->second;
}

void SensorPathCache::insert(const Key& key, std::shared_ptr<const SensorPathTables> tables) {
    m_tables[key] = std::move(tables);
}

std::shared_ptr<const ViewRefraction> SensorPathCache::find_view(const ViewKey& key) const {
    const auto it = m_views.find(key);
    return it == m_views.end() ? nullptr : it->second;
}

void SensorPathCache::insert_view(const ViewKey& key, std::shared_ptr<const ViewRefraction> view) {
    m_views[key] = std::move(view);
}

std::optional<std::shared_ptr<const std::vector<double>>> SensorPathCache::find_sky(
    const Key& key) const {
    const auto it = m_skies.find(key);
    if (it == m_skies.end()) return std::nullopt;
    return it->second;
}

void SensorPathCache::insert_sky(const Key& key, std::shared_ptr<const std::vector<double>> shape) {
    m_skies[key] = std::move(shape);
}

Environment::Environment(const SpectralGrid& grid)
    : m_grid(grid),
      m_bands(grid.size()),
      m_sun_half_angle_rad(kSunAngularRadiusRad),
      m_sun_cone_one_minus_cos(cone_one_minus_cos(kSunAngularRadiusRad)),
      m_sun(grid.size(), 0.0),
      m_sky(grid.size(), 0.0) {}

Environment Environment::uniform(const SpectralGrid& grid, const Vec3& sun_direction,
                                 std::vector<double> sun_irradiance_w_per_cm2_um,
                                 std::vector<double> sky_radiance_w_per_cm2_sr_um) {
    Environment env(grid);
    env.m_sun_begin = env.m_sun_end = checked_unit(sun_direction, "the sun direction");
    check_spectrum(sun_irradiance_w_per_cm2_um, grid.size(), "the sun irradiance");
    check_spectrum(sky_radiance_w_per_cm2_sr_um, grid.size(), "the sky radiance");
    env.m_sun = std::move(sun_irradiance_w_per_cm2_um);
    env.m_sky = std::move(sky_radiance_w_per_cm2_sr_um);
    env.m_sun_visible = any_positive(env.m_sun);
    env.m_sky_black = !any_positive(env.m_sky);
    return env;
}

Environment Environment::make(const SpectralGrid& grid,
                              const glint::atmosphere::AtmosphereModel& atmosphere,
                              const glint::atmosphere::SolarSpectrum& sun,
                              const EnvironmentInputs& in, SensorPathCache* cache) {
    if (!std::isfinite(in.window_begin_s) || !std::isfinite(in.window_end_s) ||
        in.window_end_s < in.window_begin_s) {
        throw input_error("the capture window must be finite with end >= begin");
    }
    if (!std::isfinite(in.surface_altitude_m) || !std::isfinite(in.sensor_altitude_m)) {
        throw input_error("the surface and sensor altitudes must be finite");
    }
    if (in.levels_z_m.size() > kMaxLevels) {
        throw input_error("the environment takes at most " + std::to_string(kMaxLevels) +
                          " levels (" + std::to_string(in.levels_z_m.size()) + " given)");
    }
    Environment env(grid);
    if (!in.levels_z_m.empty()) {
        env.m_levels_z = in.levels_z_m;
        for (const double z : env.m_levels_z) {
            if (!std::isfinite(z)) throw input_error("the environment's levels must be finite");
        }
        std::sort(env.m_levels_z.begin(), env.m_levels_z.end());
        env.m_levels_z.erase(std::unique(env.m_levels_z.begin(), env.m_levels_z.end()),
                             env.m_levels_z.end());
    }
    env.m_sun_begin = checked_unit(in.sun_direction_begin, "the sun direction at the window begin");
    env.m_sun_end = checked_unit(in.sun_direction_end, "the sun direction at the window end");
    env.m_window_begin_s = in.window_begin_s;
    env.m_window_end_s = in.window_end_s;

    const Vec3 sun_mid = env.sun_direction(0.5 * (in.window_begin_s + in.window_end_s));
    glint::atmosphere::AtmosphereGeometry geometry;
    geometry.sun_zenith_deg = zenith_deg(sun_mid);
    geometry.sun_azimuth_deg = azimuth_deg(sun_mid);

    if (!(in.source_irradiance_scale > 0.0) || !std::isfinite(in.source_irradiance_scale) ||
        !(in.source_half_angle_rad > 0.0) || !(in.source_half_angle_rad < 0.1)) {
        throw input_error(
            "the source's irradiance scale must be > 0 and its angular radius in "
            "(0, 0.1) rad");
    }
    env.m_sun_half_angle_rad = in.source_half_angle_rad;
    env.m_sun_cone_one_minus_cos = cone_one_minus_cos(in.source_half_angle_rad);
    // The source's scale, rounded as the sensor-path key rounds it (log steps of
    // kSourceScaleStep): the sun's is exactly 1.
    const long long scale_key =
        std::llround(std::log(in.source_irradiance_scale) / SensorPathCache::kSourceScaleStep);
    const double scale =
        std::exp(static_cast<double>(scale_key) * SensorPathCache::kSourceScaleStep);
    std::vector<double> toa = sun.resample(grid, in.sun_distance_au);
    for (double& v : toa) v *= scale;

    const std::size_t levels = env.m_levels_z.size();
    env.m_sun.assign(levels * env.m_bands, 0.0);
    std::vector<double> sky_zeniths_deg, sky_air_mass;
    for (std::size_t node = 0; node < kSkyZenithNodes; ++node) {
        sky_zeniths_deg.push_back(static_cast<double>(node) * kSkyZenithStepDeg);
        sky_air_mass.push_back(glint::atmosphere::relative_air_mass(sky_zeniths_deg.back()));
    }
    // The scattered sky's shape at the lowest level, computed at the geometry rounded as the
    // sensor-path tables' (whether or not a cache is given).
    {
        const SensorPathCache::Key key{
            std::llround(geometry.sun_zenith_deg / SensorPathCache::kAngleStepDeg),
            std::llround(geometry.sun_azimuth_deg / SensorPathCache::kAngleStepDeg),
            std::llround((in.surface_altitude_m + env.m_levels_z.front()) /
                         SensorPathCache::kAltitudeStepM),
            0,
            std::llround(in.sun_distance_au / SensorPathCache::kSunDistanceStepAu),
            scale_key};
        const auto cached = cache != nullptr ? cache->find_sky(key) : std::nullopt;
        if (cached) {
            env.m_sky_shape = *cached;
        } else {
            glint::atmosphere::AtmosphereGeometry rounded = geometry;
            rounded.sun_zenith_deg = static_cast<double>(key[0]) * SensorPathCache::kAngleStepDeg;
            rounded.sun_azimuth_deg = static_cast<double>(key[1]) * SensorPathCache::kAngleStepDeg;
            rounded.surface_altitude_m =
                static_cast<double>(key[2]) * SensorPathCache::kAltitudeStepM;
            rounded.sensor_altitude_m = std::max(in.sensor_altitude_m, rounded.surface_altitude_m);
            std::vector<double> rounded_toa = sun.resample(
                grid, static_cast<double>(key[4]) * SensorPathCache::kSunDistanceStepAu);
            for (double& v : rounded_toa) v *= scale;
            env.m_sky_shape =
                detail::sky_shape(grid, atmosphere, rounded, rounded_toa, sky_air_mass, in.threads);
            if (cache != nullptr) cache->insert_sky(key, env.m_sky_shape);
        }
    }
    const bool by_zenith = atmosphere.directional_thermal_sky() || env.m_sky_shape != nullptr;
    env.m_sky_nodes = by_zenith ? kSkyZenithNodes : 1;
    env.m_sky.assign(levels * env.m_sky_nodes * env.m_bands, 0.0);
    if (env.m_sky_shape) env.m_sky_diffuse.assign(levels * env.m_bands, 0.0);
    sky_zeniths_deg.resize(env.m_sky_nodes);
    sky_air_mass.resize(env.m_sky_nodes);
    env.m_sky_air_mass = sky_air_mass;
    env.m_paths.assign(levels, nullptr);
    env.m_upward.assign(levels, false);
    for (std::size_t level = 0; level < levels; ++level) {
        const double altitude_m = in.surface_altitude_m + env.m_levels_z[level];
        // A level above the sensor: the path between them is the reversed one, the sensor
        // as its lower end (transmittance is reciprocal; see docs/scene.md).
        const bool upward = altitude_m > in.sensor_altitude_m;
        env.m_upward[level] = upward;
        geometry.surface_altitude_m = altitude_m;
        geometry.sensor_altitude_m = std::max(in.sensor_altitude_m, altitude_m);
        const std::vector<double> t_sun = atmosphere.sun_transmittance(grid, geometry);
        for (std::size_t b = 0; b < env.m_bands; ++b) {
            env.m_sun[level * env.m_bands + b] = toa[b] * t_sun[b];
        }
        if (env.m_sky_nodes == 1) {
            const std::vector<double> sky =
                atmosphere.sky_radiance_w_per_cm2_sr_um(grid, geometry, toa);
            std::copy(sky.begin(), sky.end(), env.m_sky.begin() + level * env.m_bands);
        } else {
            const std::vector<double> diffuse =
                atmosphere.diffuse_sky_irradiance_w_per_cm2_um(grid, geometry, toa);
            const auto thermal = atmosphere.thermal_sky_at_zeniths(grid, geometry, sky_zeniths_deg);
            // With a shape, E_diffuse/π is kept apart (sky_lookup multiplies it by the shape).
            const double isotropic = env.m_sky_shape ? 0.0 : 1.0;
            for (std::size_t node = 0; node < env.m_sky_nodes; ++node) {
                double* row = &env.m_sky[(level * env.m_sky_nodes + node) * env.m_bands];
                for (std::size_t b = 0; b < env.m_bands; ++b) {
                    row[b] = isotropic * diffuse[b] / std::numbers::pi + thermal[node][b];
                }
            }
            if (env.m_sky_shape) {
                for (std::size_t b = 0; b < env.m_bands; ++b) {
                    env.m_sky_diffuse[level * env.m_bands + b] = diffuse[b] / std::numbers::pi;
                }
            }
        }

        // The sensor path at the rounded geometry (see SensorPathCache).
        glint::atmosphere::AtmosphereGeometry path = geometry;
        if (upward) {
            path.surface_altitude_m = in.sensor_altitude_m;
            path.sensor_altitude_m = altitude_m;
        }
        const SensorPathCache::Key key{
            std::llround(path.sun_zenith_deg / SensorPathCache::kAngleStepDeg),
            std::llround(path.sun_azimuth_deg / SensorPathCache::kAngleStepDeg),
            std::llround(path.surface_altitude_m / SensorPathCache::kAltitudeStepM),
            std::llround(path.sensor_altitude_m / SensorPathCache::kAltitudeStepM),
            std::llround(in.sun_distance_au / SensorPathCache::kSunDistanceStepAu),
            scale_key};
        std::shared_ptr<const SensorPathTables> tables =
            cache != nullptr ? cache->find(key) : nullptr;
        if (!tables) {
            glint::atmosphere::AtmosphereGeometry rounded = path;
            rounded.sun_zenith_deg = static_cast<double>(key[0]) * SensorPathCache::kAngleStepDeg;
            rounded.sun_azimuth_deg = static_cast<double>(key[1]) * SensorPathCache::kAngleStepDeg;
            rounded.surface_altitude_m =
                static_cast<double>(key[2]) * SensorPathCache::kAltitudeStepM;
            rounded.sensor_altitude_m =
                static_cast<double>(key[3]) * SensorPathCache::kAltitudeStepM;
            // The exo-atmospheric sun at the rounded distance too: the tables are a function
            // of the key alone (a shard renders the bytes of the whole run).
            std::vector<double> rounded_toa = sun.resample(
                grid, static_cast<double>(key[4]) * SensorPathCache::kSunDistanceStepAu);
            for (double& v : rounded_toa) v *= scale;
            tables = sensor_path_tables(grid, atmosphere, rounded, rounded_toa, in.threads);
            if (cache != nullptr) cache->insert(key, tables);
        }
        if (upward && any_positive(tables->path_radiance)) {
            // The model's path radiance is what the upper end sees looking down: not this
            // path's. It is left out (docs/scene.md).
            auto transmittance_only = std::make_shared<SensorPathTables>(*tables);
            std::fill(transmittance_only->path_radiance.begin(),
                      transmittance_only->path_radiance.end(), 0.0);
            transmittance_only->effects = std::any_of(transmittance_only->transmittance.begin(),
                                                      transmittance_only->transmittance.end(),
                                                      [](double v) { return v != 1.0; });
            tables = std::move(transmittance_only);
        }
        env.m_sensor_path = env.m_sensor_path || tables->effects;
        env.m_paths[level] = std::move(tables);
    }
    env.m_sun_visible = any_positive(env.m_sun);
    env.m_sky_black = !any_positive(env.m_sky) && !any_positive(env.m_sky_diffuse);
    return env;
}

AltitudeLevel Environment::level_at(double z_m) const noexcept {
    const std::size_t n = m_levels_z.size();
    if (n == 1 || !(z_m > m_levels_z.front())) return {0, 0.0};
    if (!(z_m < m_levels_z.back())) return {n - 1, 0.0};
    const auto above = std::upper_bound(m_levels_z.begin(), m_levels_z.end(), z_m);
    const auto index = static_cast<std::size_t>(above - m_levels_z.begin()) - 1;
    const double lo = m_levels_z[index];
    const double fraction = (z_m - lo) / (m_levels_z[index + 1] - lo);
    return {index, fraction};
}

Vec3 Environment::sun_direction(double time_s) const noexcept {
    const double span = m_window_end_s - m_window_begin_s;
    if (!(span > 0.0)) return m_sun_begin;
    const double f = std::clamp((time_s - m_window_begin_s) / span, 0.0, 1.0);
    return normalized(m_sun_begin * (1.0 - f) + m_sun_end * f);
}

Environment::PathLookup Environment::path_lookup(std::size_t level, const Vec3& to_sensor,
                                                 double time_s) const noexcept {
    const SensorPathTables& tables = *m_paths[level];
    // Above the sensor the tables are of the reversed path (sensor → surface, upwards).
    const double zenith = m_upward[level] ? 180.0 - zenith_deg(to_sensor) : zenith_deg(to_sensor);
    const auto [z0, fz] = locate(zenith, kViewZenithStepDeg, tables.zenith_nodes);
    double relative = std::fabs(azimuth_deg(to_sensor) - azimuth_deg(sun_direction(time_s)));
    if (relative > 180.0) relative = 360.0 - relative;
    const auto [a0, fa] = locate(relative, kAzimuthStepDeg, tables.azimuth_nodes);
    PathLookup l;
    l.t0 = tables.transmittance.data() + z0 * m_bands;
    l.t1 = l.t0 + m_bands;
    l.p00 = tables.path_radiance.data() + (z0 * tables.azimuth_nodes + a0) * m_bands;
    l.p01 = l.p00 + m_bands;
    l.p10 = l.p00 + tables.azimuth_nodes * m_bands;
    l.p11 = l.p10 + m_bands;
    l.fz = fz;
    l.w00 = (1.0 - fz) * (1.0 - fa);
    l.w01 = (1.0 - fz) * fa;
    l.w10 = fz * (1.0 - fa);
    l.w11 = fz * fa;
    return l;
}

void Environment::sensor_path(const Vec3& to_sensor, double time_s, double z_m,
                              std::span<double> transmittance,
                              std::span<double> path_radiance) const noexcept {
    if (!has_sensor_path()) {
        std::fill(transmittance.begin(), transmittance.end(), 1.0);
        std::fill(path_radiance.begin(), path_radiance.end(), 0.0);
        return;
    }
    const AltitudeLevel at = level_at(z_m);
    const PathLookup l = path_lookup(at.index, to_sensor, time_s);
    for (std::size_t b = 0; b < m_bands; ++b) {
        transmittance[b] = l.transmittance(b);
        path_radiance[b] = l.path_radiance(b);
    }
    if (at.fraction == 0.0) return;
    const PathLookup h = path_lookup(at.index + 1, to_sensor, time_s);
    const double f = at.fraction;
    for (std::size_t b = 0; b < m_bands; ++b) {
        transmittance[b] = (1.0 - f) * transmittance[b] + f * h.transmittance(b);
        path_radiance[b] = (1.0 - f) * path_radiance[b] + f * h.path_radiance(b);
    }
}

void Environment::sensor_path_at(const Vec3& to_sensor, double time_s, double z_m,
                                 std::span<const std::uint32_t> bands,
                                 std::span<double> transmittance,
                                 std::span<double> path_radiance) const noexcept {
    if (!has_sensor_path()) {
        std::fill(transmittance.begin(), transmittance.end(), 1.0);
        std::fill(path_radiance.begin(), path_radiance.end(), 0.0);
        return;
    }
    const AltitudeLevel at = level_at(z_m);
    const PathLookup l = path_lookup(at.index, to_sensor, time_s);
    for (std::size_t j = 0; j < bands.size(); ++j) {
        transmittance[j] = l.transmittance(bands[j]);
        path_radiance[j] = l.path_radiance(bands[j]);
    }
    if (at.fraction == 0.0) return;
    const PathLookup h = path_lookup(at.index + 1, to_sensor, time_s);
    const double f = at.fraction;
    for (std::size_t j = 0; j < bands.size(); ++j) {
        transmittance[j] = (1.0 - f) * transmittance[j] + f * h.transmittance(bands[j]);
        path_radiance[j] = (1.0 - f) * path_radiance[j] + f * h.path_radiance(bands[j]);
    }
}

std::vector<double> altitude_levels(const scene::GeometryScene& geometry) {
    std::vector<std::pair<double, double>> ranges;
    for (std::size_t i = 0; i < geometry.time_steps().size(); ++i) {
        const scene::Bounds b = geometry.instance_bounds(i);
        if (!b.empty()) ranges.emplace_back(b.lower.z, b.upper.z);
    }
    if (ranges.empty()) return {0.0};
    std::sort(ranges.begin(), ranges.end());
    // Ranges closer than a step are one.
    std::vector<std::pair<double, double>> joined{ranges.front()};
    for (std::size_t i = 1; i < ranges.size(); ++i) {
        if (ranges[i].first <= joined.back().second + Environment::kLevelStep_m) {
            joined.back().second = std::max(joined.back().second, ranges[i].second);
        } else {
            joined.push_back(ranges[i]);
        }
    }
    std::vector<double> levels;
    for (const auto& [lo, hi] : joined) {
        if (hi - lo < Environment::kLevelStep_m) {
            levels.push_back(std::round(0.5 * (lo + hi)));
            continue;
        }
        const double steps = std::ceil((hi - lo) / Environment::kLevelStep_m);
        for (double k = 0.0; k <= steps; k += 1.0) {
            levels.push_back(std::round(lo + (hi - lo) * k / steps));
        }
    }
    std::sort(levels.begin(), levels.end());
    levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
    if (levels.size() > Environment::kMaxLevels) {
        throw input_error("the scene's surfaces span " +
                          std::to_string(static_cast<long long>(levels.back() - levels.front())) +
                          " m of height: more than the " + std::to_string(Environment::kMaxLevels) +
                          " atmosphere levels glint computes");
    }
    return levels;
}

}  // namespace glint::radiometry
