// glTF asset URIs confined to the glTF's folder: see gltf_uri.h.
#include "renderer/scene/gltf_uri.h"

#include "renderer/core/json_bounds.h"
#include "renderer/core/regular_file.h"
#include "renderer/scene/gltf_document.h"

namespace penumbra::scene {
namespace {

namespace fs = std::filesystem;

// tinygltf decodes '%XX' and also turns '+' into a space: escape both so PATH survives.
std::string encodeForTinygltf(const std::string& path) {
    std::string out;
    for (char c : path) out += c == '%' ? "%25" : c == '+' ? "%2B" : std::string(1, c);
    return out;
}

fs::path canonicalOrEmpty(const fs::path& path) {
    std::error_code ec;
    fs::path result = fs::weakly_canonical(fs::absolute(path, ec), ec);
    return ec ? fs::path() : result;
}

}  // namespace

std::string percentDecode(const std::string& uri) {
    const auto hex = [](char c) {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return -1;
    };
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
            out += static_cast<char>(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

bool insideFolder(const fs::path& base, const fs::path& file) {
    const fs::path folder = canonicalOrEmpty(base);
    const fs::path target = canonicalOrEmpty(file);
    if (folder.empty() || target.empty()) return false;
    const fs::path rel = target.lexically_relative(folder);
    return !rel.empty() && rel != "." && *rel.begin() != "..";
}

std::vector<std::string> confineAssetUris(nlohmann::json& json, const fs::path& base,
                                          const GltfDocument& doc) {
    std::vector<std::string> image_uris;
    for (const char* array : {"buffers", "images"}) {
        const auto items = json.find(array);
        if (items == json.end()) continue;
        const bool is_buffer = std::string(array) == "buffers";
        for (std::size_t i = 0; i < items->size(); ++i) {
            auto& item = (*items)[i];
            const auto uri = item.find("uri");
            const std::string text = uri == item.end() ? "" : uri->get<std::string>();
            if (!is_buffer) image_uris.push_back(text);
            if (text.empty() || text.rfind("data:", 0) == 0) continue;
            const std::string key = std::string(array) + "." + std::to_string(i) + ".uri";
            const fs::path decoded = percentDecode(text);
            const fs::path file = decoded.is_absolute() ? decoded : base / decoded;
            if (!insideFolder(base, file))
                doc.fail(key, "'" + quoteText(text) + "' is outside the glTF's folder");
            if (const std::string why = notRegularFileReason(file); is_buffer && !why.empty())
                doc.fail(key, "cannot read '" + quoteText(text) + "' (" + why + ")");
            const fs::path rel = canonicalOrEmpty(file).lexically_relative(canonicalOrEmpty(base));
            *uri = encodeForTinygltf(rel.generic_string());
        }
    }
    return image_uris;
}

}  // namespace penumbra::scene
