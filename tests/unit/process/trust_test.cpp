// SPDX-License-Identifier: Apache-2.0
// Tests of which programs processing tasks may start (glint/process/trust.h): the default
// programs and their argument rule, the allow-list file (format, where it is looked for, the
// files refused as others could have written them), the decision for one command, and the
// runner refusing before anything runs, even with --keep-going.
#include "glint/process/trust.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

#include "glint/core/error.h"
#include "glint/process/processing_runner.h"
#include "glint/test/captured_log.h"
#include "glint/test/temp_dir.h"

namespace glint::process {
namespace trust_test {

namespace fs = std::filesystem;

void write_file(const fs::path& path, const std::string& text,
                fs::perms perms = fs::perms::owner_read | fs::perms::owner_write) {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
    fs::permissions(path, perms);
}

void write_script(const fs::path& path, const std::string& body) {
    write_file(path, "#!/bin/sh\n" + body + "\n", fs::perms::owner_all);
}

std::string problem_of(const std::string& argument) {
    return argument_problem(argument).value_or("(none)");
}

TEST(ProcessingTrust, TheManualsArgumentsStayInTheFolder) {
    for (const char* argument : {"convert",
                                 "--gamma=1",
                                 "--format=png",
                                 "--output_filename=demo-t0000-c0001.png",
                                 "demo-t0000-c0001.img",
                                 "-y",
                                 "-framerate",
                                 "15",
                                 "-i",
                                 "demo-t0000-c%04d.png",
                                 "video.mp4",
                                 "--pattern=truesense",
                                 "--input_filename=a.img",
                                 "-c:v",
                                 "libx264",
                                 "scale=640:480",
                                 "frames/a.png",
                                 "-pix_fmt",
                                 "yuv420p",
                                 "a..b.png"}) {
        EXPECT_EQ(argument_problem(argument), std::nullopt) << argument;
    }
}

TEST(ProcessingTrust, ArgumentsThatLeaveTheFolderAreNamed) {
    EXPECT_EQ(problem_of("/etc/passwd"), "is an absolute path");
    EXPECT_EQ(problem_of("../escaped.mp4"),
              "is a '..' component (a file outside the output folder)");
    EXPECT_EQ(problem_of("frames/../../x"),
              "is a '..' component (a file outside the output folder)");
    EXPECT_EQ(problem_of("--output_filename=/home/me/.bashrc"), "holds an absolute path");
    EXPECT_EQ(problem_of("--output_filename=../x.png"),
              "holds a '..' component (a file outside the output folder)");
    EXPECT_EQ(problem_of("drawtext=textfile=/etc/passwd"), "holds an absolute path");
    EXPECT_EQ(problem_of("concat:a.mp4"), "is a URL or protocol (concat:)");
    EXPECT_EQ(problem_of("file:x"), "is a URL or protocol (file:)");
    EXPECT_EQ(problem_of("http://example.com/x"), "is a URL or protocol (http:)");
    EXPECT_EQ(problem_of("movie=tcp:host:9"), "holds a URL or protocol (tcp:)");
    EXPECT_EQ(problem_of("a,..,b"), "holds a '..' component (a file outside the output folder)");
    // Characters a filter graph, a shell or a terminal would act on.
    const std::string rule =
        " (only letters, digits and _ . / = : , + % @ - are given to a "
        "default program)";
    EXPECT_EQ(problem_of("echo${IFS}x"), "holds \"$\"" + rule);
    EXPECT_EQ(problem_of("a;b"), "holds \";\"" + rule);
    EXPECT_EQ(problem_of("a b"), "holds \" \"" + rule);
    EXPECT_EQ(problem_of("~/x"), "holds \"~\"" + rule);
    EXPECT_EQ(problem_of("x\x1b[2J"), "holds \"\\x1B\"" + rule);
}

TEST(ProcessingTrust, OnlyTheDefaultProgramsRunUnasked) {
    const ProcessingTrust none;
    EXPECT_EQ(refusal("ffmpeg", "/usr/bin/ffmpeg", {"-y", "-i", "a%04d.png", "v.mp4"}, none),
              std::nullopt);
    EXPECT_EQ(refusal("image_tool", "/opt/glint/bin/glint-envi", {"convert", "a.img"}, none),
              std::nullopt);
    EXPECT_EQ(refusal("glint-demosaic", "/usr/bin/glint-demosaic", {}, none), std::nullopt);
    EXPECT_EQ(default_programs_text(),
              "image_tool, demosaic, ffmpeg, glint-envi and glint-demosaic");

    EXPECT_EQ(refusal("/bin/sh", "/bin/sh", {"-c", "echo${IFS}pwned>pwned"}, none).value_or(""),
              "program \"/bin/sh\" is not one glint runs by default (image_tool, demosaic, "
              "ffmpeg, glint-envi and glint-demosaic): a program a simulation names runs only "
              "when you allow it; allow it with --allow-processing for this run "
              "(docs/processing.md, \"Which programs run\")");
    // A default program written as a path is not the default program.
    EXPECT_NE(refusal("/usr/bin/ffmpeg", "/usr/bin/ffmpeg", {}, none), std::nullopt);

    ProcessingTrust listed;
    listed.allow_list = "/home/me/.config/glint/allowed-programs";
    EXPECT_EQ(refusal("ffmpeg", "/usr/bin/ffmpeg", {"-y", "../escaped.mp4"}, listed).value_or(""),
              "argument 2 of ffmpeg, \"../escaped.mp4\", is a '..' component (a file outside "
              "the output folder): glint runs its default programs only with arguments that "
              "stay in the output folder; allow it with --allow-processing for this run, or with "
              "the line \"ffmpeg\" in /home/me/.config/glint/allowed-programs "
              "(docs/processing.md, \"Which programs run\")");
    EXPECT_NE(refusal("record", "/opt/x/record", {}, listed)
                  .value_or("")
                  .find("program \"record\" (/opt/x/record) is not one glint runs by default"),
              std::string::npos);

    ProcessingTrust all;
    all.allow_all = true;
    EXPECT_EQ(refusal("/bin/sh", "/bin/sh", {"-c", "anything"}, all), std::nullopt);
    EXPECT_EQ(refusal("ffmpeg", "/usr/bin/ffmpeg", {"/etc/passwd"}, all), std::nullopt);
}

TEST(ProcessingTrust, TheAllowListAllowsByNameOrByPath) {
    test::TempDir dir;
    write_script(dir / "bin" / "record", "exit 0");
    fs::create_symlink(dir / "bin" / "record", dir / "bin" / "record-link");
    const fs::path list = dir / "allowed-programs";
    write_file(list, "# my programs\n\n  convert   # ImageMagick\n" +
                         (dir / "bin" / "record-link").string() + "\n/no/such/program\nffmpeg\n");
    const ProcessingTrust trust = read_allow_list(list);
    EXPECT_EQ(trust.allow_list, list);
    ASSERT_EQ(trust.allowed.size(), 3u);  // a path naming nothing allows nothing, and says so
    ASSERT_EQ(trust.warnings.size(), 1u);
    EXPECT_EQ(trust.warnings[0].first.line, 5);
    EXPECT_EQ(trust.warnings[0].second,
              "allow-list entry \"/no/such/program\" names no file here: it allows nothing");
    EXPECT_EQ(trust.allowed[0].entry, "convert");
    EXPECT_EQ(trust.allowed[0].where.line, 3);
    EXPECT_EQ(trust.allowed[1].canonical, fs::canonical(dir / "bin" / "record"));

    EXPECT_EQ(refusal("convert", "/usr/bin/convert", {"a;b"}, trust), std::nullopt);
    // A path entry matches the file that runs, however the task names it.
    EXPECT_EQ(refusal((dir / "bin" / "record").string(), dir / "bin" / "record", {}, trust),
              std::nullopt);
    EXPECT_EQ(refusal("record", dir / "bin" / "record", {}, trust), std::nullopt);
    // A name entry does not allow a path that happens to end in it.
    EXPECT_NE(refusal("./convert", dir / "convert", {}, trust), std::nullopt);
    // A listed default program runs with any arguments.
    EXPECT_EQ(refusal("ffmpeg", "/usr/bin/ffmpeg", {"/etc/passwd"}, trust), std::nullopt);
}

TEST(ProcessingTrust, WhereTheAllowListIsLookedFor) {
    EXPECT_EQ(allow_list_path("/a/list", "/x", "/h"), fs::path("/a/list"));
    EXPECT_EQ(allow_list_path("", "/x", "/h"), fs::path("/x/glint/allowed-programs"));
    EXPECT_EQ(allow_list_path(nullptr, nullptr, "/h"),
              fs::path("/h/.config/glint/allowed-programs"));
    EXPECT_EQ(allow_list_path(nullptr, nullptr, nullptr), fs::path());
    // No file there: nothing is allowed, and nothing is wrong.
    test::TempDir dir;
    EXPECT_TRUE(read_allow_list(dir / "none").allowed.empty());
    EXPECT_TRUE(read_allow_list({}).allowed.empty());
}

void expect_refused(const fs::path& list, const std::string& message) {
    try {
        (void)read_allow_list(list);
        FAIL() << "expected an error for " << list;
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_EQ(e.message(), message);
        EXPECT_EQ(e.context().file, list.string());
    }
}

TEST(ProcessingTrust, AnAllowListOthersCouldWriteIsRefused) {
    test::TempDir dir;
    const fs::path list = dir / "allowed";
    write_file(list, "convert\n",
               fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_write);
    expect_refused(list,
                   "the processing allow-list is writable by its group, who could allow any "
                   "program; make it yours alone (chmod go-w)");
    fs::permissions(list, fs::perms::owner_read | fs::perms::owner_write | fs::perms::others_write);
    expect_refused(list,
                   "the processing allow-list is writable by anyone, who could allow any "
                   "program; make it yours alone (chmod go-w)");
    fs::create_directories(dir / "folder");
    expect_refused(dir / "folder", "the processing allow-list is not a regular file");
    if (::geteuid() == 0) {  // only root can give a file away
        write_file(list, "convert\n");
        ASSERT_EQ(::chown(list.c_str(), 65534, 65534), 0);
        expect_refused(list,
                       "the processing allow-list belongs to another user (uid 65534), who "
                       "could allow any program; it must be yours (or root's)");
        ASSERT_EQ(::chown(list.c_str(), 0, 0), 0);
    }
    write_file(list, "convert\nbin/tool\n");
    try {
        (void)read_allow_list(list);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.message(),
                  "allow-list entry \"bin/tool\" is a relative path; give a program name (found "
                  "on PATH) or an absolute path");
        EXPECT_EQ(e.context().line, 2);
    }
    write_file(list, std::string(2 << 20, '#'));
    expect_refused(list,
                   "the processing allow-list is 2.00 MiB; an allow-list of programs is at most "
                   "1 MiB");
}

model::ProcessingTask task(const std::string& program, std::vector<std::string> arguments,
                           int line) {
    model::ProcessingTask t;
    t.program = program;
    t.arguments = std::move(arguments);
    t.where = {"cam.platform", line, "processing/task"};
    return t;
}

TEST(ProcessingTrust, TheRunnerRefusesBeforeAnythingRunsEvenWithKeepGoing) {
    test::TempDir dir;
    write_script(dir / "path" / "record", "touch ran");
    write_script(dir / "path" / "ffmpeg", "touch ran");
    const fs::path out = dir / "out";
    fs::create_directories(out);
    ProcessingOptions options;
    options.path = (dir / "path").string();
    options.keep_going = true;
    test::CapturedLog log;
    Context context;
    context.log = log.log();
    ProcessingRunner runner(options, context);
    model::ProcessingEvent event;
    event.kind = model::ProcessingSchedule::collection_completed;
    event.focal_plane = "Cam -> Frame";
    event.file = out / "frame.img";
    event.file_complete = true;
    event.tasks = {task("record", {"$$IMG_BASENAME$$"}, 30),
                   task("ffmpeg", {"-i", "$$IMG_BASENAME$$.img", "/tmp/x.mp4"}, 36),
                   task("ffmpeg", {"-i", "$$IMG_BASENAME$$.img", "x.mp4"}, 42)};
    try {
        runner.check({event});
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.message(), "nothing written: 2 errors in the inputs");
    }
    EXPECT_NE(
        log.text().find("error: cam.platform:30: processing/task: program "
                        "\"record\" (" +
                        (dir / "path" / "record").string() + ") is not one glint runs by default"),
        std::string::npos)
        << log.text();
    EXPECT_NE(log.text().find("error: cam.platform:36: processing/task: argument "
                              "3 of ffmpeg, \"/tmp/x.mp4\", is an absolute path"),
              std::string::npos)
        << log.text();
    EXPECT_EQ(log.text().find("cam.platform:42"), std::string::npos) << log.text();
    // Run without a check first, a refused task still does not start.
    EXPECT_THROW(runner.run(event), Error);
    EXPECT_FALSE(fs::exists(out / "ran"));
    EXPECT_EQ(runner.tasks_run(), 0u);

    // The template --check shows keeps the placeholder and is judged with a plain name.
    const TaskCommand shown =
        runner.command_template(task("ffmpeg", {"-i", "$$IMG_BASENAME$$.img", "x.mp4"}, 42));
    EXPECT_EQ(shown.argv.at(2), "$$IMG_BASENAME$$.img");
    EXPECT_EQ(shown.refusal, std::nullopt);
}

}  // namespace trust_test
}  // namespace glint::process
