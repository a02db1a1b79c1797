// Untrusted JSON: the nesting limit while parsing (256 levels pass, 257 do not) and quotations of
// bad values cut at 80 characters.
#include <gtest/gtest.h>

#include <string>

#include "renderer/core/error.h"
#include "renderer/core/json_bounds.h"

using penumbra::InputError;
using penumbra::parseJsonBounded;
using penumbra::quoteJson;
using penumbra::quoteText;

namespace {
std::string nested(int levels) {
    return std::string(static_cast<size_t>(levels), '[') +
           std::string(static_cast<size_t>(levels), ']');
}
}  // namespace

TEST(JsonBounds, NestingLimitIs256Levels) {
    EXPECT_TRUE(parseJsonBounded(nested(256), "x.json").has_value());
    try {
        parseJsonBounded(nested(257), "x.json");
        FAIL() << "257 levels parsed";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "x.json: nesting deeper than 256 levels");
    }
    // Objects count as levels too, and a document far deeper is refused without recursing.
    std::string objects;
    for (int i = 0; i < 300; ++i) objects += "{\"a\":";
    objects += "1" + std::string(300, '}');
    EXPECT_THROW(parseJsonBounded(objects, "o"), InputError);
    EXPECT_THROW(parseJsonBounded(nested(1000000), "deep"), InputError);
}

TEST(JsonBounds, InvalidJsonGivesTheParsersReason) {
    std::string why;
    EXPECT_FALSE(parseJsonBounded("[1,", "x", &why).has_value());
    EXPECT_NE(why.find("syntax error"), std::string::npos) << why;
    EXPECT_EQ(why.find("[json.exception"), std::string::npos) << why;
}

TEST(JsonBounds, QuotationsStopAt80Characters) {
    EXPECT_EQ(quoteText("short"), "short");
    const std::string cut = quoteText(std::string(1000, 'a'));
    EXPECT_EQ(cut.size(), 80u);
    EXPECT_EQ(cut.substr(77), "...");
    EXPECT_EQ(quoteJson(nlohmann::json::parse("[1,\"two\",{\"k\":null}]")),
              "[1,\"two\",{\"k\":null}]");
    nlohmann::json big = nlohmann::json::array();
    for (int i = 0; i < 100000; ++i) big.push_back(i);
    EXPECT_LE(quoteJson(big).size(), 80u);
    EXPECT_EQ(quoteJson(big).substr(0, 6), "[0,1,2");
    EXPECT_LE(quoteJson(*parseJsonBounded(nested(256), "x")).size(), 80u);
    // A cut inside a UTF-8 sequence does not make the quotation throw.
    EXPECT_LE(quoteJson(nlohmann::json(std::string(79, 'a') + "\xc3\xa9\xc3\xa9")).size(), 80u);
}
