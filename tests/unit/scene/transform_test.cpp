// Object transforms: the scale, rotate X, Y, Z, translate order against hand-computed
// matrices, and the checks on given matrices.
#include <gtest/gtest.h>

#include "renderer/scene/transform.h"
#include "scene_test_support.h"

namespace penumbra::scene {
namespace {

void expectMatrixNear(const glm::mat4& a, const glm::mat4& b) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            EXPECT_NEAR(a[c][r], b[c][r], 1e-6) << "column " << c << " row " << r;
}

glm::vec3 apply(const glm::mat4& m, const glm::vec3& p) {
    return glm::vec3(m * glm::vec4(p, 1.0f));
}

void expectPointNear(const glm::vec3& a, const glm::vec3& b) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], 1e-6) << "component " << i;
}

TEST(Transform, SingleRotationsFollowTheRightHandRule) {
    expectPointNear(apply(composeTransform({}, {90, 0, 0}, glm::vec3(1)), {0, 1, 0}), {0, 0, 1});
    expectPointNear(apply(composeTransform({}, {0, 90, 0}, glm::vec3(1)), {1, 0, 0}), {0, 0, -1});
    expectPointNear(apply(composeTransform({}, {0, 0, 90}, glm::vec3(1)), {1, 0, 0}), {0, 1, 0});
}

TEST(Transform, RotatesAboutXThenYThenZ) {
    // X first: (0,1,0) -Rx90-> (0,0,1) -Ry90-> (1,0,0). (Y first would give (0,0,1).)
    expectPointNear(apply(composeTransform({}, {90, 90, 0}, glm::vec3(1)), {0, 1, 0}), {1, 0, 0});
    // Y then Z: (0,0,1) -Ry90-> (1,0,0) -Rz90-> (0,1,0). (Z first would give (1,0,0).)
    expectPointNear(apply(composeTransform({}, {0, 90, 90}, glm::vec3(1)), {0, 0, 1}), {0, 1, 0});
}

TEST(Transform, ScalesFirstAndTranslatesLast) {
    // T(1,2,3) * Rz(90) * S(2,3,4), by hand: Rz*S has columns (0,2,0), (-3,0,0), (0,0,4).
    const glm::mat4 expected(0, 2, 0, 0,   // column 0
                             -3, 0, 0, 0,  // column 1
                             0, 0, 4, 0,   // column 2
                             1, 2, 3, 1);  // column 3
    expectMatrixNear(composeTransform({1, 2, 3}, {0, 0, 90}, {2, 3, 4}), expected);
}

TEST(Transform, SceneObjectsUseTheSameOrder) {
    nlohmann::json doc = test::minimalScene();
    doc["objects"][1]["transform"] = {
        {"translate", {1, 2, 3}}, {"rotate", {0, 0, 90}}, {"scale", {2, 3, 4}}};
    doc["objects"][0]["matrix"] = {2, 0, 0, 0, 0, 3, 0, 0, 0, 0, 4, 0, 5, 6, 7, 1};
    const Scene scene = test::loadDoc(doc).at(0);
    expectMatrixNear(scene.objects[1].transform,
                     composeTransform({1, 2, 3}, {0, 0, 90}, {2, 3, 4}));
    expectMatrixNear(scene.objects[0].transform,
                     glm::mat4(2, 0, 0, 0, 0, 3, 0, 0, 0, 0, 4, 0, 5, 6, 7, 1));
}

TEST(Transform, UniformScaleNumber) {
    nlohmann::json doc = test::minimalScene();
    doc["objects"][1]["transform"] = {{"scale", 1.5}};
    expectMatrixNear(test::loadDoc(doc).at(0).objects[1].transform,
                     glm::mat4(glm::vec4(1.5, 0, 0, 0), glm::vec4(0, 1.5, 0, 0),
                               glm::vec4(0, 0, 1.5, 0), glm::vec4(0, 0, 0, 1)));
}

TEST(Transform, MatrixProblems) {
    EXPECT_STREQ(matrixProblem(glm::mat4(1.0f)), "");
    EXPECT_STREQ(matrixProblem(composeTransform({1, 2, 3}, {10, 20, 30}, {-1, 2, 3})), "");
    glm::mat4 singular(1.0f);
    singular[1][1] = 0.0f;
    EXPECT_STREQ(matrixProblem(singular), "not invertible");
    glm::mat4 projective(1.0f);
    projective[2][3] = 1.0f;
    EXPECT_STRNE(matrixProblem(projective), "");
    glm::mat4 infinite(1.0f);
    infinite[3][0] = std::numeric_limits<float>::infinity();
    EXPECT_STREQ(matrixProblem(infinite), "not finite");
    glm::mat4 tiny(1e-20f);  // its float inverse overflows
    tiny[3][3] = 1.0f;
    EXPECT_STREQ(matrixProblem(tiny), "not invertible");
}

}  // namespace
}  // namespace penumbra::scene
