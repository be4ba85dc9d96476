// SPDX-License-Identifier: Apache-2.0
// The interface between glint_io and its OpenImageIO module (glint-image-oiio.so). glint_io
// opens the module with dlopen on the first image read or written (image_module.cpp), so a
// process that touches no image never loads OpenImageIO and the ~260 shared libraries it
// brings (about 0.2 s on every start). The module only wraps OIIO calls: it throws nothing
// and reports failures as false plus error(); glint_io turns them into glint::Error.
// Both sides are built from this header by the same build, and the module says which
// version of it it was built from (kImageBackendVersion).
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace glint::io::detail {

/// Bumped whenever anything below changes.
inline constexpr int kImageBackendVersion = 1;

/// Pixel storage types, as OIIO's TypeDesc base types.
enum class RawType { uint8, int8, uint16, int16, uint32, int32, half, float32, float64 };

/// What an opened image holds (its first subimage, full resolution).
struct InputSpec {
    int width = 0;
    int height = 0;
    int depth = 1;
    int channels = 0;
    int y_origin = 0;
    std::vector<std::string> channel_names;  ///< may hold fewer names than channels
    bool mixed_types = false;                ///< per-channel storage types
    RawType type = RawType::uint8;           ///< the storage type (when not mixed)
    std::string format_name;                 ///< OIIO's name of the file format
};

/// An image opened for reading.
class InputBackend {
public:
    virtual ~InputBackend() = default;
    virtual const InputSpec& spec() const = 0;
    /// Reads the file's line `y` (spec().y_origin based), every channel, converted to `as`.
    virtual bool read_line(int y, RawType as, void* out) = 0;
    /// The last failure's message (and clears it).
    virtual std::string error() = 0;
    virtual void close() = 0;
};

/// How to write an image: OIIO's format name and the spec's attributes.
struct OutputSpec {
    std::string format;  ///< "png", "tiff", "jpeg", "openexr", "pnm"
    int width = 0;
    int height = 0;
    int channels = 0;
    RawType type = RawType::uint8;
    std::vector<std::string> channel_names;  ///< empty: the format's defaults
    std::string software;                    ///< empty: none
    std::string description;                 ///< empty: none
    std::string date_time;                   ///< Exif "YYYY:MM:DD hh:mm:ss"; empty: none
    std::string compression;                 ///< empty: the format's default
};

/// An image being written.
class OutputBackend {
public:
    virtual ~OutputBackend() = default;
    /// Opens `path` for the spec given at creation.
    virtual bool open(const std::string& path) = 0;
    /// Writes line `y` from `data` stored as `as`.
    virtual bool write_line(int y, RawType as, const void* data) = 0;
    virtual bool close() = 0;
    virtual std::string error() = 0;
};

/// The module's entry points.
struct ImageBackend {
    int version = kImageBackendVersion;
    /// Opens `path` for reading (bands as data: no alpha association); null and `error` on
    /// failure.
    std::unique_ptr<InputBackend> (*open_input)(const std::string& path, std::string& error);
    /// A writer for `spec`; null and `error` when OIIO has no writer for its format.
    std::unique_ptr<OutputBackend> (*create_output)(const OutputSpec& spec, std::string& error);
};

/// The name of the function the module exports: `const ImageBackend* (void)`.
inline constexpr const char* kImageBackendSymbol = "glint_image_backend";

/// The module's entry points, loaded on first use; throws glint::Error (runtime) naming the
/// paths tried when the module cannot be loaded.
const ImageBackend& image_backend();

}  // namespace glint::io::detail
