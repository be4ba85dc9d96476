// SPDX-License-Identifier: Apache-2.0
// Tests of what an output name part (prefix, basename, extension) may hold.
#include "glint/model/output_name.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>

namespace glint::test {
namespace output_name_test {

TEST(OutputName, PlainNamesPass) {
    for (const char* name : {"", "frame", "run1_", "img", "a.b", "caf\xC3\xA9", "x-1 (copy)"}) {
        EXPECT_FALSE(model::output_name_problem(name).has_value()) << name;
    }
}

TEST(OutputName, SeparatorsParentsAndControlCharactersAreRefused) {
    const std::pair<std::string, std::string> cases[] = {
        {"../../escaped", "contains '/'"},
        {"/etc/passwd", "contains '/'"},
        {"img/../../x", "contains '/'"},
        {"a\\b", "contains '\\'"},
        {"..", "contains '..'"},
        {"x..y", "contains '..'"},
        {"x\ty", "control character 0x09"},
        {std::string("x\0y", 3), "control character 0x00"},
        {"x\x7F", "control character 0x7F"},
    };
    for (const auto& [name, message] : cases) {
        const auto problem = model::output_name_problem(name);
        ASSERT_TRUE(problem.has_value()) << name;
        EXPECT_NE(problem->find(message), std::string::npos) << *problem;
    }
}

}  // namespace output_name_test
}  // namespace glint::test
