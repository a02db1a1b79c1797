// Errors that carry the process exit code PRODUCT.md promises: bad input (2), a failed
// frame (1), no usable OpenGL backend (3). Messages name the file, key or flag at fault.
#pragma once

#include <stdexcept>
#include <string>

namespace penumbra {

enum class ExitCode : int { Ok = 0, RuntimeFailure = 1, BadInput = 2, NoBackend = 3 };

// Base: an error with a one-line message and the exit code it maps to.
class Error : public std::runtime_error {
public:
    Error(ExitCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
    ExitCode code() const { return code_; }

private:
    ExitCode code_;
};

// Bad command line, scene, asset or value: exit 2. The message starts with the file or flag.
class InputError : public Error {
public:
    explicit InputError(const std::string& message) : Error(ExitCode::BadInput, message) {}
};

// A frame failed at run time (GL error, write failure): exit 1.
class RuntimeError : public Error {
public:
    explicit RuntimeError(const std::string& message) : Error(ExitCode::RuntimeFailure, message) {}
};

// No usable OpenGL backend: exit 3.
class BackendError : public Error {
public:
    explicit BackendError(const std::string& message) : Error(ExitCode::NoBackend, message) {}
};

}  // namespace penumbra
