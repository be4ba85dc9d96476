// SPDX-License-Identifier: Apache-2.0
// glint-image-oiio.so: the OpenImageIO calls behind glint/io/image.h, loaded by glint_io on
// first use (image_backend.h says why and how). Nothing here throws: OIIO's failures come
// back as false plus error().
#include <OpenImageIO/imageio.h>

#include "image_backend.h"

namespace {

using glint::io::detail::ImageBackend;
using glint::io::detail::InputBackend;
using glint::io::detail::InputSpec;
using glint::io::detail::OutputBackend;
using glint::io::detail::OutputSpec;
using glint::io::detail::RawType;

OIIO::TypeDesc type_desc(RawType type) {
    switch (type) {
        case RawType::uint8:
            return OIIO::TypeDesc::UINT8;
        case RawType::int8:
            return OIIO::TypeDesc::INT8;
        case RawType::uint16:
            return OIIO::TypeDesc::UINT16;
        case RawType::int16:
            return OIIO::TypeDesc::INT16;
        case RawType::uint32:
            return OIIO::TypeDesc::UINT32;
        case RawType::int32:
            return OIIO::TypeDesc::INT32;
        case RawType::half:
            return OIIO::TypeDesc::HALF;
        case RawType::float32:
            return OIIO::TypeDesc::FLOAT;
        case RawType::float64:
            return OIIO::TypeDesc::DOUBLE;
    }
    return OIIO::TypeDesc::UINT8;
}

/// The storage type of `desc`; float64 for anything else.
RawType raw_type(OIIO::TypeDesc desc) {
    switch (desc.basetype) {
        case OIIO::TypeDesc::UINT8:
            return RawType::uint8;
        case OIIO::TypeDesc::INT8:
            return RawType::int8;
        case OIIO::TypeDesc::UINT16:
            return RawType::uint16;
        case OIIO::TypeDesc::INT16:
            return RawType::int16;
        case OIIO::TypeDesc::UINT32:
            return RawType::uint32;
        case OIIO::TypeDesc::INT32:
            return RawType::int32;
        case OIIO::TypeDesc::HALF:
            return RawType::half;
        case OIIO::TypeDesc::FLOAT:
            return RawType::float32;
        default:
            return RawType::float64;
    }
}

class OiioInput final : public InputBackend {
public:
    explicit OiioInput(std::unique_ptr<OIIO::ImageInput> input) : m_input(std::move(input)) {
        const OIIO::ImageSpec& spec = m_input->spec();
        m_spec.width = spec.width;
        m_spec.height = spec.height;
        m_spec.depth = spec.depth;
        m_spec.channels = spec.nchannels;
        m_spec.y_origin = spec.y;
        m_spec.channel_names = spec.channelnames;
        m_spec.mixed_types = !spec.channelformats.empty();
        m_spec.type = raw_type(spec.format);
        m_spec.format_name = m_input->format_name();
    }
    const InputSpec& spec() const override { return m_spec; }
    bool read_line(int y, RawType as, void* out) override {
        return m_input->read_scanlines(0, 0, y, y + 1, 0, 0, m_spec.channels, type_desc(as), out);
    }
    std::string error() override { return m_input->geterror(); }
    void close() override {
        m_input->close();
        (void)m_input->geterror();
    }

private:
    std::unique_ptr<OIIO::ImageInput> m_input;
    InputSpec m_spec;
};

class OiioOutput final : public OutputBackend {
public:
    OiioOutput(std::unique_ptr<OIIO::ImageOutput> output, const OutputSpec& spec)
        : m_output(std::move(output)),
          m_spec(spec.width, spec.height, spec.channels, type_desc(spec.type)) {
        if (spec.channel_names.size() == static_cast<std::size_t>(spec.channels)) {
            m_spec.channelnames = spec.channel_names;
        }
        // Bands are data, not colour with alpha: no (un)premultiplication on the way out.
        m_spec.attribute("oiio:UnassociatedAlpha", 1);
        if (!spec.software.empty()) m_spec.attribute("Software", spec.software);
        if (!spec.description.empty()) m_spec.attribute("ImageDescription", spec.description);
        // An empty DateTime keeps the writers from recording the current time.
        m_spec.attribute("DateTime", spec.date_time);
        if (!spec.compression.empty()) m_spec.attribute("Compression", spec.compression);
    }
    bool open(const std::string& path) override { return m_output->open(path, m_spec); }
    bool write_line(int y, RawType as, const void* data) override {
        return m_output->write_scanline(y, 0, type_desc(as), data);
    }
    bool close() override { return m_output->close(); }
    std::string error() override { return m_output->geterror(); }

private:
    std::unique_ptr<OIIO::ImageOutput> m_output;
    OIIO::ImageSpec m_spec;
};

std::unique_ptr<InputBackend> open_input(const std::string& path, std::string& error) {
    // Bands are data: a fourth channel must not premultiply the first three on the way in.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::open(path, &config);
    if (!input) {
        error = OIIO::geterror();
        return nullptr;
    }
    return std::make_unique<OiioInput>(std::move(input));
}

std::unique_ptr<OutputBackend> create_output(const OutputSpec& spec, std::string& error) {
    std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(spec.format);
    if (!output) {
        error = OIIO::geterror();
        return nullptr;
    }
    return std::make_unique<OiioOutput>(std::move(output), spec);
}

}  // namespace

extern "C" __attribute__((visibility("default"))) const ImageBackend* glint_image_backend() {
    static const ImageBackend backend{glint::io::detail::kImageBackendVersion, &open_input,
                                      &create_output};
    return &backend;
}
