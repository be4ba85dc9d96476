// SPDX-License-Identifier: Apache-2.0
// Internal: a window over a sequence of lines made in increasing order (mosaic lines read from
// a file, pan lines, filtered lines). A line is made when first asked for, with every line
// before it not made yet, and kept until drop_below() passes it; dropped lines' buffers are
// reused, so a window that slides down an image allocates only its first few lines.
#pragma once

#include <cstddef>
#include <deque>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "glint/core/error.h"

namespace glint::demosaic::internal {

template <typename Line>
class LineWindow {
public:
    /// Fills `line` (a spare buffer, possibly holding an older line) with line `y`.
    using Make = std::function<void(std::size_t y, Line& line)>;

    explicit LineWindow(Make make) : m_make(std::move(make)) {}

    /// Line `y`; references stay valid until the line is dropped.
    const Line& at(std::size_t y) {
        if (y < m_first) {
            throw internal_error("demosaic line window: line " + std::to_string(y) +
                                 " was dropped (first held: " + std::to_string(m_first) + ")");
        }
        while (m_first + m_lines.size() <= y) {
            Line line;
            if (!m_spare.empty()) {
                line = std::move(m_spare.back());
                m_spare.pop_back();
            }
            m_make(m_first + m_lines.size(), line);
            m_lines.push_back(std::move(line));
        }
        return m_lines[y - m_first];
    }

    /// Forgets the lines held before line `y`.
    void drop_below(std::size_t y) {
        while (m_first < y && !m_lines.empty()) {
            m_spare.push_back(std::move(m_lines.front()));
            m_lines.pop_front();
            ++m_first;
        }
    }

    /// Lines held, spare buffers included.
    std::size_t buffers() const { return m_lines.size() + m_spare.size(); }

private:
    Make m_make;
    std::deque<Line> m_lines;  ///< lines m_first, m_first + 1, ...
    std::size_t m_first = 0;
    std::vector<Line> m_spare;
};

}  // namespace glint::demosaic::internal
