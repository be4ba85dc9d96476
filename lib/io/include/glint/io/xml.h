// SPDX-License-Identifier: Apache-2.0
// Reading DIRSIG's XML inputs: a loaded document and a read-only node view that knows its
// file, line and element path (e.g. "platform/attachment/mount[Belly]/attachment/
// instrument[Cam]/focalplane[RGB]/detectorarray/xelementcount"), plus value readers that
// parse fully, validate and report problems to a glint::Diagnostics instead of throwing, so
// that a reader can list every problem of a file.
//
// Conventions: text is trimmed (CDATA included); numbers must parse completely (no trailing
// junk, no NaN or infinity; a leading '+' is accepted); booleans are true/false/1/0/yes/no
// (any case). A missing optional child is not a problem; a missing required one is an
// error "missing required element <name>". Unknown children are reported once each as a
// warning by warn_unknown_children(). A document remembers which elements a reader looked
// into and which of their attributes it read; warn_unread() then reports each
// attribute nobody read (a misspelt `rolingreadout="true"` would otherwise just take the
// default).
#pragma once

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "glint/core/diagnostics.h"
#include "glint/core/error.h"

namespace tinyxml2 {
class XMLDocument;
class XMLElement;
}  // namespace tinyxml2

namespace glint::io {

class XmlNode;
struct XmlReadLog;

/// A parsed XML file. Malformed XML throws glint::Error(input) with the file and line; no
/// prolog is required. Nesting deeper than kMaxXmlDepth is refused.
class XmlDocument {
public:
    /// Parses the file at `path`; `display_name` (default: the path) names it in messages.
    static XmlDocument load(const std::filesystem::path& path, std::string display_name = {});
    /// Parses `text`; `display_name` names it in messages.
    static XmlDocument parse(std::string_view text, std::string display_name);

    XmlDocument(XmlDocument&&) noexcept;
    XmlDocument& operator=(XmlDocument&&) noexcept;
    ~XmlDocument();

    /// The root element; throws glint::Error(input) when its name is not `expected_name`
    /// (empty: any name).
    XmlNode root(std::string_view expected_name = {}) const;
    const std::string& display_name() const { return m_display_name; }

    /// What the readers skipped, one warning each. An attribute that no reader read, on the
    /// elements a reader looked into (asked for by name, or whose text, children or
    /// attributes it read): "attribute "x" is not read by glint here (ignored)"; `name` (it
    /// labels element paths) and XML namespace attributes (`xmlns…`, `xsi:…`) are never
    /// reported. And an element no reader looked into while one before it of the same name
    /// under the same parent was (a singular element given twice, the reader taking the
    /// first): "<x> given again (first at line N): this one is ignored". Elements no reader
    /// looked into otherwise (unknown ones, reported by warn_unknown_children, and those
    /// ignored whole) are not reported. Call it once, after reading the whole document.
    void warn_unread(Diagnostics& diagnostics) const;

private:
    XmlDocument();
    std::unique_ptr<tinyxml2::XMLDocument> m_doc;
    std::unique_ptr<XmlReadLog> m_read;
    std::string m_display_name;
};

/// Deepest element nesting accepted (DIRSIG files nest about 15 deep).
inline constexpr int kMaxXmlDepth = 64;

/// Inclusive/exclusive numeric bounds for value readers.
struct NumberRule {
    std::optional<double> min;
    std::optional<double> max;
    bool min_exclusive = false;
    bool max_exclusive = false;

    static NumberRule any() { return {}; }
    static NumberRule positive() { return {0.0, std::nullopt, true, false}; }
    static NumberRule non_negative() { return {0.0, std::nullopt, false, false}; }
    static NumberRule fraction() { return {0.0, 1.0, false, false}; }  ///< [0, 1]
    static NumberRule range(double lo, double hi) { return {lo, hi, false, false}; }
    /// Whether `value` obeys the rule; `expected` says what the rule wants (", expected > 0").
    bool accepts(double value) const;
    std::string describe() const;  ///< e.g. "a number > 0", "a number in [0, 1]"
};

/// A read-only view of one element of an XmlDocument (which must outlive it).
class XmlNode {
public:
    const std::string& name() const { return m_name; }
    /// Element path from the root, each step named `name[label]` when it has a name attribute.
    const std::string& path() const { return m_path; }
    int line() const;
    const std::string& file() const { return m_file; }
    /// file, line and path of this element, for messages.
    ErrorContext where() const;
    /// The same for an attribute of this element: path "…/element@attribute".
    ErrorContext where_attribute(std::string_view attribute) const;

    /// Trimmed text content (CDATA included); empty when none.
    std::string text() const;
    /// First child of that name, if any.
    std::optional<XmlNode> child(std::string_view name) const;
    /// Every child of that name, in document order.
    std::vector<XmlNode> children(std::string_view name) const;
    /// Every child element, in document order.
    std::vector<XmlNode> children() const;
    /// Attribute value (untrimmed), if present.
    std::optional<std::string> attribute(std::string_view name) const;

    /// One warning per child element whose name is not in `known`:
    /// "unknown element <name> ignored".
    void warn_unknown_children(std::initializer_list<std::string_view> known,
                               Diagnostics& diagnostics) const;

    // ---- value readers: child element text ----
    /// Text of child `name`; nullopt when absent.
    std::optional<std::string> optional_text(std::string_view name) const;
    /// Text of child `name`; error (and "") when absent.
    std::string required_text(std::string_view name, Diagnostics& diagnostics) const;
    /// Number in child `name` obeying `rule`; nullopt when absent or invalid (invalid: error).
    std::optional<double> optional_double(std::string_view name, Diagnostics& diagnostics,
                                          NumberRule rule = NumberRule::any()) const;
    /// As optional_double, but absence is an error too.
    std::optional<double> required_double(std::string_view name, Diagnostics& diagnostics,
                                          NumberRule rule = NumberRule::any()) const;
    /// Integer in child `name` within [min, max]; nullopt when absent or invalid.
    std::optional<std::int64_t> optional_int(std::string_view name, Diagnostics& diagnostics,
                                             std::int64_t min, std::int64_t max) const;
    std::optional<std::int64_t> required_int(std::string_view name, Diagnostics& diagnostics,
                                             std::int64_t min, std::int64_t max) const;
    /// Boolean in child `name`; nullopt when absent or invalid.
    std::optional<bool> optional_bool(std::string_view name, Diagnostics& diagnostics) const;
    /// Child text that must be one of `allowed` (compared case-insensitively; the result is
    /// the entry of `allowed`); nullopt when absent or invalid.
    std::optional<std::string> optional_enum(std::string_view name,
                                             std::initializer_list<std::string_view> allowed,
                                             Diagnostics& diagnostics) const;

    // ---- value readers: attributes ----
    std::optional<double> attribute_double(std::string_view name, Diagnostics& diagnostics,
                                           NumberRule rule = NumberRule::any()) const;
    std::optional<bool> attribute_bool(std::string_view name, Diagnostics& diagnostics) const;
    std::optional<std::string> attribute_enum(std::string_view name,
                                              std::initializer_list<std::string_view> allowed,
                                              Diagnostics& diagnostics) const;

    // ---- value readers: this element's own text ----
    std::optional<double> own_double(Diagnostics& diagnostics,
                                     NumberRule rule = NumberRule::any()) const;

private:
    friend class XmlDocument;
    XmlNode(const tinyxml2::XMLElement* element, std::string file, std::string path,
            XmlReadLog* read);
    XmlNode make_child(const tinyxml2::XMLElement* element) const;
    /// Records that a reader looked into this element (and read attribute `attribute`).
    void mark_visited() const;
    void mark_read(const char* attribute) const;

    const tinyxml2::XMLElement* m_element;
    XmlReadLog* m_read = nullptr;  ///< the document's (it outlives the node)
    std::string m_file;
    std::string m_path;
    std::string m_name;
};

}  // namespace glint::io
