// SPDX-License-Identifier: Apache-2.0
// The processing events glint-render fires (lib/render/src/render_events.cpp): the manual's
// two focal planes capturing together (tests/data/processing/manual.jsim) interleave their
// capture_completed events in schedule order and the collection completes after the last
// capture; a camera writing one file per task (events.jsim) fires every kind, its image
// complete only at the capture, task or collection that publishes it; a --schedule
// selection fires the events of its own captures only.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "../../../lib/render/src/render_parts.h"
#include "glint/model/names.h"
#include "glint/test/temp_dir.h"
#include "render_fixture.h"

namespace glint::render {
namespace render_events_test {

namespace fs = std::filesystem;
using test_render::load;
using test_render::options_into;

const fs::path kProcessing = fs::path(GLINT_TEST_DATA_DIR) / "processing";

/// "kind focal-plane file complete" per event.
std::vector<std::string> describe(const std::vector<model::ProcessingEvent>& events) {
    std::vector<std::string> out;
    for (const model::ProcessingEvent& e : events) {
        out.push_back(std::string(model::name_of(e.kind)) + " " + e.focal_plane + " " +
                      e.file.filename().string() + (e.file_complete ? " complete" : "") + " " +
                      std::to_string(e.tasks.size()));
    }
    return out;
}

std::vector<std::string> events_of(const fs::path& jsim, RenderOptions options) {
    const auto prepared = detail::plan_render(load(jsim), options, {});
    return describe(detail::plan_events(*prepared.plan).in_order());
}

TEST(RenderEvents, TwoFocalPlanesInterleaveInScheduleOrder) {
    test::TempDir dir;
    EXPECT_EQ(events_of(kProcessing / "manual.jsim", options_into(dir / "out")),
              (std::vector<std::string>{
                  "capture_completed Cam -> TrueSense truesense-t0000-c0000.img complete 1",
                  "capture_completed Cam -> Video demo-t0000-c0000.img complete 1",
                  "capture_completed Cam -> TrueSense truesense-t0000-c0001.img complete 1",
                  "capture_completed Cam -> Video demo-t0000-c0001.img complete 1",
                  "capture_completed Cam -> TrueSense truesense-t0000-c0002.img complete 1",
                  "capture_completed Cam -> Video demo-t0000-c0002.img complete 1",
                  "collection_completed Cam -> Video demo-t0000-c0002.img complete 1",
              }));
}

TEST(RenderEvents, EveryKindWithTheImageCompleteWhenPublished) {
    test::TempDir dir;
    const std::vector<std::string> expected{
        "collection_started Cam -> Frame frame-t0000.img 1",
        "task_started Cam -> Frame frame-t0000.img 1",
        "capture_started Cam -> Frame frame-t0000.img 1",
        "capture_completed Cam -> Frame frame-t0000.img 1",
        "capture_started Cam -> Frame frame-t0000.img 1",
        "capture_completed Cam -> Frame frame-t0000.img 1",
        "capture_started Cam -> Frame frame-t0000.img 1",
        "capture_completed Cam -> Frame frame-t0000.img complete 1",
        "task_completed Cam -> Frame frame-t0000.img complete 1",
        "task_started Cam -> Frame frame-t0001.img 1",
        "capture_started Cam -> Frame frame-t0001.img 1",
        "capture_completed Cam -> Frame frame-t0001.img 1",
        "capture_started Cam -> Frame frame-t0001.img 1",
        "capture_completed Cam -> Frame frame-t0001.img complete 1",
        "task_completed Cam -> Frame frame-t0001.img complete 1",
        "collection_completed Cam -> Frame frame-t0001.img complete 1",
    };
    EXPECT_EQ(events_of(kProcessing / "events.jsim", options_into(dir / "out")), expected);

    // A shard of the second task's captures (global indices 3 and 4): its own collection.
    RenderOptions shard = options_into(dir / "out");
    shard.only_captures = {3, 4};
    EXPECT_EQ(events_of(kProcessing / "events.jsim", shard),
              (std::vector<std::string>{
                  "collection_started Cam -> Frame frame-t0001.img 1",
                  "task_started Cam -> Frame frame-t0001.img 1",
                  "capture_started Cam -> Frame frame-t0001.img 1",
                  "capture_completed Cam -> Frame frame-t0001.img 1",
                  "capture_started Cam -> Frame frame-t0001.img 1",
                  "capture_completed Cam -> Frame frame-t0001.img complete 1",
                  "task_completed Cam -> Frame frame-t0001.img complete 1",
                  "collection_completed Cam -> Frame frame-t0001.img complete 1",
              }));
}

}  // namespace render_events_test
}  // namespace glint::render
