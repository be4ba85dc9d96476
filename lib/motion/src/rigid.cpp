// SPDX-License-Identifier: Apache-2.0
// Composition and inverse of rigid transforms (glint/motion/rigid.h).
#include "glint/motion/rigid.h"

namespace glint::motion {

Rigid operator*(const Rigid& a, const Rigid& b) noexcept {
    return {normalized(a.rotation * b.rotation),
            rotate(a.rotation, b.translation_m) + a.translation_m};
}

Rigid inverse(const Rigid& a) noexcept {
    const Quaternion r = conjugate(a.rotation);
    return {r, -rotate(r, a.translation_m)};
}

}  // namespace glint::motion
