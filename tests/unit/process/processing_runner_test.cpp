// SPDX-License-Identifier: Apache-2.0
// Tests of the processing-task runner (glint/process/processing_runner.h): the $$IMG_BASENAME$$
// substitution, program lookup (PATH, a path, DIRSIG's image_tool and demosaic standing for
// glint-envi and glint-demosaic in the tools folder first), the checks made before a render
// (a missing program, <removefile> before the image is complete, the basename of an
// incomplete image), running an event's tasks in the image's folder and <removefile>.
#include "glint/process/processing_runner.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "glint/core/error.h"
#include "glint/test/captured_log.h"
#include "glint/test/temp_dir.h"

namespace glint::process {
namespace processing_runner_test {

namespace fs = std::filesystem;
using model::ProcessingSchedule;

using Captured = test::CapturedLog;

void write_script(const fs::path& path, const std::string& body) {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << "#!/bin/sh\n" << body << "\n";
    fs::permissions(path, fs::perms::owner_all);
}

std::string read_text(const fs::path& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

model::ProcessingTask task(const std::string& program, std::vector<std::string> arguments,
                           bool remove = false, int line = 7) {
    model::ProcessingTask t;
    t.program = program;
    t.arguments = std::move(arguments);
    t.remove_file = remove;
    t.where = {"cam.platform", line, "processing/task"};
    return t;
}

model::ProcessingEvent event(ProcessingSchedule kind, const fs::path& file, bool complete,
                             std::vector<model::ProcessingTask> tasks) {
    model::ProcessingEvent e;
    e.kind = kind;
    e.focal_plane = "Cam -> Frame";
    e.file = file;
    e.file_complete = complete;
    e.tasks = std::move(tasks);
    return e;
}

TEST(Processing, SubstitutesEveryBasenameAsOneArgument) {
    EXPECT_EQ(substitute_basename("--in=$$IMG_BASENAME$$.img", "a b"), "--in=a b.img");
    EXPECT_EQ(substitute_basename("$$IMG_BASENAME$$/$$IMG_BASENAME$$", "x"), "x/x");
    EXPECT_EQ(substitute_basename("plain", "x"), "plain");
    // A basename holding the placeholder is not substituted again.
    EXPECT_EQ(substitute_basename("$$IMG_BASENAME$$!", "$$IMG_BASENAME$$"), "$$IMG_BASENAME$$!");
    EXPECT_EQ(substitute_basename("$$IMG_BASENAME", "x"), "$$IMG_BASENAME");
}

TEST(Processing, DirsigProgramsStandForGlintToolsInTheToolsFolderFirst) {
    test::TempDir dir;
    write_script(dir / "tools" / "glint-envi", "exit 0");
    write_script(dir / "path" / "glint-envi", "exit 0");
    write_script(dir / "path" / "glint-demosaic", "exit 0");
    write_script(dir / "path" / "ffmpeg", "exit 0");
    ProcessingOptions options;
    options.tools_dir = dir / "tools";
    options.path = (dir / "path").string();
    Captured log;
    Context context;
    context.log = log.log();
    ProcessingRunner runner(options, context);
    const auto e =
        event(ProcessingSchedule::capture_completed, dir / "out" / "frame-t0000.img", true, {});
    const TaskCommand envi =
        runner.command(task("image_tool", {"convert", "$$IMG_BASENAME$$.img"}), e);
    EXPECT_EQ(envi.program, dir / "tools" / "glint-envi");
    EXPECT_EQ(envi.stands_for, "image_tool");
    EXPECT_EQ(envi.argv, (std::vector<std::string>{(dir / "tools" / "glint-envi").string(),
                                                   "convert", "frame-t0000.img"}));
    const TaskCommand demosaic = runner.command(task("demosaic", {}), e);
    EXPECT_EQ(demosaic.program, dir / "path" / "glint-demosaic");  // not in tools: PATH
    const TaskCommand ffmpeg = runner.command(task("ffmpeg", {"-y"}), e);
    EXPECT_EQ(ffmpeg.program, dir / "path" / "ffmpeg");
    EXPECT_TRUE(ffmpeg.stands_for.empty());
    // Said once per name.
    (void)runner.command(task("image_tool", {}), e);
    const std::string said = log.text();
    EXPECT_EQ(said.find("no program \"image_tool\" on PATH"),
              said.rfind("no program \"image_tool\" on PATH"))
        << said;
    EXPECT_NE(said.find("no program \"demosaic\" on PATH; running " +
                        (dir / "path" / "glint-demosaic").string() + " in its place"),
              std::string::npos)
        << said;

    // A program of that name on PATH wins over the stand-in.
    write_script(dir / "path" / "image_tool", "exit 0");
    EXPECT_EQ(runner.command(task("image_tool", {}), e).program, dir / "path" / "image_tool");
}

TEST(Processing, CheckRefusesMissingProgramsAndEarlyRemovalAndWarnsOfIncompleteImages) {
    test::TempDir dir;
    write_script(dir / "path" / "record", "exit 0");
    ProcessingOptions options;
    options.path = (dir / "path").string();
    options.allow_all = true;  // the test helper is not a default program
    Captured log;
    Context context;
    context.log = log.log();
    ProcessingRunner runner(options, context);
    const fs::path file = dir / "out" / "frame.img";
    const std::vector<model::ProcessingEvent> events{
        event(ProcessingSchedule::capture_completed, file, false,
              {task("record", {"$$IMG_BASENAME$$"}, false, 10), task("record", {}, true, 11),
               task("nowhere", {}, false, 12)}),
        event(ProcessingSchedule::capture_completed, file, true,
              {task("record", {"$$IMG_BASENAME$$"}, false, 10), task("record", {}, true, 11),
               task("nowhere", {}, false, 12)})};
    try {
        runner.check(events);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_EQ(e.message(), "nothing written: 2 errors in the inputs");
    }
    const std::string said = log.text();
    EXPECT_NE(said.find("warning: cam.platform:10: processing/task: $$IMG_BASENAME$$ at "
                        "capture_completed names frame, whose image is not complete then"),
              std::string::npos)
        << said;
    EXPECT_NE(said.find("error: cam.platform:11: processing/task: <removefile> at "
                        "capture_completed would remove frame.img before it is complete"),
              std::string::npos)
        << said;
    EXPECT_NE(said.find("error: cam.platform:12: processing/task: program \"nowhere\" is not on "
                        "PATH"),
              std::string::npos)
        << said;
    EXPECT_EQ(said.find("cam.platform:12", said.find("cam.platform:12") + 1), std::string::npos)
        << "each task is reported once: " << said;

    // With --keep-going a missing program is a warning; the early removal stays an error.
    options.keep_going = true;
    Captured log2;
    context.log = log2.log();
    ProcessingRunner keep_going(options, context);
    EXPECT_THROW(keep_going.check(events), Error);
    EXPECT_NE(log2.text().find("warning: cam.platform:12: processing/task: program \"nowhere\" is "
                               "not on PATH (--keep-going: skipped)"),
              std::string::npos)
        << log2.text();
}

TEST(Processing, CheckRefusesArgumentsTheSystemCannotPass) {
    test::TempDir dir;
    write_script(dir / "path" / "record", "exit 0");
    ProcessingOptions options;
    options.path = (dir / "path").string();
    options.allow_all = true;
    Captured log;
    Context context;
    context.log = log.log();
    ProcessingRunner runner(options, context);
    const std::vector<model::ProcessingEvent> events{
        event(ProcessingSchedule::collection_completed, dir / "out" / "frame.img", true,
              {task("record", {"ok", std::string(200 * 1024, 'x')}, false, 20),
               task("record", {std::string("cut\0here", 8)}, false, 21)})};
    try {
        runner.check(events);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.message(), "nothing written: 2 errors in the inputs");
    }
    const std::string said = log.text();
    EXPECT_NE(said.find("error: cam.platform:20: processing/task: argument 2 is 200 KiB; the "
                        "system passes at most 128 KiB in one argument"),
              std::string::npos)
        << said;
    EXPECT_NE(said.find("error: cam.platform:21: processing/task: argument 1 holds a NUL byte, "
                        "which no program can be given"),
              std::string::npos)
        << said;
}

TEST(Processing, RunsInTheImagesFolderThenRemovesTheImage) {
    test::TempDir dir;
    write_script(dir / "path" / "record",
                 "pwd > where.txt; printf '%s\\n' \"$@\" >> args.txt; echo said on stdout; "
                 "echo said on stderr >&2");
    const fs::path out = dir / "out";
    fs::create_directories(out);
    std::ofstream(out / "frame-t0000-c0001.img") << "data";
    std::ofstream(out / "frame-t0000-c0001.img.hdr") << "ENVI";
    ProcessingOptions options;
    options.path = (dir / "path").string();
    options.allow_all = true;
    Captured log;
    Context context;
    context.log = log.log();
    ProcessingRunner runner(options, context);
    model::ProcessingTask first = task("record", {"--in=$$IMG_BASENAME$$.img", "-x"});
    first.message = "Recording";
    const auto e = event(ProcessingSchedule::capture_completed, out / "frame-t0000-c0001.img", true,
                         {first, task("record", {"second"}, true)});
    runner.run(e);
    EXPECT_EQ(read_text(out / "where.txt"), fs::canonical(out).string() + "\n");
    EXPECT_EQ(read_text(out / "args.txt"), "--in=frame-t0000-c0001.img\n-x\nsecond\n");
    EXPECT_FALSE(fs::exists(out / "frame-t0000-c0001.img"));
    EXPECT_FALSE(fs::exists(out / "frame-t0000-c0001.img.hdr"));
    EXPECT_EQ(runner.removed().count(out / "frame-t0000-c0001.img"), 1u);
    EXPECT_EQ(runner.tasks_run(), 2u);
    const std::string said = log.text();
    // The task's <message> is said before it runs, as DIRSIG does, at the level shown without
    // -v; so is each command as it starts.
    EXPECT_NE(said.find("notice: Recording\n"), std::string::npos) << said;
    // Each command is shown as it starts, at the level shown without -v.
    EXPECT_NE(said.find("notice: Processing at capture_completed of Cam -> Frame (task 1, capture "
                        "1): " +
                        (dir / "path" / "record").string() + " --in=frame-t0000-c0001.img -x\n"),
              std::string::npos)
        << said;
    EXPECT_NE(said.find("info: [record] said on stdout\n"), std::string::npos) << said;
    EXPECT_NE(said.find("info: [record] said on stderr\n"), std::string::npos) << said;
}

TEST(Processing, AProgramThatCannotStartIsNamedWithItsTask) {
    // Executable, but neither a binary nor a script (no #!): the exec fails.
    test::TempDir dir;
    fs::create_directories(dir / "path");
    std::ofstream(dir / "path" / "garbage") << "not a program\n\x7f"
                                               "ELFxx";
    fs::permissions(dir / "path" / "garbage", fs::perms::owner_all);
    const fs::path out = dir / "out";
    fs::create_directories(out);
    ProcessingOptions options;
    options.path = (dir / "path").string();
    options.allow_all = true;
    Captured log;
    Context context;
    context.log = log.log();
    ProcessingRunner runner(options, context);
    try {
        runner.run(event(ProcessingSchedule::collection_completed, out / "f.img", true,
                         {task("garbage", {})}));
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(e.message().find("processing task \"garbage\" (cam.platform:7) at "
                                   "collection_completed of Cam -> Frame (task 1, capture 1): "),
                  std::string::npos)
            << e.message();
        EXPECT_NE(e.message().find("garbage: cannot run program: Exec format error"),
                  std::string::npos)
            << e.message();
    }
}

TEST(Processing, AFailingTaskKeepsTheImage) {
    test::TempDir dir;
    write_script(dir / "path" / "fail", "echo broken >&2; exit 2");
    const fs::path out = dir / "out";
    fs::create_directories(out);
    std::ofstream(out / "f.img") << "data";
    ProcessingOptions options;
    options.path = (dir / "path").string();
    options.allow_all = true;
    options.keep_going = true;
    Captured log;
    Context context;
    context.log = log.log();
    ProcessingRunner runner(options, context);
    runner.run(event(ProcessingSchedule::collection_completed, out / "f.img", true,
                     {task("fail", {}, true)}));
    EXPECT_TRUE(fs::exists(out / "f.img"));
    EXPECT_EQ(runner.tasks_failed(), 1u);
    const std::string said = log.text();
    EXPECT_NE(said.find("exited with status 2 (its last words: \"broken\"); --keep-going"),
              std::string::npos)
        << said;
    EXPECT_NE(said.find("f.img is kept, since a task failed"), std::string::npos) << said;

    options.keep_going = false;
    ProcessingRunner strict(options, context);
    try {
        strict.run(event(ProcessingSchedule::collection_completed, out / "f.img", true,
                         {task("fail", {}, true)}));
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::runtime);
        EXPECT_NE(e.message().find("processing task \"fail\" (cam.platform:7) at "
                                   "collection_completed of Cam -> Frame (task 1, capture 1): "),
                  std::string::npos)
            << e.message();
    }
    EXPECT_TRUE(fs::exists(out / "f.img"));
}

}  // namespace processing_runner_test
}  // namespace glint::process
