// SPDX-License-Identifier: Apache-2.0
// The Embree device of a GeometryScene and the RAII handles of the Embree objects made on it.
// The device owns a small state block (no globals) that Embree's error callback and memory
// monitor write into: the first error code and message, and the bytes Embree holds against
// the --max-memory cap. check() turns a recorded error into glint::Error after the Embree call
// that raised it.
#pragma once

#include <embree3/rtcore.h>

#include <cstdint>
#include <memory>
#include <string>

#include "glint/scene/geometry_scene.h"

namespace glint::scene::detail {

/// Releases an Embree scene handle.
struct SceneRelease {
    void operator()(RTCScene scene) const noexcept { rtcReleaseScene(scene); }
};
/// Releases an Embree geometry handle.
struct GeometryRelease {
    void operator()(RTCGeometry geometry) const noexcept { rtcReleaseGeometry(geometry); }
};
/// An owned reference to an Embree scene.
using ScenePtr = std::unique_ptr<RTCSceneTy, SceneRelease>;
/// An owned reference to an Embree geometry.
using GeometryPtr = std::unique_ptr<RTCGeometryTy, GeometryRelease>;

/// The Embree ISA names DeviceSettings::isa accepts, lower case, in increasing order.
inline constexpr const char* kEmbreeIsaNames[] = {"sse2", "sse4.2", "avx", "avx2", "avx512"};

/// The rtcNewDevice configuration string of `settings` ("threads=N,isa=avx2"; parts left
/// out when defaulted). Throws glint::Error (usage) for an unknown ISA name.
std::string embree_config(const DeviceSettings& settings);

/// What the callbacks record; lives on the heap at a fixed address for as long as the device.
struct DeviceState;

/// An Embree device with an error callback and a memory monitor (counting bytes, refusing
/// those above the cap when one is set).
/// Neither copyable nor movable (Embree holds a pointer to its state).
class EmbreeDevice {
public:
    /// Creates the device. Throws glint::Error: usage for an unknown ISA, runtime when
    /// Embree refuses the configuration or the CPU.
    explicit EmbreeDevice(const DeviceSettings& settings);
    ~EmbreeDevice();
    EmbreeDevice(const EmbreeDevice&) = delete;
    EmbreeDevice& operator=(const EmbreeDevice&) = delete;

    RTCDevice handle() const noexcept { return m_device; }
    const DeviceInfo& info() const noexcept { return m_info; }

    /// Throws glint::Error when Embree recorded an error since the device was made: runtime
    /// for the memory cap (naming it and the request refused) and for every other error,
    /// with `what` (e.g. "building object \"terrain\"") in the message.
    void check(const std::string& what) const;

    /// A new scene with `flags` and `quality`, checked.
    ScenePtr new_scene(RTCSceneFlags flags, RTCBuildQuality quality, const std::string& what);
    /// A new geometry of `type`, checked.
    GeometryPtr new_geometry(RTCGeometryType type, const std::string& what);

    /// Bytes Embree holds now, as its memory monitor reported them.
    std::int64_t used_bytes() const noexcept;

private:
    std::unique_ptr<DeviceState> m_state;
    RTCDevice m_device = nullptr;
    DeviceInfo m_info;
};

}  // namespace glint::scene::detail
