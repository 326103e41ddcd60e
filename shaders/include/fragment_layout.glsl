// Which pixel a fragment of the fragment entry (trace.frag) traces. llvmpipe hands whole 64×64
// tiles to its threads, so a small image wastes them: 96×54 is one full tile and one of half its
// width, and one of two threads idles a third of the pass. Such an image is drawn instead as its
// 4×4 pixel blocks (a block's pixels stay together, as the rasteriser shades them) dealt in turn
// to `tiles` tiles side by side, a strip one tile per thread wide: tile t holds blocks t, t +
// tiles, t + 2·tiles … row by row, so every tile gets an equal share of every part of the image.
// 0 tiles keeps fragment = pixel. An adaptive pass's draw lists in its strip only the blocks
// that take it (adaptiveBlocks[], adaptive_sampling.glsl), so blocks that sit a round out cost no
// fragments. Shared by C++ (path_tracer.cpp chooses the strip) and GLSL.
#ifndef RAYLAB_FRAGMENT_LAYOUT_GLSL
#define RAYLAB_FRAGMENT_LAYOUT_GLSL
#include "compat.glsl"
RL_NAMESPACE_BEGIN

const int FRAGMENT_BLOCK = 4;                                 // pixels per block side
const int RASTER_TILE = 64;                                   // llvmpipe's tile side (lp_limits.h TILE_SIZE)
const int TILE_BLOCKS = RASTER_TILE / FRAGMENT_BLOCK;         // blocks per tile side

// The strip slot of the block fragment `frag` lies in: the k-th block of tile t is slot
// k·tiles + t, so that consecutive slots go to the tiles in turn.
RL_FN int fragmentSlot(ivec2 frag, int tiles) {
    ivec2 block = frag / FRAGMENT_BLOCK;
    int tile = block.x / TILE_BLOCKS;
    int inTile = block.y * TILE_BLOCKS + (block.x - tile * TILE_BLOCKS);
    return inTile * tiles + tile;
}

// The pixel of fragment `frag` when its slot holds image block `index` (blocks row by row).
RL_FN ivec2 blockPixel(int index, ivec2 frag, ivec2 imageSize) {
    int imageBlocksPerRow = (imageSize.x + FRAGMENT_BLOCK - 1) / FRAGMENT_BLOCK;
    ivec2 imageBlock = ivec2(index % imageBlocksPerRow, index / imageBlocksPerRow);
    return imageBlock * FRAGMENT_BLOCK + (frag - (frag / FRAGMENT_BLOCK) * FRAGMENT_BLOCK);
}

// The pixel fragment `frag` traces when slot i holds block i; outside the image (x or y >=
// imageSize) for the strip's fragments past the last block.
RL_FN ivec2 fragmentPixel(ivec2 frag, ivec2 imageSize, int tiles) {
    if (tiles == 0) return frag;
    return blockPixel(fragmentSlot(frag, tiles), frag, imageSize);
}

// The strip of `blocks` slots dealt to `tiles` tiles: tiles × RASTER_TILE wide, as many block
// rows as the fullest tile needs.
RL_FN ivec2 fragmentStripExtent(int blocks, int tiles) {
    int perTile = (blocks + tiles - 1) / tiles;
    int rows = (perTile + TILE_BLOCKS - 1) / TILE_BLOCKS;
    return ivec2(tiles * RASTER_TILE, rows * FRAGMENT_BLOCK);
}

RL_NAMESPACE_END
#endif
