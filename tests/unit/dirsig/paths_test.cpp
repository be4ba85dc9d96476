// SPDX-License-Identifier: Apache-2.0
// Unit tests of PathResolver: relative paths made absolute against the naming file's folder,
// $SCENE_DIR, $NAME and ${NAME} from an injected environment, "$$" left alone, undefined and
// malformed variables reported with the path and where it was named, Windows paths kept.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>

#include "glint/dirsig/read_options.h"

namespace glint::dirsig {
namespace paths_test {

using ::testing::HasSubstr;

const ErrorContext kWhere{"a.platform", 12, "platform/x/filename"};

PathResolver resolver_with(std::map<std::string, std::string> variables) {
    PathResolver resolver;
    resolver.environment = [variables](const std::string& name) -> std::optional<std::string> {
        const auto it = variables.find(name);
        if (it == variables.end()) return std::nullopt;
        return it->second;
    };
    return resolver;
}

TEST(PathResolver, RelativePathsAreAbsoluteAndNormal) {
    const PathResolver resolver = resolver_with({});
    Diagnostics diagnostics;
    const model::FileRef ref =
        resolver.resolve("./sub/../data/x.ppd", "/proj/sims", kWhere, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors());
    EXPECT_EQ(ref.text, "./sub/../data/x.ppd");
    EXPECT_EQ(ref.resolved, std::filesystem::path("/proj/sims/data/x.ppd"));
    EXPECT_EQ(ref.where.line, 12);
    EXPECT_EQ(ref.where.element, "platform/x/filename");

    EXPECT_EQ(resolver.resolve("/abs/./y.tasks", "/proj", kWhere, diagnostics).resolved,
              std::filesystem::path("/abs/y.tasks"));
    EXPECT_EQ(resolver.resolve("../up.atm", "/proj/sims", kWhere, diagnostics).resolved,
              std::filesystem::path("/proj/up.atm"));
    EXPECT_EQ(resolver.resolve("  spaced.atm\n", "/p", kWhere, diagnostics).resolved,
              std::filesystem::path("/p/spaced.atm"));
    EXPECT_FALSE(diagnostics.has_errors());
}

TEST(PathResolver, PathMapReplacesWholeLeadingFolders) {
    PathResolver resolver = resolver_with({{"HOME_DIR", "C:\\Sims"}});
    resolver.path_map = {PathMapping::parse("C:\\DIRSIG\\=/data/dirsig"),
                         PathMapping::parse("C:/Sims=relative/sims"),
                         PathMapping::parse("/old/root=/new/root")};
    Diagnostics diagnostics;
    const auto resolved = [&](const std::string& text) {
        return resolver.resolve(text, "/proj", kWhere, diagnostics).resolved.generic_string();
    };
    // Any case of a Windows FROM, backslashes as slashes, in whole folders only.
    EXPECT_EQ(resolved("c:\\dirsig\\scenes\\a.scene"), "/data/dirsig/scenes/a.scene");
    EXPECT_EQ(resolved("C:/DIRSIG"), "/data/dirsig");
    EXPECT_EQ(resolved("C:/DIRSIGX/a.scene"), "C:/DIRSIGX/a.scene");
    // After variable expansion; a relative TO is relative to where glint runs.
    EXPECT_EQ(resolved("$HOME_DIR/b.ppd"),
              (std::filesystem::current_path() / "relative/sims/b.ppd").generic_string());
    // A POSIX FROM matches exactly.
    EXPECT_EQ(resolved("/old/root/x.tasks"), "/new/root/x.tasks");
    EXPECT_EQ(resolved("/OLD/root/x.tasks"), "/OLD/root/x.tasks");
    EXPECT_FALSE(diagnostics.has_errors());

    for (const std::string bad : {"C:/DIRSIG", "=/data", "C:/DIRSIG="}) {
        try {
            (void)PathMapping::parse(bad);
            ADD_FAILURE() << bad;
        } catch (const Error& e) {
            EXPECT_EQ(e.category(), ErrorCategory::usage);
            EXPECT_EQ(e.message(),
                      "--path-map \"" + bad + "\": expected FROM=TO, e.g. C:/DIRSIG=/data/dirsig");
        }
    }
}

TEST(PathResolver, RelativeBaseFolderGivesAnAbsolutePath) {
    const PathResolver resolver = resolver_with({});
    Diagnostics diagnostics;
    const model::FileRef ref = resolver.resolve("x.ppd", "rel/dir", kWhere, diagnostics);
    EXPECT_TRUE(ref.resolved.is_absolute());
    EXPECT_EQ(ref.resolved, (std::filesystem::current_path() / "rel/dir/x.ppd").lexically_normal());
}

TEST(PathResolver, ExpandsVariables) {
    PathResolver resolver = resolver_with({{"DIRSIG_HOME", "/opt/dirsig"}, {"A_1", "aa"}});
    resolver.scene_dir = "/scenes/tahoe";
    Diagnostics diagnostics;
    EXPECT_EQ(resolver.resolve("$SCENE_DIR/maps/a.png", "/x", kWhere, diagnostics).resolved,
              std::filesystem::path("/scenes/tahoe/maps/a.png"));
    EXPECT_EQ(
        resolver.resolve("${DIRSIG_HOME}/lib/data/sun.txt", "/x", kWhere, diagnostics).resolved,
        std::filesystem::path("/opt/dirsig/lib/data/sun.txt"));
    EXPECT_EQ(resolver.resolve("$DIRSIG_HOME/lib", "/x", kWhere, diagnostics).resolved,
              std::filesystem::path("/opt/dirsig/lib"));
    EXPECT_EQ(resolver.resolve("d/$A_1.txt", "/x", kWhere, diagnostics).resolved,
              std::filesystem::path("/x/d/aa.txt"));
    // "$$" is not a variable and a '$' not followed by a name is an ordinary character.
    EXPECT_EQ(resolver.resolve("$$IMG_BASENAME$$.png", "/x", kWhere, diagnostics).resolved,
              std::filesystem::path("/x/$$IMG_BASENAME$$.png"));
    EXPECT_EQ(resolver.resolve("cost$5/a$", "/x", kWhere, diagnostics).resolved,
              std::filesystem::path("/x/cost$5/a$"));
    EXPECT_FALSE(diagnostics.has_errors());
}

TEST(PathResolver, DefaultsToTheProcessEnvironment) {
    ::setenv("GLINT_TEST_PATHS_VAR", "/from/env", 1);
    const PathResolver resolver;  // no lookup function: std::getenv
    Diagnostics diagnostics;
    EXPECT_EQ(resolver.resolve("$GLINT_TEST_PATHS_VAR/f", "/x", kWhere, diagnostics).resolved,
              std::filesystem::path("/from/env/f"));
    ::unsetenv("GLINT_TEST_PATHS_VAR");
    EXPECT_TRUE(
        resolver.resolve("$GLINT_TEST_PATHS_VAR/f", "/x", kWhere, diagnostics).resolved.empty());
    EXPECT_EQ(diagnostics.error_count(), 1u);
}

TEST(PathResolver, UndefinedVariableIsAnError) {
    const PathResolver resolver = resolver_with({});
    Diagnostics diagnostics;
    const model::FileRef ref =
        resolver.resolve("$DIRSIG_HOME/lib/x.txt", "/x", kWhere, diagnostics);
    EXPECT_TRUE(ref.resolved.empty());
    EXPECT_EQ(ref.text, "$DIRSIG_HOME/lib/x.txt");
    ASSERT_EQ(diagnostics.error_count(), 1u);
    EXPECT_EQ(diagnostics.items()[0].text(),
              "a.platform:12: platform/x/filename: undefined variable $DIRSIG_HOME in path "
              "\"$DIRSIG_HOME/lib/x.txt\"");
}

TEST(PathResolver, SceneDirOutsideASceneAndMalformedReferences) {
    const PathResolver resolver = resolver_with({{"SCENE_DIR", "/ignored"}});
    Diagnostics diagnostics;
    EXPECT_TRUE(resolver.resolve("$SCENE_DIR/a", "/x", kWhere, diagnostics).resolved.empty());
    EXPECT_TRUE(resolver.resolve("${BAD-NAME}/a", "/x", kWhere, diagnostics).resolved.empty());
    EXPECT_TRUE(resolver.resolve("${OPEN/a", "/x", kWhere, diagnostics).resolved.empty());
    EXPECT_TRUE(resolver.resolve("  ", "/x", kWhere, diagnostics).resolved.empty());
    ASSERT_EQ(diagnostics.error_count(), 4u);
    EXPECT_THAT(diagnostics.items()[0].message,
                HasSubstr("$SCENE_DIR used outside a scene file in path \"$SCENE_DIR/a\""));
    EXPECT_THAT(diagnostics.items()[1].message,
                HasSubstr("malformed variable reference in path \"${BAD-NAME}/a\""));
    EXPECT_THAT(diagnostics.items()[2].message, HasSubstr("malformed variable reference"));
    EXPECT_THAT(diagnostics.items()[3].message, HasSubstr("expected a file path"));
    for (const Diagnostic& d : diagnostics.items()) {
        EXPECT_EQ(d.where.line, 12);
        EXPECT_EQ(d.where.element, "platform/x/filename");
    }
}

TEST(PathResolver, WindowsPathsAreKeptWithForwardSlashes) {
    const PathResolver resolver = resolver_with({});
    Diagnostics diagnostics;
    EXPECT_EQ(resolver.resolve("C:\\Users\\me\\sim\\a.platform", "/x", kWhere, diagnostics)
                  .resolved.string(),
              "C:/Users/me/sim/a.platform");
    EXPECT_EQ(resolver.resolve("d:/data/b.ppd", "/x", kWhere, diagnostics).resolved.string(),
              "d:/data/b.ppd");
    EXPECT_EQ(
        resolver.resolve("\\\\server\\share\\c.tasks", "/x", kWhere, diagnostics).resolved.string(),
        "//server/share/c.tasks");
    // A relative path written with backslashes is still relative to the naming file.
    EXPECT_EQ(resolver.resolve("geometry\\tree.obj", "/x", kWhere, diagnostics).resolved,
              std::filesystem::path("/x/geometry/tree.obj"));
    EXPECT_FALSE(diagnostics.has_errors());
}

TEST(PathResolver, RecognisesWindowsAbsolutePaths) {
    EXPECT_TRUE(is_windows_absolute("C:\\x"));
    EXPECT_TRUE(is_windows_absolute("C:/x"));
    EXPECT_TRUE(is_windows_absolute("z:\\"));
    EXPECT_TRUE(is_windows_absolute("\\\\server\\x"));
    EXPECT_FALSE(is_windows_absolute("C:x"));
    EXPECT_FALSE(is_windows_absolute("/usr/x"));
    EXPECT_FALSE(is_windows_absolute("./C:/x"));
    EXPECT_FALSE(is_windows_absolute("1:/x"));
    EXPECT_FALSE(is_windows_absolute("_:/x"));
    EXPECT_FALSE(is_windows_absolute("\\x"));
    EXPECT_FALSE(is_windows_absolute(""));
}

}  // namespace paths_test
}  // namespace glint::dirsig
