// Lets one source file be both GLSL 4.50 and C++20 (with GLM), so CPU tests run the very maths
// the shader runs. Rules for shared files: float literals with an `f`, no swizzles (.x is fine),
// out/inout parameters through RL_OUT/RL_INOUT, functions marked RL_FN, structs built GLSL-style
// as Type(a, b) (C++20 aggregate initialisation with parentheses).
#ifndef RAYLAB_COMPAT_GLSL
#define RAYLAB_COMPAT_GLSL

#ifdef __cplusplus
#include <glm/glm.hpp>
#define RL_FN inline
#define RL_OUT(T) T&
#define RL_INOUT(T) T&
#define RL_NAMESPACE_BEGIN namespace raylab::glsl { using namespace glm;
#define RL_NAMESPACE_END }
#else
#define RL_FN
#define RL_OUT(T) out T
#define RL_INOUT(T) inout T
#define RL_NAMESPACE_BEGIN
#define RL_NAMESPACE_END
#endif

RL_NAMESPACE_BEGIN
const float PI = 3.14159265358979f;
const float INV_PI = 0.318309886183791f;
const float FLOAT_MAX = 3.402823466e38f;
RL_NAMESPACE_END

#endif
