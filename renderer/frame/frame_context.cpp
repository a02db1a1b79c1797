// Frame context: see frame_context.h.
#include "renderer/frame/frame_context.h"

#include "renderer/gl/debug.h"

namespace penumbra::frame {

void FrameContext::pass(const std::string& name, const std::function<void()>& fn) {
    std::string full = name;
    if (light >= 0 && lights.size() > 1) {
        full += '@';
        full += std::to_string(light);
    }
    gl::DebugGroup group(full);
    timer_.begin(full);
    fn();
    timer_.end();
    gl::checkErrors(full);
}

}  // namespace penumbra::frame
