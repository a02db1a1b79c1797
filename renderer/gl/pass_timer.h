// Times passes with the clock the driver can be trusted with: GL timer queries on hardware,
// glFinish-bracketed CPU time on software rasterisers (whose timer queries close before the
// rasterisation they measure has run).
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include "renderer/gl/handles.h"

namespace penumbra::gl {

struct PassTime {
    std::string name;
    double ms = 0;
};

class PassTimer {
public:
    explicit PassTimer(bool software) : software_(software) {}
    // Called with each pass's name as it begins (progress display); may be empty.
    std::function<void(const std::string&)> on_begin;
    const char* clockName() const { return software_ ? "cpu_glfinish" : "gl_timer_query"; }
    void begin(const std::string& name);
    void end();
    // Resolves pending queries (hardware) and returns this frame's passes in order.
    std::vector<PassTime> finishFrame();

private:
    bool software_;
    struct Pending {
        std::string name;
        gl::Query query;
        double cpu_ms = 0;
    };
    std::vector<Pending> pending_;
    std::vector<gl::Query> pool_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace penumbra::gl
