// Every debug view in one list for both C++ and GLSL (preprocessor only): the shader expands it into
// DEBUG_* ids (debug_views.glsl), the host into its view table (src/render/debug_views.h) that the
// display pass, raylab-render, the script language and the Debug panel read. A new view is one row
// here plus its case in debug_views.glsl when traced.
#ifndef RAYLAB_DEBUG_VIEW_TABLE_GLSL
#define RAYLAB_DEBUG_VIEW_TABLE_GLSL

// How the display pass (shaders/entry/display.frag) turns a view's accumulated value into colour.
#define DEBUG_DISPLAY_TONE_MAP 0     // radiance: exposure, tone map, sRGB
#define DEBUG_DISPLAY_RAW 1          // already a display colour
#define DEBUG_DISPLAY_SRGB 2         // a reflectance: sRGB-encoded, no exposure
#define DEBUG_DISPLAY_DEPTH 3        // a distance: near is white, depthScale and beyond black
#define DEBUG_DISPLAY_NON_FINITE 4   // magenta where the moments counted a NaN or Inf sample
#define DEBUG_DISPLAY_NOISE 5        // heat map of the moments' relative standard error
#define DEBUG_DISPLAY_HEAT_R 6       // heat map of the red channel (box tests)
#define DEBUG_DISPLAY_HEAT_G 7       // heat map of the green channel (triangle tests)

// X(id, NAME, Name, "name", traced, moments, counts, display, "legend"):
//   id       the value of DEBUG_NAME and of the host's DebugView::Name, never reused
//   name     what the script, raylab-render's --debug-view and the Debug panel call it
//   traced   1: the debug-view variant traces it in place of the beauty path (RAYLAB_DEBUG_VIEWS)
//   moments  1: drawn from the beauty path's per-pixel moments (RAYLAB_DEBUG_MOMENTS)
//   counts   1: needs the traversal counters (RAYLAB_COUNT_TRAVERSAL) and the heat-max buffer
//   display  DEBUG_DISPLAY_*
//   legend   the Debug panel's line under the view ("" for none)
// String literals are fine here (GLSL checks its character set only after preprocessing, and the
// shader's expansion drops them) as long as they hold no backslash: Mesa's preprocessor then no
// longer sees one string and splits it at its commas. Rows are in the order the panel lists them.
#define RAYLAB_DEBUG_VIEW_TABLE(X) \
    X(0, BEAUTY, Beauty, "beauty", 0, 0, 0, DEBUG_DISPLAY_TONE_MAP, "") \
    X(1, NORMALS, Normals, "normals", 1, 0, 0, DEBUG_DISPLAY_RAW, "") \
    X(2, ALBEDO, Albedo, "albedo", 1, 0, 0, DEBUG_DISPLAY_SRGB, "") \
    X(3, DEPTH, Depth, "depth", 1, 0, 0, DEBUG_DISPLAY_DEPTH, "white = at the eye, black = this far or a miss") \
    X(4, MATERIAL_ID, MaterialId, "material-id", 1, 0, 0, DEBUG_DISPLAY_RAW, \
      "one colour per material (hover for its name)") \
    X(13, OBJECT_ID, ObjectId, "object-id", 1, 0, 0, DEBUG_DISPLAY_RAW, \
      "one colour per object: spheres, then mesh instances, numbered as in the outliner (hover for it)") \
    X(5, NON_FINITE, NonFinite, "nan", 0, 1, 0, DEBUG_DISPLAY_NON_FINITE, \
      "magenta: a NaN or Inf sample was replaced by 0 there") \
    X(6, NOISE, Noise, "noise", 0, 1, 0, DEBUG_DISPLAY_NOISE, "standard error of the mean luminance / mean") \
    X(7, BOUNCE_K, BounceK, "bounce", 1, 0, 0, DEBUG_DISPLAY_TONE_MAP, \
      "k = 0: emitters and sky seen directly; k = 1: direct lighting") \
    X(8, DIRECT, Direct, "direct", 1, 0, 0, DEBUG_DISPLAY_TONE_MAP, "bounces 0 and 1 (emitters, sky, direct lighting)") \
    X(9, INDIRECT, Indirect, "indirect", 1, 0, 0, DEBUG_DISPLAY_TONE_MAP, \
      "bounces 2 and more: direct + indirect = beauty") \
    X(10, BOXES, Boxes, "boxes", 1, 0, 1, DEBUG_DISPLAY_HEAT_R, "BVH boxes tested by the camera ray (both levels)") \
    X(11, TRIANGLES, Triangles, "triangles", 1, 0, 1, DEBUG_DISPLAY_HEAT_G, "triangles tested by the camera ray") \
    X(12, UV, Uv, "uv", 1, 0, 0, DEBUG_DISPLAY_RAW, \
      "(u, v) fractional part as red, green; spheres have uv only in textured scenes") \
    X(14, AO, Ao, "ao", 1, 0, 0, DEBUG_DISPLAY_RAW, \
      "ambient occlusion: the fraction of cosine-weighted rays from the first hit that travel ao.distance unblocked") \
    X(15, BAKED_AO, BakedAo, "baked-ao", 1, 0, 0, DEBUG_DISPLAY_RAW, \
      "the material's baked occlusion map (occlusion_texture) at the first hit; white without one") \
    X(16, SAMPLES, Samples, "samples", 0, 0, 0, DEBUG_DISPLAY_HEAT_R, \
      "samples per pixel so far (adaptive sampling gives the noisy blocks more) while the render goes on")

#endif
