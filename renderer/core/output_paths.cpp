// Frame patterns: see output_paths.h.
#include "renderer/core/output_paths.h"

#include <cstdio>
#include <filesystem>
#include <system_error>

namespace penumbra {
namespace {

std::string padded(int frame, size_t width) {
    std::string digits = std::to_string(frame < 0 ? -static_cast<long>(frame) : frame);
    std::string out = frame < 0 ? "-" : "";
    if (digits.size() < width) out.append(width - digits.size(), '0');
    out += digits;
    return out;
}

size_t extensionStart(std::string_view path) {
    size_t slash = path.find_last_of('/');
    size_t dot = path.find_last_of('.');
    size_t name = slash == std::string_view::npos ? 0 : slash + 1;
    if (dot == std::string_view::npos || dot <= name) return std::string_view::npos;
    return dot;
}

}  // namespace

std::string expandFramePattern(std::string_view pattern, int frame, bool several_frames) {
    std::string out;
    bool replaced = false;
    for (size_t i = 0; i < pattern.size();) {
        if (pattern[i] == '#') {
            size_t j = i;
            while (j < pattern.size() && pattern[j] == '#') ++j;
            out += padded(frame, j - i);
            replaced = true;
            i = j;
        } else {
            out += pattern[i++];
        }
    }
    if (replaced || !several_frames) return out;
    size_t dot = extensionStart(out);
    std::string number = ".";
    number += padded(frame, 4);
    if (dot == std::string::npos) return out + number;
    out.insert(dot, number);
    return out;
}

std::string replaceExtension(std::string_view path, std::string_view ext) {
    size_t dot = extensionStart(path);
    if (dot == std::string_view::npos) return std::string(path) + std::string(ext);
    return std::string(path.substr(0, dot)) + std::string(ext);
}

std::string outputIdentity(const std::string& path) {
    std::error_code ec;
    const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
    if (ec) return path;
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(absolute, ec);
    return ec ? absolute.lexically_normal().string() : canonical.string();
}

std::set<std::string> outputIdentities(const std::vector<std::string>& files) {
    std::set<std::string> out;
    for (const std::string& f : files) out.insert(outputIdentity(f));
    return out;
}

bool namesAnyOf(const std::string& path, const std::vector<std::string>& files) {
    return outputIdentities(files).count(outputIdentity(path)) > 0;
}

}  // namespace penumbra
