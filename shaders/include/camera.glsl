// Pinhole camera: a ray through a point of the image plane at distance 1.
#ifndef RAYLAB_CAMERA_GLSL
#define RAYLAB_CAMERA_GLSL
#include "compat.glsl"
#include "ray.glsl"
RL_NAMESPACE_BEGIN

struct CameraBasis {
    vec3 origin;
    vec3 right;     // unit, image +x
    vec3 up;        // unit, image +y
    vec3 forward;   // unit, viewing direction
    float tanHalfFovY;
    float aspect;   // width / height
};

RL_FN CameraBasis cameraBasis(vec3 position, vec3 lookAt, vec3 upHint, float fovYDegrees,
                              float aspect) {
    vec3 forward = normalize(lookAt - position);
    vec3 right = normalize(cross(forward, upHint));
    vec3 up = cross(right, forward);
    return CameraBasis(position, right, up, forward, tan(radians(fovYDegrees) * 0.5f), aspect);
}

// ndc in [-1, 1]²: (-1, -1) is the bottom-left corner of the image, (1, 1) the top-right.
RL_FN Ray cameraRay(CameraBasis cam, vec2 ndc) {
    vec3 d = cam.forward + (ndc.x * cam.tanHalfFovY * cam.aspect) * cam.right +
             (ndc.y * cam.tanHalfFovY) * cam.up;
    return Ray(cam.origin, normalize(d));
}

RL_NAMESPACE_END
#endif
