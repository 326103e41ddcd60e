// The pixel path inspector's buffer layout: vec4 slots per bounce record and per path, written by
// path_record.glsl and decoded by src/inspect/path_inspector.cpp. Shared by C++ and GLSL.
#ifndef RAYLAB_PATH_RECORD_LAYOUT_GLSL
#define RAYLAB_PATH_RECORD_LAYOUT_GLSL
#include "compat.glsl"
RL_NAMESPACE_BEGIN

const int PR_VEC4S = 19;          // vec4s per bounce record
const int PR_ORIGIN = 0;          // ray origin xyz, w: 1 hit, 0 miss (the sky)
const int PR_DIRECTION = 1;       // unit ray direction xyz, w: hit distance (0 for a miss)
const int PR_POSITION = 2;        // hit point xyz, w: sphere index or triangle index
const int PR_NORMAL = 3;          // geometric normal xyz, w: material id
const int PR_SHADING = 4;         // shading normal (the BSDF frame's z) xyz, w: top-level instance
const int PR_EMISSION = 5;        // emitted radiance Le (or the sky's) rgb, w: its MIS weight
const int PR_BETA_BEFORE = 6;     // throughput arriving here rgb, w: probability of the chosen lobe
const int PR_SAMPLED = 7;         // sampled direction (world) xyz, w: lobe (LOBE_*), -1 none
const int PR_F = 8;               // f rgb, w: |cosθ| of the sampled direction
const int PR_WEIGHT = 9;          // f·|cosθ|/pdf rgb, w: pdf (discrete probability for delta lobes)
const int PR_BETA_AFTER = 10;     // throughput leaving (after roulette) rgb, w: 1 delta lobe
const int PR_RR = 11;             // x: survival probability q, y: outcome (-1 not played, 0 killed, 1 survived)
const int PR_LIGHT = 12;          // light sample f·Le·w/pdf (no throughput) rgb, w: -1 none, 0 occluded, 1 visible, 2 f = 0
const int PR_LIGHT_DIR = 13;      // shadow ray direction xyz, w: distance to the light's surface (-1: the sky)
const int PR_LIGHT_TERMS = 14;    // x: light pdf, y: BSDF pdf of that direction, z: MIS weight, w: light index
const int PR_LIGHT_F = 15;        // f·|cosθ| towards the light rgb, w: |cosθ|
const int PR_LIGHT_LE = 16;       // the light's radiance rgb; w its density as MIS weighs it
const int PR_COUNTED = 17;        // 1 when the term counts toward the value, else 0 (the viewer's bounce
                                  // views keep some bounces only): x emission (or stage albedo), y light sample
const int PR_STAGE_ALBEDO = 18;   // render.stage primary: the first hit's flat albedo rgb (that stage's whole
                                  // estimate), w: 1 when recorded
const int PR_PATH_VEC4S = 4;      // per path: final value rgb + bounce records; sample index,
                                  // the pixel, truncated; camera ray origin; camera ray direction

RL_NAMESPACE_END
#endif
