// The estimator of the rendering equation for one camera path. GLSL only.
#ifndef RAYLAB_INTEGRATOR_GLSL
#define RAYLAB_INTEGRATOR_GLSL
#include "compat.glsl"
#include "random.glsl"
#include "frame.glsl"
#include "sampling.glsl"
#include "ray.glsl"
#include "sky.glsl"
#include "scene_data.glsl"
#include "scene_intersect.glsl"
#include "features.glsl"
#ifdef RAYLAB_FEATURE_TEXTURES
#include "scene_textures.glsl"
#endif

// Radiance along one camera path (Kajiya 1986). beta is the path throughput:
// the product of f·cosθ/pdf over the bounces so far.
vec3 traceRadiance(Ray ray, inout Rng rng, inout uint rays) {
    SkyParams sky = SkyParams(uSkyType, uSkyColor, uSkyTop, uSkyBottom);
    vec3 radiance = vec3(0.0f);
    vec3 beta = vec3(1.0f);
#ifdef RAYLAB_FEATURE_TEXTURES
    // Ray cone (Ray Tracing Gems ch. 20, §20.3.4): width grows by the pixel's spread angle per
    // unit distance; diffuse bounces keep that spread (a simplification that under-blurs).
    float coneWidth = 0.0f;
#endif
    for (int bounce = 0;; ++bounce) {
        Hit hit;
        ++rays;
        if (!intersectScene(ray, hit)) {
            radiance += beta * skyRadiance(sky, normalize(ray.dir));
            break;
        }
        GpuMaterial m = materials[hit.material];
        radiance += beta * m.emission.rgb;
        if (bounce >= uMaxBounces) break;
        vec3 albedo = m.albedo.rgb;
#ifdef RAYLAB_FEATURE_TEXTURES
        coneWidth += uCamPixelSpread * hit.t * length(ray.dir);
        uint albedoTexture = materialAlbedoTexture(hit.material);
        if (albedoTexture > 0u) {
            GpuTexture tex = textureRecord(albedoTexture - 1u);
            float cosine = dot(hit.normal, ray.dir) / length(ray.dir);
            float lod = rayConeLod(tex, hit.lodBase, coneWidth, cosine);
#ifdef RAYLAB_SHOW_MIP_LEVEL
            // Debug view: the level as a colour ramp (0 blue, 4 green, 8+ red).
            albedo = clamp(vec3(lod / 4.0f - 1.0f, 1.0f - abs(lod / 4.0f - 1.0f), 1.0f - lod / 4.0f), 0.0f, 1.0f);
#else
            albedo *= sampleTexture(tex, hit.uv, lod).rgb;
#endif
        }
        uint normalTexture = materialNormalTexture(hit.material);
        if (normalTexture > 0u) {
            // Tangent-space normal map: rgb in [0, 1] encodes (x, y, z) in [-1, 1] in the frame
            // (∂p/∂u, bitangent, shading normal), ∂p/∂u made orthogonal to the normal first.
            GpuTexture tex = textureRecord(normalTexture - 1u);
            float cosine = dot(hit.normal, ray.dir) / length(ray.dir);
            vec3 m = 2.0f * sampleTexture(tex, hit.uv, rayConeLod(tex, hit.lodBase, coneWidth, cosine)).rgb - 1.0f;
            vec3 t = hit.tangent - dot(hit.tangent, hit.shadingNormal) * hit.shadingNormal;
            if (dot(t, t) > 0.0f && dot(m, m) > 0.0f) {
                t = normalize(t);
                hit.shadingNormal = normalize(m.x * t + m.y * cross(hit.shadingNormal, t) + m.z * hit.shadingNormal);
            }
        }
#endif

        // Lambert, cosine-weighted: f·cosθ/pdf = (ρ/π)·cosθ / (cosθ/π) = ρ.
        // Sampled around the shading normal (smooth meshes), on the side the ray came from; a
        // direction below the geometric surface ends the path (it would leak through).
        vec3 n = dot(hit.normal, ray.dir) < 0.0f ? hit.normal : -hit.normal;
        vec3 ns = dot(hit.shadingNormal, n) < 0.0f ? -hit.shadingNormal : hit.shadingNormal;
        vec3 dir = frameToWorld(frameFromNormal(ns), sampleCosineHemisphere(rngNext2(rng)));
        if (dot(dir, n) <= 0.0f) break;
        beta *= albedo;

        // Russian roulette (pbrt-v4 §14.1.4 style): survive with q = max throughput, at most
        // 0.95, and divide by q so the estimate stays unbiased.
        if (bounce + 1 >= uRrDepth) {
            float q = min(max(beta.r, max(beta.g, beta.b)), 0.95f);
            if (rngNextFloat(rng) >= q) break;
            beta /= q;
        }
        ray = Ray(offsetRayOrigin(hit.position, n, hit.error), dir);
    }
    return radiance;
}

#endif
