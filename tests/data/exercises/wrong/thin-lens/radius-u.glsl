Ray cameraRayThinLens(CameraBasis cam, vec2 ndc, vec2 lensSample, float lensRadius, float focusDistance) {
    vec3 d = cam.forward + (ndc.x * cam.tanHalfFovY * cam.aspect) * cam.right + (ndc.y * cam.tanHalfFovY) * cam.up;
    vec3 focus = cam.origin + focusDistance * d;
    float r = lensRadius * lensSample.x;
    float phi = 2.0 * PI * lensSample.y;
    vec3 o = cam.origin + r * cos(phi) * cam.right + r * sin(phi) * cam.up;
    return Ray(o, normalize(focus - o));
}
