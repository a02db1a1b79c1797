// `penumbra techniques [NAME] [--json]`: every technique and every parameter (key, type,
// default, range, meaning), straight from the parameter tables.
#include <algorithm>
#include <array>
#include <cstdio>
#include <iostream>

#include "cli/args.h"
#include "cli/commands.h"
#include "renderer/app/render_job.h"
#include "renderer/core/json_bounds.h"
#include "renderer/techniques/technique.h"

namespace penumbra::cli {
namespace {

constexpr const char* kHelp = R"(usage: penumbra techniques [NAME] [--json]

Lists the techniques and, for each, every parameter: key, type, default, range or choices,
and a one-line meaning. Set them in the scene's "technique" block or with -D technique.KEY=V.
)";

std::string rangeText(const ParamSpec& s) {
    nlohmann::json j = paramSpecJson(s);
    std::string out;
    if (j.contains("range")) {
        out = "[";
        out += j["range"][0].dump();
        out += ", ";
        out += j["range"][1].dump();
        out += "]";
    } else if (j.contains("choices")) {
        for (const auto& c : j["choices"]) {
            if (!out.empty()) out += '|';
            out += c.get<std::string>();
        }
    } else if (s.type == ParamType::String) {
        out = "text";
    } else {
        out = "true|false";
    }
    return out;
}

// One row per parameter, every column as wide as its widest cell (long defaults stay aligned).
void printParamTable(std::span<const ParamSpec> params) {
    std::vector<std::array<std::string, 5>> rows;
    std::array<size_t, 4> width{};
    for (const auto& s : params) {
        rows.push_back({std::string(s.key), std::string(paramTypeName(s.type)),
                        "default " + paramDefault(s).dump(), rangeText(s), std::string(s.doc)});
        for (size_t i = 0; i < width.size(); ++i)
            width[i] = std::max(width[i], rows.back()[i].size());
    }
    for (const auto& r : rows) {
        std::string line = " ";
        for (size_t i = 0; i < width.size(); ++i) {
            line += ' ';
            line += r[i];
            line.append(width[i] - r[i].size(), ' ');
        }
        std::printf("%s %s\n", line.c_str(), r[4].c_str());
    }
}

}  // namespace

int runTechniques(const Args& args) {
    ArgCursor c("techniques", args);
    bool json = false;
    std::optional<std::string> name;
    while (!c.done()) {
        if (c.flag("-h", "--help")) {
            std::fputs(kHelp, stdout);
            return 0;
        }
        if (c.flag("", "--json")) {
            json = true;
        } else if (auto p = c.positional()) {
            if (name) c.fail("unexpected argument '" + quoteText(*p) + "'");
            name = *p;
        } else {
            c.unknown();
        }
    }
    std::vector<const techniques::TechniqueInfo*> list;
    for (const auto& t : techniques::allTechniques())
        if (!name || t.name == *name) list.push_back(&t);
    if (list.empty()) c.fail(app::unknownTechniqueMessage(*name));
    if (json) {
        nlohmann::json out = nlohmann::json::array();
        for (const auto* t : list) {
            nlohmann::json params = nlohmann::json::array();
            for (const auto& s : t->params) params.push_back(paramSpecJson(s));
            out.push_back({{"name", t->name}, {"summary", t->summary}, {"params", params}});
        }
        std::cout << (name ? out[0] : out).dump(2) << "\n";
        return 0;
    }
    for (const auto* t : list) {
        std::printf("%s: %s\n", std::string(t->name).c_str(), std::string(t->summary).c_str());
        printParamTable(t->params);
        std::printf("\n");
    }
    return 0;
}

}  // namespace penumbra::cli
