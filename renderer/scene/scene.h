// The validated scene: plain CPU data (camera, lights, objects with their meshes, environment)
// that every later step reads. Nothing here is JSON except the technique block, which the
// technique registry validates against its parameter table.
#pragma once

#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace penumbra::scene {

// Which side of shadowing an object takes part in (PRODUCT.md "shadow").
enum class ShadowRole { Both, Occluder, Receiver, None };
inline bool castsShadow(ShadowRole r) {
    return r == ShadowRole::Both || r == ShadowRole::Occluder;
}
inline bool receivesShadow(ShadowRole r) {
    return r == ShadowRole::Both || r == ShadowRole::Receiver;
}

struct Camera {
    glm::vec3 position{0, 2, 5};
    glm::vec3 target{0, 0.5f, 0};
    glm::vec3 up{0, 1, 0};
    float fov_y = 40.0f;  // vertical field of view, degrees
    float near = 0.05f;
    float far = 50.0f;
};

// A one-sided rectangular area light emitting from its front face (toward `target`).
// Radiance is color * intensity, uniform over the face and over directions (Lambertian emitter).
struct RectLight {
    glm::vec3 position{0, 3, 0};
    glm::vec3 target{0, 0, 0};
    glm::vec3 up{0, 0, -1};
    glm::vec2 size{1, 1};  // full width along right(), full height along upAxis()
    glm::vec3 color{1, 1, 1};
    float intensity = 5.0f;

    glm::vec3 forward() const { return glm::normalize(target - position); }
    glm::vec3 right() const { return glm::normalize(glm::cross(forward(), up)); }
    glm::vec3 upAxis() const { return glm::cross(right(), forward()); }
    glm::vec3 radiance() const { return color * intensity; }
    // Corners in counter-clockwise order seen from the front: (-,-), (+,-), (+,+), (-,+).
    std::array<glm::vec3, 4> corners() const;
};

// 8-bit RGBA texture, sRGB-encoded colour, rows top to bottom.
struct Texture {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

struct Material {
    glm::vec4 base_color{1, 1, 1, 1};  // linear
    int texture = -1;                  // index into Model::textures, or -1
};

// Indexed triangles. normals has one entry per position; uvs is empty or one per position.
struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> indices;  // 3 per triangle, all < positions.size()
    int material = 0;                    // index into Model::materials
};

// What an object draws: a primitive or a whole glTF scene, flattened (node transforms baked).
struct Model {
    std::vector<Mesh> meshes;
    std::vector<Material> materials;  // at least one
    std::vector<Texture> textures;
    std::string source;  // file path, or "plane"/"box"/"sphere"
};

struct Object {
    std::string name;
    std::shared_ptr<const Model> model;
    glm::mat4 transform{1.0f};  // model to world
    ShadowRole shadow = ShadowRole::Both;
};

// Equirectangular HDR map, linear RGB, rows top (up, +Y) to bottom.
struct EnvironmentImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;
};

struct Environment {
    std::filesystem::path path;
    float intensity = 1.0f;
    float rotation_y = 0.0f;  // degrees
    std::shared_ptr<const EnvironmentImage> image;
};

struct ImageSettings {
    int width = 1024;
    int height = 768;
    int samples = 1;  // multisampling; 1 = off
};

// One frame's scene: values with the animation applied.
struct Scene {
    std::string name;            // "name" key, else the file's stem
    std::filesystem::path path;  // the scene file
    int frame = 0;
    Camera camera;
    ImageSettings image;
    std::vector<RectLight> lights;
    std::optional<Environment> environment;
    std::vector<Object> objects;
    // {"name": "...", ...parameters}: checked here only as an object whose "name" is a string.
    nlohmann::json technique;
};

}  // namespace penumbra::scene
