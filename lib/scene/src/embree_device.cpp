// SPDX-License-Identifier: Apache-2.0
// The Embree device: the configuration string from DeviceSettings (our own ISA check first:
// Embree silently treats an unknown ISA name as SSE2), the error callback that keeps the
// first error, the memory monitor that enforces --max-memory, and the translation of
// recorded errors into glint::Error.
#include "embree_device.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <mutex>

#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::scene::detail {

struct DeviceState {
    std::mutex mutex;  ///< guards the error fields
    RTCError first_error = RTC_ERROR_NONE;
    std::string first_message;
    std::uint64_t cap_bytes = 0;  ///< 0: no cap
    std::atomic<std::int64_t> used_bytes{0};
    std::atomic<std::int64_t> refused_bytes{0};  ///< the first request the cap refused
};

namespace {

constexpr std::uint64_t kKiB = 1024;
constexpr std::uint64_t kMiB = 1024 * kKiB;
constexpr std::uint64_t kGiB = 1024 * kMiB;

void on_error(void* user, RTCError code, const char* message) {
    auto* state = static_cast<DeviceState*>(user);
    const std::lock_guard<std::mutex> lock(state->mutex);
    if (state->first_error != RTC_ERROR_NONE) return;
    state->first_error = code;
    state->first_message = message ? message : "";
}

bool on_memory(void* user, ssize_t bytes, bool /*post*/) {
    auto* state = static_cast<DeviceState*>(user);
    const auto delta = static_cast<std::int64_t>(bytes);
    if (delta <= 0 || state->cap_bytes == 0) {
        state->used_bytes.fetch_add(delta, std::memory_order_relaxed);
        return true;
    }
    // Reserve first, then back out: concurrent builder threads cannot together pass the cap.
    const std::int64_t after =
        state->used_bytes.fetch_add(delta, std::memory_order_relaxed) + delta;
    if (after <= static_cast<std::int64_t>(state->cap_bytes)) return true;
    state->used_bytes.fetch_sub(delta, std::memory_order_relaxed);
    std::int64_t none = 0;
    state->refused_bytes.compare_exchange_strong(none, delta, std::memory_order_relaxed);
    return false;  // Embree then fails the operation with RTC_ERROR_OUT_OF_MEMORY
}

const char* error_name(RTCError code) {
    switch (code) {
        case RTC_ERROR_NONE:
            return "no error";
        case RTC_ERROR_UNKNOWN:
            return "unknown error";
        case RTC_ERROR_INVALID_ARGUMENT:
            return "invalid argument";
        case RTC_ERROR_INVALID_OPERATION:
            return "invalid operation";
        case RTC_ERROR_OUT_OF_MEMORY:
            return "out of memory";
        case RTC_ERROR_UNSUPPORTED_CPU:
            return "unsupported CPU";
        case RTC_ERROR_CANCELLED:
            return "cancelled";
    }
    return "unknown error";
}

/// "64 MiB", "1 KiB", "1000 bytes": the largest binary unit that divides `bytes`.
std::string bytes_text(std::uint64_t bytes) {
    if (bytes >= kGiB && bytes % kGiB == 0) return std::to_string(bytes / kGiB) + " GiB";
    if (bytes >= kMiB && bytes % kMiB == 0) return std::to_string(bytes / kMiB) + " MiB";
    if (bytes >= kKiB && bytes % kKiB == 0) return std::to_string(bytes / kKiB) + " KiB";
    return std::to_string(bytes) + " bytes";
}

}  // namespace

std::string embree_config(const DeviceSettings& settings) {
    std::string config;
    const auto add = [&config](const std::string& part) {
        if (!config.empty()) config += ",";
        config += part;
    };
    if (settings.threads > 0) add("threads=" + std::to_string(settings.threads));
    if (!settings.isa.empty()) {
        const std::string isa = to_lower(settings.isa);
        const bool known = std::any_of(std::begin(kEmbreeIsaNames), std::end(kEmbreeIsaNames),
                                       [&isa](const char* name) { return isa == name; });
        if (!known) {
            std::string names;
            for (const char* name : kEmbreeIsaNames)
                names += (names.empty() ? "" : ", ") + std::string(name);
            throw usage_error("unknown Embree ISA \"" + settings.isa + "\", expected one of " +
                              names);
        }
        add("isa=" + isa);
    }
    return config;
}

EmbreeDevice::EmbreeDevice(const DeviceSettings& settings)
    : m_state(std::make_unique<DeviceState>()) {
    m_info.config = embree_config(settings);
    m_info.threads = settings.threads;
    m_state->cap_bytes = settings.max_memory_bytes;
    m_device = rtcNewDevice(m_info.config.c_str());
    if (!m_device) {
        const RTCError code = rtcGetDeviceError(nullptr);
        std::string message = "cannot create the Embree device";
        if (!m_info.config.empty()) message += " (configuration \"" + m_info.config + "\")";
        message += ": ";
        message += code == RTC_ERROR_UNSUPPORTED_CPU ? "this CPU does not support the ISA asked for"
                                                     : error_name(code);
        throw runtime_error(message);
    }
    rtcSetDeviceErrorFunction(m_device, on_error, m_state.get());
    rtcSetDeviceMemoryMonitorFunction(m_device, on_memory, m_state.get());
    const auto property = [this](RTCDeviceProperty p) {
        return std::to_string(rtcGetDeviceProperty(m_device, p));
    };
    m_info.embree_version = property(RTC_DEVICE_PROPERTY_VERSION_MAJOR) + "." +
                            property(RTC_DEVICE_PROPERTY_VERSION_MINOR) + "." +
                            property(RTC_DEVICE_PROPERTY_VERSION_PATCH);
}

EmbreeDevice::~EmbreeDevice() {
    // Every scene and geometry of the device has been released by now (their owners are
    // destroyed first); Embree may still report freed memory to the monitor until here.
    if (m_device) rtcReleaseDevice(m_device);
}

void EmbreeDevice::check(const std::string& what) const {
    RTCError code;
    std::string message;
    {
        const std::lock_guard<std::mutex> lock(m_state->mutex);
        code = m_state->first_error;
        message = m_state->first_message;
    }
    if (code == RTC_ERROR_NONE) return;
    const std::int64_t refused = m_state->refused_bytes.load(std::memory_order_relaxed);
    if (code == RTC_ERROR_OUT_OF_MEMORY && refused > 0) {
        throw runtime_error("the scene needs more than the " + bytes_text(m_state->cap_bytes) +
                            " allowed by --max-memory (Embree asked for " +
                            std::to_string(refused) + " more bytes while " + what + ")");
    }
    std::string text = "Embree failed while " + what + ": " + error_name(code);
    if (!message.empty()) text += " (" + message + ")";
    throw runtime_error(text);
}

ScenePtr EmbreeDevice::new_scene(RTCSceneFlags flags, RTCBuildQuality quality,
                                 const std::string& what) {
    ScenePtr scene(rtcNewScene(m_device));
    check(what);
    if (!scene) throw runtime_error("Embree failed while " + what + ": no scene");
    rtcSetSceneFlags(scene.get(), flags);
    rtcSetSceneBuildQuality(scene.get(), quality);
    check(what);
    return scene;
}

GeometryPtr EmbreeDevice::new_geometry(RTCGeometryType type, const std::string& what) {
    GeometryPtr geometry(rtcNewGeometry(m_device, type));
    check(what);
    if (!geometry) throw runtime_error("Embree failed while " + what + ": no geometry");
    return geometry;
}

std::int64_t EmbreeDevice::used_bytes() const noexcept {
    return m_state->used_bytes.load(std::memory_order_relaxed);
}

}  // namespace glint::scene::detail
