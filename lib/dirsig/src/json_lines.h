// SPDX-License-Identifier: Apache-2.0
// A JSON text read with the line of every value (private to lib/dirsig; the .jsim reader's):
// a first, SAX pass over the text records the line of every value and object key as a tree
// of nodes (memory linear in the text) and refuses nesting deeper than kMaxJsonDepth before
// the document is built; then the document is parsed. Problems name the line, and the column
// of malformed JSON.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>

#include "glint/core/diagnostics.h"

namespace glint::dirsig::detail {

using Json = nlohmann::json;

/// JSON deeper than this is refused before it is parsed (a .jsim nests about 6 levels; each
/// level costs the parsers memory and time).
inline constexpr std::size_t kMaxJsonDepth = 64;

/// The JSON path of member `key` of `parent` ("a.b"; the key alone at the root).
std::string key_path(const std::string& parent, const std::string& key);
/// The JSON path of element `index` of `parent` ("a[3]").
std::string index_path(const std::string& parent, std::size_t index);
/// `text` cut to at most 200 bytes for a message (a JSON path or a parser's description can
/// hold a whole megabyte key or a 5000-digit number), valid UTF-8.
std::string shorten(std::string_view text);

/// The line of every value and object key of a JSON text, looked up by JSON path
/// ("[0].plugin_list[1].inputs.platform_filename"). Each value is one node named by its
/// parent and its key or index, never by its whole path, so memory is linear in the text.
class LineTable {
public:
    using Node = std::uint32_t;
    static constexpr Node kNone = 0;  ///< the parent of the root value

    /// Records a value at `line`: the root (parent kNone), an object member (`key`) or an
    /// array element (`index`). The first of duplicate keys is kept.
    Node add(Node parent, bool is_index, std::string_view name, int line) {
        const Node node = ++m_count;
        m_nodes.emplace(child_key(parent, is_index, name), std::pair<Node, int>{node, line});
        return node;
    }

    /// Line of `path`; a path not in the text (a missing key) gets the line of its deepest
    /// ancestor that is, 1 when none is.
    int line_of(std::string_view path) const {
        auto found = m_nodes.find(child_key(kNone, false, {}));  // the root value
        if (found == m_nodes.end()) return 1;
        int line = found->second.second;
        std::size_t at = 0;
        while (at < path.size()) {  // steps: "[index]", ".key", or a key at the start
            const bool is_index = path[at] == '[';
            const std::size_t begin = at + (is_index || path[at] == '.' ? 1 : 0);
            const std::size_t end = is_index
                                        ? path.find(']', begin)
                                        : std::min(path.find_first_of(".[", begin), path.size());
            if (end == std::string_view::npos) break;
            found = m_nodes.find(
                child_key(found->second.first, is_index, path.substr(begin, end - begin)));
            if (found == m_nodes.end()) break;
            line = found->second.second;
            at = end + (is_index ? 1 : 0);
        }
        return line;
    }

private:
    static std::string child_key(Node parent, bool is_index, std::string_view name) {
        std::string key(sizeof parent + 1 + name.size(), '\0');
        std::copy_n(reinterpret_cast<const char*>(&parent), sizeof parent, key.begin());
        key[sizeof parent] = is_index ? 'i' : 'k';
        std::copy(name.begin(), name.end(), key.begin() + sizeof parent + 1);
        return key;
    }

    std::unordered_map<std::string, std::pair<Node, int>> m_nodes;
    Node m_count = 0;
};

/// A JSON document and the line of each of its values.
struct LinedJson {
    Json document;
    LineTable lines;
};

/// `text` (named `name` in messages) parsed with its lines; nullopt after one error in
/// `diagnostics`: nesting deeper than kMaxJsonDepth (at the bracket's line) or malformed JSON
/// (at its line and column).
std::optional<LinedJson> parse_lined_json(const std::string& text, const std::string& name,
                                          Diagnostics& diagnostics);

}  // namespace glint::dirsig::detail
