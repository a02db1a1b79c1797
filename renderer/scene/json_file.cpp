// JSON files: whole-file reads (regular files only) with a size limit, and parsing with a nesting
// limit that reports the position of a syntax error and the dotted key of a duplicate member.
#include "renderer/scene/json_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <set>
#include <vector>

#include "renderer/core/error.h"
#include "renderer/core/json_bounds.h"
#include "renderer/core/json_field.h"
#include "renderer/core/regular_file.h"

namespace penumbra::scene {
namespace {

// One open container while parsing: its keys so far (objects) or element count (arrays).
struct OpenContainer {
    bool is_object = true;
    std::set<std::string> keys;
    std::string current_key;
    std::size_t elements = 0;
};

std::string pathOf(const std::vector<OpenContainer>& stack, std::size_t depth) {
    std::string key;
    for (std::size_t i = 0; i < depth; ++i) {
        const OpenContainer& c = stack[i];
        key = joinKey(key, c.is_object ? c.current_key : std::to_string(c.elements));
    }
    return key;
}

}  // namespace

std::string readTextFile(const std::filesystem::path& path, const std::string& label,
                         std::size_t max_bytes) {
    requireRegularFile(path, label);  // a FIFO or device would block or never end
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(label + ": cannot open file (" + std::strerror(errno) + ")");
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0) throw InputError(label + ": cannot read file");
    if (static_cast<std::uintmax_t>(size) > max_bytes)
        throw InputError(label + ": file too large (" + std::to_string(size) + " bytes, limit " +
                         std::to_string(max_bytes) + ")");
    std::string text(static_cast<std::size_t>(size), '\0');
    in.seekg(0, std::ios::beg);
    in.read(text.data(), size);
    if (!in) throw InputError(label + ": cannot read file");
    return text;
}

nlohmann::json parseJsonText(const std::string& text, const std::string& label) {
    std::vector<OpenContainer> stack;
    using Event = nlohmann::json::parse_event_t;
    auto onEvent = [&](int depth, Event event, nlohmann::json& parsed) {
        checkJsonDepth(depth, event, label);  // before anything recurses over the document
        switch (event) {
            case Event::object_start:
            case Event::array_start:
                stack.push_back({event == Event::object_start, {}, {}, 0});
                break;
            case Event::key: {
                OpenContainer& top = stack.back();
                top.current_key = parsed.get<std::string>();
                if (!top.keys.insert(top.current_key).second) {
                    const std::string where = pathOf(stack, stack.size() - 1);
                    failAt(label, where, "duplicate key '" + quoteText(top.current_key) + "'");
                }
                break;
            }
            case Event::value:
                if (!stack.empty() && !stack.back().is_object) ++stack.back().elements;
                break;
            case Event::object_end:
            case Event::array_end:
                stack.pop_back();
                if (!stack.empty() && !stack.back().is_object) ++stack.back().elements;
                break;
        }
        return true;
    };
    try {
        return nlohmann::json::parse(text, onEvent);
    } catch (const nlohmann::json::exception& e) {
        throw InputError(label + ": invalid JSON: " + jsonErrorMessage(e.what()));
    }
}

}  // namespace penumbra::scene
