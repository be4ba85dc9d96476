// SPDX-License-Identifier: Apache-2.0
// Loading glint-image-oiio.so (image_backend.h): beside the running program first, at the
// build's relative place (<program folder>/GLINT_IMAGE_MODULE_FROM_PROGRAM: the build tree
// and a relocated install keep it), then at the installed absolute path.
#include <dlfcn.h>

#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "glint/core/error.h"
#include "image_backend.h"

#ifndef GLINT_IMAGE_MODULE_FROM_PROGRAM
#error "GLINT_IMAGE_MODULE_FROM_PROGRAM must name the module relative to the programs' folder"
#endif
#ifndef GLINT_IMAGE_MODULE_INSTALLED
#error "GLINT_IMAGE_MODULE_INSTALLED must name the installed module"
#endif

namespace glint::io::detail {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> module_candidates() {
    std::vector<fs::path> out;
    std::error_code ec;
    const fs::path program = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) out.push_back(program.parent_path() / GLINT_IMAGE_MODULE_FROM_PROGRAM);
    out.emplace_back(GLINT_IMAGE_MODULE_INSTALLED);
    return out;
}

const ImageBackend* load_backend() {
    std::string tried;
    const auto refuse = [&tried](const fs::path& path, const std::string& why) {
        tried += (tried.empty() ? "" : ", ") + path.lexically_normal().string() + " (" + why + ")";
    };
    for (const fs::path& path : module_candidates()) {
        std::error_code ec;
        if (!fs::exists(path, ec)) {
            refuse(path, "missing");
            continue;
        }
        // Kept open for the life of the process: images may be read or written at any time.
        void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (handle == nullptr) {
            const char* why = ::dlerror();
            refuse(path, why != nullptr ? why : "cannot be loaded");
            continue;
        }
        using Entry = const ImageBackend* (*)();
        auto entry = reinterpret_cast<Entry>(::dlsym(handle, kImageBackendSymbol));
        const ImageBackend* backend = entry != nullptr ? entry() : nullptr;
        if (backend == nullptr || backend->version != kImageBackendVersion) {
            ::dlclose(handle);
            refuse(path, "not this build's image module");
            continue;
        }
        return backend;
    }
    throw runtime_error(
        "cannot load glint's image module (OpenImageIO), needed to read or write "
        "PNG, TIFF, JPEG, OpenEXR and PPM images: tried " +
        tried + "; reinstall glint");
}

}  // namespace

const ImageBackend& image_backend() {
    // Loaded once, on the first image (a static local: thread-safe, retried if it threw).
    static const ImageBackend* const backend = load_backend();
    return *backend;
}

}  // namespace glint::io::detail
