// A technique's parameters on the GPU: the ones its table marks `uniform` uploaded to a program
// in one call, and the ones marked `define` as the #defines a program is built with (see
// ParamSpec::gpu in renderer/core/params.h).
#pragma once

#include <span>

#include "renderer/core/params.h"
#include "renderer/gl/program.h"

namespace penumbra::gl {

// Sets every Uniform parameter of SPECS that PROGRAM's shaders declare to its value in PARAMS
// (Int and Enum as int, the enum's index; Bool as int 0 or 1; Float as float). Returns how many.
int setParamUniforms(const Program& program, std::span<const ParamSpec> specs,
                     const Params& params);

// `NAME value` for every Define parameter of SPECS (Int as its value, Bool 1 or 0, Enum its
// index).
Defines paramDefines(std::span<const ParamSpec> specs, const Params& params);

}  // namespace penumbra::gl
