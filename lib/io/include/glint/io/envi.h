// SPDX-License-Identifier: Apache-2.0
// ENVI raw image + text header: the types, the header model, and line-streaming reader and
// writer. This is the product format of every glint tool (docs/formats.md, "ENVI images").
//
// Header keys written (lowercase, this order): description, samples, lines, bands,
// header offset, file type, data type, interleave, byte order, wavelength units, wavelength,
// fwhm, band names, data units, then every extra key (glint provenance keys are prefixed
// "glint "). Brace lists are wrapped so that no line exceeds 200 characters.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "glint/core/atomic_file.h"
#include "glint/io/line_memory.h"

namespace glint::io {

/// ENVI `data type` codes. Complex types (6, 9) can be read, not written.
enum class EnviDataType : int {
    uint8 = 1,
    int16 = 2,
    int32 = 3,
    float32 = 4,
    float64 = 5,
    complex64 = 6,
    complex128 = 9,
    uint16 = 12,
    uint32 = 13,
    int64 = 14,
    uint64 = 15,
};

/// Bytes of one value of `type` (complex: both parts).
std::size_t envi_type_size(EnviDataType type);
/// The type for an ENVI code, or nullopt for an unknown code.
std::optional<EnviDataType> envi_type_from_code(long code);
/// Lowercase name ("uint8", "float64", ...).
const char* envi_type_name(EnviDataType type);
/// The type for a name as envi_type_name gives it (any case) or a code ("4"); nullopt
/// otherwise.
std::optional<EnviDataType> envi_type_from_string(std::string_view text);

enum class Interleave { bsq, bil, bip };
const char* interleave_name(Interleave interleave);  ///< "bsq", "bil", "bip"

enum class ByteOrder { little = 0, big = 1 };
/// Byte order of the machine glint runs on.
ByteOrder native_byte_order();

/// Everything an ENVI header says. Keys glint does not model are kept in `extra` in file
/// order (name lowercased, value verbatim, braces included for lists).
struct EnviHeader {
    std::string description;
    std::size_t samples = 0;
    std::size_t lines = 0;
    std::size_t bands = 0;
    std::uint64_t header_offset = 0;
    std::string file_type = "ENVI Standard";
    EnviDataType data_type = EnviDataType::float64;
    Interleave interleave = Interleave::bip;
    ByteOrder byte_order = native_byte_order();
    std::string wavelength_units;         ///< e.g. "Microns"; empty = not written
    std::vector<double> wavelength;       ///< per band, or empty
    std::vector<double> fwhm;             ///< per band, or empty
    std::vector<std::string> band_names;  ///< per band, or empty
    std::string data_units;               ///< e.g. "Watts/(cm2 sr)"; empty = not written
    std::vector<std::pair<std::string, std::string>> extra;

    /// Value of an extra key (exact lowercase name), if present.
    std::optional<std::string> find_extra(std::string_view key) const;
    /// Sets (replacing) an extra key.
    void set_extra(const std::string& key, const std::string& value);

    /// Bytes of one value.
    std::size_t value_bytes() const { return envi_type_size(data_type); }
    /// samples × lines × bands × value size; throws glint::Error (input) on 64-bit overflow.
    std::uint64_t data_bytes() const;
};

/// Throws glint::Error (input) naming `file` and the key when `header` cannot describe an
/// image: a zero size, an invalid data type, a 64-bit overflow of the data size (plus header
/// offset), a wavelength/fwhm/band names list whose length is not `bands`, or an extra key
/// that is empty, holds `=`, braces or a line break, or repeats a standard key.
void validate_envi_header(const EnviHeader& header, const std::string& file);

/// Parses header text. `file` names it in error messages, which carry the line number.
/// Validates before anything is allocated: `ENVI` magic, required keys (samples, lines,
/// bands, data type; interleave defaults to bsq and byte order to the native order when
/// absent, as ENVI does), known data type code, positive sizes, no 64-bit overflow, list
/// lengths equal to `bands`.
EnviHeader parse_envi_header(std::string_view text, const std::string& file);
/// The most bytes of a header glint reads: headers are a few kB (50 kB for 2,500 bands), so
/// anything far larger is not a header.
inline constexpr std::size_t kMaxEnviHeaderBytes = std::size_t{16} << 20;
/// Formats header text as described at the top of this file.
std::string format_envi_header(const EnviHeader& header);
/// Makes a band name safe for a brace list: `,` `{` `}` become `;` `(` `)`, newlines spaces.
std::string sanitize_band_name(std::string_view name);
/// A brace list for a header value, "{a, b, c}", each item made safe by sanitize_band_name.
std::string envi_brace_list(const std::vector<std::string>& items);
/// The items of a header value: `{a, b, c}` → "a", "b", "c" (each trimmed; `{}` gives none,
/// a value without braces is one item).
std::vector<std::string> envi_list_items(std::string_view value);

/// Header path for a data file: `<name>.hdr` beside it if that exists and `<data>.hdr`
/// does not, otherwise `<data>.hdr` (the glint and DIRSIG naming `x.img.hdr`).
std::filesystem::path envi_header_path_for(const std::filesystem::path& data_path);
/// Data path for a header or data path argument: `x.img.hdr` → `x.img`; `x.hdr` → `x`,
/// `x.img`, `x.dat`, `x.raw` or `x.bin`, whichever exists; a data path is returned as is.
std::filesystem::path envi_data_path_for(const std::filesystem::path& path);

/// Streams an ENVI file line by line. Any interleave and byte order; values are delivered
/// in BIP order (for each sample, all bands) and native byte order.
class EnviReader {
public:
    /// What the reader is opened for: reading lines (a line over `max_memory_bytes` /
    /// kLinesPerMaxMemory as doubles is refused, line_memory.h),
    /// or only describing the file (header and data size checked; no line may be read).
    enum class LineUse { read_lines, describe_only };

    /// Opens the data file (or its header), parses and validates the header and checks that
    /// the data file holds at least header offset + data bytes.
    explicit EnviReader(const std::filesystem::path& path, LineUse line_use = LineUse::read_lines,
                        std::size_t max_memory_bytes = kDefaultMaxMemoryBytes);
    ~EnviReader();
    EnviReader(EnviReader&&) noexcept;

    const EnviHeader& header() const { return m_header; }
    const std::filesystem::path& data_path() const { return m_data_path; }
    const std::filesystem::path& header_path() const { return m_header_path; }

    /// Line `y` as raw values of the file's type, BIP order, native byte order.
    /// `out` must hold samples × bands × value size bytes.
    void read_line_raw(std::size_t y, std::span<std::byte> out);
    /// Line `y` converted to double, BIP order; `out` holds samples × bands values.
    /// Complex values deliver their real part.
    void read_line(std::size_t y, std::span<double> out);

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
    EnviHeader m_header;
    std::filesystem::path m_data_path;
    std::filesystem::path m_header_path;
};

/// Writes an ENVI file line by line: `<path>` data and `<path>.hdr` header, BIP, native
/// byte order, no header offset (these fields of the given header are overridden).
/// Both files are written atomically; commit() publishes the data file, then the header.
/// Destroyed without commit(), it leaves nothing behind.
class EnviWriter {
public:
    EnviWriter(const std::filesystem::path& data_path, EnviHeader header);

    const EnviHeader& header() const { return m_header; }
    /// Appends the next line from raw values of the header's type (BIP, native order).
    void write_line_raw(std::span<const std::byte> line);
    /// Appends the next line from doubles (BIP), converting to the header's type: integers
    /// are rounded to nearest and clamped to the type's range, NaN becomes 0.
    void write_line(std::span<const double> line);
    /// Number of lines written so far.
    std::size_t lines_written() const { return m_lines_written; }
    /// Sets (replacing) an extra header key before commit(), for values known only at the
    /// end (e.g. capture times). Throws glint::Error (internal) after commit, (input) for a
    /// key or value the header cannot hold (validate_envi_header's rules).
    void set_extra(const std::string& key, const std::string& value);
    /// Checks that exactly `lines` lines were written, then publishes data and header.
    void commit();

private:
    EnviHeader m_header;
    AtomicFile m_data;
    std::filesystem::path m_header_path;
    std::size_t m_lines_written = 0;
    std::vector<std::byte> m_scratch;
};

/// Reads a whole file into memory as doubles in BIP order (samples × lines × bands).
/// For tests and small images; streaming code uses EnviReader.
std::vector<double> read_envi_bip(const std::filesystem::path& path, EnviHeader* header_out);

}  // namespace glint::io
