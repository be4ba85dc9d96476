// SPDX-License-Identifier: Apache-2.0
// Whole-file reads of inputs and the record of one load (glint/io/input_files.h).
#include "glint/io/input_files.h"

#include <cerrno>
#include <fstream>
#include <iterator>
#include <system_error>
#include <utility>

#include "glint/core/error.h"

namespace glint::io {
namespace {

/// DIRSIG inputs are a few MB at most; anything far larger is not one of them.
constexpr std::uintmax_t kMaxInputBytes = 256u << 20;

}  // namespace

std::string read_input_file(const std::filesystem::path& path, const std::string& display_name) {
    const std::string& name = display_name.empty() ? path.string() : display_name;
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (!ec && std::filesystem::is_directory(status)) {
        throw io_error("is a folder, expected a file", name);
    }
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (!ec && size > kMaxInputBytes) {
        throw input_error("file is " + std::to_string(size) + " bytes, more than the " +
                              std::to_string(kMaxInputBytes >> 20) + " MiB accepted for an input",
                          ErrorContext{name, 0, {}});
    }
    std::ifstream stream(path, std::ios::binary);
    if (!stream) {
        const int code = errno;
        throw io_error("cannot open file: " + errno_text(code), name);
    }
    std::string text((std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
    if (stream.bad()) throw io_error("cannot read file", name);
    return text;
}

std::filesystem::path InputFiles::key(const std::filesystem::path& path) {
    std::error_code ec;
    std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
    return ec ? path.lexically_normal() : canonical;
}

const std::string& InputFiles::text(const std::filesystem::path& path,
                                    const std::string& display_name) {
    const std::filesystem::path k = key(path);
    if (const auto found = m_texts.find(k); found != m_texts.end()) return found->second;
    m_opened.push_back(k);
    m_log.debug("reading " + (display_name.empty() ? path.string() : display_name));
    std::string text = read_input_file(path, display_name);
    return m_texts.emplace(k, std::move(text)).first->second;
}

std::size_t InputFiles::open_count(const std::filesystem::path& path) const {
    const std::filesystem::path k = key(path);
    std::size_t count = 0;
    for (const std::filesystem::path& opened : m_opened) count += opened == k ? 1 : 0;
    return count;
}

}  // namespace glint::io
