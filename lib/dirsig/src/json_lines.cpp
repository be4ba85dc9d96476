// SPDX-License-Identifier: Apache-2.0
// A JSON text read with the line of every value (json_lines.h).
#include "json_lines.h"

#include <cctype>
#include <iterator>
#include <vector>

#include "glint/core/text.h"

namespace glint::dirsig::detail {
namespace {

/// Line numbers of byte offsets in a text.
class LineIndex {
public:
    explicit LineIndex(const std::string& text) {
        for (std::size_t i = 0; i < text.size(); ++i) {
            if (text[i] == '\n') m_newlines.push_back(i);
        }
    }
    /// 1-based line of the byte at `offset`.
    int line_of(std::size_t offset) const {
        const auto before = std::lower_bound(m_newlines.begin(), m_newlines.end(), offset);
        return static_cast<int>(before - m_newlines.begin()) + 1;
    }
    /// 1-based column of the byte at `offset`.
    std::size_t column_of(std::size_t offset) const {
        const auto before = std::lower_bound(m_newlines.begin(), m_newlines.end(), offset);
        if (before == m_newlines.begin()) return offset + 1;
        return offset - *std::prev(before);
    }

private:
    std::vector<std::size_t> m_newlines;
};

/// A char iterator that publishes how many bytes the parser has consumed, so that SAX events
/// can be placed in the text (nlohmann's SAX interface gives no positions).
class CountingIterator {
public:
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;

    CountingIterator(const char* base, const char* at, std::size_t* consumed)
        : m_base(base), m_at(at), m_consumed(consumed) {}
    reference operator*() const { return *m_at; }
    CountingIterator& operator++() {
        ++m_at;
        *m_consumed = static_cast<std::size_t>(m_at - m_base);
        return *this;
    }
    CountingIterator operator++(int) {
        CountingIterator before = *this;
        ++*this;
        return before;
    }
    bool operator==(const CountingIterator& other) const { return m_at == other.m_at; }
    bool operator!=(const CountingIterator& other) const { return m_at != other.m_at; }

private:
    const char* m_base;
    const char* m_at;
    std::size_t* m_consumed;
};

/// SAX handler recording the line of every value (and object key) in a LineTable; stops the
/// parse at nesting deeper than kMaxJsonDepth.
class LineRecorder : public nlohmann::json_sax<Json> {
public:
    LineRecorder(const std::string& text, const LineIndex& index, const std::size_t& consumed)
        : m_text(text), m_index(index), m_consumed(consumed) {}

    LineTable take_lines() { return std::move(m_lines); }
    /// The line of the bracket that went deeper than kMaxJsonDepth, 0 when none did.
    int too_deep_line() const { return m_too_deep_line; }

    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override { return open(false); }
    bool start_array(std::size_t) override { return open(true); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }
    bool key(string_t& key) override {
        if (!m_stack.empty()) m_stack.back().key = key;
        return true;
    }
    bool parse_error(std::size_t byte, const std::string&,
                     const nlohmann::detail::exception&) override {
        m_error_byte = byte;
        return false;
    }
    /// Where the pass stopped at malformed JSON (1-based byte), 0 when it did not.
    std::size_t error_byte() const { return m_error_byte; }

private:
    struct Frame {
        LineTable::Node node = LineTable::kNone;
        bool is_array = false;
        std::size_t next_index = 0;
        std::string key;
    };

    /// Line of the last character the parser consumed that is not blank (a number's
    /// terminating character is read ahead, possibly a newline).
    int current_line() const {
        std::size_t at = std::min(m_consumed, m_text.size());
        while (at > 0 && std::isspace(static_cast<unsigned char>(m_text[at - 1]))) --at;
        return m_index.line_of(at > 0 ? at - 1 : 0);
    }

    LineTable::Node add_next() {
        if (m_stack.empty()) return m_lines.add(LineTable::kNone, false, {}, current_line());
        Frame& top = m_stack.back();
        if (top.is_array) {
            return m_lines.add(top.node, true, std::to_string(top.next_index++), current_line());
        }
        return m_lines.add(top.node, false, top.key, current_line());
    }

    bool value() {
        add_next();
        return true;
    }
    bool open(bool is_array) {
        if (m_stack.size() >= kMaxJsonDepth) {
            m_too_deep_line = current_line();
            return false;
        }
        const LineTable::Node node = add_next();
        m_stack.push_back(Frame{node, is_array, 0, {}});
        return true;
    }
    bool close() {
        if (!m_stack.empty()) m_stack.pop_back();
        return true;
    }

    const std::string& m_text;
    const LineIndex& m_index;
    const std::size_t& m_consumed;
    std::vector<Frame> m_stack;
    LineTable m_lines;
    int m_too_deep_line = 0;
    std::size_t m_error_byte = 0;
};

}  // namespace

std::string key_path(const std::string& parent, const std::string& key) {
    return parent.empty() ? key : parent + "." + key;
}

/// `text` cut to at most 200 bytes for a message (a JSON path or a parser's description can
/// hold a whole megabyte key or a 5000-digit number), valid UTF-8.
std::string shorten(std::string_view text) {
    constexpr std::size_t kMaxBytes = 200;
    if (text.size() <= kMaxBytes) return to_valid_utf8(text);
    return to_valid_utf8(text.substr(0, kMaxBytes)) + "...";
}

std::string index_path(const std::string& parent, std::size_t index) {
    return parent + "[" + std::to_string(index) + "]";
}

std::optional<LinedJson> parse_lined_json(const std::string& text, const std::string& name,
                                          Diagnostics& diagnostics) {
    const LineIndex index(text);

    // The line pass comes first: it refuses deep nesting before the document is built.
    std::size_t consumed = 0;
    LineRecorder recorder(text, index, consumed);
    Json::sax_parse(CountingIterator(text.data(), text.data(), &consumed),
                    CountingIterator(text.data(), text.data() + text.size(), &consumed), &recorder);
    if (recorder.too_deep_line() > 0) {
        diagnostics.error(ErrorContext{name, recorder.too_deep_line(), {}},
                          "JSON nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels");
        return std::nullopt;
    }

    Json document;
    try {
        document = Json::parse(text);
    } catch (const Json::exception& error) {
        // A syntax error carries its byte; any other (406: a number too large for a double)
        // is placed where the line pass stopped. `byte` is 1-based: text[byte - 1].
        const auto* syntax = dynamic_cast<const Json::parse_error*>(&error);
        const std::size_t byte = syntax ? syntax->byte : recorder.error_byte();
        const std::size_t offset = byte > 0 ? byte - 1 : 0;
        std::string description = error.what();
        if (const std::size_t bracket = description.find("] "); bracket != std::string::npos) {
            description.erase(0, bracket + 2);  // drop "[json.exception...] "
        }
        if (const std::size_t colon = description.find(": ");
            syntax && colon != std::string::npos) {
            description.erase(0, colon + 2);  // drop "parse error at line 4, column 30"
        }
        description = shorten(description);
        diagnostics.error(ErrorContext{name, index.line_of(offset), {}},
                          "malformed JSON at column " + std::to_string(index.column_of(offset)) +
                              ": " + description);
        return std::nullopt;
    }

    return LinedJson{std::move(document), recorder.take_lines()};
}

}  // namespace glint::dirsig::detail
