// The scene on the GPU: one vertex/index buffer set per model (shared by the objects that use
// it), material textures, and per-frame object transforms and world bounds.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

#include "renderer/gl/handles.h"
#include "renderer/gl/program.h"
#include "renderer/passes/bindings.h"
#include "renderer/scene/scene.h"

namespace penumbra::passes {

struct Bounds {
    glm::vec3 min{1e30f}, max{-1e30f};
    bool empty() const { return min.x > max.x; }
    void extend(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void extend(const Bounds& b) {
        if (!b.empty()) extend(b.min), extend(b.max);
    }
    // Corner I (0-7): bit 0 picks max.x, bit 1 max.y, bit 2 max.z.
    glm::vec3 corner(int i) const {
        return {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z};
    }
};

// A model-space box carried into the world by an object's transform: the 8 corners of a
// parallelepiped, numbered as Bounds::corner (so each still lies on the faces of its bits). Views
// are fitted to these, not to the axis-aligned boxes around them: a floor turned about two axes
// (scripts/scale-scenes --rotate) has an axis-aligned box as deep as it is wide, whose corners
// set `css`'s depth range and every light-centred map's near plane where nothing is.
struct WorldBox {
    std::array<glm::vec3, 8> corners{};
    bool valid = false;
    WorldBox() = default;
    // Implicit from an axis-aligned world box (the identity transform).
    WorldBox(const Bounds& model, const glm::mat4& transform = glm::mat4(1.0f));
    bool empty() const { return !valid; }
    const glm::vec3& corner(int i) const { return corners[static_cast<size_t>(i)]; }
};

// World boxes, one per object: views are fitted to these rather than to their union, whose
// corners can lie where no object does (behind a tilted light's plane).
using Boxes = std::span<const WorldBox>;

struct GpuDraw {
    GLsizei count = 0;   // indices
    GLintptr first = 0;  // byte offset into the index buffer
    GLint base_vertex = 0;
    int material = 0;
    bool has_uvs = false;  // a texture is only sampled where the mesh has coordinates
};

struct GpuModel {
    gl::VertexArray vao;
    gl::Buffer positions, normals, uvs, indices;
    std::vector<GpuDraw> draws;
    std::vector<glm::vec4> base_colors;  // per material
    std::vector<int> material_texture;   // per material: index into textures or -1
    std::vector<gl::Texture> textures;
    Bounds bounds;  // model space
    size_t triangles = 0;
    bool closed = false;  // scene::isClosedSurface: no open sheet, back faces lie behind
    bool convex = false;  // scene::isConvexSurface: it shadows itself only below a tangent plane
};

struct GpuObject {
    const GpuModel* model = nullptr;
    glm::mat4 transform{1.0f};
    scene::ShadowRole shadow = scene::ShadowRole::Both;
    WorldBox world_box;
    int id = 0;             // index in Scene::objects
    bool mirrored = false;  // the transform's determinant is negative: front faces turn clockwise
};

class GpuScene {
public:
    // Uploads every model of SCENE once.
    explicit GpuScene(const scene::Scene& scene);
    // Takes the transforms of SCENE (same objects, animated values).
    void update(const scene::Scene& scene);

    const std::vector<GpuObject>& objects() const { return objects_; }
    // World bounds of each object that casts shadows (ShadowRole Both or Occluder), and of
    // every object.
    Boxes casterBoxes() const { return caster_boxes_; }
    Boxes sceneBoxes() const { return scene_boxes_; }
    // Per object of the scene (by its index, the G-buffer id): 1 when it casts shadows (role
    // both or occluder), else 0; an SSBO of int for glsl/common/caster_flags.glsl.
    const gl::Buffer& casterFlags() const { return caster_flags_; }
    size_t triangleCount() const;

    // Receivers: role receiver or both; ReceiversOnly: role receiver.
    enum class Filter { All, Casters, Receivers, ReceiversOnly };
    // Draws the objects FILTER selects with PROGRAM bound by the caller. Sets uniform "u_model"
    // and those of "u_normal_matrix", "u_object_id", "u_closed" (GpuModel::closed),
    // "u_base_color" that PROGRAM's shaders declare. With TEXTURED (PROGRAM's variant that samples
    // the base colour texture, its other uniforms set by the caller as PROGRAM's), a draw whose
    // material has a texture (and uvs) uses it, the texture bound to unit TEXTURE_UNIT, and PROGRAM
    // is bound again after it. INSTANCES > 1 draws instanced.
    void draw(const gl::Program& program, Filter filter, int instances = 1,
              const gl::Program* textured = nullptr, int texture_unit = UNIT_BASE_TEXTURE) const;

private:
    std::unordered_map<const scene::Model*, std::unique_ptr<GpuModel>> models_;
    std::vector<GpuObject> objects_;
    std::vector<WorldBox> caster_boxes_, scene_boxes_;
    gl::Buffer caster_flags_;
};

}  // namespace penumbra::passes
