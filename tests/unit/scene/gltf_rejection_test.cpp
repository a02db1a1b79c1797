// glTF files refused: each malformed file (assimp's broken samples and one-change variants of a
// valid quad, as .gltf and .glb) gives an InputError naming the glTF key at fault.
#include <gtest/gtest.h>

#include "gltf_builder.h"
#include "renderer/scene/gltf_loader.h"
#include "scene_test_support.h"

namespace penumbra::scene {
namespace {

using nlohmann::json;
using test::expectMessage;
using test::GltfBuilder;
using test::inputErrorOf;

TEST(GltfRejection, AssimpBrokenFilesAreRejected) {
    const auto dir = test::assimpGltfDir();
    if (!std::filesystem::exists(dir)) GTEST_SKIP() << dir << " not installed";
    struct Case {
        const char* file;
        std::string expected;
    };
    const std::vector<Case> cases = {
        {"IndexOutOfRange/IndexOutOfRange.gltf",
         "meshes.0.primitives.0.indices: index 255 out of range (24 vertices)"},
        {"BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb",
         "meshes.0.primitives.0.attributes.POSITION: non-finite value"},
        {"MissingBin/BoxTextured.gltf",
         "buffers.0.uri: cannot read 'BoxTextured0.bin' (no such file)"},
        {"RecursiveNodes/RecursiveNodes.gltf", "nodes.1.children: cycle in the node hierarchy"},
        {"SchemaFailures/sceneWrongType.gltf",
         "scene: expected an integer in 0..2147483647, got \"hello\""},
        {"wrongTypes/badArray.gltf", "meshes.0.primitives: expected an array, got {\"indices\":0,"},
        {"wrongTypes/badObject.gltf",
         "materials.0.pbrMetallicRoughness: expected an object, got [\"not an object\"]"},
        {"wrongTypes/badUint.gltf",
         "materials.0.pbrMetallicRoughness.baseColorTexture.index: expected an integer in "
         "0..2147483647, got -1"},
        {"TestNoRootNode/NoScene.gltf", "scene: scene 0 does not exist"},
        {"TestNoRootNode/SceneWithoutNodes.gltf", "no triangles to draw"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.file);
        const auto path = dir / c.file;
        expectMessage(inputErrorOf([&] { loadGltf(path); }), path.string() + ": " + c.expected);
    }
}

// One malformed file: a change to the quad and the part of the message it must produce.
struct Broken {
    const char* name;
    std::function<void(GltfBuilder&)> change;
    std::string expected;  // after "<path>: "
};

const std::vector<Broken>& brokenFiles() {
    static const std::vector<Broken> cases = {
        {"asset missing", [](GltfBuilder& b) { b.doc.erase("asset"); }, "asset: missing"},
        {"version 1", [](GltfBuilder& b) { b.doc["asset"]["version"] = "1.0"; },
         "asset.version: expected glTF version 2.x, got \"1.0\""},
        {"required extension",
         [](GltfBuilder& b) { b.doc["extensionsRequired"] = {"EXT_meshopt_compression"}; },
         "extensionsRequired: unsupported extension 'EXT_meshopt_compression'"},
        {"accessor bufferView", [](GltfBuilder& b) { b.doc["accessors"][0]["bufferView"] = 9; },
         "meshes.0.primitives.0.attributes.POSITION (accessor 0): bufferView 9 does not exist"},
        {"accessor too long", [](GltfBuilder& b) { b.doc["accessors"][0]["count"] = 5; },
         "meshes.0.primitives.0.attributes.POSITION: accessor 0: needs 60 bytes of bufferView 0, "
         "which has 48"},
        {"accessor offset", [](GltfBuilder& b) { b.doc["accessors"][0]["byteOffset"] = 4; },
         "meshes.0.primitives.0.attributes.POSITION: accessor 0: needs 52 bytes"},
        {"accessor missing",
         [](GltfBuilder& b) { b.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 42; },
         "meshes.0.primitives.0.attributes.POSITION: accessor 42 does not exist"},
        {"indices accessor missing",
         [](GltfBuilder& b) { b.doc["meshes"][0]["primitives"][0]["indices"] = 42; },
         "meshes.0.primitives.0.indices: accessor 42 does not exist"},
        {"position component type",
         [](GltfBuilder& b) { b.doc["accessors"][0]["componentType"] = 5123; },
         "meshes.0.primitives.0.attributes.POSITION: accessor 0: expected VEC3 float, got VEC3 "
         "unsigned short"},
        {"position type", [](GltfBuilder& b) { b.doc["accessors"][0]["type"] = "VEC2"; },
         "meshes.0.primitives.0.attributes.POSITION: accessor 0: expected VEC3 float, got VEC2 "
         "float"},
        {"normal type", [](GltfBuilder& b) { b.doc["accessors"][1]["type"] = "VEC4"; },
         "meshes.0.primitives.0.attributes.NORMAL: accessor 1: expected VEC3 float, got VEC4 "
         "float"},
        {"indices type", [](GltfBuilder& b) { b.doc["accessors"][3]["componentType"] = 5126; },
         "meshes.0.primitives.0.indices: accessor 3: expected SCALAR unsigned byte, short or int, "
         "got SCALAR float"},
        {"texcoord not normalized",
         [](GltfBuilder& b) {
             b.doc["accessors"][2] = {
                 {"bufferView", 3}, {"componentType", 5121}, {"count", 4}, {"type", "VEC2"}};
         },
         "meshes.0.primitives.0.attributes.TEXCOORD_0: accessor 2: expected VEC2 float or "
         "normalized unsigned byte/short, got unsigned byte not normalized"},
        {"normal count", [](GltfBuilder& b) { b.doc["accessors"][1]["count"] = 3; },
         "meshes.0.primitives.0.attributes.NORMAL: 3 values, but POSITION has 4"},
        {"no position",
         [](GltfBuilder& b) {
             b.doc["meshes"][0]["primitives"][0]["attributes"].erase("POSITION");
         },
         "meshes.0.primitives.0.attributes: no POSITION"},
        {"index out of range",
         [](GltfBuilder& b) {
             b.poke(b.viewOffset(3) + 2, test::bytesOf(std::vector<std::uint16_t>{7}));
         },
         "meshes.0.primitives.0.indices: index 7 out of range (4 vertices)"},
        {"index count", [](GltfBuilder& b) { b.doc["accessors"][3]["count"] = 5; },
         "meshes.0.primitives.0.indices: count 5 is not a multiple of 3"},
        {"non-finite position",
         [](GltfBuilder& b) {
             b.poke(b.viewOffset(0) + 28,
                    test::bytesOf(std::vector<float>{std::numeric_limits<float>::quiet_NaN()}));
         },
         "meshes.0.primitives.0.attributes.POSITION: non-finite value at vertex 2"},
        {"view past buffer", [](GltfBuilder& b) { b.doc["bufferViews"][0]["byteLength"] = 1000; },
         "bufferViews.0: byteOffset + byteLength = 1000 exceeds the byteLength of buffers.0"},
        {"view buffer missing", [](GltfBuilder& b) { b.doc["bufferViews"][0]["buffer"] = 3; },
         "bufferViews.0.buffer: buffer 3 does not exist"},
        {"view stride small", [](GltfBuilder& b) { b.doc["bufferViews"][0]["byteStride"] = 4; },
         "meshes.0.primitives.0.attributes.POSITION: accessor 0: bufferView byteStride 4 is "
         "smaller than an "
         "element (12 bytes)"},
        {"view stride odd", [](GltfBuilder& b) { b.doc["bufferViews"][0]["byteStride"] = 13; },
         "bufferViews.0.byteStride: must be a multiple of 4 in 4..252"},
        {"lines", [](GltfBuilder& b) { b.doc["meshes"][0]["primitives"][0]["mode"] = 1; },
         "meshes.0.primitives.0.mode: unsupported primitive mode 1 (LINES"},
        {"points", [](GltfBuilder& b) { b.doc["meshes"][0]["primitives"][0]["mode"] = 0; },
         "meshes.0.primitives.0.mode: unsupported primitive mode 0 (POINTS"},
        {"mode 9", [](GltfBuilder& b) { b.doc["meshes"][0]["primitives"][0]["mode"] = 9; },
         "meshes.0.primitives.0.mode: invalid primitive mode 9"},
        {"mode type",
         [](GltfBuilder& b) { b.doc["meshes"][0]["primitives"][0]["mode"] = "TRIANGLES"; },
         "meshes.0.primitives.0.mode: expected an integer in 0..2147483647, got \"TRIANGLES\""},
        {"mesh missing", [](GltfBuilder& b) { b.doc["nodes"][0]["mesh"] = 5; },
         "nodes.0.mesh: mesh 5 does not exist"},
        {"child missing", [](GltfBuilder& b) { b.doc["nodes"][0]["children"] = {7}; },
         "nodes.0.children.0: node 7 does not exist"},
        {"cycle",
         [](GltfBuilder& b) {
             b.doc["nodes"] = {
                 {{"children", {1}}}, {{"children", {2}}}, {{"mesh", 0}, {"children", {0}}}};
         },
         "nodes.2.children: cycle in the node hierarchy (node 0 is an ancestor of node 2)"},
        {"self cycle", [](GltfBuilder& b) { b.doc["nodes"][0]["children"] = {0}; },
         "nodes.0.children: cycle"},
        {"two parents",
         [](GltfBuilder& b) {
             b.doc["nodes"] = {{{"children", {2}}}, {{"children", {2}}}, {{"mesh", 0}}};
             b.doc["scenes"][0]["nodes"] = {0, 1};
         },
         "nodes.2: reached twice in the node hierarchy"},
        {"scene node missing", [](GltfBuilder& b) { b.doc["scenes"][0]["nodes"] = {3}; },
         "scenes.0.nodes.0: node 3 does not exist"},
        {"default scene missing", [](GltfBuilder& b) { b.doc["scene"] = 4; },
         "scene: scene 4 does not exist"},
        {"empty scene", [](GltfBuilder& b) { b.doc["scenes"][0]["nodes"] = json::array(); },
         "no triangles to draw"},
        {"matrix size",
         [](GltfBuilder& b) {
             b.doc["nodes"][0]["matrix"] = {1, 0, 0};
         },
         "nodes.0.matrix: expected 16 numbers"},
        {"rotation zero",
         [](GltfBuilder& b) {
             b.doc["nodes"][0]["rotation"] = {0, 0, 0, 0};
         },
         "nodes.0.rotation: not a rotation"},
        {"translation type",
         [](GltfBuilder& b) {
             b.doc["nodes"][0]["translation"] = {0, "up", 0};
         },
         "nodes.0.translation: expected 3 numbers, got [0,\"up\",0]"},
        {"material missing",
         [](GltfBuilder& b) { b.doc["meshes"][0]["primitives"][0]["material"] = 2; },
         "meshes.0.primitives.0.material: material 2 does not exist"},
        {"base color factor",
         [](GltfBuilder& b) {
             b.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1}}}}}};
         },
         "materials.0.pbrMetallicRoughness.baseColorFactor: expected 4 numbers"},
        {"texture missing",
         [](GltfBuilder& b) {
             b.doc["materials"] = {
                 {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 3}}}}}}};
             b.doc["meshes"][0]["primitives"][0]["material"] = 0;
         },
         "materials.0.pbrMetallicRoughness.baseColorTexture.index: texture 3 does not exist"},
        {"image missing",
         [](GltfBuilder& b) {
             b.doc["materials"] = {
                 {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
             b.doc["meshes"][0]["primitives"][0]["material"] = 0;
             b.doc["textures"] = {{{"source", 2}}};
         },
         "textures.0.source: image 2 does not exist"},
        {"image undecodable",
         [](GltfBuilder& b) {
             b.doc["materials"] = {
                 {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
             b.doc["meshes"][0]["primitives"][0]["material"] = 0;
             b.doc["textures"] = {{{"source", 0}}};
             b.doc["images"] = {
                 {{"bufferView", b.view("this is not a picture")}, {"mimeType", "image/png"}}};
         },
         "images.0: cannot decode image"},
        {"image file missing",
         [](GltfBuilder& b) {
             b.doc["materials"] = {
                 {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
             b.doc["meshes"][0]["primitives"][0]["material"] = 0;
             b.doc["textures"] = {{{"source", 0}}};
             b.doc["images"] = {{{"uri", "nothere.png"}}};
         },
         "images.0.uri: cannot read image 'nothere.png'"},
        {"sparse index",
         [](GltfBuilder& b) {
             const int indices = b.view(test::bytesOf(std::vector<std::uint8_t>{9, 0, 0, 0}));
             const int values = b.view(test::bytesOf(std::vector<float>{2, 2, 0}));
             b.doc["accessors"][0]["sparse"] = {
                 {"count", 1},
                 {"indices", {{"bufferView", indices}, {"componentType", 5121}}},
                 {"values", {{"bufferView", values}}}};
         },
         "meshes.0.primitives.0.attributes.POSITION (accessor 0.sparse): index 9 out of range (4 "
         "elements)"},
        {"buffer size",
         [](GltfBuilder& b) {
             b.doc["buffers"] = {
                 {{"byteLength", 4}, {"uri", "data:application/octet-stream;base64,AAAAAAAA"}}};
             b.doc["bufferViews"] = json::array();
         },
         "Failed to decode 'uri'"},
        {"draco view missing",
         [](GltfBuilder& b) {
             b.doc["meshes"][0]["primitives"][0]["extensions"] = {
                 {"KHR_draco_mesh_compression",
                  {{"bufferView", 12}, {"attributes", {{"POSITION", 0}}}}}};
         },
         "meshes.0.primitives.0.extensions.KHR_draco_mesh_compression.bufferView: bufferView 12 "
         "does not exist"},
        {"draco garbage",
         [](GltfBuilder& b) {
             b.doc["meshes"][0]["primitives"][0]["extensions"] = {
                 {"KHR_draco_mesh_compression",
                  {{"bufferView", 0}, {"attributes", {{"POSITION", 0}}}}}};
         },
         "meshes.0.primitives.0.extensions.KHR_draco_mesh_compression: Draco decoding failed"},
        {"draco type",
         [](GltfBuilder& b) {
             b.doc["meshes"][0]["primitives"][0]["extensions"] = {
                 {"KHR_draco_mesh_compression", {{"bufferView", 0}}}};
         },
         "meshes.0.primitives.0.extensions.KHR_draco_mesh_compression: needs bufferView and "
         "attributes"},
    };
    return cases;
}

TEST(GltfRejection, EveryBrokenFileNamesItsKey) {
    for (const Broken& c : brokenFiles()) {
        SCOPED_TRACE(c.name);
        GltfBuilder b = GltfBuilder::quad();
        c.change(b);
        for (const auto& path : {b.writeGltf("broken"), b.writeGlb("broken")}) {
            if (path.extension() == ".glb" && std::string(c.name) == "buffer size") continue;
            expectMessage(inputErrorOf([&] { loadGltf(path); }), path.string() + ": " + c.expected);
        }
    }
}

TEST(GltfRejection, DracoReferencesThatCrashTinygltf) {
    // tinygltf 2.7's own Draco path (TINYGLTF_ENABLE_DRACO) segfaults on both of these.
    const auto source = test::assimpGltfDir() / "draco";
    if (!std::filesystem::exists(source)) GTEST_SKIP() << source << " not installed";
    const auto folder = test::scratchDir() / "draco-refs";
    std::filesystem::create_directories(folder);
    std::filesystem::copy_file(source / "2CylinderEngine.bin", folder / "2CylinderEngine.bin",
                               std::filesystem::copy_options::overwrite_existing);
    const json original = json::parse(test::readFile(source / "2CylinderEngine.gltf"));
    const std::string draco = "meshes.0.primitives.0.extensions.KHR_draco_mesh_compression";
    json bad_id = original;
    bad_id["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]
          ["NORMAL"] = 77;
    const auto id_path = test::writeFile("draco-refs/bad-id.gltf", bad_id.dump());
    expectMessage(
        inputErrorOf([&] { loadGltf(id_path); }),
        id_path.string() + ": " + draco + ".attributes.NORMAL: no attribute with unique id 77");
    json bad_view = original;
    bad_view["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]
            ["bufferView"] = 100000;
    const auto view_path = test::writeFile("draco-refs/bad-view.gltf", bad_view.dump());
    expectMessage(
        inputErrorOf([&] { loadGltf(view_path); }),
        view_path.string() + ": " + draco + ".bufferView: bufferView 100000 does not exist");
}

TEST(GltfRejection, BrokenContainers) {
    const GltfBuilder quad = GltfBuilder::quad();
    const std::string glb = test::readFile(quad.writeGlb("container"));
    struct Case {
        const char* name;
        std::string bytes;
        std::string expected;
    };
    std::string bad_version = glb;
    bad_version[4] = 1;
    std::string bad_chunk = glb;
    bad_chunk[16] = 'X';
    const std::vector<Case> cases = {
        {"truncated", glb.substr(0, glb.size() - 10), "GLB header says"},
        {"too short", glb.substr(0, 14), "GLB file too short"},
        {"version", bad_version, "unsupported GLB version 1"},
        {"first chunk", bad_chunk, "GLB does not start with a JSON chunk"},
        {"empty", "", "invalid JSON"},
        {"not json", "solid cube\nendsolid", "invalid JSON: "},
        {"array", "[]", "expected an object, got []"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const auto path = test::writeFile(std::string("container-") + c.name + ".glb", c.bytes);
        expectMessage(inputErrorOf([&] { loadGltf(path); }), path.string() + ": " + c.expected);
    }
    const auto missing = test::scratchDir() / "no-such-model.glb";
    expectMessage(inputErrorOf([&] { loadGltf(missing); }), missing.string() + ": no such file");
}

}  // namespace
}  // namespace penumbra::scene
