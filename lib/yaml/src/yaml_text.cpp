// SPDX-License-Identifier: Apache-2.0
// Parsing YAML text with its problems at file:line (yaml_text.h).
#include "yaml_text.h"

namespace glint::yaml::detail {
namespace {

int line_of(const YAML::Mark& mark) { return mark.line >= 0 ? mark.line + 1 : 0; }

}  // namespace

std::optional<YAML::Node> parse_yaml(const std::string& text, const std::string& file,
                                     Diagnostics& diagnostics) {
    try {
        return YAML::Load(text);
    } catch (const YAML::DeepRecursion& error) {
        // yaml-cpp's own message for this is "bad file".
        diagnostics.error(ErrorContext{file, line_of(error.mark), {}},
                          "invalid YAML: nested deeper than " + std::to_string(kMaxYamlDepth) +
                              " levels, expected a document a few levels deep");
    } catch (const YAML::Exception& error) {
        diagnostics.error(ErrorContext{file, line_of(error.mark), {}},
                          "invalid YAML: " + error.msg);
    }
    return std::nullopt;
}

}  // namespace glint::yaml::detail
