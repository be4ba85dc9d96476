// SPDX-License-Identifier: Apache-2.0
// The illumination and path terms of one capture, precomputed on the focal plane's spectral
// grid from an atmosphere model and the solar spectrum so that tracing a path queries no
// model and allocates nothing:
//   - the sun: its direction in scene ENU at the window's begin and end (interpolated per
//     sample time), its angular radius, and its spectral irradiance at the surface normal to
//     the beam, E_sun(λ) = E_toa(λ, d) T_sun(λ, θs) [W/(cm² µm)];
//   - the sky radiance L_sky(λ) [W/(cm² sr µm)]: the scattered sunlight E_diffuse/π, times
//     the model's directional shape where it has one (tabulated over zenith and azimuth from
//     the sun, normalised so that it integrates to E_diffuse on a horizontal surface), plus the
//     thermal sky L_thermal, isotropic or by zenith angle (every kSkyZenithStepDeg, linear in
//     air mass between) where the model's thermal sky is directional;
//   - the sensor path: transmittance T_v(λ) and path radiance L_p(λ) [W/(cm² sr µm)] for the
//     direction surface → sensor, tabulated over view zenith (0–88° every 4°) and azimuth
//     relative to the sun (0–180° every 15°; the single-scatter terms are symmetric about
//     the sun's vertical plane) and bilinearly interpolated.
// All of it is computed at each of a few surface levels (heights above the scene origin where
// the scene has surfaces, altitude_levels()), and a vertex reads it at its own height,
// linearly between the two levels around it: a vehicle 50 km up is lit by the sun and sky of
// 50 km and seen through the air above 50 km. Paths between surfaces inside the scene have no
// atmospheric effects. docs/physics.md ("Path tracer") gives the formulas, docs/scene.md
// ("At which altitude each light path sees the atmosphere") the levels.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "glint/atmosphere/atmosphere.h"
#include "glint/atmosphere/solar.h"
#include "glint/core/spectral.h"
#include "glint/motion/geometry.h"
#include "glint/radiometry/sampling.h"
#include "glint/scene/geometry_scene.h"

namespace glint::radiometry {

using motion::Vec3;

class ViewRefraction;  // glint/radiometry/view_refraction.h

/// The sensor-path tables of one geometry (shared between captures with the same rounded
/// geometry).
struct SensorPathTables {
    std::size_t zenith_nodes = 0;
    std::size_t azimuth_nodes = 0;
    std::vector<double> transmittance;  ///< [zenith][band]
    std::vector<double> path_radiance;  ///< [zenith][azimuth][band], W/(cm² sr µm)
    bool effects = false;               ///< T_v ≠ 1 or L_p ≠ 0 somewhere
};

/// Sensor-path tables already computed, by rounded geometry. One per focal plane (one grid);
/// not thread-safe.
class SensorPathCache {
public:
    /// The key of a geometry: sun zenith and azimuth rounded to kAngleStepDeg, sensor and
    /// surface altitude to kAltitudeStepM, the sun's distance to kSunDistanceStepAu, the
    /// source's irradiance scale to kSourceScaleStep of itself (in log). The
    /// tables are computed from the rounded values alone, so what a key holds never depends
    /// on which capture filled it.
    static constexpr double kAngleStepDeg = 0.05;
    static constexpr double kAltitudeStepM = 1.0;
    static constexpr double kSunDistanceStepAu = 1e-5;
    /// The source's irradiance scale (1 for the sun) is rounded to this relative step.
    static constexpr double kSourceScaleStep = 1e-6;
    using Key = std::array<long long, 6>;
    std::shared_ptr<const SensorPathTables> find(const Key& key) const;
    void insert(const Key& key, std::shared_ptr<const SensorPathTables> tables);
    std::size_t size() const noexcept { return m_tables.size(); }
    /// The sky's directional shapes, by the same key (sensor altitude 0): nullopt when none
    /// is stored, a null pointer stored for an isotropic sky.
    std::optional<std::shared_ptr<const std::vector<double>>> find_sky(const Key& key) const;
    void insert_sky(const Key& key, std::shared_ptr<const std::vector<double>> shape);

    /// Refracted view-ray tables (glint/radiometry/view_refraction.h), by ground and sensor
    /// altitude (m) and wavelength (pm), all rounded.
    using ViewKey = std::array<long long, 3>;
    std::shared_ptr<const ViewRefraction> find_view(const ViewKey& key) const;
    void insert_view(const ViewKey& key, std::shared_ptr<const ViewRefraction> view);

private:
    std::map<Key, std::shared_ptr<const SensorPathTables>> m_tables;
    std::map<ViewKey, std::shared_ptr<const ViewRefraction>> m_views;
    std::map<Key, std::shared_ptr<const std::vector<double>>> m_skies;
};

/// Everything make_environment needs.
struct EnvironmentInputs {
    /// Unit direction towards the sun (scene ENU) at the window's begin and end.
    Vec3 sun_direction_begin{0.0, 0.0, 1.0};
    Vec3 sun_direction_end{0.0, 0.0, 1.0};
    double window_begin_s = 0.0;
    double window_end_s = 0.0;
    double sun_distance_au = 1.0;
    /// The directional source: the sun (1, its angular radius), or the moon at night (its
    /// irradiance as a fraction of the sun's, glint/atmosphere/lunar.h, and its radius).
    /// The source's light passes through the atmosphere as the sun's does.
    double source_irradiance_scale = 1.0;
    double source_half_angle_rad = kSunAngularRadiusRad;
    double surface_altitude_m = 0.0;  ///< the scene origin's altitude
    double sensor_altitude_m = 0.0;   ///< the sensor's altitude
    /// Heights above the scene origin (scene z, m) at which the environment is computed
    /// (altitude_levels()); finite, at most kMaxLevels. Empty: the origin's height, 0, alone.
    std::vector<double> levels_z_m;
    /// Threads that compute the sensor-path tables, one view zenith each (0: all cores); the
    /// tables are the same numbers whatever the count.
    unsigned threads = 0;
};

/// The levels, heights above the scene origin (scene z, m), at which a capture's environment
/// is computed for `geometry`: the union of its instances' height ranges (swept, for moving
/// ones), ranges closer than kLevelStep_m joined; a range less than kLevelStep_m tall is one
/// level at its middle, a taller one has levels at both ends and between, at most
/// kLevelStep_m apart. Rounded to 1 m (the sensor-path cache's step), ascending, distinct;
/// {0} for an empty scene.
std::vector<double> altitude_levels(const scene::GeometryScene& geometry);

/// Where a height falls among an environment's levels: between level `index` and the next,
/// at `fraction` of the way (0 at or below the lowest level, and at or above the highest).
struct AltitudeLevel {
    std::size_t index = 0;
    double fraction = 0.0;
};

/// The precomputed illumination of one capture.
class Environment {
public:
    /// Largest spacing of the levels altitude_levels() places through a tall range, m: linear
    /// interpolation between levels this far apart moves the sun's transmittance by < 0.1 %
    /// (docs/scene.md).
    static constexpr double kLevelStep_m = 250.0;
    /// Most levels one environment takes.
    static constexpr std::size_t kMaxLevels = 512;

    /// View-zenith nodes of the sensor-path tables, degrees.
    static constexpr double kViewZenithStepDeg = 4.0;
    static constexpr double kViewZenithMaxDeg = 88.0;
    /// Relative-azimuth nodes, degrees.
    static constexpr double kAzimuthStepDeg = 15.0;
    /// Zenith nodes of a directional sky, 0° … 90°, degrees.
    static constexpr double kSkyZenithStepDeg = 3.0;
    static constexpr std::size_t kSkyZenithNodes = 31;
    /// Azimuth nodes of the scattered sky's shape, degrees from the sun's azimuth (the sky is
    /// symmetric about the sun's vertical plane): dense towards the sun for its aureole.
    static constexpr std::array<double, 18> kSkyAzimuthNodesDeg = {
        0.0,  2.0,  4.0,  7.0,   10.0,  15.0,  20.0,  30.0,  45.0,
        60.0, 75.0, 90.0, 105.0, 120.0, 135.0, 150.0, 165.0, 180.0};

    /// An environment given directly (tests, user-defined skies): no path effects
    /// (T_v = 1, L_p = 0). Throws glint::Error (input) for vectors of the wrong size,
    /// negative or non-finite values, or a zero sun direction.
    static Environment uniform(const SpectralGrid& grid, const Vec3& sun_direction,
                               std::vector<double> sun_irradiance_w_per_cm2_um,
                               std::vector<double> sky_radiance_w_per_cm2_sr_um);

    /// The environment of a capture from an atmosphere model and the solar spectrum. The
    /// sensor-path tables are computed for the geometry rounded as SensorPathCache says
    /// (whether or not a cache is given, so results never depend on what was cached) and
    /// taken from / stored in `cache` when one is given. Throws glint::Error (input) for
    /// non-finite inputs, a zero sun direction or a window with end < begin.
    static Environment make(const SpectralGrid& grid,
                            const glint::atmosphere::AtmosphereModel& atmosphere,
                            const glint::atmosphere::SolarSpectrum& sun,
                            const EnvironmentInputs& inputs, SensorPathCache* cache = nullptr);

    /// Number of bands.
    std::size_t bands() const noexcept { return m_bands; }
    /// The grid.
    const SpectralGrid& grid() const noexcept { return m_grid; }
    /// Unit direction towards the sun at `time_s` (normalized linear interpolation over the
    /// window, clamped outside it).
    Vec3 sun_direction(double time_s) const noexcept;
    /// Angular radius of the sun disk, rad.
    double sun_half_angle_rad() const noexcept { return m_sun_half_angle_rad; }
    /// 1 − cos of sun_half_angle_rad() (cone_one_minus_cos), for sample_uniform_cone_1mc.
    double sun_cone_one_minus_cos() const noexcept { return m_sun_cone_one_minus_cos; }
    /// The levels, heights above the scene origin (m), ascending (at least one).
    std::span<const double> levels_z_m() const noexcept { return m_levels_z; }
    /// Where height `z_m` (scene z) falls among the levels.
    AltitudeLevel level_at(double z_m) const noexcept;
    /// E_sun(λ) at level `level`, normal to the beam, W/(cm² µm) (0 with the sun below the
    /// horizon).
    std::span<const double> sun_irradiance_w_per_cm2_um(std::size_t level = 0) const noexcept {
        return std::span<const double>(m_sun).subspan(level * m_bands, m_bands);
    }
    /// Whether the sun contributes at all (any band > 0 at any level).
    bool sun_visible() const noexcept { return m_sun_visible; }
    /// Zenith nodes of the sky: 1 (isotropic) or kSkyZenithNodes (0°, 3°, … 90°).
    std::size_t sky_nodes() const noexcept { return m_sky_nodes; }
    /// The sky's part that depends on the zenith alone, at level `level` and zenith node
    /// `node`, W/(cm² sr µm): L_thermal, plus E_diffuse/π where the sky has no directional
    /// shape (sky_radiance() adds the shaped part).
    std::span<const double> sky_radiance_w_per_cm2_sr_um(std::size_t level = 0,
                                                         std::size_t node = 0) const noexcept {
        return std::span<const double>(m_sky).subspan((level * m_sky_nodes + node) * m_bands,
                                                      m_bands);
    }
    /// Where a direction of z component `cos_zenith` falls among the sky's zenith nodes:
    /// between node `index` and the next, at `fraction` of the way in relative air mass
    /// (index 0, fraction 0 for an isotropic sky; the horizon node for a direction at or
    /// below it).
    AltitudeLevel sky_node(double cos_zenith) const noexcept;
    /// Whether the scattered sky has a directional shape (kSkyZenithNodes ×
    /// kSkyAzimuthNodesDeg, computed at the lowest level).
    bool sky_shaped() const noexcept { return m_sky_shape != nullptr; }
    /// The rows around one sky direction and their weights: the zenith-dependent part (level ×
    /// zenith), the scattered sky's E_diffuse/π (level) and its shape (zenith × azimuth).
    struct SkyLookup {
        std::array<const double*, 4> rows{};
        std::array<double, 4> row_weights{};
        std::array<const double*, 2> diffuse{};  ///< null without a shape
        std::array<double, 2> diffuse_weights{};
        std::array<const double*, 4> shape{};
        std::array<double, 4> shape_weights{};
        /// L_sky at band `b`, W/(cm² sr µm).
        double at(std::size_t b) const noexcept {
            double v = row_weights[0] * rows[0][b] + row_weights[1] * rows[1][b] +
                       row_weights[2] * rows[2][b] + row_weights[3] * rows[3][b];
            if (diffuse[0] == nullptr) return v;
            const double d =
                diffuse_weights[0] * diffuse[0][b] + diffuse_weights[1] * diffuse[1][b];
            return v + d * (shape_weights[0] * shape[0][b] + shape_weights[1] * shape[1][b] +
                            shape_weights[2] * shape[2][b] + shape_weights[3] * shape[3][b]);
        }
    };
    /// Where the sky radiance for a ray leaving upwards in unit direction `wi` (scene ENU) from
    /// height level `at` at `time_s` comes from (the sun's azimuth at that time sets the
    /// relative azimuth). A direction at or below the horizon reads the horizon.
    SkyLookup sky_lookup(const Vec3& wi, double time_s, const AltitudeLevel& at) const noexcept;
    /// L_sky(λ) for `wi` from height `z_m` (scene z) at `time_s`, every band.
    std::vector<double> sky_radiance(const Vec3& wi, double time_s, double z_m) const;
    /// Whether the sky is black on the whole grid at every level.
    bool sky_black() const noexcept { return m_sky_black; }
    /// Whether the sensor path changes anything (T_v ≠ 1 or L_p ≠ 0 somewhere).
    bool has_sensor_path() const noexcept { return m_sensor_path; }
    /// Writes T_v(λ) and L_p(λ) for the unit direction `to_sensor` (surface → sensor, scene
    /// ENU) from height `z_m` (scene z) at `time_s` (the sun's azimuth at that time sets the
    /// relative azimuth). A direction below the horizon uses the 88° node (one above it,
    /// from a level above the sensor, the 88° node of the reversed path).
    void sensor_path(const Vec3& to_sensor, double time_s, double z_m,
                     std::span<double> transmittance,
                     std::span<double> path_radiance_w_per_cm2_sr_um) const noexcept;
    /// sensor_path() from the lowest level.
    void sensor_path(const Vec3& to_sensor, double time_s, std::span<double> transmittance,
                     std::span<double> path_radiance_w_per_cm2_sr_um) const noexcept {
        sensor_path(to_sensor, time_s, m_levels_z.front(), transmittance,
                    path_radiance_w_per_cm2_sr_um);
    }

    /// sensor_path() at the bands `bands` only (indices into the grid): transmittance[j] and
    /// path_radiance[j] are T_v and L_p at bands[j], the same numbers sensor_path() gives there.
    void sensor_path_at(const Vec3& to_sensor, double time_s, double z_m,
                        std::span<const std::uint32_t> bands, std::span<double> transmittance,
                        std::span<double> path_radiance_w_per_cm2_sr_um) const noexcept;

private:
    /// The four table rows around a direction and their bilinear weights.
    struct PathLookup {
        const double* t0 = nullptr;
        const double* t1 = nullptr;
        const double* p00 = nullptr;
        const double* p01 = nullptr;
        const double* p10 = nullptr;
        const double* p11 = nullptr;
        double fz = 0.0;
        double w00 = 0.0, w01 = 0.0, w10 = 0.0, w11 = 0.0;
        double transmittance(std::size_t b) const noexcept {
            return (1.0 - fz) * t0[b] + fz * t1[b];
        }
        double path_radiance(std::size_t b) const noexcept {
            return w00 * p00[b] + w01 * p01[b] + w10 * p10[b] + w11 * p11[b];
        }
    };
    /// The lookup in the tables of level `level`.
    PathLookup path_lookup(std::size_t level, const Vec3& to_sensor, double time_s) const noexcept;

    Environment(const SpectralGrid& grid);

    SpectralGrid m_grid;
    std::size_t m_bands = 0;
    Vec3 m_sun_begin{0.0, 0.0, 1.0};
    Vec3 m_sun_end{0.0, 0.0, 1.0};
    double m_window_begin_s = 0.0;
    double m_window_end_s = 0.0;
    double m_sun_half_angle_rad = 0.0;
    double m_sun_cone_one_minus_cos = 0.0;
    std::vector<double> m_levels_z{0.0};
    std::vector<double> m_sun;  ///< [level][band]
    std::vector<double> m_sky;  ///< [level][zenith node][band]
    std::size_t m_sky_nodes = 1;
    std::vector<double> m_sky_air_mass;  ///< the Kasten–Young air mass of each zenith node
    /// [level][band] E_diffuse/π, with a shape.
    std::vector<double> m_sky_diffuse;
    /// [zenith node][azimuth node][band], ∫ shape cos dΩ = π per band; empty: isotropic.
    std::shared_ptr<const std::vector<double>> m_sky_shape;
    bool m_sun_visible = false;
    bool m_sky_black = true;
    bool m_sensor_path = false;
    /// Per level; null for none (Environment::uniform).
    std::vector<std::shared_ptr<const SensorPathTables>> m_paths;
    /// Per level: whether it lies above the sensor (its tables are of the reversed path,
    /// sensor → level, and hold no path radiance).
    std::vector<bool> m_upward;
};

}  // namespace glint::radiometry
