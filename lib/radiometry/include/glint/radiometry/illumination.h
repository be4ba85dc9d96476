// SPDX-License-Identifier: Apache-2.0
// The light of a run, made once before its first capture: the simulation's atmosphere model
// with the solar spectrum, the scene's origin (where the ephemeris places the sun and the
// moon) and the trajectories of the scene's moving point sources. Each capture asks it for
// its Environment (the sun's, or at night the moon's, direction at both ends of the window,
// through the atmosphere at the surfaces' heights) and its PointLights (each source where it
// is at mid-window). docs/physics.md gives the models ("The moon", "Point sources").
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "glint/atmosphere/atmosphere.h"
#include "glint/atmosphere/solar.h"
#include "glint/core/datetime.h"
#include "glint/core/error.h"
#include "glint/core/log.h"
#include "glint/core/spectral.h"
#include "glint/model/atmosphere.h"
#include "glint/model/scene.h"
#include "glint/motion/frames.h"
#include "glint/motion/moon.h"
#include "glint/motion/sun.h"
#include "glint/motion/trajectory.h"
#include "glint/radiometry/environment.h"
#include "glint/radiometry/point_lights.h"
#include "glint/radiometry/view_refraction.h"
#include "glint/scene/geometry_scene.h"

namespace glint::radiometry {

/// A capture's window: its begin and end, seconds after its tasks' reference time.
struct CaptureWindow {
    DateTime reference_utc;
    double begin_s = 0.0;
    double end_s = 0.0;
};

/// The light of a run. Immutable once made; the queries may run from any thread.
class Illumination {
public:
    /// Makes the light of `scene` under `atmosphere`, the scene's origin at `frame`'s, its
    /// moving point sources on the tasks reference time `reference_utc`. `data` must hold the
    /// solar spectrum, and the gas table when the atmosphere needs one
    /// (glint::atmosphere::needs_gas_table); glint's readers read both
    /// (inputs::read_data_tables). Throws glint::Error: internal when `data` lacks them, input
    /// (at the element) for an atmosphere or a point source's motion that cannot be used.
    static Illumination make(const model::Atmosphere& atmosphere,
                             const glint::atmosphere::DataTables& data, const model::Scene& scene,
                             const motion::SceneFrame& frame, const DateTime& reference_utc,
                             Log log = {});

    /// The environment of a capture seen from `sensor_z_m` above the scene's origin, computed
    /// at the heights `levels_z_m` (altitude_levels() of the capture's geometry) on `grid`:
    /// lit by the sun at both ends of `window`, or by the moon when the sun's mean zenith over
    /// the window is 90° or more (docs/physics.md, "The moon"). As Environment::make
    /// (`threads`, `cache`).
    Environment environment(const SpectralGrid& grid, const CaptureWindow& window,
                            double sensor_z_m, std::vector<double> levels_z_m, unsigned threads,
                            SensorPathCache* cache) const;

    /// The refracted view rays of a sensor `sensor_z_m` above the scene's origin at
    /// `wavelength_um` (docs/physics.md, "Refraction in the renderer"), from the sensor's
    /// altitude rounded to 1 m (taken from / stored in `cache` when given); null without
    /// refraction (the parametric model's `refraction`, with a profile that has levels) or
    /// with the sensor less than kMinRefractionHeight_m above the origin.
    std::shared_ptr<const ViewRefraction> view_refraction(double wavelength_um, double sensor_z_m,
                                                          SensorPathCache* cache) const;
    /// Whether the atmosphere refracts (view rays, the sun and the moon).
    bool refracts() const noexcept { return !m_refraction_levels.empty(); }
    /// The lowest sensor height above the scene's origin whose view rays are bent, m.
    static constexpr double kMinRefractionHeight_m = 1.0;

    /// The point sources of `scene` (the scene it was made for) on `grid` at `t_s` (a capture's
    /// mid-window time): each one's material intensity resampled on the grid (0 outside the
    /// curve), its position at that time. Throws glint::Error (input, at the source) for a
    /// non-finite position; internal for a source whose material is no point-source material.
    PointLights point_lights_at(const model::Scene& scene, const SpectralGrid& grid,
                                double t_s) const;

    /// The atmosphere model and the solar spectrum the environments are computed from.
    const glint::atmosphere::AtmosphereModel& atmosphere_model() const noexcept { return *m_model; }
    const glint::atmosphere::SolarSpectrum& solar_spectrum() const noexcept { return *m_sun; }

    /// The sun's and the moon's positions seen from the scene's origin at `utc`.
    motion::SunPosition sun_at(const DateTime& utc) const;
    motion::MoonPosition moon_at(const DateTime& utc) const;

    /// The wavelengths the gas absorption table covers, µm (first, last), when the atmosphere
    /// model absorbs by it.
    std::optional<std::array<double, 2>> gas_table_range_um() const;

    /// When the atmosphere is tabulated (one geometry) and `geometry` has surfaces at more than
    /// one level, the warning that its terms are applied at every height, at the atmosphere's
    /// file:line (once per call: the caller calls it once).
    void warn_if_one_geometry(const scene::GeometryScene& geometry, const Log& log) const;

    Illumination(Illumination&&) noexcept;
    Illumination& operator=(Illumination&&) noexcept;
    ~Illumination();

private:
    Illumination() = default;

    model::AtmosphereKind m_atmosphere_kind = model::AtmosphereKind::none;
    ErrorContext m_atmosphere_where;
    std::unique_ptr<glint::atmosphere::AtmosphereModel> m_model;
    std::shared_ptr<const glint::atmosphere::SolarSpectrum> m_sun;
    /// The levels refraction follows (the profile's, its temperatures shifted with
    /// air_temperature_k); empty when the atmosphere does not refract.
    std::vector<model::AtmosphereLevel> m_refraction_levels;
    motion::SceneFrame m_frame;
    /// Indexed like the scene's point sources; nullptr for static ones.
    std::vector<std::unique_ptr<motion::Trajectory>> m_source_trajectories;
};

}  // namespace glint::radiometry
