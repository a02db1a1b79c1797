// GPU scene upload and drawing: see gpu_scene.h.
#include "renderer/passes/gpu_scene.h"

#include <glm/gtc/matrix_inverse.hpp>

#include "renderer/scene/mesh_topology.h"

namespace penumbra::passes {

WorldBox::WorldBox(const Bounds& model, const glm::mat4& transform) : valid(!model.empty()) {
    if (!valid) return;
    for (int i = 0; i < 8; ++i)
        corners[static_cast<size_t>(i)] = glm::vec3(transform * glm::vec4(model.corner(i), 1.0f));
}

namespace {

template <typename T>
gl::Buffer uploadBuffer(const std::vector<T>& data, std::string_view label) {
    gl::Buffer b = gl::createBuffer(label);
    glNamedBufferStorage(b.id(),
                         static_cast<GLsizeiptr>(std::max<size_t>(data.size(), 1) * sizeof(T)),
                         data.empty() ? nullptr : data.data(), 0);
    return b;
}

gl::Texture uploadTexture(const scene::Texture& t, std::string_view label) {
    gl::Texture tex = gl::createTexture(GL_TEXTURE_2D, label);
    int levels = 1;
    for (int s = std::max(t.width, t.height); s > 1; s >>= 1) ++levels;
    glTextureStorage2D(tex.id(), levels, GL_SRGB8_ALPHA8, t.width, t.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(tex.id(), 0, 0, 0, t.width, t.height, GL_RGBA, GL_UNSIGNED_BYTE,
                        t.rgba.data());
    glGenerateTextureMipmap(tex.id());
    glTextureParameteri(tex.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(tex.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(tex.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(tex.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
    return tex;
}

std::unique_ptr<GpuModel> uploadModel(const scene::Model& m) {
    auto g = std::make_unique<GpuModel>();
    std::vector<glm::vec3> pos, nrm;
    std::vector<glm::vec2> uv;
    std::vector<std::uint32_t> idx;
    for (const auto& mesh : m.meshes) {
        GpuDraw d;
        d.count = static_cast<GLsizei>(mesh.indices.size());
        d.first = static_cast<GLintptr>(idx.size() * sizeof(std::uint32_t));
        d.base_vertex = static_cast<GLint>(pos.size());
        d.material = mesh.material;
        d.has_uvs = mesh.uvs.size() == mesh.positions.size();
        g->draws.push_back(d);
        pos.insert(pos.end(), mesh.positions.begin(), mesh.positions.end());
        nrm.insert(nrm.end(), mesh.normals.begin(), mesh.normals.end());
        if (mesh.uvs.size() == mesh.positions.size())
            uv.insert(uv.end(), mesh.uvs.begin(), mesh.uvs.end());
        else
            uv.resize(uv.size() + mesh.positions.size(), glm::vec2(0));
        idx.insert(idx.end(), mesh.indices.begin(), mesh.indices.end());
        for (const auto& p : mesh.positions) g->bounds.extend(p);
        g->triangles += mesh.indices.size() / 3;
    }
    g->closed = scene::isClosedSurface(m);
    g->convex = g->closed && scene::isConvexGivenClosed(m);
    const std::string label = "model " + m.source;
    g->vao = gl::createVertexArray(label);
    g->positions = uploadBuffer(pos, label + " positions");
    g->normals = uploadBuffer(nrm, label + " normals");
    g->uvs = uploadBuffer(uv, label + " uvs");
    g->indices = uploadBuffer(idx, label + " indices");
    GLuint vao = g->vao.id();
    glVertexArrayVertexBuffer(vao, 0, g->positions.id(), 0, sizeof(glm::vec3));
    glVertexArrayVertexBuffer(vao, 1, g->normals.id(), 0, sizeof(glm::vec3));
    glVertexArrayVertexBuffer(vao, 2, g->uvs.id(), 0, sizeof(glm::vec2));
    for (GLuint a = 0; a < 3; ++a) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribFormat(vao, a, a == 2 ? 2 : 3, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(vao, a, a);
    }
    glVertexArrayElementBuffer(vao, g->indices.id());
    for (size_t i = 0; i < m.textures.size(); ++i)
        g->textures.push_back(
            uploadTexture(m.textures[i], label + " texture " + std::to_string(i)));
    for (const auto& mat : m.materials) {
        g->base_colors.push_back(mat.base_color);
        g->material_texture.push_back(mat.texture);
    }
    if (g->base_colors.empty()) {
        g->base_colors.push_back(glm::vec4(1));
        g->material_texture.push_back(-1);
    }
    return g;
}

}  // namespace

GpuScene::GpuScene(const scene::Scene& scene) {
    for (const auto& o : scene.objects) {
        const scene::Model* key = o.model.get();
        if (key && !models_.count(key)) models_[key] = uploadModel(*key);
    }
    // Roles do not animate: the flags are uploaded once (at least one entry, for GL).
    std::vector<int> flags(std::max<size_t>(scene.objects.size(), 1), 0);
    for (size_t i = 0; i < scene.objects.size(); ++i)
        flags[i] = scene::castsShadow(scene.objects[i].shadow) ? 1 : 0;
    caster_flags_ = gl::createBuffer("caster flags");
    glNamedBufferStorage(caster_flags_.id(), GLsizeiptr(flags.size() * sizeof(int)), flags.data(),
                         0);
    update(scene);
}

void GpuScene::update(const scene::Scene& scene) {
    objects_.clear();
    caster_boxes_.clear();
    scene_boxes_.clear();
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const auto& o = scene.objects[i];
        GpuObject g;
        auto it = models_.find(o.model.get());
        if (it == models_.end()) continue;
        g.model = it->second.get();
        g.transform = o.transform;
        g.shadow = o.shadow;
        g.id = static_cast<int>(i);
        g.mirrored = glm::determinant(glm::mat3(o.transform)) < 0.0f;
        g.world_box = WorldBox(g.model->bounds, o.transform);
        scene_boxes_.push_back(g.world_box);
        if (scene::castsShadow(o.shadow)) caster_boxes_.push_back(g.world_box);
        objects_.push_back(g);
    }
}

size_t GpuScene::triangleCount() const {
    size_t n = 0;
    for (const auto& o : objects_) n += o.model->triangles;
    return n;
}

void GpuScene::draw(const gl::Program& program, Filter filter, int instances,
                    const gl::Program* textured, int texture_unit) const {
    // Each program gets the per-object uniforms its shaders declare: a depth pass has no
    // normals or colours (strict uniforms would refuse them, see gl::setStrictUniforms).
    const auto& declared = gl::programUniforms(program);
    const bool normals = declared.count("u_normal_matrix") > 0;
    const bool ids = declared.count("u_object_id") > 0;
    const bool closed = declared.count("u_closed") > 0;
    const bool colours = declared.count("u_base_color") > 0;
    const gl::Program* bound = &program;
    const GpuObject* set_for[2] = {nullptr, nullptr};  // whose uniforms each program holds
    for (const auto& o : objects_) {
        if (filter == Filter::Casters && !scene::castsShadow(o.shadow)) continue;
        if (filter == Filter::Receivers && !scene::receivesShadow(o.shadow)) continue;
        if (filter == Filter::ReceiversOnly && o.shadow != scene::ShadowRole::Receiver) continue;
        // A mirrored transform turns the model's counter-clockwise front faces clockwise: without
        // this, gl_FrontFacing called every face seen a back face and the G-buffer turned its
        // normals inward (a duck scaled by -1 along x rendered black).
        glFrontFace(o.mirrored ? GL_CW : GL_CCW);
        glBindVertexArray(o.model->vao.id());
        for (const auto& d : o.model->draws) {
            size_t m = static_cast<size_t>(d.material) < o.model->base_colors.size()
                           ? static_cast<size_t>(d.material)
                           : 0;
            int tex = o.model->material_texture[m];
            if (!d.has_uvs || static_cast<size_t>(tex) >= o.model->textures.size()) tex = -1;
            const bool use_textured = textured && tex >= 0;
            const gl::Program& p = use_textured ? *textured : program;
            if (bound != &p) {
                glUseProgram(p.id());
                bound = &p;
            }
            if (set_for[use_textured] != &o) {
                gl::setUniform(p, "u_model", o.transform);
                if (normals)
                    gl::setUniform(p, "u_normal_matrix",
                                   glm::mat3(glm::inverseTranspose(o.transform)));
                if (ids) gl::setUniform(p, "u_object_id", o.id);
                if (closed) gl::setUniform(p, "u_closed", o.model->closed ? 1 : 0);
                set_for[use_textured] = &o;
            }
            if (colours) gl::setUniform(p, "u_base_color", o.model->base_colors[m]);
            if (use_textured)
                glBindTextureUnit(static_cast<GLuint>(texture_unit),
                                  o.model->textures[static_cast<size_t>(tex)].id());
            glDrawElementsInstancedBaseVertex(GL_TRIANGLES, d.count, GL_UNSIGNED_INT,
                                              reinterpret_cast<const void*>(d.first), instances,
                                              d.base_vertex);
        }
    }
    if (bound != &program) glUseProgram(program.id());
    glFrontFace(GL_CCW);
    glBindVertexArray(0);
}

}  // namespace penumbra::passes
