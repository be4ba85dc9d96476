// SPDX-License-Identifier: Apache-2.0
// The spectral path tracer (glint/radiometry/path_tracer.h).
#include "glint/radiometry/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "glint/core/error.h"
#include "glint/radiometry/clear_sheets.h"
#include "glint/radiometry/mixture_draw.h"
#include "glint/radiometry/sampling.h"
#include "glint/radiometry/shading_normal.h"

namespace glint::radiometry {
namespace {

/// The bands a path follows, as indices into the environment's grid: a contiguous range (the
/// whole spectrum of the tracer) ...
struct RangeBands {
    std::size_t first = 0;
    std::size_t count = 0;
    std::size_t size() const noexcept { return count; }
    std::size_t operator[](std::size_t j) const noexcept { return first + j; }
};

/// ... or a list of them (the wavelengths one path samples, spectral_samples > 0).
struct ListBands {
    std::span<const std::uint32_t> list;
    std::size_t size() const noexcept { return list.size(); }
    std::size_t operator[](std::size_t j) const noexcept { return list[j]; }
};

/// One surface vertex's contribution: L += β ⊙ (emission + ρ ⊙ E_sun · sun_factor), any of
/// the two terms switched off by a null pointer (spectra indexed by grid band).
template <typename Bands>
void add_vertex_light(const Bands& bands, std::span<double> radiance,
                      std::span<const double> throughput, const double* emission,
                      const double* reflectance, const double* sun, double sun_factor) {
    const std::size_t n = radiance.size();
    if (emission != nullptr && sun != nullptr) {
        for (std::size_t j = 0; j < n; ++j) {
            const std::size_t b = bands[j];
            radiance[j] += throughput[j] * (emission[b] + reflectance[b] * sun[b] * sun_factor);
        }
    } else if (emission != nullptr) {
        for (std::size_t j = 0; j < n; ++j) radiance[j] += throughput[j] * emission[bands[j]];
    } else if (sun != nullptr) {
        for (std::size_t j = 0; j < n; ++j) {
            const std::size_t b = bands[j];
            radiance[j] += throughput[j] * reflectance[b] * sun[b] * sun_factor;
        }
    }
}

/// The first vertex's contribution, where L = 0 and β = 1: L = 0 + (emission + ρ ⊙ E_sun ·
/// sun_factor), 0 where both terms are off. The same numbers as add_vertex_light from L = 0,
/// β = 1 (1 · x is exact, and the 0 + keeps the sign of zero), without filling or reading
/// either span first.
template <typename Bands>
void first_vertex_light(const Bands& bands, std::span<double> radiance, const double* emission,
                        const double* reflectance, const double* sun, double sun_factor) {
    const std::size_t n = radiance.size();
    if (emission != nullptr && sun != nullptr) {
        for (std::size_t j = 0; j < n; ++j) {
            const std::size_t b = bands[j];
            radiance[j] = 0.0 + (emission[b] + reflectance[b] * sun[b] * sun_factor);
        }
    } else if (emission != nullptr) {
        for (std::size_t j = 0; j < n; ++j) radiance[j] = 0.0 + emission[bands[j]];
    } else if (sun != nullptr) {
        for (std::size_t j = 0; j < n; ++j) {
            const std::size_t b = bands[j];
            radiance[j] = 0.0 + reflectance[b] * sun[b] * sun_factor;
        }
    } else {
        std::fill(radiance.begin(), radiance.end(), 0.0);
    }
}

/// The first scattering's throughput, where β = 1: β ← ρ · weight (as scale_throughput from
/// β = 1: 1 · x is exact); returns max β.
template <typename Bands>
double first_throughput(const Bands& bands, std::span<double> throughput, const double* reflectance,
                        double weight) {
    double largest = 0.0;
    for (std::size_t j = 0; j < throughput.size(); ++j) {
        throughput[j] = reflectance[bands[j]] * weight;
        largest = std::max(largest, throughput[j]);
    }
    return largest;
}

/// β ← β ⊙ ρ · weight; returns max β.
template <typename Bands>
double scale_throughput(const Bands& bands, std::span<double> throughput, const double* reflectance,
                        double weight) {
    double largest = 0.0;
    for (std::size_t j = 0; j < throughput.size(); ++j) {
        throughput[j] *= reflectance[bands[j]] * weight;
        largest = std::max(largest, throughput[j]);
    }
    return largest;
}

/// A per-level spectrum of the environment (E_sun or L_sky) at `at`: level at.index's row, or
/// the blend of it and the next, written into `scratch` at the bands followed (indexed by grid
/// band, as the rows are).
template <typename Bands>
const double* at_height(const Bands& bands, const AltitudeLevel& at,
                        std::span<const double> (Environment::*row)(std::size_t) const noexcept,
                        const Environment& env, std::vector<double>& scratch) {
    const double* lo = (env.*row)(at.index).data();
    if (at.fraction == 0.0) return lo;
    const double* hi = (env.*row)(at.index + 1).data();
    const double f = at.fraction;
    for (std::size_t j = 0; j < bands.size(); ++j) {
        const std::size_t b = bands[j];
        scratch[b] = (1.0 - f) * lo[b] + f * hi[b];
    }
    return scratch.data();
}

/// L += β ⊙ E_sun / Ω_sun · weight for a path leaving the scene from a vertex at `level` in
/// direction `wi`, when wi lies in the sun's disc (radiance E/Ω of a uniform disc; `sun_pdf`
/// = 1/Ω).
template <typename Bands>
void add_sun_disc(const Bands& bands, const Environment& env, const AltitudeLevel& level,
                  const Vec3& wi, double time_s, double weight, double sun_pdf,
                  std::span<const double> beta, std::span<double> radiance,
                  std::vector<double>& scratch) {
    if (!(weight > 0.0)) return;
    if (1.0 - dot(wi, env.sun_direction(time_s)) > env.sun_cone_one_minus_cos()) return;
    const double* sun =
        at_height(bands, level, &Environment::sun_irradiance_w_per_cm2_um, env, scratch);
    const double factor = weight * sun_pdf;
    for (std::size_t j = 0; j < radiance.size(); ++j) {
        radiance[j] += beta[j] * sun[bands[j]] * factor;
    }
}

/// L ← T_v ⊙ L + L_p for the primary ray's direction, from the primary hit's height z_m.
void apply_sensor_path(const Environment& env, const RangeBands& bands, const Vec3& to_sensor,
                       double time_s, double z_m, PathScratch& scratch,
                       std::span<double> radiance) {
    env.sensor_path(to_sensor, time_s, z_m, scratch.sensor_transmittance, scratch.path_radiance);
    const double* transmittance = scratch.sensor_transmittance.data() + bands.first;
    const double* path = scratch.path_radiance.data() + bands.first;
    for (std::size_t b = 0; b < radiance.size(); ++b) {
        radiance[b] = transmittance[b] * radiance[b] + path[b];
    }
}

void apply_sensor_path(const Environment& env, const ListBands& bands, const Vec3& to_sensor,
                       double time_s, double z_m, PathScratch& scratch,
                       std::span<double> radiance) {
    const std::span<double> transmittance =
        std::span<double>(scratch.sensor_transmittance).first(bands.size());
    const std::span<double> path = std::span<double>(scratch.path_radiance).first(bands.size());
    env.sensor_path_at(to_sensor, time_s, z_m, bands.list, transmittance, path);
    for (std::size_t j = 0; j < radiance.size(); ++j) {
        radiance[j] = transmittance[j] * radiance[j] + path[j];
    }
}

}  // namespace

PathTracer::PathTracer(const scene::GeometryScene& scene, const MaterialTable& materials,
                       const Environment& environment, TracerSettings settings,
                       const PointLights* lights)
    : PathTracer(scene, materials, environment, settings, BandRange{0, environment.bands()},
                 lights) {}

PathTracer::PathTracer(const scene::GeometryScene& scene, const MaterialTable& materials,
                       const Environment& environment, TracerSettings settings, BandRange range,
                       const PointLights* lights)
    : m_scene(scene),
      m_materials(materials),
      m_environment(environment),
      m_settings(settings),
      m_range(range),
      m_lights(lights != nullptr && !lights->empty() ? lights : nullptr) {
    if (m_lights != nullptr && m_lights->bands() != environment.bands()) {
        throw input_error("the point sources have " + std::to_string(m_lights->bands()) +
                          " bands and the environment " + std::to_string(environment.bands()));
    }
    if (range.count == 0 || range.first > environment.bands() ||
        range.count > environment.bands() - range.first) {
        throw usage_error("band range " + std::to_string(range.first) + " + " +
                          std::to_string(range.count) + " does not fit " +
                          std::to_string(environment.bands()) + " bands");
    }
    if (materials.size() > 0 && materials.bands() != environment.bands()) {
        throw input_error("the materials have " + std::to_string(materials.bands()) +
                          " bands and the environment " + std::to_string(environment.bands()));
    }
    if (settings.spectral_samples == 1) {
        throw usage_error(
            "1 spectral sample per path cannot be drawn: use 0 (every band) or at least 2 (the "
            "reference band and one more)");
    }
    if (settings.max_bounces > kMaxBouncesLimit) {
        throw usage_error("max bounces " + std::to_string(settings.max_bounces) +
                          " exceeds the limit of " + std::to_string(kMaxBouncesLimit));
    }
}

template <typename Bands>
void PathTracer::add_point_lights(const Bands& bands, const scene::RayHit& hit, const Vec3& normal,
                                  const Vec3& geometric, const Vec3& wo_local, const Frame& frame,
                                  std::size_t material, double time_s, std::span<const double> beta,
                                  std::span<double> radiance, PathScratch& scratch) const {
    const double* rho = m_materials.reflectance(material).data();
    const double* tau = m_materials.transmittance(material).data();
    const bool reflects = m_materials.reflects(material);
    const bool transmits = m_materials.transmits(material);
    const bool straight = m_materials.straight(material);  // no diffuse light through a pane
    for (std::size_t l = 0; l < m_lights->size(); ++l) {
        const Vec3 to_light = m_lights->position_m(l) - hit.position_m;
        const double r2_m2 = dot(to_light, to_light);
        if (!(r2_m2 > 0.0)) continue;
        const Vec3 wi = (1.0 / std::sqrt(r2_m2)) * to_light;
        const double cos_i = dot(normal, wi);
        // In front: reflected; behind a thin sheet: transmitted (f = τ/π).
        if (cos_i > 0.0 ? !reflects : !(cos_i < 0.0 && transmits && !straight)) continue;
        if (hit.bumped && !same_side(geometric, normal, wi)) continue;
        const Vec3 origin = m_scene.spawn_origin(hit, wi);
        ++scratch.rays;
        const double reach_m = norm(m_lights->position_m(l) - origin);
        const double* through = nullptr;  // clear sheets' τ on the way, when any
        if (m_scene.occluded(origin, wi, time_s, 0.0, reach_m)) {
            if (!m_materials.any_straight()) continue;
            std::fill(scratch.sheets.begin(), scratch.sheets.end(), 1.0);
            if (!pass_clear_sheets(m_scene, m_materials, origin, wi, time_s, reach_m,
                                   scratch.sheets)) {
                continue;
            }
            through = scratch.sheets.data();
        }
        // I |cos θ| / r², m² → cm² (10⁴), times the lobe's BRDF or 1/π through the sheet.
        const double factor =
            cos_i > 0.0 ? m_materials.bsdf(material).reflection(wo_local, frame.to_local(wi)) *
                              cos_i / (r2_m2 * 1e4)
                        : -cos_i / kPi / (r2_m2 * 1e4);
        const double* spectrum = cos_i > 0.0 ? rho : tau;
        const double* intensity = m_lights->intensity_w_per_sr_um(l).data();
        for (std::size_t j = 0; j < radiance.size(); ++j) {
            const std::size_t b = bands[j];
            const double pass = through != nullptr ? through[b] : 1.0;
            radiance[j] += beta[j] * spectrum[b] * intensity[b] * factor * pass;
        }
    }
}

FirstSun PathTracer::draw_sun(const scene::RayHit& hit, const Vec3& normal, const Vec3& geometric,
                              double wo_z, double time_s, bool transmits, RandomStream& rng) const {
    const Environment& env = m_environment;
    const Vec3 sun = env.sun_direction(time_s);
    const Vec3 local =
        sample_uniform_cone_1mc(rng.uniform(), rng.uniform(), env.sun_cone_one_minus_cos());
    FirstSun drawn;
    drawn.wi = Frame::from_normal(sun).to_world(local);
    drawn.cos_i = dot(normal, drawn.wi);
    // A bump map's normal may face the sun where the facet does not: the geometry shadows.
    if ((drawn.cos_i > 0.0 || (transmits && drawn.cos_i < 0.0)) && wo_z > 0.0 &&
        same_side(geometric, normal, drawn.wi)) {
        drawn.query = true;
        drawn.ray = scene::PacketRay{m_scene.spawn_origin(hit, drawn.wi), drawn.wi, time_s};
    }
    return drawn;
}

FirstSun PathTracer::first_sun(const SampleRay& ray,
                               const std::optional<scene::RayHit>& primary_hit, RandomStream& rng,
                               bool records_first_hit) const {
    if (!primary_hit || !m_environment.sun_visible()) return {};
    const scene::RayHit& hit = *primary_hit;
    // As trace_path's first vertex: the normal facing the ray, the outgoing direction's z, and
    // the black back face of a single-sided material.
    const Vec3 wo = -ray.direction;
    const bool back_face = dot(hit.normal, wo) < 0.0;
    const bool dark = back_face && !m_materials.double_sided(hit.material);
    if ((dark || !m_materials.scatters(hit.material)) && !records_first_hit) return {};
    const Vec3 normal = back_face ? -hit.normal : hit.normal;
    const Vec3 shading = shading_normal(hit, normal, back_face);
    const double wo_z = Frame::from_normal(shading).to_local(wo).z;
    return draw_sun(
        hit, shading, normal, wo_z, ray.time_s,
        !dark && m_materials.transmits(hit.material) && !m_materials.straight(hit.material), rng);
}

template <typename Bands>
void PathTracer::trace_path(const Bands& bands, const SampleRay& ray, RandomStream& rng,
                            PathScratch& scratch, std::span<double> radiance, FirstHit* first_hit,
                            const std::optional<scene::RayHit>* primary_hit,
                            const FirstSun* sun) const {
    const Environment& env = m_environment;
    const std::size_t count = bands.size();
    // L = 0 and β = 1 until the first vertex: first_vertex_light and first_throughput write
    // them without these fills (a pass over the bands each); β is stored as ones only when a
    // point light needs it first.
    std::span<double> beta = std::span<double>(scratch.throughput).first(count);
    bool beta_is_one = true;
    const double time = ray.time_s;

    // The current vertex: the given primary hit, or the one traced into `traced` (pointers,
    // not copies of the 80-byte hit, from one bounce to the next).
    scene::RayHit traced;
    const scene::RayHit* hit = nullptr;
    if (primary_hit != nullptr) {
        hit = primary_hit->has_value() ? &**primary_hit : nullptr;
    } else if (m_scene.intersect_into(ray.origin_m, ray.direction, time, traced)) {
        draw_mixture_material(m_scene, traced, rng);
        hit = &traced;
    }
    ++scratch.rays;
    if (first_hit != nullptr) first_hit->hit = hit != nullptr;
    if (hit == nullptr) {
        if (ray.direction.z > 0.0 && !env.sky_black()) {
            // The sky of the lowest level: a camera ray that meets nothing.
            const Environment::SkyLookup sky = env.sky_lookup(ray.direction, time, AltitudeLevel{});
            for (std::size_t j = 0; j < count; ++j) radiance[j] = sky.at(bands[j]);
        } else {
            std::fill(radiance.begin(), radiance.end(), 0.0);
        }
        return;
    }

    Vec3 direction = ray.direction;
    const double first_z_m = hit->position_m.z;  // the sensor path starts here
    // The density of a direction drawn uniformly in the sun's disc, per steradian.
    const double sun_pdf = 1.0 / (2.0 * kPi * env.sun_cone_one_minus_cos());
    // A glossy draw's share of the sun it finds (the balance heuristic against the disc).
    const auto sun_weight = [sun_pdf](const BsdfSample& s) {
        return s.pdf_per_sr / (s.pdf_per_sr + sun_pdf);
    };
    // The weight with which a path leaving the scene inside the sun's disc counts it: 0 when
    // the last vertex that drew a direction counted the sun by its shadow ray alone
    // (Lambertian), its draw's MIS share when glossy, 1 after a mirror; a straight pass
    // through a clear sheet keeps it (the direction is unchanged). The camera's ray: 0.
    double disc_weight = 0.0;
    for (unsigned bounce = 0;; ++bounce) {
        const std::size_t m = hit->material;
        // The sun and sky at this vertex's height (docs/scene.md).
        const AltitudeLevel level = env.level_at(hit->position_m.z);
        const Vec3 wo = -direction;
        const bool back_face = dot(hit->normal, wo) < 0.0;
        const Vec3 normal = back_face ? -hit->normal : hit->normal;
        // A bump map's tilted normal: the BSDF's frame and cosines (shading_normal.h).
        const Vec3 shading = shading_normal(*hit, normal, back_face);
        // The back face of a single-sided material is black: no light, and the path ends.
        const bool dark = back_face && !m_materials.double_sided(m);
        const bool reflects = !dark && m_materials.reflects(m);
        const bool transmits = !dark && m_materials.transmits(m);
        // A clear sheet's light passes straight through: no diffuse next-event term behind it.
        const bool diffuses = transmits && !m_materials.straight(m);
        const bool scatters = reflects || transmits;
        const double* rho = m_materials.reflectance(m).data();
        const double* tau = m_materials.transmittance(m).data();
        // The spectrum the sun's next-event term scales: ρ in front, τ from behind a sheet.
        const double* sun_spectrum = rho;

        const Bsdf& bsdf = m_materials.bsdf(m);
        // Emission and the sun by next-event estimation.
        double sun_factor = 0.0;
        const Frame frame = shading_frame(bsdf, shading);
        const Vec3 wo_local = frame.to_local(wo);
        const double* emission =
            dark ? nullptr
                 : m_materials.emission_towards(m, hit->temperature_k, wo_local.z, bands,
                                                scratch.emission_towards);
        // The first hit's record: its shadow ray is traced even on a black material (whose
        // path ends here, so the numbers drawn for it change nothing after).
        FirstHit* record = bounce == 0 ? first_hit : nullptr;
        bool sun_blocked = true;
        bool sun_through_sheets = false;  // the shadow ray passed clear sheets (scratch.sheets)
        // The sun's draw is read where it lies (the 120-byte draw is not copied).
        const auto take_sun = [&](const FirstSun& drawn) {
            if (!drawn.query) return;
            ++scratch.rays;
            sun_blocked = drawn.blocked;
            if (sun_blocked && m_materials.any_straight()) {
                std::fill(scratch.sheets.begin(), scratch.sheets.end(), 1.0);
                sun_blocked =
                    !pass_clear_sheets(m_scene, m_materials, drawn.ray.origin_m, drawn.wi, time,
                                       std::numeric_limits<double>::infinity(), scratch.sheets);
                sun_through_sheets = !sun_blocked;
            }
            if (sun_blocked) return;
            if (drawn.cos_i > 0.0) {
                if (reflects) {
                    const Vec3 wi_local = frame.to_local(drawn.wi);
                    sun_factor = bsdf.reflection(wo_local, wi_local) * drawn.cos_i;
                    // A glossy lobe's draws may find the sun too: the balance heuristic
                    // between the two (the draw's share is added where a path escapes).
                    if (bsdf.glossy()) {
                        sun_factor /= 1.0 + bsdf.pdf_per_sr(wo_local, wi_local) / sun_pdf;
                    }
                }
            } else if (diffuses) {
                sun_factor = -drawn.cos_i / kPi;  // through the sheet: f = τ/π
                sun_spectrum = tau;
            }
        };
        if ((scatters || record != nullptr) && env.sun_visible()) {
            if (bounce == 0 && sun != nullptr) {
                take_sun(*sun);  // drawn, and its shadow ray answered, before the path
            } else {
                FirstSun drawn = draw_sun(*hit, shading, normal, wo_local.z, time, diffuses, rng);
                if (drawn.query) {
                    const scene::PacketRay& q = drawn.ray;
                    drawn.blocked = m_scene.occluded(q.origin_m, q.direction, q.time_s);
                }
                take_sun(drawn);
            }
        }
        if (record != nullptr) {
            record->position_m = hit->position_m;
            record->normal = normal;
            record->distance_m = hit->distance_m;
            record->material = hit->material;
            record->temperature_k = hit->temperature_k;
            record->mix = hit->mixture_map == scene::kNoMixture
                              ? scene::MaterialMix{}
                              : m_scene.maps().mix(hit->mixture_map, hit->mixture_texel);
            record->instance = hit->instance;
            record->sun_blocked = sun_blocked;
        }
        const double* sun_irradiance =
            sun_factor > 0.0 ? at_height(bands, level, &Environment::sun_irradiance_w_per_cm2_um,
                                         env, scratch.sun_at_height)
                             : nullptr;
        if (sun_irradiance != nullptr && sun_through_sheets) {
            // E_sun as it arrives through the panes.
            for (std::size_t j = 0; j < count; ++j) {
                const std::size_t b = bands[j];
                scratch.sheets[b] *= sun_irradiance[b];
            }
            sun_irradiance = scratch.sheets.data();
        }
        if (bounce == 0) {
            first_vertex_light(bands, radiance, emission, sun_spectrum, sun_irradiance, sun_factor);
        } else {
            add_vertex_light(bands, radiance, beta, emission, sun_spectrum, sun_irradiance,
                             sun_factor);
        }
        if (m_lights != nullptr && scatters && wo_local.z > 0.0) {
            if (beta_is_one) {
                std::fill(beta.begin(), beta.end(), 1.0);
                beta_is_one = false;
            }
            add_point_lights(bands, *hit, shading, normal, wo_local, frame, m, time, beta, radiance,
                             scratch);
        }

        // Continue the path: through a thin sheet with probability P_t (cosine-weighted on
        // the far side, weight τ / P_t), else reflected by the lobe (weight ρ · w / (1 − P_t)).
        // An opaque material has P_t = 0 and draws no number for the choice.
        if (!scatters || bounce >= m_settings.max_bounces) break;
        const double p_transmit = bsdf.transmission_probability();
        const double u_side = p_transmit > 0.0 ? rng.uniform() : 1.0;
        const double u_lobe = rng.uniform();
        const double u1 = rng.uniform();
        const double u2 = rng.uniform();
        const auto sample = bsdf.sample(wo_local, u_side, u_lobe, u1, u2);
        if (!sample || !(sample->weight > 0.0)) break;
        const Vec3 wi = normalized(frame.to_world(sample->wi));
        if (hit->bumped && !same_side(normal, shading, wi)) break;  // into the bumps' facet
        const double weight = sample->weight;
        if (!(sample->delta && sample->side == ScatterSide::transmitted)) {
            disc_weight = sample->delta ? 1.0 : bsdf.glossy() ? sun_weight(*sample) : 0.0;
        }
        const double* spectrum = sample->side == ScatterSide::transmitted ? tau : rho;
        const double largest = beta_is_one ? first_throughput(bands, beta, spectrum, weight)
                                           : scale_throughput(bands, beta, spectrum, weight);
        beta_is_one = false;
        if (!(largest > 0.0)) break;
        if (bounce + 1 >= m_settings.roulette_start_bounce) {
            const double survive = std::min(1.0, largest);
            if (rng.uniform() >= survive) break;
            if (survive < 1.0) {
                for (double& b : beta) b /= survive;
            }
        }
        const Vec3 origin = m_scene.spawn_origin(*hit, wi);
        hit = m_scene.intersect_into(origin, wi, time, traced) ? &traced : nullptr;
        if (hit != nullptr) draw_mixture_material(m_scene, traced, rng);
        ++scratch.rays;
        if (hit == nullptr) {
            if (wi.z > 0.0 && !env.sky_black()) {
                const Environment::SkyLookup sky = env.sky_lookup(wi, time, level);
                for (std::size_t j = 0; j < count; ++j) radiance[j] += beta[j] * sky.at(bands[j]);
            }
            if (disc_weight > 0.0 && env.sun_visible()) {
                add_sun_disc(bands, env, level, wi, time, disc_weight, sun_pdf, beta, radiance,
                             scratch.sun_at_height);
            }
            break;
        }
        direction = wi;
    }

    if (env.has_sensor_path()) {
        apply_sensor_path(env, bands, -ray.direction, time, first_z_m, scratch, radiance);
    }
}

void PathTracer::trace(const SampleRay& ray, RandomStream& rng, PathScratch& scratch,
                       std::span<double> radiance, FirstHit* first_hit,
                       const std::optional<scene::RayHit>* primary_hit, const FirstSun* sun) const {
    trace_path(RangeBands{m_range.first, m_range.count}, ray, rng, scratch, radiance, first_hit,
               primary_hit, sun);
}

void PathTracer::trace_bands(const SampleRay& ray, RandomStream& rng, PathScratch& scratch,
                             std::span<const std::uint32_t> bands, std::span<double> radiance,
                             FirstHit* first_hit, const std::optional<scene::RayHit>* primary_hit,
                             const FirstSun* sun) const {
    if (bands.size() != radiance.size() || bands.empty() ||
        bands.size() > scratch.throughput.size()) {
        throw internal_error("trace_bands: " + std::to_string(bands.size()) + " bands for " +
                             std::to_string(radiance.size()) + " values");
    }
    trace_path(ListBands{bands}, ray, rng, scratch, radiance, first_hit, primary_hit, sun);
}

}  // namespace glint::radiometry
