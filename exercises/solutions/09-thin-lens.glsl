// Exercise thin-lens: a solution (pbrt-v4 §5.2.3).
Ray cameraRayThinLens(CameraBasis cam, vec2 ndc, vec2 lensSample, float lensRadius, float focusDistance) {
    vec3 d = cam.forward + (ndc.x * cam.tanHalfFovY * cam.aspect) * cam.right + (ndc.y * cam.tanHalfFovY) * cam.up;
    vec3 focus = cam.origin + focusDistance * d;
    vec2 lens = lensRadius * sampleDiskConcentric(lensSample);
    vec3 o = cam.origin + lens.x * cam.right + lens.y * cam.up;
    return Ray(o, normalize(focus - o));
}
