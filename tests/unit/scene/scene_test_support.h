// Helpers shared by the scene unit tests: a scratch folder, writing files, a minimal valid
// scene document, and checking that a call throws an InputError with a given message part.
#pragma once

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <gtest/gtest.h>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "renderer/core/error.h"
#include "renderer/scene/scene_source.h"

namespace penumbra::scene::test {

// A folder for this test process's files, created on first use and removed at exit.
inline std::filesystem::path scratchDir() {
    static const std::filesystem::path dir = [] {
        const char* base = std::getenv("PENUMBRA_TEST_TMP");
        std::filesystem::path root = base ? base : std::filesystem::temp_directory_path().string();
        root /= "scene-unit-" + std::to_string(::getpid());
        std::filesystem::create_directories(root);
        return root;
    }();
    // Registered after DIR's destructor, so it runs while DIR is still alive.
    static const bool cleanup = (std::atexit([] {
                                     std::error_code ec;
                                     std::filesystem::remove_all(scratchDir(), ec);
                                 }),
                                 true);
    (void)cleanup;
    return dir;
}

inline std::filesystem::path writeFile(const std::string& name, const std::string& contents) {
    const std::filesystem::path path = scratchDir() / name;
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << contents;
    return path;
}

inline std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::string bytes(std::filesystem::file_size(path), '\0');
    in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return bytes;
}

inline std::filesystem::path sourceDir() {
    return PENUMBRA_SOURCE_DIR;
}
inline std::filesystem::path dataDir() {
    return sourceDir() / "tests/data/scene";
}
inline std::filesystem::path assimpGltfDir() {
    return "/usr/share/assimp/models/glTF2";
}

// A small valid scene: one rect light, a floor plane and a ball.
inline nlohmann::json minimalScene() {
    return nlohmann::json::parse(R"({
        "format": "penumbra-scene/1",
        "camera": {"position": [0, 2, 5], "target": [0, 0.5, 0], "up": [0, 1, 0],
                   "fov_y": 40, "near": 0.05, "far": 50},
        "image": {"width": 64, "height": 48},
        "lights": [{"type": "rect", "position": [0, 3, 0], "target": [0, 0, 0], "up": [0, 0, -1],
                    "size": [1, 1], "color": [1, 1, 1], "intensity": 5}],
        "objects": [
            {"name": "floor", "plane": {"size": [8, 8]}, "shadow": "receiver"},
            {"name": "ball", "sphere": {"radius": 0.3}, "transform": {"translate": [0, 1, 0]}}
        ]
    })");
}

// Writes DOC to NAME in the scratch folder and loads it.
inline SceneSource loadDoc(const nlohmann::json& doc, const std::vector<Override>& overrides = {},
                           const LoadOptions& options = {},
                           const std::string& name = "scene.json") {
    return SceneSource::load(writeFile(name, doc.dump(2)), overrides, options);
}

// The message of the InputError FN throws ("" and a test failure when it throws none).
inline std::string inputErrorOf(const std::function<void()>& fn) {
    try {
        fn();
    } catch (const InputError& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "expected an InputError, got another exception: " << e.what();
        return "";
    }
    ADD_FAILURE() << "expected an InputError, nothing was thrown";
    return "";
}

// Checks that A and B agree within TOLERANCE in each component.
inline void expectNear(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

// Checks that MESSAGE is one line and contains PART.
inline void expectMessage(const std::string& message, const std::string& part) {
    EXPECT_NE(message.find(part), std::string::npos)
        << "message: " << message << "\nwanted: " << part;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
}

}  // namespace penumbra::scene::test
