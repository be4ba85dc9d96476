// SPDX-License-Identifier: Apache-2.0
// Where a glint-schedule output goes: the caller's stream (`-o -`) or a file written
// atomically through glint::AtomicFile. Both are seen as a std::ostream so the writers can
// stream into either; a file appears under its name only after commit().
#pragma once

#include <memory>
#include <ostream>
#include <streambuf>
#include <string>

#include "glint/core/atomic_file.h"

namespace glint::app_schedule::internal {

/// A streambuf that appends everything to an AtomicFile (which buffers and throws
/// glint::Error on write errors).
class AtomicFileBuf final : public std::streambuf {
public:
    explicit AtomicFileBuf(AtomicFile& file) : m_file(file) {}

protected:
    std::streamsize xsputn(const char* data, std::streamsize count) override {
        m_file.write(data, static_cast<std::size_t>(count));
        return count;
    }
    int_type overflow(int_type ch) override {
        if (traits_type::eq_int_type(ch, traits_type::eof())) return traits_type::not_eof(ch);
        const char c = traits_type::to_char_type(ch);
        m_file.write(&c, 1);
        return ch;
    }

private:
    AtomicFile& m_file;
};

/// One output: `target` "-" or empty is `out`, anything else a file written atomically.
class OutputTarget {
public:
    OutputTarget(const std::string& target, std::ostream& out);
    OutputTarget(const OutputTarget&) = delete;
    OutputTarget& operator=(const OutputTarget&) = delete;

    /// The stream to write to. Write errors of a file throw glint::Error (io).
    std::ostream& stream() { return m_file ? *m_file_stream : m_out; }
    /// Flushes; renames a file into place. Throws glint::Error (io) when anything written
    /// was lost (stream errors, close or flush failures).
    void commit();

private:
    std::ostream& m_out;
    std::string m_name;
    std::unique_ptr<AtomicFile> m_file;
    std::unique_ptr<AtomicFileBuf> m_buf;
    std::unique_ptr<std::ostream> m_file_stream;
};

/// True when `target` names the caller's stream ("-" or empty).
inline bool is_stdout(const std::string& target) { return target.empty() || target == "-"; }

}  // namespace glint::app_schedule::internal
