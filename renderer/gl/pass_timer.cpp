// Pass timing: see pass_timer.h.
#include "renderer/gl/pass_timer.h"

namespace penumbra::gl {

void PassTimer::begin(const std::string& name) {
    if (on_begin) on_begin(name);
    Pending p;
    p.name = name;
    if (software_) {
        glFinish();
        start_ = std::chrono::steady_clock::now();
    } else {
        if (pool_.empty()) {
            p.query = gl::createQuery(GL_TIME_ELAPSED, "pass timer");
        } else {
            p.query = std::move(pool_.back());
            pool_.pop_back();
        }
        glBeginQuery(GL_TIME_ELAPSED, p.query.id());
    }
    pending_.push_back(std::move(p));
}

void PassTimer::end() {
    if (software_) {
        glFinish();
        pending_.back().cpu_ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_)
                .count();
    } else {
        glEndQuery(GL_TIME_ELAPSED);
    }
}

std::vector<PassTime> PassTimer::finishFrame() {
    std::vector<PassTime> out;
    for (auto& p : pending_) {
        double ms = p.cpu_ms;
        if (!software_) {
            GLuint64 ns = 0;
            glGetQueryObjectui64v(p.query.id(), GL_QUERY_RESULT, &ns);
            ms = static_cast<double>(ns) * 1e-6;
            pool_.push_back(std::move(p.query));
        }
        out.push_back({p.name, ms});
    }
    pending_.clear();
    return out;
}

}  // namespace penumbra::gl
