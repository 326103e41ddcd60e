// Orthonormal basis around a unit normal, without the singularity of a fixed "up" vector:
// Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017, listing 3.
#ifndef RAYLAB_FRAME_GLSL
#define RAYLAB_FRAME_GLSL
#include "compat.glsl"
RL_NAMESPACE_BEGIN

struct Frame {
    vec3 t;   // tangent
    vec3 b;   // bitangent
    vec3 n;   // normal (local +z)
};

RL_FN Frame frameFromNormal(vec3 n) {
    float s = n.z >= 0.0f ? 1.0f : -1.0f;   // copysign(1, n.z); sign() would give 0 at n.z = 0
    float a = -1.0f / (s + n.z);
    float b = n.x * n.y * a;
    vec3 t = vec3(1.0f + s * n.x * n.x * a, s * b, -s * n.x);
    vec3 bt = vec3(b, s + n.y * n.y * a, -n.y);
    return Frame(t, bt, n);
}

RL_FN vec3 frameToWorld(Frame f, vec3 v) { return f.t * v.x + f.b * v.y + f.n * v.z; }
RL_FN vec3 frameToLocal(Frame f, vec3 v) { return vec3(dot(v, f.t), dot(v, f.b), dot(v, f.n)); }

RL_NAMESPACE_END
#endif
