// SPDX-License-Identifier: Apache-2.0
// The baseline the path tracer is measured against: the same model::Scene built directly with
// the Embree 3 API, two-level as GeometryScene builds it (one robust, high-quality scene per
// object, one instance per model instance in a robust, high-quality top-level scene), and a
// loop that does nothing but rtcIntersect1 over prepared single-precision rays, in parallel
// with oneTBB in a task_arena of the requested size. No clipping, no double precision, no
// normals: the ceiling of what a tracer could reach on this CPU.
#pragma once

#include <embree3/rtcore.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "glint/model/scene.h"

namespace glint::bench {

/// A prepared ray: origin (m, scene ENU), unit direction; traced over (0, ∞).
struct BareRay {
    float origin[3];
    float direction[3];
};

/// One timed run of rtcIntersect1 over a ray set.
struct BareTiming {
    double seconds = 0.0;    ///< wall time of all passes
    std::uint64_t rays = 0;  ///< rays traced in all passes
    std::uint64_t hits = 0;  ///< of those, rays that hit something
    unsigned passes = 0;     ///< passes over the ray set
    double rays_per_s() const noexcept { return seconds > 0.0 ? double(rays) / seconds : 0.0; }
};

/// A two-level Embree scene of a model::Scene (static instances only).
class BareEmbreeScene {
public:
    /// Builds the scene on a device made with the rtcNewDevice configuration `config`.
    /// Throws glint::Error (runtime) when Embree reports an error, (input) for a dynamic
    /// instance or an invalid transform.
    BareEmbreeScene(const model::Scene& scene, const std::string& config);
    ~BareEmbreeScene();
    BareEmbreeScene(const BareEmbreeScene&) = delete;
    BareEmbreeScene& operator=(const BareEmbreeScene&) = delete;

    /// The top-level scene.
    RTCScene top() const noexcept { return m_top; }
    /// Wall time of the build (object scenes and top level), seconds.
    double build_seconds() const noexcept { return m_build_seconds; }
    /// The device's Embree version, e.g. "3.13.5".
    std::string version() const;
    /// Widest ray packet Embree reports as native on this CPU (16: AVX-512, 8: AVX/AVX2,
    /// 4: SSE), 0 when it reports none.
    unsigned native_packet_width() const;

private:
    void check(const std::string& what) const;

    RTCDevice m_device = nullptr;
    std::vector<RTCScene> m_objects;
    RTCScene m_top = nullptr;
    double m_build_seconds = 0.0;
    /// First error Embree's callback reported (written by the callback).
    struct ErrorState {
        RTCError code = RTC_ERROR_NONE;
        std::string message;
    } m_error;
};

/// Traces every ray of `rays` with rtcIntersect1 on `threads` threads (a tbb::task_arena),
/// pass after pass until at least `min_seconds` have gone by, and times the passes; does that
/// `repeats` times and returns the fastest (highest rays/s) of them.
BareTiming time_intersect(const BareEmbreeScene& scene, std::span<const BareRay> rays,
                          unsigned threads, double min_seconds, unsigned repeats = 1);

/// The hit distance of every ray (infinity for a miss), untimed; for checking that the
/// baseline and the tracer's scene agree.
std::vector<float> intersect_distances(const BareEmbreeScene& scene, std::span<const BareRay> rays,
                                       unsigned threads);

}  // namespace glint::bench
