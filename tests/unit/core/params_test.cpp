// Parameter tables: defaults, every kind of rejection, and the JSON form `techniques` prints.
#include <gtest/gtest.h>

#include <array>

#include "renderer/core/error.h"
#include "renderer/core/params.h"

using penumbra::InputError;
using penumbra::resolveParams;

namespace {
constexpr std::array kSpecs = {
    penumbra::intParam("samples", 16, 1, 32, "grid size"),
    penumbra::floatParam("epsilon", 0.01, 0.0, 1.0, "threshold"),
    penumbra::boolParam("jitter", true, "jitter"),
    penumbra::enumParam("mode", "absolute", "absolute|relative", "comparison"),
};

std::string rejection(const char* json) {
    try {
        resolveParams(kSpecs, nlohmann::json::parse(json), "s.json: technique");
    } catch (const InputError& e) {
        return e.what();
    }
    return "accepted";
}
}  // namespace

TEST(Params, DefaultsFillEveryKey) {
    auto p = resolveParams(kSpecs, nlohmann::json{{"name", "x"}}, "s.json: technique");
    EXPECT_EQ(p.getInt("samples"), 16);
    EXPECT_DOUBLE_EQ(p.getFloat("epsilon"), 0.01);
    EXPECT_TRUE(p.getBool("jitter"));
    EXPECT_EQ(p.getString("mode"), "absolute");
    EXPECT_EQ(p.json().size(), kSpecs.size());  // "name" is not a parameter
}

TEST(Params, GivenValuesWin) {
    auto p =
        resolveParams(kSpecs,
                      nlohmann::json::parse(
                          R"({"samples": 4, "epsilon": 0, "jitter": false, "mode": "relative"})"),
                      "s.json: technique");
    EXPECT_EQ(p.getInt("samples"), 4);
    EXPECT_EQ(p.getFloat("epsilon"), 0.0);
    EXPECT_FALSE(p.getBool("jitter"));
    EXPECT_EQ(p.getString("mode"), "relative");
    // A whole float is accepted for an int parameter: JSON does not tell 4 from 4.0.
    EXPECT_EQ(
        resolveParams(kSpecs, nlohmann::json::parse(R"({"samples": 4.0})"), "t").getInt("samples"),
        4);
}

TEST(Params, RejectionsNameTheKey) {
    struct Case {
        const char* json;
        const char* expected;
    };
    for (const Case& c : std::initializer_list<Case>{
             {R"({"sampels": 4})", "s.json: technique.sampels: unknown parameter"},
             {R"({"samples": 0})", "technique.samples: 0 is out of range [1, 32]"},
             {R"({"samples": 33})", "technique.samples: 33 is out of range"},
             {R"({"samples": 2.5})", "technique.samples: expected a whole number"},
             {R"({"samples": "4"})", "technique.samples: expected a whole number"},
             {R"({"epsilon": -0.1})", "technique.epsilon: -0.1 is out of range [0, 1]"},
             {R"({"epsilon": true})", "technique.epsilon: expected a number"},
             {R"({"jitter": 1})", "technique.jitter: expected true or false"},
             {R"({"mode": "other"})", "technique.mode: expected one of absolute, relative"},
             {R"([1])", "s.json: technique: expected an object"},
         }) {
        EXPECT_NE(rejection(c.json).find(c.expected), std::string::npos)
            << c.json << " -> " << rejection(c.json);
    }
}

TEST(Params, SpecJson) {
    auto j = penumbra::paramSpecJson(kSpecs[3]);
    EXPECT_EQ(j["type"], "enum");
    EXPECT_EQ(j["choices"], nlohmann::json::array({"absolute", "relative"}));
    EXPECT_EQ(penumbra::paramSpecJson(kSpecs[0])["range"], nlohmann::json::array({1, 32}));
}

TEST(Params, StringParameters) {
    constexpr std::array kText = {penumbra::stringParam("file", "", "a path")};
    auto p = penumbra::resolveParams(kText, nlohmann::json::object(), "s.json: technique");
    EXPECT_EQ(p.getString("file"), "");
    p = penumbra::resolveParams(kText, {{"file", "lights.json"}}, "s.json: technique");
    EXPECT_EQ(p.getString("file"), "lights.json");
    EXPECT_EQ(penumbra::paramSpecJson(kText[0])["type"], "string");
    try {
        penumbra::resolveParams(kText, {{"file", 3}}, "s.json: technique");
        FAIL() << "expected an InputError";
    } catch (const penumbra::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("technique.file: expected a string"),
                  std::string::npos);
    }
}
