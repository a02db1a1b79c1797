// Parameter tables: defaults, every kind of rejection, and the JSON form `techniques` prints.
#include <gtest/gtest.h>

#include <array>

#include "renderer/core/error.h"
#include "renderer/core/params.h"

using penumbra::InputError;
using penumbra::resolveParams;

namespace {
enum class Mode { Absolute, Relative };
constexpr penumbra::EnumKey<Mode, 2> kMode{"mode", {"absolute", "relative"}};

constexpr std::array kSpecs = {
    penumbra::intParam({"samples"}, 16, 1, 32, "grid size"),
    penumbra::floatParam({"epsilon"}, 0.01, 0.0, 1.0, "threshold"),
    penumbra::boolParam({"jitter"}, true, "jitter"),
    penumbra::enumParam(kMode, Mode::Absolute, "comparison"),
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
             {R"({"samples": 0})",
              "s.json: technique.samples: expected an integer in 1..32, got 0"},
             {R"({"samples": 33})", "technique.samples: expected an integer in 1..32, got 33"},
             {R"({"samples": 2.5})", "technique.samples: expected an integer in 1..32, got 2.5"},
             {R"({"samples": "4"})", "technique.samples: expected an integer in 1..32, got \"4\""},
             {R"({"epsilon": -0.1})", "technique.epsilon: expected a number in 0..1, got -0.1"},
             {R"({"epsilon": true})", "technique.epsilon: expected a number"},
             {R"({"jitter": 1})", "technique.jitter: expected true or false, got 1"},
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
    constexpr std::array kText = {penumbra::stringParam({"file"}, "", "a path")};
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

// Enum parameters read as C++ enums: the names are the enum's, in enumerator order.
TEST(Params, EnumsReadAsTheirEnumerators) {
    static_assert(kMode.name(Mode::Relative) == "relative");
    static_assert(kSpecs[3].enum_def == "absolute" && kSpecs[3].choices.size() == 2);
    auto p = resolveParams(kSpecs, nlohmann::json::object(), "s.json: technique");
    EXPECT_EQ(p.getEnum(kMode), Mode::Absolute);
    p = resolveParams(kSpecs, nlohmann::json{{"mode", "relative"}}, "s.json: technique");
    EXPECT_EQ(p.getEnum(kMode), Mode::Relative);
    EXPECT_EQ(p.getString("mode"), "relative");  // the chosen name, e.g. for printing
}

TEST(Params, EnumKeyThatIsNotTheTablesFails) {
    // A key whose names the table's spec was not made from: a bug, never a silent default.
    enum class Other { Absolute, Relatve };
    constexpr penumbra::EnumKey<Other, 2> kOther{"mode", {"absolute", "relatve"}};
    auto p = resolveParams(kSpecs, nlohmann::json{{"mode", "relative"}}, "s.json: technique");
    EXPECT_THROW(p.getEnum(kOther), std::logic_error);
}

TEST(Params, EnumChoicesMustBeDistinctAndNamed) {
    // Evaluated at compile time in a constexpr table these fail to compile; here they throw.
    enum class E { A, B };
    static const penumbra::EnumKey<E, 2> twice{"e", {"a", "a"}};
    static const penumbra::EnumKey<E, 2> unnamed{"e", {"a", ""}};
    static const penumbra::EnumKey<E, 2> barred{"e", {"a", "b|c"}};
    EXPECT_ANY_THROW(penumbra::enumParam(twice, E::A, "doc"));
    EXPECT_ANY_THROW(penumbra::enumParam(unnamed, E::A, "doc"));
    EXPECT_ANY_THROW(penumbra::enumParam(barred, E::A, "doc"));
}

// How each parameter reaches the GPU, and the GL limit it is checked against, in the spec and
// in `techniques --json`.
TEST(Params, GpuRouteAndLimit) {
    constexpr std::array kRouted = {
        penumbra::intParam({"budget"}, 12, 0, 64, "b").uniform(),
        penumbra::intParam({"smooth_radius"}, 6, 1, 32, "r").uniform("u_radius"),
        penumbra::intParam({"max_aniso"}, 8, 1, 16, "a").define(),
        penumbra::intParam({"map_size"}, 256, 16, 4096, "m")
            .limitedBy(penumbra::GlLimit::MaxTextureSize),
    };
    EXPECT_EQ(penumbra::paramGpuName(kRouted[0]), "u_budget");
    EXPECT_EQ(penumbra::paramGpuName(kRouted[1]), "u_radius");
    EXPECT_EQ(penumbra::paramGpuName(kRouted[2]), "MAX_ANISO");
    EXPECT_EQ(penumbra::paramGpuName(kRouted[3]), "");
    const auto j0 = penumbra::paramSpecJson(kRouted[0]);
    EXPECT_EQ(j0["gpu"], "uniform");
    EXPECT_EQ(j0["glsl"], "u_budget");
    EXPECT_EQ(penumbra::paramSpecJson(kRouted[2])["gpu"], "define");
    const auto j3 = penumbra::paramSpecJson(kRouted[3]);
    EXPECT_EQ(j3["gpu"], "host");
    EXPECT_FALSE(j3.contains("glsl"));
    EXPECT_EQ(j3["limited_by"], "GL_MAX_TEXTURE_SIZE");
    EXPECT_FALSE(j0.contains("limited_by"));
}

TEST(Params, JoinedTablesKeepTheirOrder) {
    constexpr std::array kA = {penumbra::intParam({"a"}, 1, 0, 2, "a")};
    constexpr std::array kB = {penumbra::boolParam({"b"}, true, "b"),
                               penumbra::enumParam(kMode, Mode::Relative, "m")};
    constexpr auto kJoined = penumbra::joinParams(kA, kB);
    static_assert(kJoined.size() == 3);
    EXPECT_EQ(kJoined[0].key, "a");
    EXPECT_EQ(kJoined[2].key, "mode");
    EXPECT_EQ(kJoined[2].enum_def, "relative");
}
