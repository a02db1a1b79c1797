// -D KEY=VALUE and -t NAME applied to scene documents: nesting, array indices, bare words,
// and errors that name the flag and key.
#include <gtest/gtest.h>

#include "renderer/scene/overrides.h"
#include "scene_test_support.h"

namespace penumbra::scene {
namespace {

using nlohmann::json;
using test::expectMessage;
using test::inputErrorOf;

json applied(json doc, const std::vector<Override>& overrides) {
    applyOverrides(doc, overrides);
    return doc;
}

TEST(Overrides, SetNumbersArraysAndNestedValues) {
    const json doc = applied(test::minimalScene(), {{"camera.fov_y", "35"},
                                                    {"lights.0.size", "[0.5, 0.25]"},
                                                    {"lights.0.position.1", "4"},
                                                    {"objects.1.transform.scale", "2"}});
    EXPECT_EQ(doc["camera"]["fov_y"], 35);
    EXPECT_EQ(doc["lights"][0]["size"], json({0.5, 0.25}));
    EXPECT_EQ(doc["lights"][0]["position"], json({0, 4, 0}));
    EXPECT_EQ(doc["objects"][1]["transform"]["scale"], 2);
}

TEST(Overrides, CreateMissingObjectMembers) {
    const json doc =
        applied(test::minimalScene(),
                {{"technique.epsilon", "0.01"}, {"objects.0.material.base_color", "[1, 0, 0]"}});
    EXPECT_EQ(doc["technique"]["epsilon"], 0.01);
    EXPECT_EQ(doc["objects"][0]["material"]["base_color"], json({1, 0, 0}));
}

TEST(Overrides, BareWordsAreStrings) {
    const json doc = applied(test::minimalScene(), {{"technique.name", "hard"},
                                                    {"name", "my shot"},
                                                    {"objects.0.shadow", "none"},
                                                    {"technique.flag", "true"},
                                                    {"technique.empty", ""}});
    EXPECT_EQ(doc["technique"]["name"], "hard");
    EXPECT_EQ(doc["name"], "my shot");
    EXPECT_EQ(doc["objects"][0]["shadow"], "none");
    EXPECT_EQ(doc["technique"]["flag"], true);  // JSON, not a bare word
    EXPECT_EQ(doc["technique"]["empty"], "");
}

TEST(Overrides, LaterOverridesWin) {
    const json doc =
        applied(test::minimalScene(), {{"camera.fov_y", "35"}, {"camera.fov_y", "50"}});
    EXPECT_EQ(doc["camera"]["fov_y"], 50);
}

TEST(Overrides, ErrorsNameTheFlag) {
    struct Case {
        Override o;
        std::string expected;
    };
    const std::vector<Case> cases = {
        {{"lights.3.size", "[1, 1]"},
         "-D lights.3.size: index 3 out of range (lights has 1 element)"},
        {{"lights.x.size", "1"}, "-D lights.x.size: lights is an array; 'x' is not an index"},
        {{"camera.fov_y.x", "1"},
         "-D camera.fov_y.x: camera.fov_y is a number, not an object or array"},
        {{"shots.0.name", "a"}, "-D shots.0.name: shots does not exist, so it has no element 0"},
        {{"camera..fov_y", "1"}, "-D camera..fov_y: malformed key"},
        {{"", "1"}, "-D : malformed key"},
        {{"lights.0.size", "[0.5, 0.5"}, "-D lights.0.size: value is not valid JSON: "},
        {{"name", "\"unterminated"}, "-D name: value is not valid JSON: "},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.o.key);
        expectMessage(inputErrorOf([&] { applied(test::minimalScene(), {c.o}); }), c.expected);
    }
}

TEST(Overrides, ValuesAreValidatedLikeTheFile) {
    const std::string path = (test::scratchDir() / "scene.json").string();
    expectMessage(inputErrorOf([] {
                      test::loadDoc(test::minimalScene(), {{"camera.fov_y", "200"}});
                  }),
                  path + ": camera.fov_y: expected degrees in (0, 180)");
    expectMessage(inputErrorOf([] {
                      test::loadDoc(test::minimalScene(), {{"camera.fvo", "20"}});
                  }),
                  "-D camera.fvo: unknown key 'fvo'");  // the flag that made it, named
    const SceneSource source = test::loadDoc(test::minimalScene(), {{"camera.fov_y", "35"}});
    EXPECT_EQ(source.at(0).camera.fov_y, 35.0f);
    EXPECT_EQ(source.document()["camera"]["fov_y"], 35);  // the document after overrides
}

TEST(Overrides, TechniqueOptionReplacesAnotherTechniquesBlock) {
    json doc = test::minimalScene();
    doc["technique"] = {{"name", "adaptive"}, {"epsilon", 0.01}};
    json other = doc;
    applyTechniqueOption(other, "hard");
    EXPECT_EQ(other["technique"], json({{"name", "hard"}}));
    json same = doc;
    applyTechniqueOption(same, "adaptive");
    EXPECT_EQ(same["technique"], doc["technique"]);
    json none = test::minimalScene();
    applyTechniqueOption(none, "ssm");
    EXPECT_EQ(none["technique"], json({{"name", "ssm"}}));
    json unchanged = doc;
    applyTechniqueOption(unchanged, std::nullopt);
    EXPECT_EQ(unchanged, doc);
}

TEST(Overrides, TechniqueOptionComesBeforeOverrides) {
    json doc = test::minimalScene();
    doc["technique"] = {{"name", "adaptive"}, {"epsilon", 0.01}};
    LoadOptions options;
    options.technique = "bitmask";
    const SceneSource source = test::loadDoc(doc, {{"technique.budget", "4"}}, options);
    EXPECT_EQ(source.at(0).technique, json({{"name", "bitmask"}, {"budget", 4}}));
}

}  // namespace
}  // namespace penumbra::scene
