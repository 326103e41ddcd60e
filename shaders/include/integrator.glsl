// The estimator of the rendering equation for one camera path. GLSL only.
#ifndef RAYLAB_INTEGRATOR_GLSL
#define RAYLAB_INTEGRATOR_GLSL
#include "compat.glsl"
#include "sampler.glsl"
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
#include "russian_roulette.glsl"
// The path inspector's RAYLAB_RECORD hooks: empty unless its variant defines RAYLAB_INSPECT_PATHS.
#include "path_record.glsl"
#include "light_selection.glsl"
#if RAYLAB_FEATURE_TEXTURES
#include "material_textures.glsl"
#include "ray_cone.glsl"
#endif

// Radiance from the sky along a unit direction: the image texel it falls in (nearest, so the
// radiance is piecewise constant over texels), or the analytic skies.
vec3 skyLookup(SkyParams sky, vec3 dir) {
#if !RAYLAB_SKY_MAP
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
#if RAYLAB_SKY_MAP
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
    return BsdfParams(m.albedo.rgb, vec3(0.0f), 1.0f, 0.0f, 1.0f, RAYLAB_DIFFUSE_SAMPLING,
                      RAYLAB_GGX_SAMPLING);   // render.stage: Lambert only
#endif
    return BsdfParams(m.albedo.rgb, m.f0Ior.rgb, ggxAlpha(m.albedo.a), m.emission.a, m.f0Ior.a,
                      RAYLAB_DIFFUSE_SAMPLING, RAYLAB_GGX_SAMPLING);
}

// Lights that next-event estimation picks from (light_selection.glsl): the emissive spheres and
// triangles by power, and the sky. Each part is compiled in only when the host defines its feature,
// because llvmpipe pays for the light-sampling block even where it is never taken: RAYLAB_NEE
// (render.nee), RAYLAB_GENERAL_BSDF (some material has f0 > 0 or transmission > 0), RAYLAB_SKY_MAP
// (sky.type map), RAYLAB_EMISSIVE_TRIANGLES (some mesh emits), RAYLAB_SPHERE_LIGHTS (some sphere
// emits), RAYLAB_SKY_LIGHT (the sky may emit).
#if RAYLAB_NEE
int neeLightCount() { return params.nee ? boundedLightCount() + (skyIsLight() ? 1 : 0) : 0; }
#else
int neeLightCount() { return 0; }
#endif

// Density with which next-event estimation would have produced the direction from p that hit
// sphere k: the light that sphere is (its record's info.z, 1 + its index; 0 for none), by its cone.
float emitterLightPdf(vec3 p, uint k) {
#if RAYLAB_SPHERE_LIGHTS
    uint light = sphereAt(k).info.z;
    if (light == 0u) return 0.0f;
    vec4 s = lights[light - 1u].centerRadius;
    return sphereConePdf(p, s.xyz, s.w) * boundedLightPmf(int(light - 1u));
#else
    return 0.0f;
#endif
}

// The same for a ray from p (direction d, not unit) that hit a triangle: the light that triangle is
// (triangleLightIndexAt, 1 + index; 0 for none) as sampleTriangleLight draws it, a solid-angle density.
float triangleEmitterLightPdf(vec3 p, vec3 d, Hit hit) {
#if RAYLAB_EMISSIVE_TRIANGLES
    uint light = triangleLightIndexAt(hit.primitive);
#if RAYLAB_ONE_SIDED_EMITTERS
    light &= ~TRIANGLE_FRONT_ONLY;
#endif
    if (light == 0u) return 0.0f;
    int j = int(light) - 1;
    float len = length(d);
    float dist = hit.t * len;
    GpuTriangleLight tl = triangleLightAt(j);
    float pdf = triangleLightDirectionPdf(p, tl.p0Area.xyz, tl.p1.xyz, tl.p2.xyz, tl.p0Area.w, dist * dist,
                                          dot(hit.normal, d) / len);
    return pdf * boundedLightPmf(sphereLightCount() + j);
#else
    return 0.0f;
#endif
}

// Whether the surface a ray hit emits nothing on the side the ray came from: the back of a mesh
// with emission_sides front.
bool emitterBackFace(vec3 rayDir, Hit hit) {
#if RAYLAB_ONE_SIDED_EMITTERS
    return (RAYLAB_FEATURE_SPHERES == 0 || instances[hit.instance].info.x == INSTANCE_MESH) &&
           (triangleLightIndexAt(hit.primitive) & TRIANGLE_FRONT_ONLY) != 0u && dot(rayDir, hit.normal) >= 0.0f;
#else
    return false;
#endif
}

// What multiple importance sampling needs of the bounce that sent the current ray.
struct PrevBounce {
    float pdf;       // BSDF density of the direction it followed
    bool delta;      // a camera ray or a delta lobe: light sampling could not have found it
    vec3 position;   // where it left from
};

// Weight of emission a BSDF sample reached where a light sample would have drawn it with density
// lightPdf: the power heuristic with MIS; without, the light sample alone counts what it can find.
float bsdfHitWeight(float bsdfPdf, float lightPdf) {
    return params.mis ? powerHeuristic(bsdfPdf, lightPdf) : (lightPdf > 0.0f ? 0.0f : 1.0f);
}

// That weight for the sky a ray escaped to (unit direction dir).
float skyHitWeight(vec3 dir, PrevBounce prev, int lightCount) {
    float w = 1.0f;
#if RAYLAB_NEE
    if (skyIsLight() && lightCount > 0 && !prev.delta)
        w = bsdfHitWeight(prev.pdf, skyLightPdf(dir) * skySelectionPmf());
#endif
    return w;
}

#if RAYLAB_ANALYTIC_LIGHTS
// Radiance of the distant lights with a disc (angular radius > 0) that a ray leaving the scene
// along unit dir looks into, each weighted against its light sample like the sky.
vec3 distantLightsSeen(vec3 dir, PrevBounce prev, int lightCount) {
    vec3 L = vec3(0.0f);
    for (int a = 0; a < analyticLightCount(); ++a) {
        GpuAnalyticLight l = analyticLights[a];
        float oneMinusCos = l.axis.w;
        if (int(l.positionType.w) != ANALYTIC_LIGHT_DISTANT || !(oneMinusCos > 0.0f) ||
            !insideCone(dir, l.axis.xyz, oneMinusCos))
            continue;
        float w = 1.0f;
#if RAYLAB_NEE
        if (lightCount > 0 && !prev.delta)
            w = bsdfHitWeight(prev.pdf, uniformConePdf(oneMinusCos) * boundedLightPmf(firstAnalyticLight() + a));
#endif
        L += l.emitted.rgb * w;
    }
    return L;
}
#endif

// That weight for an emitting surface a ray hit.
float surfaceHitWeight(Ray ray, Hit hit, PrevBounce prev, int lightCount) {
    float w = 1.0f;
#if RAYLAB_NEE
    if (lightCount > 0 && !prev.delta) {
#if RAYLAB_EMISSIVE_TRIANGLES
#if RAYLAB_FEATURE_SPHERES
        float lightPdf = instances[hit.instance].info.x == INSTANCE_SPHERE
                             ? emitterLightPdf(prev.position, hit.primitive)
                             : triangleEmitterLightPdf(prev.position, ray.dir, hit);
#else
        // No spheres: no sphere lights, and no per-lane read of the hit's instance (bench/mesh_rays.md).
        float lightPdf = triangleEmitterLightPdf(prev.position, ray.dir, hit);
#endif
#else
        float lightPdf = emitterLightPdf(prev.position, hit.primitive);   // only spheres are lights
#endif
        w = bsdfHitWeight(prev.pdf, lightPdf);
    }
#endif
    return w;
}

// A hit as the BSDF sees it. The BSDF works in the shading frame (smooth or normal-mapped normals),
// turned to the geometric normal's side; it tells inside from outside by the sign of wo.z.
struct ShadingPoint {
    BsdfParams bsdf;
    Frame frame;
    vec3 wo;             // towards where the path came from, shading frame
    float arrivalSide;   // > 0: the path arrived on the geometric normal's side
};

ShadingPoint shadingPoint(BsdfParams bsdf, Hit hit, vec3 rayDir) {
    vec3 ns = dot(hit.shadingNormal, hit.normal) < 0.0f ? -hit.shadingNormal : hit.shadingNormal;
    Frame frame = frameFromNormal(ns);
    return ShadingPoint(bsdf, frame, frameToLocal(frame, -normalize(rayDir)), dot(-rayDir, hit.normal));
}

// Whether the shading frame and the geometric surface agree on the side of a direction wi (local
// and world): where they do not, following it would leak light through the surface.
bool sidesAgree(ShadingPoint sp, vec3 wiLocal, vec3 wiWorld, vec3 geometricNormal) {
    return (wiLocal.z * sp.wo.z > 0.0f) == (dot(wiWorld, geometricNormal) * sp.arrivalSide > 0.0f);
}

// A ray leaving the hit along dir, from the side of the surface dir points to.
Ray spawnRay(Hit hit, vec3 dir) {
    vec3 side = dot(dir, hit.normal) > 0.0f ? hit.normal : -hit.normal;
    return Ray(offsetRayOrigin(hit.position, side, hit.error), dir);
}

// A direction towards light k (-1: the sky) from p.
struct LightSample {
    vec3 wi;        // world, unit
    vec3 L;         // radiance arriving along wi
    float pdf;      // solid-angle density wi was drawn with (divides)
    float misPdf;   // density the BSDF side sees for wi (weights only)
    vec3 point;     // triangle lights: the point sampled
};

#if RAYLAB_ANALYTIC_LIGHTS
// Point and spot lights and a distant light without a disc are deltas (pbrt-v4 §12.1): their one
// direction has pdf 1 in the estimator, and FLOAT_MAX for MIS, so the power heuristic gives the
// light sample weight 1 (no BSDF sample can hit them). A distant disc is sampled as its cone.
LightSample sampleAnalyticLight(GpuAnalyticLight l, vec3 p, vec2 u) {
    LightSample ls = LightSample(vec3(0.0f), vec3(0.0f), 1.0f, FLOAT_MAX, vec3(0.0f));
    int type = int(l.positionType.w);
    if (type == ANALYTIC_LIGHT_DISTANT) {
        float oneMinusCos = l.axis.w;
        ls.wi = l.axis.xyz;
        if (oneMinusCos > 0.0f) {
            ls.wi = sampleUniformCone(l.axis.xyz, oneMinusCos, u);
            ls.pdf = uniformConePdf(oneMinusCos);
            ls.misPdf = ls.pdf;
        }
        ls.L = l.emitted.rgb;
        return ls;
    }
    ls.point = l.positionType.xyz;
    vec3 d = ls.point - p;
    float dist2 = dot(d, d);
    if (!(dist2 > 0.0f)) {
        ls.pdf = 0.0f;
        return ls;
    }
    ls.wi = d / sqrt(dist2);
    // Intensity to radiance at p: I / r² (the inverse-square law).
    ls.L = l.emitted.rgb / dist2;
    if (type == ANALYTIC_LIGHT_SPOT) ls.L *= spotFalloff(dot(-ls.wi, l.axis.xyz), l.axis.w, l.emitted.w);
    return ls;
}
#endif

// Spheres by the cone they subtend, triangles by solid angle or area (triangle_light.glsl), the sky map by its distribution and an
// analytic sky uniformly; a pdf of 0 means no direction.
LightSample sampleLight(int k, vec3 p, vec2 u, SkyParams sky) {
#if RAYLAB_ANALYTIC_LIGHTS
    if (k >= firstAnalyticLight()) return sampleAnalyticLight(analyticLights[k - firstAnalyticLight()], p, u);
#endif
    LightSample ls = LightSample(vec3(0.0f), vec3(0.0f), 0.0f, 0.0f, vec3(0.0f));
    if (k >= sphereLightCount()) {
#if RAYLAB_EMISSIVE_TRIANGLES
        GpuTriangleLight tl = triangleLightAt(k - sphereLightCount());
        vec3 p0 = tl.p0Area.xyz;
        ls.pdf = sampleTriangleLight(p, p0, tl.p1.xyz, tl.p2.xyz, tl.p0Area.w, u, ls.wi, ls.point);
        if (ls.pdf > 0.0f) {
            ls.L = tl.radiance.rgb;
#if RAYLAB_ONE_SIDED_EMITTERS
            // The front faces along (p1 − p0) × (p2 − p0); p behind it receives nothing.
            if (tl.radiance.a > 0.0f && dot(cross(tl.p1.xyz - p0, tl.p2.xyz - p0), ls.wi) >= 0.0f) ls.L = vec3(0.0f);
#endif
        }
        ls.misPdf = ls.pdf;
#endif
        return ls;
    }
#if RAYLAB_SPHERE_LIGHTS
    if (k >= 0) {
        vec4 s = lights[k].centerRadius;
        ls.pdf = sphereConePdf(p, s.xyz, s.w);
        if (ls.pdf > 0.0f) {
            ls.wi = sphereConeSample(p, s.xyz, s.w, u);
            ls.L = lights[k].radiance.rgb;
        }
        ls.misPdf = ls.pdf;
        return ls;
    }
#endif
#if RAYLAB_SKY_LIGHT
    if (skyByMap()) {
        vec2 uv;
        ls.wi = sampleEnvironment(u, ls.pdf, uv);
        ls.misPdf = skyLightPdf(ls.wi);   // equal but at texel edges, where it re-maps
        ls.L = skyLookup(sky, ls.wi);
    } else {
        ls.wi = sampleUniformSphere(u);
        ls.pdf = UNIFORM_SPHERE_PDF;
        ls.misPdf = ls.pdf;
        ls.L = skyLookup(sky, ls.wi);
    }
#endif
    return ls;
}

// Where a shadow ray towards light k must stop so that it does not hit the light itself: just
// short of its surface (-1 when the ray misses it); the sky is at infinity.
float shadowRayEnd(int k, Ray shadow, vec3 lightPoint) {
#if RAYLAB_ANALYTIC_LIGHTS
    // A distant light is at infinity; point and spot lights end at their point, as triangles.
    if (k >= firstAnalyticLight() && int(analyticLights[k - firstAnalyticLight()].positionType.w) == ANALYTIC_LIGHT_DISTANT)
        return FLOAT_MAX;
#endif
    if (k >= sphereLightCount()) {
        float tMax = dot(lightPoint - shadow.origin, shadow.dir) * (1.0f - 1e-4f);
        return tMax > 0.0f ? tMax : -1.0f;
    }
#if RAYLAB_SPHERE_LIGHTS
    if (k >= 0) {
        vec4 s = lights[k].centerRadius;
        float t = intersectSphere(shadow, s.xyz, s.w, 0.0f, FLOAT_MAX);
        return t > 0.0f ? t * (1.0f - 1e-4f) : -1.0f;
    }
#endif
    return FLOAT_MAX;
}

// Next-event estimation at a hit (pbrt-v4 PathIntegrator::SampleLd): one light picked by power
// (light_selection.glsl), a direction towards it, the shadow ray, and the MIS weight against the
// BSDF sample that could have found the same light (Veach 1997, §9.2). True when the light is seen;
// Ld is then the path's contribution through it, beta included.
bool sampleLd(Hit hit, ShadingPoint sp, SkyParams sky, vec3 beta, int bounce, inout Sampler smp, inout uint rays,
              out vec3 Ld) {
    Ld = vec3(0.0f);
    float selectPmf;
    vec2 u = sample2D(smp, sampleDim(bounce, SAMPLE_BOUNCE_LIGHT));
    int k = selectLight(smp, u.x, selectPmf);
    LightSample ls = sampleLight(k, hit.position, u, sky);
    float lightPdf = ls.pdf * selectPmf;
    float misPdf = ls.misPdf * selectPmf;
    vec3 wiL = frameToLocal(sp.frame, ls.wi);
    vec3 f = lightPdf > 0.0f ? bsdfEval(sp.bsdf, sp.wo, wiL) : vec3(0.0f);
    if (!sidesAgree(sp, wiL, ls.wi, hit.normal)) f = vec3(0.0f);
    // No shadow ray where nothing could arrive: f = 0, or a one-sided light seen from behind (L = 0).
    vec3 fL = f * ls.L;
    if (!(max(fL.r, max(fL.g, fL.b)) > 0.0f)) {
        RAYLAB_RECORD(recordLight(bounce, k, ls.wi, -1.0f, ls.L, f, abs(wiL.z), lightPdf, misPdf, 0.0f, 2));
        return false;
    }
    Ray shadow = spawnRay(hit, ls.wi);
    float tMax = shadowRayEnd(k, shadow, ls.point);
    ++rays;
    bool visible = tMax > 0.0f && !occluded(shadow, tMax, leavingInstance(hit, ls.wi));
    if (visible) {
        float w = params.mis ? powerHeuristic(misPdf, bsdfPdf(sp.bsdf, sp.wo, wiL)) : 1.0f;
        Ld = beta * f * ls.L * (w / lightPdf);
    }
    RAYLAB_RECORD(recordLight(bounce, k, ls.wi, k >= 0 ? tMax : -1.0f, ls.L, f, abs(wiL.z), lightPdf, misPdf,
                              bsdfPdf(sp.bsdf, sp.wo, wiL), visible ? 1 : 0));
    return visible;
}

// A direction from the BSDF. Pure Lambert (f0 0, no glass) takes the short path of the foundation:
// the same random numbers and f·cos/pdf = ρ exactly, without the general code's cost.
BsdfSample sampleScattering(ShadingPoint sp, int bounce, inout Sampler smp) {
    // bsdfSampleDim with a constant dimension on each side, as sobol folds its matrices only for a
    // known one (bench/samplers.md, "The first bounce in the pixel's block").
#if RAYLAB_FEATURE_DOF
    vec2 u = sample2D(smp, sampleDim(bounce, SAMPLE_BOUNCE_BSDF));
#else
    vec2 u = bounce == 0 ? sample2D(smp, bsdfSampleDim(0, false)) : sample2D(smp, sampleDim(bounce, SAMPLE_BOUNCE_BSDF));
#endif
#if RAYLAB_DIFFUSE_SAMPLING == RAYLAB_DIFFUSE_UNIFORM
    if (!bsdfNeedsLobeChoice(sp.bsdf)) return bsdfSample(sp.bsdf, sp.wo, vec3(u.x, u.y, 0.0f));   // the short path is cosine's
#endif
#if RAYLAB_GENERAL_BSDF
    if (bsdfNeedsLobeChoice(sp.bsdf))
        return bsdfSample(sp.bsdf, sp.wo, vec3(u.x, u.y, sample1D(smp, sampleDim(bounce, SAMPLE_BOUNCE_LOBE))));
#endif
    vec3 wi = sampleCosineHemisphere(u);
    return BsdfSample(sp.wo.z < 0.0f ? vec3(wi.x, wi.y, -wi.z) : wi, sp.bsdf.albedo, pdfCosineHemisphere(wi.z),
                      LOBE_DIFFUSE, false);
}

// A camera path between bounces (Kajiya 1986): the ray it follows next, its radiance so far, and
// beta, the path throughput: the product of f·|cosθ|/pdf over the bounces so far.
struct PathState {
    Ray ray;
    uint leaving;           // the instance the ray leaves outwards (leavingInstance), or NO_INSTANCE
    vec3 radiance;
    vec3 beta;
    float survival;         // Russian roulette: the product of the survival probabilities so far
    float rouletteNumber;   // and the path's one number, -1 until its first roulette
    PrevBounce prev;
    int bounce;
#if RAYLAB_FEATURE_TEXTURES
    // Ray cone (Ray Tracing Gems ch. 20, §20.3.4): the width grows by the spread angle per unit
    // distance; the spread starts at the pixel's and widens at rough bounces (ray_cone.glsl).
    float coneWidth;
    float coneSpread;
#endif
};

PathState pathStart(Ray ray) {
    PathState st;
    st.ray = ray;
    st.leaving = NO_INSTANCE;
    st.radiance = vec3(0.0f);
    st.beta = vec3(1.0f);
    st.survival = 1.0f;
    st.rouletteNumber = -1.0f;
    st.prev = PrevBounce(0.0f, true, vec3(0.0f));
    st.bounce = 0;
#if RAYLAB_FEATURE_TEXTURES
    st.coneWidth = 0.0f;
    st.coneSpread = params.camPixelSpread;
#endif
    return st;
}

// Russian roulette (russian_roulette.glsl): the path's one roulette number, drawn at its first
// roulette (the independent sampler's stream gives a new number at every call), against the
// product of its survival probabilities so far; a survivor's throughput is divided by this q.
bool survivesRoulette(int bounce, inout PathState st, bool delta, inout Sampler smp) {
    if (st.rouletteNumber < 0.0f) st.rouletteNumber = sample1D(smp, SAMPLE_DIM_ROULETTE);
    float q = rouletteProbability(st.beta);
    bool survived = rouletteSurvives(st.rouletteNumber, q, st.survival);
    RAYLAB_RECORD(recordRoulette(bounce, q, survived));
    if (!survived) return false;
    st.beta /= q;
    RAYLAB_RECORD(recordThroughput(bounce, st.beta, delta));
    return true;
}

// One bounce of a camera path: its ray's hit, the emission found there, the light sample and the
// BSDF sample that continues the path. True when the path has ended. With params.nee, each
// bounce also adds a light sample; emission that a BSDF sample reaches is then weighted so
// nothing is counted twice.
bool pathStep(inout PathState st, inout Sampler smp, inout uint rays) {
    SkyParams sky = SkyParams(params.skyType, params.skyColor, params.skyTop, params.skyBottom);
    int lightCount = neeLightCount();
    int bounce = st.bounce;
    Ray ray = st.ray;
    Hit hit;
    ++rays;
    bool found = intersectScene(ray, st.leaving, hit);
    RAYLAB_RECORD(recordSegment(bounce, ray, found, hit, st.beta));
    RAYLAB_RECORD(recordCounted(bounce, RAYLAB_KEEP_BOUNCE(bounce), RAYLAB_KEEP_BOUNCE(bounce + 1)));
    if (!found) {
#if RAYLAB_STAGE == RAYLAB_STAGE_PRIMARY
        return true;   // render.stage primary: black sky, as the albedo view
#endif
        vec3 dir = normalize(ray.dir);
        float w = skyHitWeight(dir, st.prev, lightCount);
#if RAYLAB_ANALYTIC_LIGHTS
        // The sky and the discs of distant lights, each weighted: one term, weight folded in.
        vec3 Lesc = skyLookup(sky, dir) * w + distantLightsSeen(dir, st.prev, lightCount);
        RAYLAB_ADD_RADIANCE(st.radiance, bounce, st.beta * Lesc);
        RAYLAB_RECORD(recordEmission(bounce, Lesc, 1.0f));
#else
        RAYLAB_ADD_RADIANCE(st.radiance, bounce, st.beta * skyLookup(sky, dir) * w);
        RAYLAB_RECORD(recordEmission(bounce, skyLookup(sky, dir), w));
#endif
        return true;
    }
    GpuMaterial m = materialAt(hit.material);
#if RAYLAB_STAGE == RAYLAB_STAGE_PRIMARY
    // render.stage primary: the flat albedo of the first hit is the whole estimate (beta is 1).
    RAYLAB_ADD_RADIANCE(st.radiance, bounce, st.beta * m.albedo.rgb);
    RAYLAB_RECORD(recordStageAlbedo(bounce, m.albedo.rgb));
    return true;
#endif
    vec3 Le = m.emission.rgb;
#if RAYLAB_FEATURE_TEXTURES
    st.coneWidth += st.coneSpread * hit.t * length(ray.dir);
    Le *= materialEmissionScale(hit, ray.dir, st.coneWidth);
#endif
    if (emitterBackFace(ray.dir, hit)) Le = vec3(0.0f);
    if (max(Le.r, max(Le.g, Le.b)) > 0.0f) {
        float w = surfaceHitWeight(ray, hit, st.prev, lightCount);
        RAYLAB_ADD_RADIANCE(st.radiance, bounce, st.beta * Le * w);
        RAYLAB_RECORD(recordEmission(bounce, Le, w));
    }
    if (bounce >= params.maxBounces || RAYLAB_STAGE == RAYLAB_STAGE_EMISSION) return true;

    BsdfParams bsdf = materialBsdf(m);
#if RAYLAB_FEATURE_TEXTURES
    applyMaterialTextures(hit, ray.dir, st.coneWidth, bsdf);
#endif
    ShadingPoint sp = shadingPoint(bsdf, hit, ray.dir);
    RAYLAB_RECORD(recordShadingFrame(bounce, sp.frame.n));
#if RAYLAB_NEE
    vec3 Ld;
    if (lightCount > 0 && sampleLd(hit, sp, sky, st.beta, bounce, smp, rays, Ld))
        RAYLAB_ADD_RADIANCE(st.radiance, bounce + 1, Ld);
#endif

    BsdfSample bs = sampleScattering(sp, bounce, smp);
    vec3 dir = frameToWorld(sp.frame, bs.wi);
    // f·|cosθ| as the sampler used it (weight × pdf): a second bsdfEval of a narrow GGX lobe
    // differs from the sampler's by rounding the peak amplifies, and the inspector's columns
    // must multiply out to the weight the throughput took.
    RAYLAB_RECORD(recordBsdfSample(bounce, dir, bs.lobe, bsdfLobeProbability(sp.bsdf, sp.wo, bs.lobe),
                                   bs.weight * bs.pdf, abs(bs.wi.z), bs.weight, bs.pdf, bs.delta));
    if (bs.lobe == LOBE_NONE || !sidesAgree(sp, bs.wi, dir, hit.normal)) return true;
    st.beta *= bs.weight;
#if RAYLAB_FEATURE_TEXTURES
    st.coneSpread += rayConeBounceSpread(bs.lobe, bs.delta, sp.bsdf.alpha);
#endif
    st.prev = PrevBounce(bs.pdf, bs.delta, hit.position);
    RAYLAB_RECORD(recordThroughput(bounce, st.beta, bs.delta));
    if (bounce + 1 >= params.rrDepth && !survivesRoulette(bounce, st, bs.delta, smp)) return true;
    st.ray = spawnRay(hit, dir);
    st.leaving = leavingInstance(hit, dir);
    st.bounce = bounce + 1;
    return false;
}

// Radiance along one camera path: its bounces until it ends.
vec3 traceRadiance(Ray ray, inout Sampler smp, inout uint rays) {
    PathState st = pathStart(ray);
    while (!pathStep(st, smp, rays)) {
    }
    return st.radiance;
}

#endif
