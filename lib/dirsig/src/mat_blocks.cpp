// SPDX-License-Identifier: Apache-2.0
// The block structure of a `.mat` text (mat_blocks.h).
#include "mat_blocks.h"

#include <cctype>
#include <optional>
#include <sstream>

namespace glint::dirsig::detail {

std::string trim(std::string_view text) {
    std::size_t begin = 0;
    std::size_t end = text.size();
    while (begin < end && std::isspace(static_cast<unsigned char>(text[begin]))) ++begin;
    while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
    return std::string(text.substr(begin, end - begin));
}

std::string to_upper(std::string text) {
    for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

MatBlock parse_blocks(const std::string& text, const std::string& file, Diagnostics& diagnostics) {
    MatBlock root;
    std::vector<MatBlock*> stack{&root};
    std::optional<MatEntry> pending;  // a bare name waiting for its "{"
    std::istringstream lines(text);
    std::string raw;
    int number = 0;
    const auto flush_pending = [&] {
        if (pending) {
            diagnostics.error({file, pending->line, pending->key},
                              "expected \"KEY = value\" or \"NAME {\"");
            pending.reset();
        }
    };
    while (std::getline(lines, raw)) {
        ++number;
        // A comment is a line whose first non-blank character is '#'; elsewhere '#' is text
        // ("NAME = Class #2").
        const std::string content = trim(raw).starts_with('#') ? std::string() : raw;
        // One-line blocks ("NAME { KEY = value }") are split into "NAME {", "KEY = value", "}".
        std::vector<std::string> pieces;
        std::string piece;
        for (const char c : content) {
            if (c == '}') {
                pieces.push_back(trim(piece));
                pieces.emplace_back("}");
                piece.clear();
            } else {
                piece += c;
                if (c == '{') {
                    pieces.push_back(trim(piece));
                    piece.clear();
                }
            }
        }
        pieces.push_back(trim(piece));
        for (const std::string& line : pieces) {
            if (line.empty()) continue;
            if (line == "}") {
                flush_pending();
                if (stack.size() == 1) {
                    diagnostics.error({file, number, {}}, "unmatched \"}\"");
                } else {
                    stack.pop_back();
                }
                continue;
            }
            if (line.back() == '{') {
                std::string name = to_upper(trim(line.substr(0, line.size() - 1)));
                int at = number;
                if (name.empty() && pending) {
                    name = pending->key;
                    at = pending->line;
                } else {
                    flush_pending();
                }
                pending.reset();
                if (name.empty()) {
                    diagnostics.error({file, number, {}}, "block \"{\" without a name");
                    name = "?";
                }
                stack.back()->blocks.push_back(MatBlock{name, at, {}, {}});
                stack.push_back(&stack.back()->blocks.back());
                continue;
            }
            flush_pending();
            const std::size_t eq = line.find('=');
            if (eq == std::string::npos) {
                pending = MatEntry{to_upper(line), {}, number};
                continue;
            }
            stack.back()->entries.push_back(
                MatEntry{to_upper(trim(line.substr(0, eq))), trim(line.substr(eq + 1)), number});
        }
    }
    flush_pending();
    if (stack.size() > 1) {
        diagnostics.error({file, stack.back()->line, stack.back()->name},
                          "block is not closed by \"}\"");
    }
    return root;
}

}  // namespace glint::dirsig::detail
