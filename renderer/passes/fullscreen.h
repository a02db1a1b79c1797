// Drawing a full-viewport triangle (glsl/passes/fullscreen.vert) with an attribute-less VAO.
#pragma once

#include "renderer/gl/handles.h"

namespace penumbra::passes {

class Fullscreen {
public:
    Fullscreen() : vao_(gl::createVertexArray("fullscreen")) {}
    void draw() const {
        glBindVertexArray(vao_.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
    }

private:
    gl::VertexArray vao_;
};

}  // namespace penumbra::passes
