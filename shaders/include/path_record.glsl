// The pixel path inspector's recorder (src/inspect/path_inspector.h): with RAYLAB_INSPECT_PATHS
// the tracer writes every term of the estimator of one chosen pixel's samples to its two buffers,
// bounce by bounce. Without it this file adds nothing and the integrator's RAYLAB_RECORD hooks
// are empty, so normal renders pay nothing. Recording only writes: radiance, random numbers and
// control flow are those of the normal tracer. The slot layout is
// path_record_layout.glsl, shared with the decoder (src/inspect/path_inspector.cpp). GLSL only.
#ifndef RAYLAB_PATH_RECORD_GLSL
#define RAYLAB_PATH_RECORD_GLSL
#include "compat.glsl"
#include "path_record_layout.glsl"
#include "ray.glsl"
#include "scene_data.glsl"
#include "scene_intersect.glsl"
#include "light_sampling.glsl"   // powerHeuristic

#if RAYLAB_INSPECT_PATHS
layout(std430, binding = BINDING_INSPECT_BOUNCES) buffer InspectBounceBuffer { vec4 inspectBounces[]; };
layout(std430, binding = BINDING_INSPECT_PATHS) writeonly buffer InspectPathBuffer { vec4 inspectPaths[]; };
uniform ivec2 uInspectPixel;       // GL pixel (bottom row 0) whose samples are recorded
uniform int uInspectMaxRecords;    // bounce records per path that fit the buffer
uniform uint uInspectFirstSample;  // sample index of the first recorded path (the host may split it into draws)

bool gRecording = false;   // this invocation is the inspected pixel's
int gRecordPath = 0;       // recorded path: sample index minus uInspectFirstSample
int gRecordCount = 0;      // bounce records written for the current path
bool gRecordTruncated = false;

int recordSlot(int bounce, int field) { return (gRecordPath * uInspectMaxRecords + bounce) * PR_VEC4S + field; }
void recordPut(int bounce, int field, vec4 v) {
    if (!gRecording) return;
    if (bounce >= uInspectMaxRecords) {
        gRecordTruncated = true;
        return;
    }
    inspectBounces[recordSlot(bounce, field)] = v;
    gRecordCount = max(gRecordCount, bounce + 1);
}

void recordPathBegin(ivec2 pixel, int path, Ray ray) {
    gRecording = pixel == uInspectPixel;
    if (!gRecording) return;
    path += int(params.sampleStart - uInspectFirstSample);
    gRecordPath = path;
    gRecordCount = 0;
    gRecordTruncated = false;
    // Every field of every slot defaults to "not played" so the host reads no stale values.
    for (int b = 0; b < uInspectMaxRecords; ++b)
        for (int f = 0; f < PR_VEC4S; ++f) inspectBounces[recordSlot(b, f)] = vec4(0.0f);
    int base = gRecordPath * PR_PATH_VEC4S;
    inspectPaths[base + 2] = vec4(ray.origin, 0.0f);
    inspectPaths[base + 3] = vec4(normalize(ray.dir), 0.0f);
}

void recordPathEnd(ivec2 pixel, int path, vec3 L) {
    if (!gRecording) return;
    int base = gRecordPath * PR_PATH_VEC4S;
    inspectPaths[base] = vec4(L, float(gRecordCount));
    inspectPaths[base + 1] = vec4(float(params.sampleStart + uint(path)), float(pixel.x), float(pixel.y),
                                  gRecordTruncated ? 1.0f : 0.0f);
}

// A bounce starts: the ray it follows, what it hit (or not), the throughput it carries.
void recordSegment(int bounce, Ray ray, bool hitSomething, Hit hit, vec3 beta) {
    if (!gRecording) return;
    recordPut(bounce, PR_ORIGIN, vec4(ray.origin, hitSomething ? 1.0f : 0.0f));
    recordPut(bounce, PR_DIRECTION, vec4(normalize(ray.dir), hitSomething ? hit.t * length(ray.dir) : 0.0f));
    recordPut(bounce, PR_BETA_BEFORE, vec4(beta, 0.0f));
    recordPut(bounce, PR_SAMPLED, vec4(0.0f, 0.0f, 0.0f, -1.0f));
    recordPut(bounce, PR_RR, vec4(0.0f, -1.0f, 0.0f, 0.0f));
    recordPut(bounce, PR_LIGHT, vec4(0.0f, 0.0f, 0.0f, -1.0f));
    if (!hitSomething) return;
    recordPut(bounce, PR_POSITION, vec4(hit.position, float(hit.primitive)));
    recordPut(bounce, PR_NORMAL, vec4(hit.normal, float(hit.material)));
    recordPut(bounce, PR_SHADING, vec4(hit.shadingNormal, float(hit.instance)));
}

void recordEmission(int bounce, vec3 Le, float w) { recordPut(bounce, PR_EMISSION, vec4(Le, w)); }

// Whether this bounce's emission and its light sample (counted as bounce + 1) reach the value: the
// integrator's RAYLAB_KEEP_BOUNCE, all true but in the viewer's bounce views.
void recordCounted(int bounce, bool emission, bool light) {
    recordPut(bounce, PR_COUNTED, vec4(emission ? 1.0f : 0.0f, light ? 1.0f : 0.0f, 0.0f, 0.0f));
}

// render.stage primary returns the first hit's albedo: the one term of that stage's estimate.
void recordStageAlbedo(int bounce, vec3 albedo) { recordPut(bounce, PR_STAGE_ALBEDO, vec4(albedo, 1.0f)); }

void recordShadingFrame(int bounce, vec3 ns) {
    if (!gRecording || bounce >= uInspectMaxRecords) return;
    vec4 v = inspectBounces[recordSlot(bounce, PR_SHADING)];
    recordPut(bounce, PR_SHADING, vec4(ns, v.w));
}

// Next-event estimation at this bounce: status -1 none, 0 occluded, 1 visible, 2 f·L = 0. The
// contribution is recomputed here from the terms (the inspector's test checks it against the
// integrator's sum): f·|cosθ| · Le · w / pdf, w the power heuristic when MIS is on.
void recordLight(int bounce, int light, vec3 dir, float dist, vec3 Le, vec3 fCos, float cosTheta, float lightPdf,
                 float misPdf, float bsdfPdfValue, int status) {
    float w = status == 2 ? 0.0f : (params.mis ? powerHeuristic(misPdf, bsdfPdfValue) : 1.0f);
    vec3 contribution = status == 1 ? fCos * Le * (w / lightPdf) : vec3(0.0f);
    recordPut(bounce, PR_LIGHT, vec4(contribution, float(status)));
    recordPut(bounce, PR_LIGHT_DIR, vec4(dir, dist));
    recordPut(bounce, PR_LIGHT_TERMS, vec4(lightPdf, bsdfPdfValue, w, float(light)));
    recordPut(bounce, PR_LIGHT_F, vec4(fCos, cosTheta));
    recordPut(bounce, PR_LIGHT_LE, vec4(Le, misPdf));
}

// The BSDF sample taken at this bounce (fCos = f·|cosθ| as the sampler used it; for delta lobes
// f is recorded as the weight).
void recordBsdfSample(int bounce, vec3 dirWorld, int lobe, float lobeProbability, vec3 fCos, float cosTheta,
                      vec3 weight, float pdf, bool delta) {
    if (!gRecording || bounce >= uInspectMaxRecords) {
        recordPut(bounce, PR_SAMPLED, vec4(0.0f));   // marks truncation
        return;
    }
    vec4 before = inspectBounces[recordSlot(bounce, PR_BETA_BEFORE)];
    recordPut(bounce, PR_BETA_BEFORE, vec4(before.xyz, lobeProbability));
    recordPut(bounce, PR_SAMPLED, vec4(dirWorld, float(lobe)));
    vec3 f = delta ? weight : fCos / max(cosTheta, 1e-30f);
    recordPut(bounce, PR_F, vec4(f, cosTheta));
    recordPut(bounce, PR_WEIGHT, vec4(weight, pdf));
}

void recordThroughput(int bounce, vec3 beta, bool delta) { recordPut(bounce, PR_BETA_AFTER, vec4(beta, delta ? 1.0f : 0.0f)); }

void recordRoulette(int bounce, float q, bool survived) {
    recordPut(bounce, PR_RR, vec4(q, survived ? 1.0f : 0.0f, 0.0f, 0.0f));
}

// The integrator's hooks: one statement each, evaluated for the inspected pixel only.
#define RAYLAB_RECORD(call) if (gRecording) call
#define RAYLAB_RECORD_PATH_BEGIN(pixel, path, ray) recordPathBegin(pixel, path, ray)
#define RAYLAB_RECORD_PATH_END(pixel, path, L) recordPathEnd(pixel, path, L)
#else
#define RAYLAB_RECORD(call)
#define RAYLAB_RECORD_PATH_BEGIN(pixel, path, ray)
#define RAYLAB_RECORD_PATH_END(pixel, path, L)
#endif

#endif
