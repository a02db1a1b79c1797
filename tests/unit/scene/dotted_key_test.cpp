// Dotted keys as json_pointers: the lookup follows json_pointer's rules (no leading zero, no
// "-", '~' and '/' ordinary characters), and -D's set refuses what json_pointer's set would do.
#include <gtest/gtest.h>

#include "renderer/scene/dotted_key.h"
#include "renderer/scene/overrides.h"
#include "scene_test_support.h"

namespace penumbra::scene {
namespace {

using nlohmann::json;

const json* lookup(const json& doc, std::string_view key) {
    const auto parts = splitDottedKey(key);
    return parts ? findAt(doc, *parts) : nullptr;
}

TEST(DottedKey, FindsObjectMembersAndArrayElements) {
    const json doc = {{"lights", {{{"size", {1, 2}}}}}, {"obj", {{"0", "zero"}}}};
    ASSERT_NE(lookup(doc, "lights.0.size.1"), nullptr);
    EXPECT_EQ(*lookup(doc, "lights.0.size.1"), 2);
    EXPECT_EQ(*lookup(doc, "obj.0"), "zero");  // a numeric name in an object is a member name
    EXPECT_EQ(lookup(doc, "lights.1"), nullptr);
    EXPECT_EQ(lookup(doc, "lights.x"), nullptr);
    EXPECT_EQ(lookup(doc, "lights.0.size.0.x"), nullptr);
}

TEST(DottedKey, ArrayIndicesArePlainDecimal) {
    const json doc = {{"lights", {1, 2}}};
    for (const char* key : {"lights.00", "lights.01", "lights.-", "lights.+1", "lights. 1",
                            "lights.99999999999999999999999"})
        EXPECT_EQ(lookup(doc, key), nullptr) << key;
    EXPECT_EQ(arrayIndex("0"), 0u);
    EXPECT_EQ(arrayIndex("10"), 10u);
    EXPECT_EQ(arrayIndex("00"), std::nullopt);
    EXPECT_EQ(arrayIndex("-"), std::nullopt);
}

TEST(DottedKey, TildeAndSlashAreOrdinaryCharacters) {
    const json doc = {{"a/b", {{"c~d", 5}}}, {"c~1d", 6}};
    ASSERT_NE(lookup(doc, "a/b.c~d"), nullptr);
    EXPECT_EQ(*lookup(doc, "a/b.c~d"), 5);
    EXPECT_EQ(*lookup(doc, "c~1d"), 6);  // not unescaped to "c/d"
    EXPECT_EQ(toJsonPointer({"a/b", "c~d"}).to_string(), "/a~1b/c~0d");
}

TEST(DottedKey, OverridesRefuseWhatJsonPointersSetWouldDo) {
    struct Case {
        Override o;
        std::string expected;
    };
    const std::vector<Case> cases = {
        {{"lights.-", "{}"}, "-D lights.-: lights is an array; '-' is not an index"},
        {{"lights.00.size", "[1, 1]"},
         "-D lights.00.size: lights is an array; '00' is not an index"},
        {{"lights.1", "{}"}, "-D lights.1: index 1 out of range (lights has 1 element)"},
        {{"camera.new.0", "1"},
         "-D camera.new.0: camera.new does not exist, so it has no element 0"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.o.key);
        json doc = test::minimalScene();
        test::expectMessage(test::inputErrorOf([&] { applyOverrides(doc, {c.o}); }), c.expected);
    }
}

}  // namespace
}  // namespace penumbra::scene
