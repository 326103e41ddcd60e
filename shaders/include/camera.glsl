// Pinhole camera: a ray through a point of the image plane at distance 1; thin lens: the same
// ray's point at the focus distance, seen from a point of the lens disk.
#ifndef RAYLAB_CAMERA_GLSL
#define RAYLAB_CAMERA_GLSL
#include "compat.glsl"
#include "ray.glsl"
#include "sampling.glsl"
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

// Thin lens (pbrt-v4 PerspectiveCamera::GenerateRay, §5.2.3): the lens is a disk of radius
// lensRadius around the eye across the view, sampled uniformly by the concentric map; every ray
// through a pixel meets the pinhole ray of that pixel on the plane focusDistance ahead, which is
// therefore sharp. lensRadius 0 gives the pinhole ray exactly (direction normalised the same way).
#ifdef RAYLAB_EXERCISE_THIN_LENS
#include RAYLAB_EXERCISE_THIN_LENS   // a pupil's cameraRayThinLens (exercises/README.md)
#else
RL_FN Ray cameraRayThinLens(CameraBasis cam, vec2 ndc, vec2 lensSample, float lensRadius, float focusDistance) {
    vec3 d = cam.forward + (ndc.x * cam.tanHalfFovY * cam.aspect) * cam.right +
             (ndc.y * cam.tanHalfFovY) * cam.up;   // its forward component is 1
    vec3 focus = cam.origin + focusDistance * d;
    vec2 lens = lensRadius * sampleDiskConcentric(lensSample);
    vec3 o = cam.origin + lens.x * cam.right + lens.y * cam.up;
    return Ray(o, normalize(focus - o));
}
#endif

RL_NAMESPACE_END
#endif
