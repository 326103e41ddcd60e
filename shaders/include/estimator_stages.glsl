// The estimator's switchable stages, the thesis's story from naive to better (render.diffuse_sampling,
// render.ggx_sampling, render.light_selection, render.light_sampling, render.accel; scene.h's enums
// take these numbers).
// The host sets each RAYLAB_* below per scene (render/shader_variant.cpp), so a variant holds only
// its own stage's code; C++ sees the defaults, today's best estimator. Preprocessor only, for both
// C++ and GLSL.
#ifndef RAYLAB_ESTIMATOR_STAGES_GLSL
#define RAYLAB_ESTIMATOR_STAGES_GLSL

// The diffuse lobe's directions: cosine-weighted (pdf cos θ / π) or uniform over the hemisphere
// (pdf 1 / 2π, the thesis's first estimator, §3.5.2).
#define RAYLAB_DIFFUSE_COSINE 0
#define RAYLAB_DIFFUSE_UNIFORM 1
#ifndef RAYLAB_DIFFUSE_SAMPLING
#define RAYLAB_DIFFUSE_SAMPLING RAYLAB_DIFFUSE_COSINE
#endif

// GGX microfacet normals: visible normals (Heitz 2018) or D(h) cos θh (Walter et al. 2007, the
// thesis's §3.5.1), for the specular lobe and rough glass alike.
#define RAYLAB_GGX_VNDF 0
#define RAYLAB_GGX_D_COS 1
#ifndef RAYLAB_GGX_SAMPLING
#define RAYLAB_GGX_SAMPLING RAYLAB_GGX_VNDF
#endif

// Which light next-event estimation picks: by power (the alias table, when powers differ) or each
// with an equal share (light_selection.glsl's branch without the table).
#define RAYLAB_LIGHT_SELECTION_POWER 0
#define RAYLAB_LIGHT_SELECTION_UNIFORM 1

// How a light sample finds a point on an emissive triangle: uniform over the solid angle it
// subtends (Arvo 1995) where that is well conditioned, or uniform over its area, whose density per
// solid angle carries the 1/r² and cosine of the light (triangle_light.glsl).
#define RAYLAB_LIGHT_SAMPLING_SOLID_ANGLE 0
#define RAYLAB_LIGHT_SAMPLING_AREA 1
#ifndef RAYLAB_LIGHT_SAMPLING
#define RAYLAB_LIGHT_SAMPLING RAYLAB_LIGHT_SAMPLING_SOLID_ANGLE
#endif

// How rays find the nearest surface: the two-level BVH (bvh_traversal.glsl), a flat list of object
// boxes each followed by all the object's primitives (the thesis's scheme, Fig. 5.2), or every
// primitive of the scene (flat_traversal.glsl).
#define RAYLAB_ACCEL_BVH 0
#define RAYLAB_ACCEL_BOXES 1
#define RAYLAB_ACCEL_NONE 2
#ifndef RAYLAB_ACCEL
#define RAYLAB_ACCEL RAYLAB_ACCEL_BVH
#endif
// With boxes or none: 1 when one sample's search, a triangle per loop iteration, would not fit in
// llvmpipe's loop budget (a large mesh): the search then takes whole steps of 16 triangles
// (flat_traversal.glsl). Off otherwise, as a step no lane fills still runs, masked.
#ifndef RAYLAB_FLAT_STEPS
#define RAYLAB_FLAT_STEPS 1
#endif

#endif
