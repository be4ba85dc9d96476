// SPDX-License-Identifier: Apache-2.0
// Reader of DIRSIG5 `.jsim` files: a JSON array of simulation objects (scene_list,
// plugin_list, medium_list). BasicPlatform and BasicAtmosphere inputs are read into the model
// with their paths resolved against the .jsim's folder; other plugins and medium_list are kept
// verbatim. Problems name the JSON path ("[0].plugin_list[1].inputs.platform_filename") and
// its line, which a first, SAX pass over the text records for every value (as a tree of
// nodes, so memory stays linear in the text) while refusing nesting deeper than 64 levels.
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string_view>
#include <unordered_map>
#include <utility>

#include "glint/core/text.h"
#include "glint/dirsig/readers.h"
#include "glint/io/xml.h"
#include "glint/model/output_name.h"
#include "jsim_keys.h"

namespace glint::dirsig {
namespace {

using Json = nlohmann::json;

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

/// JSON deeper than this is refused before it is parsed (a .jsim nests about 6 levels; each
/// level costs the parsers memory and time).
constexpr std::size_t kMaxJsonDepth = 64;

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

/// What the reading functions share: where messages point and where paths resolve from.
class JsimReader {
public:
    JsimReader(std::string file, LineTable lines, std::filesystem::path base_dir,
               const ReadOptions& options, Diagnostics& diagnostics)
        : m_file(std::move(file)),
          m_lines(std::move(lines)),
          m_base_dir(std::move(base_dir)),
          m_options(options),
          m_diagnostics(diagnostics) {}

    model::Simulation read_simulation(const Json& value, const std::string& path) const;

private:
    ErrorContext at(const std::string& path) const {
        // A path that is not in the text (a missing key) is placed at its parent's line.
        return ErrorContext{m_file, m_lines.line_of(path), shorten(path)};
    }

    static std::string describe(const Json& value) {
        std::string out = value.type_name();
        if (value.is_primitive()) {
            std::string text = value.dump();
            if (text.size() > 64) text = to_valid_utf8(text.substr(0, 64)) + "...";
            out += " " + text;
        }
        return out;
    }

    void wrong_type(const std::string& path, const char* expected, const Json& value) const {
        m_diagnostics.error(at(path),
                            std::string("expected ") + expected + ", got " + describe(value));
    }

    void warn_unknown_keys(const Json& object, const std::string& path,
                           std::initializer_list<std::string_view> known,
                           const std::string& what) const {
        for (const auto& [key, value] : object.items()) {
            if (std::find(known.begin(), known.end(), key) != known.end()) continue;
            m_diagnostics.warning(at(key_path(path, key)),
                                  "unknown key " + quote(key) + what + " ignored");
        }
    }

    /// The string at `object[key]`; nullopt (and an error when `required` or mistyped)
    /// otherwise.
    std::optional<std::string> string_at(const Json& object, const std::string& path,
                                         const char* key, bool required) const {
        const auto it = object.find(key);
        if (it == object.end()) {
            if (required) {
                m_diagnostics.error(at(path), std::string("missing required key \"") + key + "\"");
            }
            return std::nullopt;
        }
        if (!it->is_string()) {
            wrong_type(key_path(path, key), "a string", *it);
            return std::nullopt;
        }
        return it->get<std::string>();
    }

    /// A required path-valued string resolved against the .jsim's folder.
    model::FileRef file_at(const Json& object, const std::string& path, const char* key) const {
        const std::optional<std::string> text = string_at(object, path, key, true);
        if (!text) return {};
        return m_options.paths.resolve(*text, m_base_dir, at(key_path(path, key)), m_diagnostics);
    }

    void read_scenes(const Json& list, const std::string& path, model::Simulation& out) const;
    model::Plugin read_plugin(const Json& value, const std::string& path) const;
    model::BasicPlatformInputs read_basic_platform(const Json& inputs,
                                                   const std::string& path) const;

    std::string m_file;
    LineTable m_lines;
    std::filesystem::path m_base_dir;
    const ReadOptions& m_options;
    Diagnostics& m_diagnostics;
};

model::Simulation JsimReader::read_simulation(const Json& value, const std::string& path) const {
    model::Simulation simulation;
    simulation.file = m_file;
    if (!value.is_object()) {
        wrong_type(path, "a simulation object", value);
        return simulation;
    }
    warn_unknown_keys(value, path, {"scene_list", "plugin_list", "medium_list"}, "");

    if (const auto it = value.find("scene_list"); it != value.end()) {
        read_scenes(*it, key_path(path, "scene_list"), simulation);
    }

    const std::string plugins_path = key_path(path, "plugin_list");
    if (const auto it = value.find("plugin_list"); it == value.end()) {
        m_diagnostics.error(at(path), "missing required key \"plugin_list\"");
    } else if (!it->is_array()) {
        wrong_type(plugins_path, "an array of plugins", *it);
    } else {
        for (std::size_t i = 0; i < it->size(); ++i) {
            simulation.plugins.push_back(read_plugin((*it)[i], index_path(plugins_path, i)));
        }
    }
    // One warning per plugin glint does not run, saying what it does instead (known once
    // every plugin is read: an atmosphere plugin beside a BasicAtmosphere changes nothing).
    const bool has_basic_atmosphere = simulation.atmosphere() != nullptr;
    for (const model::Plugin& plugin : simulation.plugins) {
        if (plugin.basic_platform || plugin.basic_atmosphere || plugin.name.empty()) continue;
        m_diagnostics.warning(plugin.where,
                              "plugin \"" + plugin.name +
                                  "\" is read, not applied: glint runs BasicPlatform and "
                                  "BasicAtmosphere only; instead " +
                                  unsupported_plugin_fallback(plugin.name, has_basic_atmosphere) +
                                  " (the plugin is kept when the .jsim is rewritten)");
    }

    if (const auto it = value.find("medium_list"); it != value.end()) {
        if (it->is_array()) {
            simulation.medium_list_json = it->dump();
            if (!it->empty()) {
                m_diagnostics.warning(at(key_path(path, "medium_list")),
                                      "medium_list is read, not applied: glint models no "
                                      "participating media (kept when the .jsim is rewritten)");
            }
        } else {
            wrong_type(key_path(path, "medium_list"), "an array", *it);
        }
    }
    return simulation;
}

void JsimReader::read_scenes(const Json& list, const std::string& path,
                             model::Simulation& out) const {
    if (!list.is_array()) {
        wrong_type(path, "an array of scenes", list);
        return;
    }
    for (std::size_t i = 0; i < list.size(); ++i) {
        const Json& entry = list[i];
        const std::string entry_path = index_path(path, i);
        if (!entry.is_object()) {
            wrong_type(entry_path, "a scene object", entry);
            continue;
        }
        warn_unknown_keys(entry, entry_path, {"inputs", "offset"}, " in a scene_list entry");
        model::SceneEntry scene;
        scene.file = file_at(entry, entry_path, "inputs");
        scene.offset = string_at(entry, entry_path, "offset", false).value_or("");
        if (entry.contains("offset")) scene.offset_where = at(key_path(entry_path, "offset"));
        out.scenes.push_back(std::move(scene));
    }
}

model::Plugin JsimReader::read_plugin(const Json& value, const std::string& path) const {
    model::Plugin plugin;
    plugin.where = at(path);
    plugin.inputs_json = "{}";
    if (!value.is_object()) {
        wrong_type(path, "a plugin object", value);
        return plugin;
    }
    warn_unknown_keys(value, path, {"name", "inputs"}, " in a plugin_list entry");
    plugin.name = string_at(value, path, "name", true).value_or("");

    const std::string inputs_path = key_path(path, "inputs");
    Json inputs = Json::object();
    if (const auto it = value.find("inputs"); it != value.end()) {
        if (it->is_object()) {
            inputs = *it;
        } else {
            wrong_type(inputs_path, "an object", *it);
        }
    }
    plugin.inputs_json = inputs.dump();

    if (plugin.name == kBasicPlatform) {
        plugin.basic_platform = read_basic_platform(inputs, inputs_path);
    } else if (plugin.name == kBasicAtmosphere) {
        warn_unknown_keys(inputs, inputs_path, {kAtmosphereFilename}, " in BasicAtmosphere inputs");
        plugin.basic_atmosphere =
            model::BasicAtmosphereInputs{file_at(inputs, inputs_path, kAtmosphereFilename)};
    }
    return plugin;
}

model::BasicPlatformInputs JsimReader::read_basic_platform(const Json& inputs,
                                                           const std::string& path) const {
    warn_unknown_keys(inputs, path,
                      {kPlatformFilename, kMotionFilename, kTasksFilename, kOutputFolder,
                       kOutputPrefix, kSplitChannels},
                      " in BasicPlatform inputs");
    model::BasicPlatformInputs out;
    out.platform_file = file_at(inputs, path, kPlatformFilename);
    out.motion_file = file_at(inputs, path, kMotionFilename);
    out.tasks_file = file_at(inputs, path, kTasksFilename);
    out.output_folder = string_at(inputs, path, kOutputFolder, false);
    out.output_prefix = string_at(inputs, path, kOutputPrefix, false);
    if (out.output_prefix) {
        if (const auto problem = model::output_name_problem(*out.output_prefix)) {
            m_diagnostics.error(at(key_path(path, kOutputPrefix)),
                                "output_prefix " + quote(*out.output_prefix) + " " + *problem);
            out.output_prefix.reset();
        }
    }
    if (const auto it = inputs.find(kSplitChannels); it != inputs.end()) {
        std::optional<bool> value;
        if (it->is_boolean()) {
            value = it->get<bool>();
        } else if (it->is_string()) {
            std::string text = it->get<std::string>();
            for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            if (text == "true") value = true;
            if (text == "false") value = false;
        }
        if (value) {
            out.split_channels = *value;
        } else {
            wrong_type(key_path(path, kSplitChannels), "true or false", *it);
        }
    }
    return out;
}

}  // namespace

PluginKind plugin_kind(std::string_view name) {
    if (name == kBasicPlatform) return PluginKind::basic_platform;
    if (name == kBasicAtmosphere) return PluginKind::basic_atmosphere;
    const std::string lower = to_lower(std::string(name));
    const auto has = [&](std::string_view word) { return lower.find(word) != std::string::npos; };
    if (has("atmosphere")) return PluginKind::atmosphere;
    if (has("ephemeris")) return PluginKind::ephemeris;
    if (has("weather") || has("therm") || has("temperature")) return PluginKind::thermal;
    return PluginKind::other;
}

std::string unsupported_plugin_fallback(std::string_view name, bool has_basic_atmosphere) {
    switch (plugin_kind(name)) {
        case PluginKind::atmosphere:
            return has_basic_atmosphere
                       ? std::string("glint uses the BasicAtmosphere entry's atmosphere")
                       : std::string(
                             "glint uses its default parametric atmosphere (glint-render "
                             "--atmosphere none|parametric|FILE picks another)");
        case PluginKind::ephemeris:
            return "glint computes the sun and moon positions itself from the tasks' times and "
                   "the scene origin (NREL SPA, ELP 2000)";
        case PluginKind::thermal:
            return "glint uses each material's own temperature (no weather, no thermal model)";
        case PluginKind::basic_platform:
        case PluginKind::basic_atmosphere:
        case PluginKind::other:
            break;
    }
    return "it has no effect on the run";
}

std::vector<model::Simulation> read_jsim(const std::filesystem::path& file,
                                         const ReadOptions& options, Diagnostics& diagnostics) {
    const std::string name = file.string();
    std::string text;
    try {
        text = options.read_text(file, name);
    } catch (const Error& error) {
        diagnostics.add(error);
        return {};
    }
    const LineIndex index(text);

    // The line pass comes first: it refuses deep nesting before the document is built.
    std::size_t consumed = 0;
    LineRecorder recorder(text, index, consumed);
    Json::sax_parse(CountingIterator(text.data(), text.data(), &consumed),
                    CountingIterator(text.data(), text.data() + text.size(), &consumed), &recorder);
    if (recorder.too_deep_line() > 0) {
        diagnostics.error(ErrorContext{name, recorder.too_deep_line(), {}},
                          "JSON nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels");
        return {};
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
        return {};
    }

    const JsimReader reader(name, recorder.take_lines(), file.parent_path(), options, diagnostics);
    std::vector<model::Simulation> simulations;
    if (document.is_object()) {
        simulations.push_back(reader.read_simulation(document, ""));
    } else if (!document.is_array()) {
        diagnostics.error(
            ErrorContext{name, 1, {}},
            std::string("expected an array of simulation objects, got ") + document.type_name());
    } else if (document.empty()) {
        diagnostics.error(ErrorContext{name, 1, {}},
                          "expected at least one simulation object, got an empty array");
    } else {
        for (std::size_t i = 0; i < document.size(); ++i) {
            simulations.push_back(reader.read_simulation(document[i], index_path("", i)));
        }
    }
    return simulations;
}

}  // namespace glint::dirsig
