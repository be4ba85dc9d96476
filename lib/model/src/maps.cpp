// SPDX-License-Identifier: Apache-2.0
// Property maps (glint/model/maps.h).
#include "glint/model/maps.h"

namespace glint::model {

const char* map_element_name(MapKind kind) {
    return kind == MapKind::material ? "materialmap" : "mixturemap";
}

}  // namespace glint::model
