// The typed-JSON checker: every check's message in the one style "<file>: <key>: expected
// <what>, got <value>", the value quoted as JSON and cut at 80 characters.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <string_view>

#include "renderer/core/error.h"
#include "renderer/core/json_field.h"

namespace penumbra {
namespace {

using nlohmann::json;

const std::string kFile = "s.json";

// The message CHECK throws for VALUE at "a.b" of s.json, or "accepted".
std::string messageOf(const json& value, const std::function<void(const Field&)>& check) {
    try {
        check(Field(&value, "a.b", kFile));
    } catch (const InputError& e) {
        return e.what();
    }
    return "accepted";
}

TEST(JsonField, EveryTypeCheckNamesFileKeyAndValue) {
    constexpr std::array<std::string_view, 2> kChoices = {"rect", "square"};
    struct Case {
        json value;
        std::function<void(const Field&)> check;
        std::string expected;
    };
    const std::vector<Case> cases = {
        {"wide", [](const Field& f) { f.number(); },
         "s.json: a.b: expected a number, got \"wide\""},
        {1e39, [](const Field& f) { f.number(); },
         "s.json: a.b: expected a number within +-3.4e38, got 1e+39"},
        {-0.5, [](const Field& f) { f.number(0, 1); },
         "s.json: a.b: expected a number in 0..1, got -0.5"},
        {33, [](const Field& f) { f.integer(1, 32); },
         "s.json: a.b: expected an integer in 1..32, got 33"},
        {2.5, [](const Field& f) { f.integer(1, 32); },
         "s.json: a.b: expected an integer in 1..32, got 2.5"},
        {2.0, [](const Field& f) { f.strictInteger(0, 10); },
         "s.json: a.b: expected an integer in 0..10, got 2.0"},
        {1, [](const Field& f) { f.boolean(); }, "s.json: a.b: expected true or false, got 1"},
        {4, [](const Field& f) { f.string(); }, "s.json: a.b: expected a string, got 4"},
        {"disc", [&](const Field& f) { f.choice(kChoices); },
         "s.json: a.b: expected one of rect, square, got \"disc\""},
        {json::array({1, "x", 3}), [](const Field& f) { f.vec3(); },
         "s.json: a.b: expected 3 numbers, got [1,\"x\",3]"},
        {json::array({1, 2}), [](const Field& f) { f.vec3(); },
         "s.json: a.b: expected 3 numbers, got [1,2]"},
        {json::array(), [](const Field& f) { f.expectObject(); },
         "s.json: a.b: expected an object, got []"},
        {json::object(), [](const Field& f) { f.arraySize(); },
         "s.json: a.b: expected an array, got {}"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.expected);
        EXPECT_EQ(messageOf(c.value, c.check), c.expected);
    }
}

TEST(JsonField, AcceptedValuesComeBack) {
    constexpr std::array<std::string_view, 2> kChoices = {"rect", "square"};
    const json doc = {{"n", 3.0}, {"s", "square"}, {"b", false}, {"v", {1, 2, 3}}};
    const Field root(&doc, "", kFile);
    EXPECT_EQ(root.member("n").integer(1, 32), 3);  // 3.0 counts as an integer here
    EXPECT_EQ(root.member("s").choice(kChoices), "square");
    EXPECT_FALSE(root.member("b").boolean());
    EXPECT_EQ(root.member("v").vec3(), glm::vec3(1, 2, 3));
    EXPECT_FALSE(root.member("missing").present());
}

TEST(JsonField, LongAndNonFiniteValuesAreQuotedShort) {
    const std::string long_text(500, 'x');
    const std::string m = messageOf(long_text, [](const Field& f) { f.number(); });
    EXPECT_EQ(m.rfind("s.json: a.b: expected a number, got \"xxx", 0), 0u) << m;
    EXPECT_LE(m.size(), std::string("s.json: a.b: expected a number, got ").size() + 80);
    EXPECT_EQ(m.substr(m.size() - 3), "...");
    const json inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(messageOf(json::array({inf, 1, 1}), [](const Field& f) { f.vec3(); }),
              "s.json: a.b: expected 3 numbers within +-3.4e38, got [inf,1,1]");
}

TEST(JsonField, WithoutAFileTheKeyLocates) {
    const json value = "x";
    const std::string none;
    try {
        Field(&value, "s.json: technique.samples", none).integer(1, 32);
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "s.json: technique.samples: expected an integer in 1..32, got \"x\"");
    }
}

TEST(JsonField, AnAbsentValueIsNamedAsMissing) {
    const json doc = json::object();
    const Field missing = Field(&doc, "", kFile).member("lights");
    EXPECT_EQ(messageOf(doc, [&](const Field&) { missing.arraySize(); }),
              "s.json: lights: expected an array, got nothing");
}

}  // namespace
}  // namespace penumbra
