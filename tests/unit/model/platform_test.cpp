// SPDX-License-Identifier: Apache-2.0
// Tests of the platform model's behaviours: identity affine transforms (parts and matrix),
// whether a mount jitters, and the document-order instrument list with the chain of
// attachments and mounts holding each instrument.
#include "glint/model/platform.h"

#include <gtest/gtest.h>

namespace glint::model {
namespace platform_test {

TEST(AffineTransform, DefaultAndIdentityMatrixAreIdentity) {
    AffineTransform t;
    EXPECT_TRUE(t.is_identity());
    t.rotation_order = "zyx";  // the order alone changes nothing
    EXPECT_TRUE(t.is_identity());
    t.matrix = std::array<double, 16>{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    EXPECT_TRUE(t.is_identity());
}

TEST(AffineTransform, AnyPartMakesItNonIdentity) {
    for (int i = 0; i < 3; ++i) {
        AffineTransform translated;
        translated.translation_m[i] = 0.5;
        EXPECT_FALSE(translated.is_identity()) << i;
        AffineTransform rotated;
        rotated.rotation_rad[i] = -1e-9;
        EXPECT_FALSE(rotated.is_identity()) << i;
    }
    AffineTransform matrix;
    matrix.matrix = std::array<double, 16>{1, 0, 0, 2, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    EXPECT_FALSE(matrix.is_identity());
}

TEST(RotationDeviates, AnyAxisThatIsNotNone) {
    RotationDeviates d;
    EXPECT_FALSE(d.any());
    d.axes[2].kind = JitterSpec::Kind::psd;
    EXPECT_TRUE(d.any());
    d.axes[2].kind = JitterSpec::Kind::none;
    d.axes[0].kind = JitterSpec::Kind::normal;
    EXPECT_TRUE(d.any());
}

Instrument named(const std::string& name) {
    Instrument i;
    i.name = name;
    return i;
}

TEST(ListInstruments, EmptyPlatform) { EXPECT_TRUE(list_instruments(Platform{}).empty()); }

TEST(ListInstruments, DocumentOrderWithMountChains) {
    // attachment A: instrument a1, mount M1 > attachment B: instrument b1,
    //                                          mount M2 > attachment C: instrument c1
    //               mount M3 (no attachments)
    // attachment D: instrument d1, d2
    Platform p;
    p.attachments.resize(2);
    Attachment& a = p.attachments[0];
    a.instruments.push_back(named("a1"));
    a.mounts.resize(2);
    a.mounts[0].name = "M1";
    a.mounts[1].name = "M3";
    a.mounts[0].attachments.resize(1);
    Attachment& b = a.mounts[0].attachments[0];
    b.instruments.push_back(named("b1"));
    b.mounts.resize(1);
    b.mounts[0].name = "M2";
    b.mounts[0].attachments.resize(1);
    Attachment& c = b.mounts[0].attachments[0];
    c.instruments.push_back(named("c1"));
    Attachment& d = p.attachments[1];
    d.instruments.push_back(named("d1"));
    d.instruments.push_back(named("d2"));

    const std::vector<InstrumentPath> list = list_instruments(p);
    ASSERT_EQ(list.size(), 5u);
    const char* order[] = {"a1", "b1", "c1", "d1", "d2"};
    for (std::size_t i = 0; i < list.size(); ++i) {
        EXPECT_EQ(list[i].instrument->name, order[i]);
        EXPECT_EQ(list[i].attachments.size(), list[i].mounts.size() + 1) << i;
    }
    EXPECT_EQ(list[0].attachments, (std::vector<const Attachment*>{&a}));
    EXPECT_TRUE(list[0].mounts.empty());
    EXPECT_EQ(list[1].attachments, (std::vector<const Attachment*>{&a, &b}));
    EXPECT_EQ(list[1].mounts, (std::vector<const Mount*>{&a.mounts[0]}));
    EXPECT_EQ(list[2].attachments, (std::vector<const Attachment*>{&a, &b, &c}));
    EXPECT_EQ(list[2].mounts, (std::vector<const Mount*>{&a.mounts[0], &b.mounts[0]}));
    EXPECT_EQ(list[3].attachments, (std::vector<const Attachment*>{&d}));
    EXPECT_EQ(list[4].instrument, &d.instruments[1]);
}

}  // namespace platform_test
}  // namespace glint::model
