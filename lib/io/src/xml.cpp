// SPDX-License-Identifier: Apache-2.0
// XmlDocument and XmlNode: loading and parsing DIRSIG XML with tinyxml2 (errors turned into
// glint::Error with file and line, nesting depth checked with an explicit stack before anyone
// walks the tree), and the node view that navigates children and knows its element path.
// The value readers (numbers, booleans, enums) live in xml_values.cpp.
#include "glint/io/xml.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <fstream>
#include <iterator>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "glint/io/input_files.h"

namespace glint::io {
namespace {

/// "mismatched element (element <b>)" from tinyxml2's error name and detail text.
std::string describe_tinyxml_error(const tinyxml2::XMLDocument& doc) {
    std::string name = doc.ErrorName() ? doc.ErrorName() : "XML_ERROR_PARSING";
    for (const char* prefix : {"XML_ERROR_", "XML_"}) {
        if (name.rfind(prefix, 0) == 0) {
            name.erase(0, std::char_traits<char>::length(prefix));
            break;
        }
    }
    for (char& c : name) {
        c = c == '_' ? ' ' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    // ErrorStr() reads "Error=XML_... ErrorID=14 (0xe) Line number=2: <detail>".
    const std::string full = doc.ErrorStr() ? doc.ErrorStr() : "";
    const std::size_t marker = full.find("Line number=");
    if (marker != std::string::npos) {
        const std::size_t colon = full.find(": ", marker);
        if (colon != std::string::npos) {
            std::string detail = full.substr(colon + 2);
            const std::string element_prefix = "XMLElement name=";
            if (detail.rfind(element_prefix, 0) == 0) {
                detail = "element <" + detail.substr(element_prefix.size()) + ">";
            }
            if (!detail.empty()) name += " (" + detail + ")";
        }
    }
    return name;
}

std::string depth_message() {
    return "elements nested deeper than " + std::to_string(kMaxXmlDepth) + " levels";
}

/// Walks the whole tree with an explicit stack and refuses nesting deeper than kMaxXmlDepth.
void check_depth(const tinyxml2::XMLElement* root, const std::string& file) {
    std::vector<std::pair<const tinyxml2::XMLElement*, int>> stack;
    stack.emplace_back(root, 1);
    while (!stack.empty()) {
        const auto [element, depth] = stack.back();
        stack.pop_back();
        if (depth > kMaxXmlDepth) {
            throw input_error(depth_message(), ErrorContext{file, element->GetLineNum(), {}});
        }
        for (const tinyxml2::XMLElement* child = element->FirstChildElement(); child;
             child = child->NextSiblingElement()) {
            stack.emplace_back(child, depth + 1);
        }
    }
}

/// One step of an element path: "name" or "name[label]" when it has a name attribute.
std::string path_step(const tinyxml2::XMLElement* element) {
    std::string step = element->Name();
    if (const char* label = element->Attribute("name")) {
        step += "[";
        step += label;
        step += "]";
    }
    return step;
}

}  // namespace

/// What the readers of a document looked into and read.
struct XmlReadLog {
    std::unordered_set<const tinyxml2::XMLElement*> visited;
    std::unordered_set<const tinyxml2::XMLAttribute*> read;
};

XmlDocument::XmlDocument()
    : m_doc(std::make_unique<tinyxml2::XMLDocument>()), m_read(std::make_unique<XmlReadLog>()) {}
XmlDocument::XmlDocument(XmlDocument&&) noexcept = default;
XmlDocument& XmlDocument::operator=(XmlDocument&&) noexcept = default;
XmlDocument::~XmlDocument() = default;

XmlDocument XmlDocument::load(const std::filesystem::path& path, std::string display_name) {
    if (display_name.empty()) display_name = path.string();
    const std::string text = read_input_file(path, display_name);
    return parse(text, std::move(display_name));
}

XmlDocument XmlDocument::parse(std::string_view text, std::string display_name) {
    XmlDocument document;
    document.m_display_name = std::move(display_name);
    tinyxml2::XMLDocument& doc = *document.m_doc;
    const tinyxml2::XMLError status = doc.Parse(text.data(), text.size());
    if (status == tinyxml2::XML_ELEMENT_DEPTH_EXCEEDED) {
        throw input_error(
            depth_message(),
            ErrorContext{document.m_display_name, std::max(1, doc.ErrorLineNum()), {}});
    }
    if (status != tinyxml2::XML_SUCCESS) {
        throw input_error(
            "malformed XML: " + describe_tinyxml_error(doc),
            ErrorContext{document.m_display_name, std::max(1, doc.ErrorLineNum()), {}});
    }
    const tinyxml2::XMLElement* root = doc.RootElement();
    if (root == nullptr) {
        throw input_error("malformed XML: no root element",
                          ErrorContext{document.m_display_name, 1, {}});
    }
    if (const tinyxml2::XMLElement* second = root->NextSiblingElement()) {
        throw input_error("malformed XML: a second root element <" + std::string(second->Name()) +
                              "> after <" + root->Name() + ">",
                          ErrorContext{document.m_display_name, second->GetLineNum(), {}});
    }
    check_depth(root, document.m_display_name);
    return document;
}

XmlNode XmlDocument::root(std::string_view expected_name) const {
    const tinyxml2::XMLElement* root = m_doc->RootElement();
    if (root == nullptr) {
        throw input_error("malformed XML: no root element", ErrorContext{m_display_name, 1, {}});
    }
    if (!expected_name.empty() && expected_name != root->Name()) {
        throw input_error("expected root element <" + std::string(expected_name) + ">, got <" +
                              root->Name() + ">",
                          ErrorContext{m_display_name, root->GetLineNum(), {}});
    }
    return XmlNode(root, m_display_name, path_step(root), m_read.get());
}

void XmlDocument::warn_unread(Diagnostics& diagnostics) const {
    const tinyxml2::XMLElement* root = m_doc->RootElement();
    if (root == nullptr) return;
    // Depth first in document order (the nesting is bounded by kMaxXmlDepth), each element
    // with its path; the walk itself marks nothing.
    std::vector<std::pair<const tinyxml2::XMLElement*, std::string>> stack{{root, path_step(root)}};
    while (!stack.empty()) {
        const auto [element, path] = stack.back();
        stack.pop_back();
        std::vector<std::pair<const tinyxml2::XMLElement*, std::string>> children;
        for (const tinyxml2::XMLElement* c = element->FirstChildElement(); c;
             c = c->NextSiblingElement()) {
            children.emplace_back(c, path + "/" + path_step(c));
        }
        stack.insert(stack.end(), children.rbegin(), children.rend());
        if (m_read->visited.count(element) == 0) {
            // A repeat of an element the reader took: the first of its name that it read.
            const tinyxml2::XMLElement* parent = element->Parent()->ToElement();
            if (parent == nullptr || m_read->visited.count(parent) == 0) continue;
            for (const tinyxml2::XMLElement* before =
                     element->PreviousSiblingElement(element->Name());
                 before; before = before->PreviousSiblingElement(element->Name())) {
                if (m_read->visited.count(before) == 0) continue;
                diagnostics.warning(
                    ErrorContext{m_display_name, element->GetLineNum(), path},
                    "<" + std::string(element->Name()) + "> given again (first at line " +
                        std::to_string(before->GetLineNum()) + "): this one is ignored");
                break;
            }
            continue;
        }
        for (const tinyxml2::XMLAttribute* a = element->FirstAttribute(); a; a = a->Next()) {
            const std::string_view name = a->Name();
            if (name == "name" || name.substr(0, 5) == "xmlns" || name.substr(0, 4) == "xsi:") {
                continue;
            }
            if (m_read->read.count(a) != 0) continue;
            diagnostics.warning(
                ErrorContext{m_display_name, element->GetLineNum(), path + "@" + std::string(name)},
                "attribute \"" + std::string(name) + "\" is not read by glint here (ignored)");
        }
    }
}

XmlNode::XmlNode(const tinyxml2::XMLElement* element, std::string file, std::string path,
                 XmlReadLog* read)
    : m_element(element),
      m_read(read),
      m_file(std::move(file)),
      m_path(std::move(path)),
      m_name(element->Name()) {}

XmlNode XmlNode::make_child(const tinyxml2::XMLElement* element) const {
    return XmlNode(element, m_file, m_path + "/" + path_step(element), m_read);
}

void XmlNode::mark_visited() const {
    if (m_read != nullptr) m_read->visited.insert(m_element);
}

void XmlNode::mark_read(const char* attribute) const {
    if (m_read == nullptr) return;
    m_read->visited.insert(m_element);
    if (const tinyxml2::XMLAttribute* a = m_element->FindAttribute(attribute)) {
        m_read->read.insert(a);
    }
}

int XmlNode::line() const { return m_element->GetLineNum(); }

ErrorContext XmlNode::where() const { return ErrorContext{m_file, line(), m_path}; }

ErrorContext XmlNode::where_attribute(std::string_view attribute) const {
    mark_read(std::string(attribute).c_str());
    return ErrorContext{m_file, line(), m_path + "@" + std::string(attribute)};
}

std::string XmlNode::text() const {
    mark_visited();
    std::string out;
    for (const tinyxml2::XMLNode* node = m_element->FirstChild(); node;
         node = node->NextSibling()) {
        if (const tinyxml2::XMLText* text = node->ToText()) {
            if (const char* value = text->Value()) out += value;
        }
    }
    const auto blank = [](char c) {
        return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
    };
    std::size_t first = 0;
    std::size_t last = out.size();
    while (first < last && blank(out[first])) ++first;
    while (last > first && blank(out[last - 1])) --last;
    return out.substr(first, last - first);
}

std::optional<XmlNode> XmlNode::child(std::string_view name) const {
    mark_visited();
    const std::string key(name);
    if (const tinyxml2::XMLElement* element = m_element->FirstChildElement(key.c_str())) {
        XmlNode node = make_child(element);
        node.mark_visited();
        return node;
    }
    return std::nullopt;
}

std::vector<XmlNode> XmlNode::children(std::string_view name) const {
    mark_visited();
    const std::string key(name);
    std::vector<XmlNode> out;
    for (const tinyxml2::XMLElement* element = m_element->FirstChildElement(key.c_str()); element;
         element = element->NextSiblingElement(key.c_str())) {
        out.push_back(make_child(element));
        out.back().mark_visited();
    }
    return out;
}

std::vector<XmlNode> XmlNode::children() const {
    mark_visited();
    std::vector<XmlNode> out;
    for (const tinyxml2::XMLElement* element = m_element->FirstChildElement(); element;
         element = element->NextSiblingElement()) {
        out.push_back(make_child(element));
    }
    return out;
}

std::optional<std::string> XmlNode::attribute(std::string_view name) const {
    const std::string key(name);
    mark_read(key.c_str());
    if (const char* value = m_element->Attribute(key.c_str())) return std::string(value);
    return std::nullopt;
}

void XmlNode::warn_unknown_children(std::initializer_list<std::string_view> known,
                                    Diagnostics& diagnostics) const {
    for (const tinyxml2::XMLElement* element = m_element->FirstChildElement(); element;
         element = element->NextSiblingElement()) {
        const std::string_view name = element->Name();
        if (std::find(known.begin(), known.end(), name) != known.end()) continue;
        const XmlNode node = make_child(element);
        diagnostics.warning(node.where(), "unknown element <" + node.name() + "> ignored");
    }
}

std::optional<std::string> XmlNode::optional_text(std::string_view name) const {
    if (const auto node = child(name)) return node->text();
    return std::nullopt;
}

std::string XmlNode::required_text(std::string_view name, Diagnostics& diagnostics) const {
    if (const auto node = child(name)) return node->text();
    diagnostics.error(where(), "missing required element <" + std::string(name) + ">");
    return {};
}

}  // namespace glint::io
