// SPDX-License-Identifier: Apache-2.0
// ENVI data types and layouts (glint/io/envi.h): the data type table (codes, sizes, names),
// interleave names and the machine's byte order.
#include <bit>
#include <string>

#include "envi_text.h"
#include "glint/core/error.h"
#include "glint/io/envi.h"

namespace glint::io {
namespace {

struct TypeInfo {
    EnviDataType type;
    std::size_t size;
    const char* name;
};

constexpr TypeInfo kTypes[] = {
    {EnviDataType::uint8, 1, "uint8"},
    {EnviDataType::int16, 2, "int16"},
    {EnviDataType::int32, 4, "int32"},
    {EnviDataType::float32, 4, "float32"},
    {EnviDataType::float64, 8, "float64"},
    {EnviDataType::complex64, 8, "complex64"},
    {EnviDataType::complex128, 16, "complex128"},
    {EnviDataType::uint16, 2, "uint16"},
    {EnviDataType::uint32, 4, "uint32"},
    {EnviDataType::int64, 8, "int64"},
    {EnviDataType::uint64, 8, "uint64"},
};

const TypeInfo* find_type(EnviDataType type) {
    for (const TypeInfo& info : kTypes) {
        if (info.type == type) return &info;
    }
    return nullptr;
}

}  // namespace

std::size_t envi_type_size(EnviDataType type) {
    const TypeInfo* info = find_type(type);
    if (!info) throw internal_error("envi_type_size: invalid EnviDataType");
    return info->size;
}

std::optional<EnviDataType> envi_type_from_code(long code) {
    for (const TypeInfo& info : kTypes) {
        if (static_cast<long>(info.type) == code) return info.type;
    }
    return std::nullopt;
}

std::optional<EnviDataType> envi_type_from_string(std::string_view text) {
    const std::string name = detail::normalize_key(text);
    for (const TypeInfo& info : kTypes) {
        if (name == info.name || name == std::to_string(static_cast<long>(info.type))) {
            return info.type;
        }
    }
    return std::nullopt;
}

const char* envi_type_name(EnviDataType type) {
    const TypeInfo* info = find_type(type);
    return info ? info->name : "invalid";
}

const char* interleave_name(Interleave interleave) {
    switch (interleave) {
        case Interleave::bsq:
            return "bsq";
        case Interleave::bil:
            return "bil";
        case Interleave::bip:
            return "bip";
    }
    return "invalid";
}

ByteOrder native_byte_order() {
    static_assert(std::endian::native == std::endian::little ||
                  std::endian::native == std::endian::big);
    return std::endian::native == std::endian::little ? ByteOrder::little : ByteOrder::big;
}

}  // namespace glint::io
