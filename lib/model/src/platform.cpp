// SPDX-License-Identifier: Apache-2.0
// The few behaviours of the platform model: whether a placement is the identity, whether a
// mount jitters, and the flat list of instruments (with the attachments and mounts that hold
// each) that gives every instrument its index in the schedule and in output names.
#include "glint/model/platform.h"

namespace glint::model {

namespace {

constexpr std::array<double, 16> kIdentity4x4 = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

/// Depth-first walk of one attachment: the instruments sitting directly on it first, then
/// those on each of its mounts, in file order.
void collect(const Attachment& attachment, std::vector<const Attachment*>& attachments,
             std::vector<const Mount*>& mounts, std::vector<InstrumentPath>& out) {
    attachments.push_back(&attachment);
    for (const Instrument& instrument : attachment.instruments) {
        out.push_back(InstrumentPath{&instrument, attachments, mounts});
    }
    for (const Mount& mount : attachment.mounts) {
        mounts.push_back(&mount);
        for (const Attachment& inner : mount.attachments) {
            collect(inner, attachments, mounts, out);
        }
        mounts.pop_back();
    }
    attachments.pop_back();
}

}  // namespace

bool AffineTransform::is_identity() const {
    for (int i = 0; i < 3; ++i) {
        if (translation_m[i] != 0.0 || rotation_rad[i] != 0.0) return false;
    }
    return !matrix || *matrix == kIdentity4x4;
}

bool RotationDeviates::any() const {
    for (const JitterSpec& axis : axes) {
        if (axis.kind != JitterSpec::Kind::none) return true;
    }
    return false;
}

std::vector<InstrumentPath> list_instruments(const Platform& platform) {
    std::vector<InstrumentPath> out;
    std::vector<const Attachment*> attachments;
    std::vector<const Mount*> mounts;
    for (const Attachment& attachment : platform.attachments) {
        collect(attachment, attachments, mounts, out);
    }
    return out;
}

}  // namespace glint::model
