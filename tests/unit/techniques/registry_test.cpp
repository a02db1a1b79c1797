// Every technique's parameter table is sound: unique keys, documented, defaults inside their
// ranges and accepted by validation; names are unique.
#include <gtest/gtest.h>

#include <set>

#include "renderer/techniques/technique.h"

using namespace penumbra;

TEST(Registry, NamesAreUniqueAndFindable) {
    std::set<std::string_view> names;
    for (const auto& t : techniques::allTechniques()) {
        EXPECT_TRUE(names.insert(t.name).second) << t.name;
        EXPECT_EQ(techniques::findTechnique(t.name), &t);
        EXPECT_FALSE(t.summary.empty());
        EXPECT_NE(t.create, nullptr);
    }
    EXPECT_TRUE(names.count("hard") && names.count("reference"));
    EXPECT_EQ(techniques::findTechnique("nope"), nullptr);
}

TEST(Registry, TablesAreSound) {
    for (const auto& t : techniques::allTechniques()) {
        std::set<std::string_view> keys;
        for (const auto& s : t.params) {
            EXPECT_TRUE(keys.insert(s.key).second) << t.name << "." << s.key;
            EXPECT_NE(s.key, "name") << "'name' is the technique's own key";
            EXPECT_FALSE(s.doc.empty()) << t.name << "." << s.key;
            if (s.type == ParamType::Int || s.type == ParamType::Float) {
                EXPECT_LE(s.min, s.def) << t.name << "." << s.key;
                EXPECT_LE(s.def, s.max) << t.name << "." << s.key;
            }
        }
        // The defaults, written out explicitly, validate and round-trip.
        nlohmann::json block = {{"name", t.name}};
        for (const auto& s : t.params) block[std::string(s.key)] = paramDefault(s);
        Params p = resolveParams(t.params, block, "test");
        for (const auto& s : t.params) EXPECT_EQ(p.json()[std::string(s.key)], paramDefault(s));
    }
}
