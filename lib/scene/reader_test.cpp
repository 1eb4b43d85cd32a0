#include "scene/reader.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "scene/raypath.h"
#include "scene_text.h"
#include "scoped_directory.h"

namespace brume {
namespace {

const std::string kData = std::string(BRUME_TEST_DATA) + "/scene";

Scene parse(const std::string& text, const ReadOptions& options = {}) {
    Scene scene;
    std::istringstream in(text);
    readSceneText(scene, in, "t.rad", options);
    return scene;
}

// The message of the brume::Error that parsing `text` throws.
std::string parseError(const std::string& text, const ReadOptions& options = {}) {
    try {
        parse(text, options);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

std::string fileError(const std::string& path, const ReadOptions& options = {}) {
    try {
        Scene scene;
        readSceneFile(scene, path, options);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

using test::ScopedRayPath;

TEST(SceneReader, ObjectsAreReadWithTheirArguments) {
    Scene scene = parse("void plastic red 0 0 5 .8 .1 .1 0 0\n"
                        "red brightfunc f 2 a.cal b 1 7 1 2\n");
    ASSERT_EQ(scene.objects.size(), 2u);
    const SceneObject& red = scene.objects[0];
    EXPECT_EQ(red.type, "plastic");
    EXPECT_EQ(red.name, "red");
    EXPECT_EQ(red.modifier, -1);
    EXPECT_EQ(red.reals, (std::vector<double>{.8, .1, .1, 0, 0}));
    const SceneObject& f = scene.objects[1];
    EXPECT_EQ(f.modifier, 0);
    EXPECT_EQ(f.strings, (std::vector<std::string>{"a.cal", "b"}));
    EXPECT_EQ(f.integers, (std::vector<long>{7}));
    EXPECT_EQ(f.reals, (std::vector<double>{2}));
}

TEST(SceneReader, ObjectsRecordWhereTheyStart) {
    Scene scene = parse("\n# comment\nvoid plastic a 0 0 5 1 1 1 0 0\n\n  void\nplastic b\n0\n0\n0\n");
    EXPECT_EQ(scene.objects[0].where.str(), "t.rad:3");
    EXPECT_EQ(scene.objects[1].where.str(), "t.rad:5");
}

TEST(SceneReader, CommentsRunToTheEndOfTheLine) {
    Scene scene = parse("# void plastic hidden 0 0 0\nvoid plastic a 0 0 0 # void plastic b 0 0 0\n"
                        "#\n#void plastic c 0 0 0");
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.objects[0].name, "a");
}

TEST(SceneReader, HashInsideAnObjectIsAnArgumentAsInRadiance) {
    Scene scene = parse("void brightfunc f 1 #x 0 0");
    EXPECT_EQ(scene.objects[0].strings, (std::vector<std::string>{"#x"}));
}

TEST(SceneReader, TokensMaySpanLinesFreely) {
    Scene scene = parse("void\nplastic\n\nred\n0\n0 5\n.8\n.1 .1\n0\n0");
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.objects[0].reals.size(), 5u);
}

TEST(SceneReader, QuotesKeepSpacesAndAreRemoved) {
    Scene scene = parse("void brightfunc f 3 \"a b\" 'c\"d' x'y z'w 0 0");
    EXPECT_EQ(scene.objects[0].strings, (std::vector<std::string>{"a b", "c\"d", "xy zw"}));
}

TEST(SceneReader, UnknownTypesAreKeptAsWritten) {
    Scene scene = parse("void frobnicate thing 1 s 0 1 2");
    EXPECT_EQ(scene.objects[0].type, "frobnicate");
}

TEST(SceneReader, RadianceNumberSyntaxIsAccepted) {
    Scene scene = parse("void x y 0 3 +4 -5 007 8 1 .5 -3e-2 +4 5. 1E+2 -0.25e1 6");
    EXPECT_EQ(scene.objects[0].integers, (std::vector<long>{4, -5, 7}));
    EXPECT_EQ(scene.objects[0].reals, (std::vector<double>{1, .5, -3e-2, 4, 5, 100, -2.5, 6}));
}

TEST(SceneReader, NonNumbersAreRejectedAsReals) {
    for (const char* bad : {"nan", "inf", "-inf", "NaN", "0x10", ".", "1e", "1e+", "abc", "1.2.3", "--1", "1,5"})
        EXPECT_EQ(parseError(std::string("void x y 0 0\n2 1 ") + bad),
                  std::string("t.rad:2: bad real number '") + bad + "'");
}

TEST(SceneReader, RealsTooLargeForADoubleAreRejected) {
    EXPECT_EQ(parseError("void x y 0 0 1 1e999"), "t.rad:1: real number out of range '1e999'");
}

TEST(SceneReader, IntegersMustBeIntegers) {
    EXPECT_EQ(parseError("void x y 0 1 1.5 0"), "t.rad:1: bad integer '1.5'");
    EXPECT_EQ(parseError("void x y 0 1 99999999999999999999 0"),
              "t.rad:1: integer out of range '99999999999999999999'");
}

TEST(SceneReader, BadArgumentCountsAreErrors) {
    EXPECT_EQ(parseError("void x y 1.5"), "t.rad:1: bad number of string arguments '1.5'");
    EXPECT_EQ(parseError("void x y 0 -1"), "t.rad:1: bad number of integer arguments '-1'");
    EXPECT_EQ(parseError("void x y 0 0\n\nfive"), "t.rad:3: bad number of real arguments 'five'");
}

TEST(SceneReader, EndOfFileInsideAnObjectIsAnError) {
    EXPECT_EQ(parseError("void plastic"), "t.rad:1: unexpected end of file, expected identifier");
    EXPECT_EQ(parseError("void plastic red\n0\n0\n5 1 1\n"),
              "t.rad:5: unexpected end of file, expected real argument");
    EXPECT_EQ(parseError("void alias a"), "t.rad:1: unexpected end of file, expected alias reference");
}

TEST(SceneReader, UnterminatedQuoteIsAnError) {
    EXPECT_EQ(parseError("void brightfunc f 1\n'abc\n0 0"), "t.rad:2: unterminated quote");
}

TEST(SceneReader, VoidModifierIsMinusOne) {
    EXPECT_EQ(parse("void plastic a 0 0 0").objects[0].modifier, -1);
}

TEST(SceneReader, ModifierRefersToTheLatestDefinition) {
    Scene scene = parse("void plastic m 0 0 0\nm sphere s1 0 0 4 0 0 0 1\n"
                        "void metal m 0 0 0\nm sphere s2 0 0 4 0 0 0 1\n");
    EXPECT_EQ(scene.objects[1].modifier, 0);
    EXPECT_EQ(scene.objects[3].modifier, 2);
    EXPECT_EQ(scene.findModifier("m"), 2);
}

TEST(SceneReader, VolumesNeverShadowAModifierOfTheirName) {
    Scene scene = parse("void plastic m 0 0 0\nvoid smoke m 1 m.vdb 0 3 1 1 1\nvoid instance m 1 m.oct 0 0\n"
                        "m sphere s 0 0 4 0 0 0 1\n");
    EXPECT_EQ(scene.objects[3].modifier, 0);
}

TEST(SceneReader, IdenticalRedefinitionKeepsTheFirstAsInRadiance) {
    Scene scene = parse("void plastic m 0 0 5 .5 .5 .5 0 0\nvoid plastic m 0 0 5 .5 .5 .5000000001 0 0\n"
                        "m sphere s 0 0 4 0 0 0 1\n");
    EXPECT_EQ(scene.objects[2].modifier, 0);
}

TEST(SceneReader, RedefinitionWithADifferentModifierChainReplaces) {
    Scene scene = parse("void brightfunc p 2 f . 0 0\nvoid brightfunc q 2 g . 0 0\n"
                        "p plastic m 0 0 0\nq plastic m 0 0 0\nq plastic m 0 0 0\nm sphere s 0 0 4 0 0 0 1\n");
    EXPECT_EQ(scene.objects[5].modifier, 3);
}

TEST(SceneReader, MixtureRedefinitionComparesTheModifiersItNames) {
    Scene scene = parse("void plastic a 0 0 0\nvoid plastic b 0 0 0\nvoid mixfunc x 4 a b m m.cal 0 0\n"
                        "void plastic a 0 0 1 1\nvoid mixfunc x 4 a b m m.cal 0 0\nx sphere s 0 0 4 0 0 0 1\n");
    EXPECT_EQ(scene.objects[5].modifier, 4);
}

TEST(SceneReader, SurfacesDoNotShadowModifiersOfTheSameName) {
    Scene scene = parse("void plastic m 0 0 0\nm sphere m 0 0 4 0 0 0 1\nm sphere s 0 0 4 0 0 0 1\n");
    EXPECT_EQ(scene.objects[2].modifier, 0);
    EXPECT_EQ(parseError("void plastic m 0 0 0\nm sphere ball 0 0 4 0 0 0 1\nball sphere s 0 0 4 0 0 0 1"),
              "t.rad:3: undefined modifier 'ball'");
}

TEST(SceneReader, UndefinedModifierIsAnError) {
    EXPECT_EQ(parseError("void plastic a 0 0 0\n\n  b sphere s 0 0 4 0 0 0 1"), "t.rad:3: undefined modifier 'b'");
    // A modifier may not refer to itself or to a later definition.
    EXPECT_EQ(parseError("c plastic c 0 0 0"), "t.rad:1: undefined modifier 'c'");
}

TEST(SceneReader, ModifierMayNotBeNamedLikeAKeyword) {
    EXPECT_EQ(parseError("void plastic void 0 0 0"), "t.rad:1: illegal modifier name 'void'");
    EXPECT_EQ(parseError("void plastic inherit 0 0 0"), "t.rad:1: illegal modifier name 'inherit'");
    EXPECT_EQ(parse("void plastic m 0 0 0\nm sphere void 0 0 4 0 0 0 1").objects[1].name, "void");
}

TEST(SceneReader, TabsInNamesAreErrors) {
    EXPECT_EQ(parseError("void plastic 'a\tb' 0 0 0"), "t.rad:1: tab in identifier 'a\tb'");
}

TEST(SceneReader, AliasIsACopyOfItsTargetUnderTheNewName) {
    Scene scene = parse("void plastic red 0 0 5 .8 .1 .1 0 0\n\nvoid alias crimson red\ncrimson sphere s 0 0 4 0 0 0 1");
    ASSERT_EQ(scene.objects.size(), 3u);
    const SceneObject& alias = scene.objects[1];
    EXPECT_EQ(alias.type, "plastic");
    EXPECT_EQ(alias.name, "crimson");
    EXPECT_EQ(alias.modifier, -1);
    EXPECT_EQ(alias.reals, scene.objects[0].reals);
    EXPECT_EQ(alias.where.str(), "t.rad:3");
    EXPECT_EQ(scene.objects[2].modifier, 1);
}

TEST(SceneReader, AliasTakesItsOwnModifier) {
    Scene scene = parse("void brightfunc p 2 f . 0 0\nvoid plastic red 0 0 5 1 1 1 0 0\np alias pred red");
    EXPECT_EQ(scene.objects[2].type, "plastic");
    EXPECT_EQ(scene.objects[2].modifier, 0);
}

TEST(SceneReader, InheritAliasKeepsItsTargetsModifier) {
    Scene scene = parse("void brightfunc p 2 f . 0 0\np plastic red 0 0 5 1 1 1 0 0\ninherit alias r2 red");
    EXPECT_EQ(scene.objects[2].modifier, 0);
}

TEST(SceneReader, VoidAliasDropsItsTargetsModifier) {
    Scene scene = parse("void brightfunc p 2 f . 0 0\np plastic red 0 0 5 1 1 1 0 0\nvoid alias r2 red");
    EXPECT_EQ(scene.objects[2].modifier, -1);
}

TEST(SceneReader, AliasOfAnAliasCopiesTheResolvedTarget) {
    Scene scene = parse("void plastic red 0 0 5 1 1 1 0 0\nvoid alias a red\nvoid alias b a\n");
    EXPECT_EQ(scene.objects[2].type, "plastic");
    EXPECT_EQ(scene.objects[2].name, "b");
}

TEST(SceneReader, AliasTargetIsTheLatestEarlierDefinition) {
    Scene scene = parse("void plastic m 0 0 0\nvoid alias a m\nvoid metal m 0 0 0\n");
    EXPECT_EQ(scene.objects[1].type, "plastic");
}

TEST(SceneReader, AliasErrors) {
    EXPECT_EQ(parseError("void alias a\nmissing"), "t.rad:2: alias of undefined modifier 'missing'");
    EXPECT_EQ(parseError("void plastic m 0 0 0\nm sphere s 0 0 4 0 0 0 1\nvoid alias a s"),
              "t.rad:3: alias of undefined modifier 's'");
    EXPECT_EQ(parseError("void plastic m 0 0 0\ninherit sphere s 0 0 4 0 0 0 1"),
              "t.rad:2: 'inherit' modifier outside an alias");
}

TEST(SceneReader, CommandLineOutputIsParsedAsScene) {
    Scene scene = parse("void plastic m 0 0 0\n!echo m sphere s 0 0 4 1 2 3 4; echo m sphere t 0 0 4 0 0 0 1\n"
                        "m sphere u 0 0 4 0 0 0 1");
    ASSERT_EQ(scene.objects.size(), 4u);
    EXPECT_EQ(scene.objects[1].name, "s");
    EXPECT_EQ(scene.objects[1].modifier, 0);
    EXPECT_EQ(scene.objects[1].where.str(), "t.rad:2: !echo m sphere s 0 0 4 1 2 3 4; echo m sphere t 0 0 4 0 0 0 1:1");
    EXPECT_EQ(scene.objects[3].name, "u");
}

TEST(SceneReader, CommandOutputMayIncludeFiles) {
    Scene scene = parse("!cat " + kData + "/lib/found.rad\n");
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.objects[0].name, "found");
}

TEST(SceneReader, CommandLinesContinueAfterABackslash) {
    Scene scene = parse("!echo void plastic \\\n  m 0 0 0\n");
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.objects[0].name, "m");
}

TEST(SceneReader, ErrorsInCommandOutputNameTheCommandLine) {
    EXPECT_EQ(parseError("\n!printf 'void plastic a 0 0 0\\nb sphere s 0 0 4 0 0 0 1\\n'"),
              "t.rad:2: !printf 'void plastic a 0 0 0\\nb sphere s 0 0 4 0 0 0 1\\n':2: undefined modifier 'b'");
}

TEST(SceneReader, FailingCommandIsAnError) {
    EXPECT_EQ(parseError("void plastic a 0 0 0\n!echo void plastic b 0 0 0; exit 3"),
              "t.rad:2: !echo void plastic b 0 0 0; exit 3: command exited with status 3");
}

TEST(SceneReader, CommandsAreAnErrorWhenDisabled) {
    EXPECT_EQ(parseError("\n!touch /tmp/brume_must_not_exist", {.allowCommands = false}),
              "t.rad:2: commands are not allowed here: !touch /tmp/brume_must_not_exist");
    EXPECT_FALSE(std::filesystem::exists("/tmp/brume_must_not_exist"));
    EXPECT_EQ(fileError("!echo", {.allowCommands = false}), "!echo: commands are not allowed here");
}

TEST(SceneReader, CommandFileNameIsRun) {
    Scene scene;
    readSceneFile(scene, "!echo void plastic m 0 0 0");
    EXPECT_EQ(scene.objects.at(0).where.str(), "!echo void plastic m 0 0 0:1");
}

TEST(SceneReader, FilesAreFoundAlongRayPath) {
    ScopedRayPath path(("/nonexistent::" + kData + "/lib").c_str());
    Scene scene;
    readSceneFile(scene, "found.rad");
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.objects[0].where.str(), kData + "/lib/found.rad:2");
    EXPECT_EQ(scene.sources, (std::vector<std::string>{kData + "/lib/found.rad"}));
}

TEST(SceneReader, ErrorsInFilesNameTheFileAndLine) {
    EXPECT_EQ(fileError(kData + "/broken.rad"), kData + "/broken.rad:3: bad real number 'x'");
}

TEST(SceneReader, MissingFileIsAnError) {
    ScopedRayPath path(kData.c_str());
    EXPECT_EQ(fileError("nothing.rad"), "nothing.rad: cannot find scene file along RAYPATH");
    EXPECT_EQ(fileError("lib/found.rad", {.searchRayPath = false}), "lib/found.rad: cannot find scene file");
    EXPECT_EQ(fileError("./scene.rad"), "./scene.rad: cannot find scene file along RAYPATH");
}

TEST(SceneReader, DirectoryIsAnError) { EXPECT_EQ(fileError(kData + "/lib"), kData + "/lib: is a directory"); }

TEST(SceneReader, UnreadableFileIsAnError) {
    if (geteuid() == 0) GTEST_SKIP() << "root can read any file";
    std::string path = testing::TempDir() + "brume_unreadable.rad";
    std::ofstream(path) << "void plastic a 0 0 0\n";
    chmod(path.c_str(), 0);
    EXPECT_EQ(fileError(path), path + ": cannot read scene file");
    std::filesystem::remove(path);
}

TEST(SceneReader, LoadSceneReadsAllFilesInOrder) {
    Scene scene = loadScene({kData + "/lib/found.rad", "!echo found sphere s 0 0 4 0 0 0 1"});
    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_EQ(scene.objects[1].modifier, 0);
    EXPECT_FALSE(scene.cube);
}

TEST(RayPath, ExplicitNamesAreUsedAsGiven) {
    ScopedRayPath path(kData.c_str());
    EXPECT_EQ(findOnRayPath(kData + "/scene.rad"), kData + "/scene.rad");
    EXPECT_EQ(findOnRayPath("./scene.rad"), "");
    EXPECT_EQ(findOnRayPath("scene.rad"), kData + "/scene.rad");
}

TEST(RayPath, DirectoriesAreSearchedInOrder) {
    ScopedRayPath path((kData + ":" + kData + "/lib/").c_str());
    EXPECT_EQ(findOnRayPath("found.rad"), kData + "/lib/found.rad");
    EXPECT_EQ(findOnRayPath("lib/found.rad"), kData + "/lib/found.rad");
    EXPECT_EQ(findOnRayPath("nothing.rad"), "");
}

TEST(RayPath, EmptyOrDotDirectoryIsTheCurrentOne) {
    brume_test::ScopedDirectory here(kData);
    {
        ScopedRayPath path("/nonexistent:.");
        EXPECT_EQ(findOnRayPath("scene.rad"), "scene.rad");
    }
    {
        ScopedRayPath path(nullptr);  // default ".:/usr/local/lib/ray"
        EXPECT_EQ(findOnRayPath("scene.rad"), "scene.rad");
    }
}

}  // namespace
}  // namespace brume
