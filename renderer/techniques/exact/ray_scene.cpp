// The Embree scene of shadow casters: see ray_scene.h.
#include "renderer/techniques/exact/ray_scene.h"

#include <algorithm>
#include <string>

#include "renderer/core/error.h"

namespace penumbra::techniques::exact {
namespace {

void throwOnError(RTCDevice device, const char* what) {
    const RTCError e = rtcGetDeviceError(device);
    if (e != RTC_ERROR_NONE)
        throw RuntimeError(std::string("exact: Embree ") + what + " failed (error " +
                           std::to_string(int(e)) + ")");
}

}  // namespace

RayScene::RayScene() {
    device_ = rtcNewDevice(nullptr);
    if (!device_) throw RuntimeError("exact: Embree could not create a device");
}

RayScene::~RayScene() {
    if (scene_) rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
}

void RayScene::update(const scene::Scene& s) {
    std::vector<glm::mat4> transforms;
    for (const auto& o : s.objects)
        if (scene::castsShadow(o.shadow)) transforms.push_back(o.transform);
    if (scene_ && transforms == transforms_) return;
    if (scene_) rtcReleaseScene(scene_);
    scene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    triangles_ = 0;
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const auto& o : s.objects) {
        if (!scene::castsShadow(o.shadow)) continue;
        for (const auto& mesh : o.model->meshes) {
            const size_t tris = mesh.indices.size() / 3;
            if (tris == 0) continue;
            RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
            auto* v = static_cast<float*>(
                rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                        3 * sizeof(float), mesh.positions.size()));
            auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
                g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), tris));
            throwOnError(device_, "buffer allocation");
            // The vertex shader's transform, in the same float arithmetic.
            for (size_t i = 0; i < mesh.positions.size(); ++i) {
                const glm::vec3 w = glm::vec3(o.transform * glm::vec4(mesh.positions[i], 1.0f));
                v[3 * i] = w.x, v[3 * i + 1] = w.y, v[3 * i + 2] = w.z;
                lo = glm::min(lo, w), hi = glm::max(hi, w);
            }
            for (size_t i = 0; i < mesh.indices.size(); ++i) idx[i] = mesh.indices[i];
            rtcCommitGeometry(g);
            rtcAttachGeometry(scene_, g);
            rtcReleaseGeometry(g);
            triangles_ += tris;
        }
    }
    rtcCommitScene(scene_);
    throwOnError(device_, "scene build");
    transforms_ = std::move(transforms);
    extent_ = triangles_ > 0 ? glm::length(hi - lo) : 0.0f;
    centre_ = triangles_ > 0 ? 0.5f * (lo + hi) : glm::vec3(0.0f);
}

void RayScene::occluded8(const glm::vec3 origins[8], const glm::vec3 dirs[8], const bool active[8],
                         float near, bool hit[8]) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    alignas(32) RTCRay8 rays;
    alignas(32) int valid[8];
    for (int i = 0; i < 8; ++i) {
        valid[i] = active[i] ? -1 : 0;
        rays.org_x[i] = origins[i].x, rays.org_y[i] = origins[i].y, rays.org_z[i] = origins[i].z;
        rays.dir_x[i] = dirs[i].x, rays.dir_y[i] = dirs[i].y, rays.dir_z[i] = dirs[i].z;
        // t runs in units of the direction's length: 1 is the light sample itself.
        rays.tnear[i] = near / std::max(glm::length(dirs[i]), 1e-20f);
        rays.tfar[i] = 1.0f;
        rays.time[i] = 0.0f;
        rays.mask[i] = 0xFFFFFFFFu;
        rays.id[i] = unsigned(i);
        rays.flags[i] = 0;
    }
    rtcOccluded8(valid, scene_, &context, &rays);
    for (int i = 0; i < 8; ++i) hit[i] = active[i] && rays.tfar[i] < 0.0f;
}

}  // namespace penumbra::techniques::exact
