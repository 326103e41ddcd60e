// Exercise thin-lens · level first-year university · about 50 minutes.
// A camera ray through a thin lens: depth of field. (pbrt-v4 §5.2.3, PerspectiveCamera with a
// lens; Ray Tracing in One Weekend §13.)
//
// cam.origin is the centre of the lens; cam.right, cam.up, cam.forward are unit vectors; the
// pinhole ray through the image point ndc ∈ [-1, 1]² has direction
//     d = cam.forward + ndc.x·cam.tanHalfFovY·cam.aspect·cam.right + ndc.y·cam.tanHalfFovY·cam.up.
// Everything on the plane focusDistance ahead of the lens (along cam.forward) is sharp: every ray
// of the pixel passes through the pinhole ray's point on that plane. Pick the ray's origin
// uniformly on the lens disk of radius lensRadius (centre cam.origin, spanned by right and up) from
// the two uniform numbers lensSample, and aim it at that point. Return Ray(origin, unit direction).
// sampleDiskConcentric(u) (sampling.glsl) gives a uniform point on the unit disk.
Ray cameraRayThinLens(CameraBasis cam, vec2 ndc, vec2 lensSample, float lensRadius, float focusDistance) {
    return Ray(cam.origin, cam.forward);   // replace: every pixel looks straight ahead
}
