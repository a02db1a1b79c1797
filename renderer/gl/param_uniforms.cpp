// Parameters as uniforms and #defines: see param_uniforms.h.
#include "renderer/gl/param_uniforms.h"

#include <stdexcept>
#include <string>

namespace penumbra::gl {
namespace {

// The value of an Int, Bool or Enum parameter as an integer (an enum: its choice's index).
int integerValue(const ParamSpec& s, const Params& params) {
    switch (s.type) {
        case ParamType::Int:
            return params.getInt(s.key);
        case ParamType::Bool:
            return params.getBool(s.key) ? 1 : 0;
        case ParamType::Enum: {
            const std::string value = params.getString(s.key);
            for (size_t i = 0; i < s.choices.size(); ++i)
                if (s.choices[i] == value) return static_cast<int>(i);
            break;
        }
        case ParamType::Float:
        case ParamType::String:
            break;
    }
    throw std::logic_error("parameter '" + std::string(s.key) + "' has no integer GPU value");
}

}  // namespace

int setParamUniforms(const Program& program, std::span<const ParamSpec> specs,
                     const Params& params) {
    const auto& declared = programUniforms(program);
    int count = 0;
    for (const auto& s : specs) {
        if (s.gpu != ParamGpu::Uniform) continue;
        const std::string name = paramGpuName(s);
        if (!declared.count(name)) continue;
        if (s.type == ParamType::Float)
            setUniform(program, name.c_str(), static_cast<float>(params.getFloat(s.key)));
        else
            setUniform(program, name.c_str(), integerValue(s, params));
        ++count;
    }
    return count;
}

Defines paramDefines(std::span<const ParamSpec> specs, const Params& params) {
    Defines out;
    for (const auto& s : specs)
        if (s.gpu == ParamGpu::Define)
            out.emplace_back(paramGpuName(s), std::to_string(integerValue(s, params)));
    return out;
}

}  // namespace penumbra::gl
