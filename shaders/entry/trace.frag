#version 450 core
// Fragment entry of the path tracer: a full-screen triangle, one fragment per pixel (a small
// image's pixels laid out as a strip, fragment_layout.glsl), drawn into a framebuffer with no
// attachments; results go to uAccum by imageStore. The scene's data arrives in buffers and uniforms.
// Defines set by the host: the scene's features, every one 0 or 1 (include/features.glsl), and
// the optional debug and test defines; the one list is src/render/tracer_defines.h.
#include "../include/path_tracer.glsl"
#include "../include/fragment_layout.glsl"

void main() {
    ivec2 frag = ivec2(gl_FragCoord.xy);
#if RAYLAB_ADAPTIVE
    ivec2 pixel;
    if (params.fragmentStripBlocks > 0) {   // the strip lists the blocks that take this draw
        int slot = fragmentSlot(frag, params.fragmentStripTiles);
        if (slot >= params.fragmentStripBlocks) return;
        pixel = blockPixel(int(adaptiveBlocks[slot]), frag, params.imageSize);
    } else {
        pixel = fragmentPixel(frag, params.imageSize, params.fragmentStripTiles);
    }
#else
    ivec2 pixel = fragmentPixel(frag, params.imageSize, params.fragmentStripTiles);
#endif
    if (pixel.x >= params.imageSize.x || pixel.y >= params.imageSize.y) return;   // past the strip's last block
    tracePixelPass(pixel);
}
