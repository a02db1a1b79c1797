// --vary parsing (lists, JSON values, ranges) and the cartesian product.
#include <gtest/gtest.h>

#include "renderer/core/error.h"
#include "renderer/core/sweep_spec.h"

using nlohmann::json;
using penumbra::InputError;
using penumbra::parseVary;

TEST(SweepSpec, Lists) {
    auto a = parseVary("technique.pcf=1,3,5");
    EXPECT_EQ(a.key, "technique.pcf");
    EXPECT_EQ(json(a.values), json::parse("[1,3,5]"));
    auto b = parseVary("lights.0.size=[0.5,0.5],[1,1]");
    EXPECT_EQ(json(b.values), json::parse("[[0.5,0.5],[1,1]]"));
    auto c = parseVary("technique.mode=absolute,relative");
    EXPECT_EQ(json(c.values), json::parse(R"(["absolute","relative"])"));
    auto d = parseVary(R"(x="a,b",true)");
    EXPECT_EQ(json(d.values), json::parse(R"(["a,b",true])"));
}

TEST(SweepSpec, Ranges) {
    auto lin = parseVary("technique.epsilon=0:1:5");
    EXPECT_EQ(json(lin.values), json::parse("[0.0,0.25,0.5,0.75,1.0]"));
    EXPECT_FALSE(lin.log_scale);
    auto ints = parseVary("technique.samples=2:8:4");
    EXPECT_EQ(json(ints.values), json::parse("[2,4,6,8]"));  // whole steps stay integers
    auto lg = parseVary("technique.epsilon=0.001:0.1:3:log");
    ASSERT_EQ(lg.values.size(), 3u);
    EXPECT_TRUE(lg.log_scale);
    EXPECT_NEAR(lg.values[1].get<double>(), 0.01, 1e-12);
    EXPECT_EQ(lg.values[2].get<double>(), 0.1);
    EXPECT_EQ(json(parseVary("k=3:9:1").values), json::parse("[3]"));
}

TEST(SweepSpec, Rejections) {
    for (const char* bad : {"novalue", "=1,2", "k=", "k=1:2:0", "k=1:2:x", "k=1:2:3:lin",
                            "k=0:1:3:log", "k=[1,2", "k=1,,2", "k=1:2:2.5"}) {
        try {
            parseVary(bad);
            ADD_FAILURE() << "accepted " << bad;
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()).rfind("--vary ", 0), 0u) << e.what();
        }
    }
}

TEST(SweepSpec, CartesianProductLastAxisFastest) {
    auto points = penumbra::cartesianProduct({parseVary("a=1,2"), parseVary("b=x,y,z")}, 100);
    ASSERT_EQ(points.size(), 6u);
    EXPECT_EQ(points[0][0].second, 1);
    EXPECT_EQ(points[0][1].second, "x");
    EXPECT_EQ(points[1][1].second, "y");
    EXPECT_EQ(points[3][0].second, 2);
    EXPECT_THROW(penumbra::cartesianProduct({parseVary("a=1,2"), parseVary("a=3")}, 100),
                 InputError);
    EXPECT_THROW(penumbra::cartesianProduct({parseVary("a=1:2:50"), parseVary("b=1:2:50")}, 1000),
                 InputError);
}
