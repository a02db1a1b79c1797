// glTF's component and element types: sizes, names and decoding (see gltf_components.h).
#include "renderer/scene/gltf_components.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace penumbra::scene {

std::size_t componentSize(int type) {
    switch (type) {
        case kByte:
        case kUByte:
            return 1;
        case kShort:
        case kUShort:
            return 2;
        case kUInt:
        case kFloat:
            return 4;
        default:
            return 0;
    }
}

const char* componentName(int type) {
    switch (type) {
        case kByte:
            return "byte";
        case kUByte:
            return "unsigned byte";
        case kShort:
            return "short";
        case kUShort:
            return "unsigned short";
        case kUInt:
            return "unsigned int";
        case kFloat:
            return "float";
        default:
            return "unknown component type";
    }
}

const char* typeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return "SCALAR";
        case TINYGLTF_TYPE_VEC2:
            return "VEC2";
        case TINYGLTF_TYPE_VEC3:
            return "VEC3";
        case TINYGLTF_TYPE_VEC4:
            return "VEC4";
        case TINYGLTF_TYPE_MAT2:
            return "MAT2";
        case TINYGLTF_TYPE_MAT3:
            return "MAT3";
        case TINYGLTF_TYPE_MAT4:
            return "MAT4";
        default:
            return "unknown type";
    }
}

double decode(const unsigned char* p, int type, bool normalized) {
    switch (type) {
        case kByte: {
            std::int8_t v;
            std::memcpy(&v, p, 1);
            return normalized ? std::max(v / 127.0, -1.0) : v;
        }
        case kUByte:
            return normalized ? *p / 255.0 : *p;
        case kShort: {
            std::int16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? std::max(v / 32767.0, -1.0) : v;
        }
        case kUShort: {
            std::uint16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? v / 65535.0 : v;
        }
        case kUInt: {
            std::uint32_t v;
            std::memcpy(&v, p, 4);
            return v;
        }
        default: {
            float v;
            std::memcpy(&v, p, 4);
            return v;
        }
    }
}

}  // namespace penumbra::scene
