// Every technique's parameter table is sound: unique keys, documented, defaults inside their
// ranges and accepted by validation; names are unique.
#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <string>

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

// The memory budget (renderer/app/memory_budget.cpp) knows no technique by name: each lists
// its own allocations, sized by its own keys, and grows with the key that names them.
TEST(Registry, EveryTechniqueListsItsMemory) {
    for (const auto& t : techniques::allTechniques()) {
        ASSERT_NE(t.memory, nullptr) << t.name;
        const Params defaults = resolveParams(t.params, {{"name", t.name}}, "test");
        const MemoryTerms terms = t.memory(defaults, 320 * 240);
        ASSERT_FALSE(terms.empty()) << t.name;
        for (const MemoryTerm& term : terms) {
            EXPECT_GT(term.bytes, 0u) << t.name << ": " << term.what;
            EXPECT_FALSE(term.what.empty()) << t.name;
            const std::string key = term.key.substr(term.key.find('.') + 1);
            if (term.key.rfind("technique.", 0) == 0) {
                bool known = false;
                for (const auto& s : t.params) known = known || s.key == key;
                EXPECT_TRUE(known) << t.name << ": " << term.key << " is no key of its table";
            } else {
                EXPECT_EQ(term.key.rfind("image.", 0), 0u) << t.name << ": " << term.key;
            }
        }
    }
}

TEST(Registry, MemoryGrowsWithMapSize) {
    for (const auto& t : techniques::allTechniques()) {
        bool has_map = false;
        for (const auto& s : t.params) has_map = has_map || s.key == "map_size";
        if (!has_map) continue;
        auto total = [&](int map) {
            const Params p = resolveParams(t.params, {{"name", t.name}, {"map_size", map}}, "test");
            std::uint64_t sum = 0;
            for (const MemoryTerm& term : t.memory(p, 1)) sum += term.bytes;
            return sum;
        };
        EXPECT_GT(total(512), total(256)) << t.name;
    }
}

// ssm's splat-work bound is its own (TechniqueInfo::limit_error): map_size x ssm_size <= 2^21.
TEST(Registry, SsmRefusesSplatWorkBeyondItsBound) {
    const auto* ssm = techniques::findTechnique("ssm");
    ASSERT_NE(ssm, nullptr);
    ASSERT_NE(ssm->limit_error, nullptr);
    auto error = [&](int map, int size) {
        return ssm->limit_error(resolveParams(
            ssm->params, {{"name", "ssm"}, {"map_size", map}, {"ssm_size", size}}, "test"));
    };
    EXPECT_EQ(error(1024, 2048), "");
    EXPECT_EQ(error(2048, 2048).rfind("technique.ssm_size: map_size x ssm_size = 2048 x 2048", 0),
              0u);
}
