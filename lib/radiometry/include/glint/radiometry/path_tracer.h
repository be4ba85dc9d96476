// SPDX-License-Identifier: Apache-2.0
// The spectral path tracer. One path carries a whole spectral vector over the environment's
// grid; its geometry (directions, Russian roulette) is wavelength-independent, because every
// material's BRDF is ρ(λ) times one lobe shape. At each surface vertex the path adds the
// surface's emission ε B(λ, T) and the sun by next-event estimation (a direction drawn
// uniformly in the sun's disk, one shadow ray), then continues in a direction drawn from the
// lobe shape (cosine-weighted diffuse or GGX visible normals). A path that leaves the scene
// upwards sees the isotropic sky; one that leaves it downwards sees nothing. Primary rays
// that hit a surface get the sensor path: L = T_v ⊙ L_surface + L_p. Triangles are two-sided
// (the shading normal is flipped to face the incoming ray). After `roulette_start_bounce`
// bounces a path survives with probability min(1, max_λ β(λ)) (β the throughput), and it
// stops after `max_bounces`. docs/physics.md ("Path tracer") states the estimator.
//
// A tracer follows all of the environment's bands, or a contiguous range of them (a
// BandRange: one channel's spectral state when channels are split, docs/camera.md); its
// roulette then watches the range's throughput only.
//
// trace() allocates nothing: scratch vectors live in a PathScratch the caller keeps per
// thread.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "glint/core/rng.h"
#include "glint/radiometry/environment.h"
#include "glint/radiometry/materials.h"
#include "glint/radiometry/point_lights.h"
#include "glint/radiometry/sampling.h"
#include "glint/scene/geometry_scene.h"

namespace glint::radiometry {

/// One sample ray of a pixel problem.
struct SampleRay {
    Vec3 origin_m;      ///< scene ENU
    Vec3 direction;     ///< unit, scene ENU
    double time_s = 0;  ///< seconds after the tasks reference time
    double weight = 1;  ///< relative weight of the sample in the pixel (e.g. a PSF weight), > 0
};

/// What a sample's first surface hit was, for truth (docs/truth.md). Filled by trace() when
/// asked; recording it traces no extra ray except the sun shadow ray of a first hit on a
/// material that reflects nothing (the radiance, and the random numbers it draws, are the
/// same either way).
struct FirstHit {
    bool hit = false;            ///< the primary ray hit a surface (else the rest is unset)
    Vec3 position_m;             ///< scene ENU
    Vec3 normal;                 ///< unit geometric normal, facing the ray's origin
    double distance_m = 0.0;     ///< from the ray's origin
    std::uint32_t material = 0;  ///< index into the scene's materials (drawn from `mix`)
    /// A mixture map's texel at the point: its materials and weights (empty otherwise).
    scene::MaterialMix mix;
    /// A temperature map's temperature at the point, K; 0: the material's.
    double temperature_k = 0.0;
    std::uint32_t instance = 0;  ///< index into the scene's instances
    /// The sun does not light the point: the sun is below the horizon (or switched off), it
    /// is behind the surface, or the shadow ray towards the point drawn in its disc is
    /// blocked.
    bool sun_blocked = false;
};

/// The sun's next-event estimate at a path's first vertex, prepared before the path is
/// traced (PathTracer::first_sun), so that a renderer can trace many paths' shadow rays
/// together (GeometryScene::occluded_packet) and hand each answer to trace().
struct FirstSun {
    bool query = false;    ///< a shadow ray is needed: `ray`, whose answer goes in `blocked`
    scene::PacketRay ray;  ///< from the first hit towards the drawn point of the sun's disc
    bool blocked = true;   ///< the answer (true when no ray is needed)
    Vec3 wi;               ///< the drawn direction towards the sun
    double cos_i = 0.0;    ///< its cosine with the facing normal
};

/// The largest `max_bounces` the path tracer and the lidar tracer accept (a guard against a
/// typo turning into a hang).
inline constexpr unsigned kMaxBouncesLimit = 10'000;

/// Path tracer settings.
struct TracerSettings {
    /// Surface scatterings after the first hit. 32: in a canopy whose leaves scatter ρ + τ ≈ 0.9
    /// of the near infrared, Russian roulette keeps paths alive; 8 left a canopy's NIR radiance
    /// 0.6 % low (examples/vegetation, docs/performance.md), 16 by 0.01 %, 32 by nothing
    /// measurable, for 0.3 % more rays than 8. Scenes of ρ below ~0.5 end by roulette first.
    unsigned max_bounces = 32;
    unsigned roulette_start_bounce = 3;  ///< Russian roulette from this bounce on
    /// Wavelengths each path follows (docs/physics.md, "Spectral sampling"): 0, or at least
    /// the tracer's band count, follows every band (the full-spectrum estimator); K >= 2
    /// follows the reference band and K - 1 others drawn as a stratified rotation, each
    /// weighted by the inverse of its chance of being drawn (solve() does the drawing).
    unsigned spectral_samples = 0;
};

/// Per-thread scratch space for trace(), sized for the environment's bands.
class PathScratch {
public:
    explicit PathScratch(std::size_t bands)
        : throughput(bands),
          sensor_transmittance(bands),
          path_radiance(bands),
          sun_at_height(bands),
          emission_towards(bands),
          sheets(bands) {}
    std::vector<double> throughput;            ///< of the path so far, per band
    std::vector<double> sensor_transmittance;  ///< T_v(λ): surface → sensor
    std::vector<double> path_radiance;         ///< L_p(λ): the atmosphere's own, at the sensor
    /// E_sun(λ) at a vertex between two of the environment's levels (grid bands)
    std::vector<double> sun_at_height;
    /// ε(λ, θo) B(λ, T) of a material whose emission depends on the direction (grid bands)
    std::vector<double> emission_towards;
    /// The clear sheets' τ(λ) along a shadow ray (grid bands)
    std::vector<double> sheets;
    std::uint64_t rays = 0;  ///< intersection and shadow queries traced so far (statistics)
};

/// Traces sample rays through a built scene.
class PathTracer {
public:
    /// The tracer keeps references: the scene, materials and environment must outlive it.
    /// Throws glint::Error (input) when the materials and environment have different band
    /// counts, or (usage) for max_bounces > 10000 or spectral_samples 1.
    /// `lights`, when given, are the scene's point sources on the environment's grid (kept by
    /// reference too); every surface vertex is lit by each of them as by the sun.
    PathTracer(const scene::GeometryScene& scene, const MaterialTable& materials,
               const Environment& environment, TracerSettings settings = {},
               const PointLights* lights = nullptr);

    /// The same tracer for the bands `range` of the environment only. Throws what the
    /// constructor above throws, and glint::Error (usage) for an empty range or one beyond
    /// the environment's bands, (input) for lights on another band count.
    PathTracer(const scene::GeometryScene& scene, const MaterialTable& materials,
               const Environment& environment, TracerSettings settings, BandRange range,
               const PointLights* lights = nullptr);
    /// Number of bands of the radiance trace() writes (the range's).
    std::size_t bands() const noexcept { return m_range.count; }
    /// The bands of the environment it follows.
    BandRange range() const noexcept { return m_range; }
    /// The environment.
    const Environment& environment() const noexcept { return m_environment; }

    /// Traces one path for `ray` and writes its at-aperture radiance, W/(cm² sr µm), to
    /// `radiance` (bands() values: the range's; overwritten). Draws from `rng` only.
    /// `scratch` must have been made for environment().bands(). With `first_hit`, records
    /// the first surface hit there. With `primary_hit`, the primary ray has already been
    /// traced: *primary_hit is scene().intersect(ray.origin_m, ray.direction, ray.time_s)'s
    /// answer (e.g. from GeometryScene::intersect_packet) and is used instead of tracing it
    /// again; the radiance and draws are the same.
    void trace(const SampleRay& ray, RandomStream& rng, PathScratch& scratch,
               std::span<double> radiance, FirstHit* first_hit = nullptr,
               const std::optional<scene::RayHit>* primary_hit = nullptr,
               const FirstSun* sun = nullptr) const;
    /// What trace() draws and asks at the first vertex for the sun, given the primary ray's
    /// hit (`primary_hit`, as for trace()) and whether trace() will record the first hit.
    /// Draws from `rng` exactly what trace() would at that point; then trace(…, primary_hit,
    /// &sun) with sun.blocked set to the shadow ray's answer (when sun.query) goes on from
    /// there and gives the radiance trace() gives alone. Nothing to ask (no hit, no sun, a
    /// black surface not recorded): query false.
    FirstSun first_sun(const SampleRay& ray, const std::optional<scene::RayHit>& primary_hit,
                       RandomStream& rng, bool records_first_hit) const;
    /// trace() at the bands `bands` only (indices into the environment's grid, inside
    /// range(), at most environment().bands() of them): radiance[j] is what trace() would give
    /// at bands[j] for a path with the same geometry. The path's geometry does not depend on
    /// the bands but its Russian roulette does (it watches these bands' throughput).
    /// Throws glint::Error (internal) when the two spans differ in size or are empty.
    void trace_bands(const SampleRay& ray, RandomStream& rng, PathScratch& scratch,
                     std::span<const std::uint32_t> bands, std::span<double> radiance,
                     FirstHit* first_hit = nullptr,
                     const std::optional<scene::RayHit>* primary_hit = nullptr,
                     const FirstSun* sun = nullptr) const;
    /// The settings.
    const TracerSettings& settings() const noexcept { return m_settings; }
    /// The scene it traces.
    const scene::GeometryScene& scene() const noexcept { return m_scene; }

private:
    const scene::GeometryScene& m_scene;
    const MaterialTable& m_materials;
    const Environment& m_environment;
    TracerSettings m_settings;
    BandRange m_range;
    const PointLights* m_lights = nullptr;  ///< none or empty: no point source

    /// The path at `bands` (a band range or list, path_tracer.cpp).
    template <typename Bands>
    void trace_path(const Bands& bands, const SampleRay& ray, RandomStream& rng,
                    PathScratch& scratch, std::span<double> radiance, FirstHit* first_hit,
                    const std::optional<scene::RayHit>* primary_hit, const FirstSun* sun) const;
    /// The sun's direction drawn at a vertex (two draws) and, when it lights the surface from
    /// the side the path came from (or from behind, through a material that `transmits`), the
    /// shadow ray to ask. `normal`: the shading normal (a bump map's), `geometric`: the
    /// facet's, both facing the path; the sun must lie on the same side of both.
    FirstSun draw_sun(const scene::RayHit& hit, const Vec3& normal, const Vec3& geometric,
                      double wo_z, double time_s, bool transmits, RandomStream& rng) const;
    /// Adds the point sources' light reflected (or, from behind a thin sheet, transmitted) at
    /// a vertex (next-event estimation); `normal` the shading normal, `geometric` the facet's.
    template <typename Bands>
    void add_point_lights(const Bands& bands, const scene::RayHit& hit, const Vec3& normal,
                          const Vec3& geometric, const Vec3& wo_local, const Frame& frame,
                          std::size_t material, double time_s, std::span<const double> beta,
                          std::span<double> radiance, PathScratch& scratch) const;
};

}  // namespace glint::radiometry
