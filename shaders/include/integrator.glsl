// The estimator of the rendering equation for one camera path. GLSL only.
#ifndef RAYLAB_INTEGRATOR_GLSL
#define RAYLAB_INTEGRATOR_GLSL
#include "compat.glsl"
#include "random.glsl"
#include "frame.glsl"
#include "sampling.glsl"
#include "ray.glsl"
#include "sky.glsl"
#include "bsdf.glsl"
#include "light_sampling.glsl"
#include "triangle_light.glsl"
#include "environment_map.glsl"
#include "scene_data.glsl"
#include "environment_sampling.glsl"
#include "scene_intersect.glsl"
#include "features.glsl"
#include "bsdf_lobes.glsl"
// The path inspector's RAYLAB_RECORD hooks: empty unless its variant defines RAYLAB_INSPECT_PATHS.
#include "path_record.glsl"
#include "light_selection.glsl"
#ifdef RAYLAB_FEATURE_TEXTURES
#include "material_textures.glsl"
#include "ray_cone.glsl"
#endif

// Radiance from the sky along a unit direction: the image texel it falls in (nearest, so the
// radiance is piecewise constant over texels), or the analytic skies.
vec3 skyLookup(SkyParams sky, vec3 dir) {
#ifndef RAYLAB_SKY_MAP
    return skyRadiance(sky, dir);
#else
    if (sky.type != SKY_MAP) return skyRadiance(sky, dir);
    ivec2 size = textureSize(uSkyMap, 0);
    vec2 uv = equirectFromDirection(dir, params.skyRotation);
    ivec2 texel = min(ivec2(uv * vec2(size)), size - ivec2(1));
    return params.skyMapScale * texelFetch(uSkyMap, texel, 0).rgb;
#endif
}

// Next-event estimation of the sky: the map by its own distribution, analytic skies uniformly.
#ifdef RAYLAB_SKY_MAP
bool skyByMap() { return params.skyType == SKY_MAP && params.envMeanWeight > 0.0f; }
#else
bool skyByMap() { return false; }
#endif
float skyLightPdf(vec3 dir) { return skyByMap() ? environmentPdf(dir) : UNIFORM_SPHERE_PDF; }

// Every radiance contribution goes through this hook, so the viewer's bounce views
// (debug_views.glsl) can keep only some bounces: RAYLAB_KEEP_BOUNCE(bounce) says which (bounce 0:
// the camera ray; a light sample taken at bounce k counts as k + 1). By default: all of them. The
// path inspector records the same verdict with each term, so its sum matches the filtered value.
#ifndef RAYLAB_KEEP_BOUNCE
#define RAYLAB_KEEP_BOUNCE(bounce) true
#endif
#define RAYLAB_ADD_RADIANCE(radiance, bounce, value) if (RAYLAB_KEEP_BOUNCE(bounce)) radiance += (value)

BsdfParams materialBsdf(GpuMaterial m) {
#if RAYLAB_STAGE < RAYLAB_STAGE_GGX
    return BsdfParams(m.albedo.rgb, vec3(0.0f), 1.0f, 0.0f, 1.0f);   // render.stage: Lambert only
#endif
    return BsdfParams(m.albedo.rgb, m.f0Ior.rgb, ggxAlpha(m.albedo.a), m.emission.a, m.f0Ior.a);
}

// Lights that next-event estimation picks from (light_selection.glsl): the emissive spheres and
// triangles by power, and the sky.
// Compiled in only when the host defines them (absent features cost nothing; on llvmpipe the mere
// presence of the light-sampling block, even never taken, cost about 2.5× in throughput):
// RAYLAB_NEE (render.nee), RAYLAB_GENERAL_BSDF (some material has f0 > 0 or transmission > 0),
// RAYLAB_SKY_MAP (sky.type map), RAYLAB_EMISSIVE_TRIANGLES (some mesh emits).
#ifdef RAYLAB_NEE
int neeLightCount() { return params.nee ? boundedLightCount() + (params.skyIsLight ? 1 : 0) : 0; }
#else
int neeLightCount() { return 0; }
#endif

// Density with which next-event estimation would have produced the direction from p that hit
// the emitter at q (an emissive sphere's surface): found as the light whose surface q lies on.
float emitterLightPdf(vec3 p, vec3 q) {
    int best = -1;
    float bestMiss = FLOAT_MAX;
    for (int i = 0; i < params.lightCount; ++i) {
        vec4 s = lights[i].centerRadius;
        float miss = abs(length(q - s.xyz) - s.w) / s.w;
        if (miss < bestMiss) {
            bestMiss = miss;
            best = i;
        }
    }
    if (best < 0 || bestMiss > 1e-3f) return 0.0f;
    vec4 s = lights[best].centerRadius;
    return sphereConePdf(p, s.xyz, s.w) * boundedLightPmf(best);
}

// The same for a ray from p (direction d, not unit) that hit a triangle: the light that triangle is
// (triangleLightIndex[], 1 + index; 0 for none) sampled by area, as a solid-angle density.
float triangleEmitterLightPdf(vec3 d, Hit hit) {
#ifdef RAYLAB_EMISSIVE_TRIANGLES
    uint light = triangleLightIndex[hit.primitive];
    if (light == 0u) return 0.0f;
    int j = int(light) - 1;
    float len = length(d);
    float dist = hit.t * len;
    float pdf = triangleLightPdf(dist * dist, dot(hit.normal, d) / len, triangleLights[j].p0Area.w);
    return pdf * boundedLightPmf(params.lightCount + j);
#else
    return 0.0f;
#endif
}

// Radiance along one camera path (Kajiya 1986). beta is the path throughput: the product of
// f·|cosθ|/pdf over the bounces so far. With params.nee, each bounce also adds a light sample; emission
// that a BSDF sample reaches is then weighted so nothing is counted twice (Veach 1997, §9.2).
vec3 traceRadiance(Ray ray, inout Rng rng, inout uint rays) {
    SkyParams sky = SkyParams(params.skyType, params.skyColor, params.skyTop, params.skyBottom);
    int lightCount = neeLightCount();
    vec3 radiance = vec3(0.0f);
    vec3 beta = vec3(1.0f);
    float prevPdf = 0.0f;      // BSDF density of the direction just followed
    bool prevDelta = true;     // camera rays and delta bounces: light sampling could not help
    vec3 prevPos = vec3(0.0f);
#ifdef RAYLAB_FEATURE_TEXTURES
    // Ray cone (Ray Tracing Gems ch. 20, §20.3.4): the width grows by the spread angle per unit
    // distance; the spread starts at the pixel's and widens at rough bounces (ray_cone.glsl).
    float coneWidth = 0.0f;
    float coneSpread = params.camPixelSpread;
#endif
    for (int bounce = 0;; ++bounce) {
        Hit hit;
        ++rays;
        bool found = intersectScene(ray, hit);
        RAYLAB_RECORD(recordSegment(bounce, ray, found, hit, beta));
        RAYLAB_RECORD(recordCounted(bounce, RAYLAB_KEEP_BOUNCE(bounce), RAYLAB_KEEP_BOUNCE(bounce + 1)));
        if (!found) {
#if RAYLAB_STAGE == RAYLAB_STAGE_PRIMARY
            break;   // render.stage primary: black sky, as the albedo view
#endif
            vec3 dir = normalize(ray.dir);
            float w = 1.0f;
#ifdef RAYLAB_NEE
            if (params.skyIsLight && lightCount > 0 && !prevDelta) {
                float lightPdf = skyLightPdf(dir) * skySelectionPmf();
                w = params.mis ? powerHeuristic(prevPdf, lightPdf) : (lightPdf > 0.0f ? 0.0f : 1.0f);
            }
#endif
            RAYLAB_ADD_RADIANCE(radiance, bounce, beta * skyLookup(sky, dir) * w);
            RAYLAB_RECORD(recordEmission(bounce, skyLookup(sky, dir), w));
            break;
        }
        GpuMaterial m = materials[hit.material];
#if RAYLAB_STAGE == RAYLAB_STAGE_PRIMARY
        // render.stage primary: the flat albedo of the first hit is the whole estimate (beta is 1).
        RAYLAB_ADD_RADIANCE(radiance, bounce, beta * m.albedo.rgb);
        RAYLAB_RECORD(recordStageAlbedo(bounce, m.albedo.rgb));
        break;
#endif
        vec3 Le = m.emission.rgb;
#ifdef RAYLAB_FEATURE_TEXTURES
        coneWidth += coneSpread * hit.t * length(ray.dir);
        Le *= materialEmissionScale(hit, ray.dir, coneWidth);
#endif
        if (max(Le.r, max(Le.g, Le.b)) > 0.0f) {
            float w = 1.0f;
#ifdef RAYLAB_NEE
            if (lightCount > 0 && !prevDelta) {
#ifdef RAYLAB_EMISSIVE_TRIANGLES
                float lightPdf = instances[hit.instance].info.x == INSTANCE_SPHERE
                                     ? emitterLightPdf(prevPos, hit.position)
                                     : triangleEmitterLightPdf(ray.dir, hit);
#else
                float lightPdf = emitterLightPdf(prevPos, hit.position);   // only spheres are lights
#endif
                w = params.mis ? powerHeuristic(prevPdf, lightPdf) : (lightPdf > 0.0f ? 0.0f : 1.0f);
            }
#endif
            RAYLAB_ADD_RADIANCE(radiance, bounce, beta * Le * w);
            RAYLAB_RECORD(recordEmission(bounce, Le, w));
        }
        if (bounce >= params.maxBounces || RAYLAB_STAGE == RAYLAB_STAGE_EMISSION) break;
        BsdfParams bsdf = materialBsdf(m);
#ifdef RAYLAB_FEATURE_TEXTURES
        applyMaterialTextures(hit, ray.dir, coneWidth, bsdf);
#endif
        // The BSDF works in the shading frame (smooth or normal-mapped normals), turned to the
        // geometric normal's side; it tells inside from outside by the sign of wo.z.
        vec3 ns = dot(hit.shadingNormal, hit.normal) < 0.0f ? -hit.shadingNormal : hit.shadingNormal;
        Frame frame = frameFromNormal(ns);
        vec3 wo = frameToLocal(frame, -normalize(ray.dir));
        // Which side of the true (geometric) surface the path arrived on.
        float arrivalSide = dot(-ray.dir, hit.normal);
        RAYLAB_RECORD(recordShadingFrame(bounce, ns));

#ifdef RAYLAB_NEE
        // Next-event estimation: one light, picked by power (the sky: see light_selection.glsl),
        // sampled by solid angle (spheres, sky) or by area (triangles).
        if (lightCount > 0) {
            float selectPmf;
            int k = selectLight(rng, selectPmf);
            vec2 ul = rngNext2(rng);
            vec3 wiW = vec3(0.0f);
            vec3 Ll = vec3(0.0f);
            float lightPdf = 0.0f;   // density the direction was drawn with (divides)
            float misPdf = 0.0f;     // density the BSDF side sees for it (weights only)
            float tMax = FLOAT_MAX;
            vec3 lightPoint = vec3(0.0f);   // triangle lights: the point sampled
            if (k >= params.lightCount) {
#ifdef RAYLAB_EMISSIVE_TRIANGLES
                GpuTriangleLight tl = triangleLights[k - params.lightCount];
                vec3 p0 = tl.p0Area.xyz;
                lightPoint = sampleTrianglePoint(p0, tl.p1.xyz, tl.p2.xyz, ul);
                vec3 d = lightPoint - hit.position;
                float dist2 = dot(d, d);
                if (dist2 > 0.0f) {
                    wiW = d / sqrt(dist2);
                    lightPdf = triangleLightPdf(dist2, dot(normalize(cross(tl.p1.xyz - p0, tl.p2.xyz - p0)), wiW),
                                                tl.p0Area.w);
                    Ll = tl.radiance.rgb;
                }
                misPdf = lightPdf;
#endif
            } else if (k >= 0) {
                vec4 s = lights[k].centerRadius;
                lightPdf = sphereConePdf(hit.position, s.xyz, s.w);
                if (lightPdf > 0.0f) {
                    wiW = sphereConeSample(hit.position, s.xyz, s.w, ul);
                    Ll = lights[k].radiance.rgb;
                }
                misPdf = lightPdf;
            } else if (skyByMap()) {
                vec2 uv;
                wiW = sampleEnvironment(ul, lightPdf, uv);
                misPdf = skyLightPdf(wiW);   // equal but at texel edges, where it re-maps
                Ll = skyLookup(sky, wiW);
            } else {
                wiW = sampleUniformSphere(ul);
                lightPdf = UNIFORM_SPHERE_PDF;
                misPdf = lightPdf;
                Ll = skyLookup(sky, wiW);
            }
            lightPdf *= selectPmf;
            misPdf *= selectPmf;
            vec3 wiL = frameToLocal(frame, wiW);
            vec3 f = lightPdf > 0.0f ? bsdfEval(bsdf, wo, wiL) : vec3(0.0f);
            // A direction the shading frame calls reflected but the geometry calls transmitted
            // (or the reverse) would leak light through the surface: drop it.
            if ((wiL.z * wo.z > 0.0f) != (dot(wiW, hit.normal) * arrivalSide > 0.0f)) f = vec3(0.0f);
            if (max(f.r, max(f.g, f.b)) > 0.0f) {
                vec3 side = dot(wiW, hit.normal) > 0.0f ? hit.normal : -hit.normal;
                Ray shadow = Ray(offsetRayOrigin(hit.position, side, hit.error), wiW);
                if (k >= params.lightCount) {
                    // Stop just short of the light's own triangle.
                    tMax = dot(lightPoint - shadow.origin, wiW) * (1.0f - 1e-4f);
                    if (!(tMax > 0.0f)) tMax = -1.0f;
                } else if (k >= 0) {
                    // Stop just short of the light's own surface.
                    vec4 s = lights[k].centerRadius;
                    float t = intersectSphere(shadow, s.xyz, s.w, 0.0f, FLOAT_MAX);
                    tMax = t > 0.0f ? t * (1.0f - 1e-4f) : -1.0f;
                }
                ++rays;
                bool visible = tMax > 0.0f && !occluded(shadow, tMax);
                if (visible) {
                    float w = params.mis ? powerHeuristic(misPdf, bsdfPdf(bsdf, wo, wiL)) : 1.0f;
                    RAYLAB_ADD_RADIANCE(radiance, bounce + 1, beta * f * Ll * (w / lightPdf));
                }
                RAYLAB_RECORD(recordLight(bounce, k, wiW, k >= 0 ? tMax : -1.0f, Ll, f, abs(wiL.z), lightPdf,
                                          misPdf, bsdfPdf(bsdf, wo, wiL), visible ? 1 : 0));
            } else {
                RAYLAB_RECORD(recordLight(bounce, k, wiW, -1.0f, Ll, f, abs(wiL.z), lightPdf, misPdf, 0.0f, 2));
            }
        }

#endif
        // BSDF sample. Pure Lambert (f0 0, no glass) takes the short path of the foundation: the
        // same random numbers and f·cos/pdf = ρ exactly, without the general code's cost.
        vec2 u = rngNext2(rng);
        BsdfSample bs;
#ifdef RAYLAB_GENERAL_BSDF
        if (!bsdfNeedsLobeChoice(bsdf)) {
#else
        {   // every material of the scene is Lambertian
#endif
            vec3 wi = sampleCosineHemisphere(u);
            bs = BsdfSample(wo.z < 0.0f ? vec3(wi.x, wi.y, -wi.z) : wi, bsdf.albedo, pdfCosineHemisphere(wi.z),
                            LOBE_DIFFUSE, false);
        }
#ifdef RAYLAB_GENERAL_BSDF
        else {
            bs = bsdfSample(bsdf, wo, vec3(u.x, u.y, rngNextFloat(rng)));
        }
#endif
        vec3 dir = frameToWorld(frame, bs.wi);
        // f·|cosθ| as the sampler used it (weight × pdf): a second bsdfEval of a narrow GGX lobe
        // differs from the sampler's by rounding the peak amplifies (5e-5 at α 0.0025 on llvmpipe),
        // and the inspector's columns must multiply out to the weight the throughput took.
        RAYLAB_RECORD(recordBsdfSample(bounce, dir, bs.lobe, bsdfLobeProbability(bsdf, wo, bs.lobe), bs.weight * bs.pdf,
                                       abs(bs.wi.z), bs.weight, bs.pdf, bs.delta));
        if (bs.lobe == LOBE_NONE) break;
        // As for light samples: the geometric surface must agree with the lobe's side.
        if ((bs.wi.z * wo.z > 0.0f) != (dot(dir, hit.normal) * arrivalSide > 0.0f)) break;
        beta *= bs.weight;
#ifdef RAYLAB_FEATURE_TEXTURES
        coneSpread += rayConeBounceSpread(bs.lobe, bs.delta, bsdf.alpha);
#endif
        prevPdf = bs.pdf;
        prevDelta = bs.delta;
        prevPos = hit.position;
        RAYLAB_RECORD(recordThroughput(bounce, beta, bs.delta));

        // Russian roulette (pbrt-v4 §14.1.4 style): survive with q = max throughput, at most
        // 0.95, and divide by q so the estimate stays unbiased.
        if (bounce + 1 >= params.rrDepth) {
            float q = min(max(beta.r, max(beta.g, beta.b)), 0.95f);
            bool survived = !(rngNextFloat(rng) >= q);   // a NaN q survives (the NaN guard counts it)
            RAYLAB_RECORD(recordRoulette(bounce, q, survived));
            if (!survived) break;
            beta /= q;
            RAYLAB_RECORD(recordThroughput(bounce, beta, bs.delta));
        }
        vec3 side = dot(dir, hit.normal) > 0.0f ? hit.normal : -hit.normal;
        ray = Ray(offsetRayOrigin(hit.position, side, hit.error), dir);
    }
    return radiance;
}

#endif
