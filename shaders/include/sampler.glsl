// The random numbers of a camera path, by dimension: render.sampler picks how they are made
// (RAYLAB_SAMPLER, features.glsl). Every sampler gives the number of sample `index` of `pixel` in
// dimension `dim`; the layout below fixes what each dimension means, for every path and sampler.
#ifndef RAYLAB_SAMPLER_GLSL
#define RAYLAB_SAMPLER_GLSL
#include "compat.glsl"
#include "features.glsl"
#include "random.glsl"
RL_NAMESPACE_BEGIN

// The dimension layout: pixel, lens, then a fixed block per bounce, used or not, so that a
// dimension means the same thing on every path. 2D pairs start on even offsets and a bounce is
// two whole blocks of four, so sobol draws each pair from one 4D Sobol block.
const uint SAMPLE_DIM_PIXEL = 0u;            // 2: position inside the pixel
const uint SAMPLE_DIM_LENS = 2u;             // 2: point on the thin lens; bounce 0's BSDF direction without one
const uint SAMPLE_DIM_BOUNCE = 4u;           // first dimension of bounce 0
const uint SAMPLE_DIMS_PER_BOUNCE = 8u;
const uint SAMPLE_BOUNCE_BSDF = 0u;          // 2: BSDF direction (bsdfSampleDim)
const uint SAMPLE_BOUNCE_LOBE = 2u;          // 1: lobe choice; offset 3 is unused
const uint SAMPLE_BOUNCE_LIGHT = 4u;         // 2: which light next-event estimation samples and the point on it
const uint SAMPLE_BOUNCE_ROULETTE = 6u;      // 1: bounce 0's is Russian roulette's (below); offset 7 is unused

RL_FN uint sampleDim(int bounce, uint offset) {
    return SAMPLE_DIM_BOUNCE + uint(bounce) * SAMPLE_DIMS_PER_BOUNCE + offset;
}

// A pinhole camera (RAYLAB_FEATURE_DOF 0) leaves the lens pair unused, and bounce 0's BSDF
// direction takes it: the position in the pixel and the first scattered direction are then one 4D
// Sobol block, stratified jointly instead of pair by pair (bench/samplers.md, "The first bounce
// in the pixel's block").
RL_FN uint bsdfSampleDim(int bounce, bool lens) {
    return bounce == 0 && !lens ? SAMPLE_DIM_LENS : sampleDim(bounce, SAMPLE_BOUNCE_BSDF);
}

// Russian roulette takes one number per path, compared at every bounce with the product of the
// survival probabilities (russian_roulette.glsl): bounce 0's roulette slot; later bounces leave theirs unused.
const uint SAMPLE_DIM_ROULETTE = SAMPLE_DIM_BOUNCE + SAMPLE_BOUNCE_ROULETTE;

// The top 24 bits as a float in [0, 1), as rngNextFloat.
RL_FN float sampleUnitFloat(uint bits) { return float(bits >> 8u) * (1.0f / 16777216.0f); }

// --- stratified: jittered strata, the strata of each pixel and dimension in a random order ---

// A pseudo-random permutation of [0, n), element i, keyed by p (Kensler 2013, "Correlated
// Multi-Jittered Sampling", §3): a hash on the next power of two, cycle-walked into [0, n).
RL_FN uint permuteIndex(uint i, uint n, uint p) {
    uint w = n - 1u;
    w |= w >> 1u; w |= w >> 2u; w |= w >> 4u; w |= w >> 8u; w |= w >> 16u;
    do {
        i ^= p; i *= 0xe170893du; i ^= p >> 16u; i ^= (i & w) >> 4u;
        i ^= p >> 8u; i *= 0x0929eb3fu; i ^= p >> 23u; i ^= (i & w) >> 1u;
        i *= 1u | p >> 27u; i *= 0x6935fa69u; i ^= (i & w) >> 11u;
        i *= 0x74dcb303u; i ^= (i & w) >> 2u; i *= 0x9e501cc3u;
        i ^= (i & w) >> 2u; i *= 0xc860a3dfu; i &= w; i ^= i >> 5u;
    } while (i >= n);
    return (i + p) % n;
}

// Hash words for (pixel, a counter, dimension, seed): .xy jitter, .z a permutation key.
RL_FN uvec4 stratifiedHash(uvec2 pixel, uint counter, uint dim, uint seed) {
    return pcg4d(uvec4(pixel.x, pixel.y, counter, seed ^ (dim * 0x9e3779b9u)));
}

// Sample `index` of `count` in 1D: count strata, each taken once in a per-pixel order; samples
// beyond count start a new round with a new order, so every sample alone is uniform.
RL_FN float stratifiedSample1D(uvec2 pixel, uint index, uint dim, uint seed, uint count) {
    uint n = max(count, 1u);
    uint key = stratifiedHash(pixel, index / n, dim, seed).z;
    uint stratum = permuteIndex(index % n, n, key);
    float jitter = sampleUnitFloat(stratifiedHash(pixel, index, dim, seed).x);
    return min((float(stratum) + jitter) / float(n), 0.99999994f);
}

// The same in 2D on a k×k grid, k = floor(sqrt(count)).
RL_FN vec2 stratifiedSample2D(uvec2 pixel, uint index, uint dim, uint seed, uint count) {
    uint k = max(uint(sqrt(float(max(count, 1u)))), 1u);
    if (k * k > count && k > 1u) --k;
    uint n = k * k;
    uint key = stratifiedHash(pixel, index / n, dim, seed).z;
    uint stratum = permuteIndex(index % n, n, key);
    uvec4 h = stratifiedHash(pixel, index, dim, seed);
    vec2 cell = vec2(float(stratum % k), float(stratum / k));
    vec2 jitter = vec2(sampleUnitFloat(h.x), sampleUnitFloat(h.y));
    return min((cell + jitter) / float(k), vec2(0.99999994f));
}

// --- sobol: Owen-scrambled Sobol (Burley 2020, "Practical Hash-based Owen Scrambling") ---

// Generator matrices of Sobol dimensions 1-4 (Joe & Kuo 2008 direction numbers), one column per
// bit of the index.
#define RAYLAB_SOBOL_MATRICES \
    0x80000000u, 0x40000000u, 0x20000000u, 0x10000000u, 0x08000000u, 0x04000000u, 0x02000000u, 0x01000000u, \
    0x00800000u, 0x00400000u, 0x00200000u, 0x00100000u, 0x00080000u, 0x00040000u, 0x00020000u, 0x00010000u, \
    0x00008000u, 0x00004000u, 0x00002000u, 0x00001000u, 0x00000800u, 0x00000400u, 0x00000200u, 0x00000100u, \
    0x00000080u, 0x00000040u, 0x00000020u, 0x00000010u, 0x00000008u, 0x00000004u, 0x00000002u, 0x00000001u, \
    0x80000000u, 0xc0000000u, 0xa0000000u, 0xf0000000u, 0x88000000u, 0xcc000000u, 0xaa000000u, 0xff000000u, \
    0x80800000u, 0xc0c00000u, 0xa0a00000u, 0xf0f00000u, 0x88880000u, 0xcccc0000u, 0xaaaa0000u, 0xffff0000u, \
    0x80008000u, 0xc000c000u, 0xa000a000u, 0xf000f000u, 0x88008800u, 0xcc00cc00u, 0xaa00aa00u, 0xff00ff00u, \
    0x80808080u, 0xc0c0c0c0u, 0xa0a0a0a0u, 0xf0f0f0f0u, 0x88888888u, 0xccccccccu, 0xaaaaaaaau, 0xffffffffu, \
    0x80000000u, 0xc0000000u, 0x60000000u, 0x90000000u, 0xe8000000u, 0x5c000000u, 0x8e000000u, 0xc5000000u, \
    0x68800000u, 0x9cc00000u, 0xee600000u, 0x55900000u, 0x80680000u, 0xc09c0000u, 0x60ee0000u, 0x90550000u, \
    0xe8808000u, 0x5cc0c000u, 0x8e606000u, 0xc5909000u, 0x6868e800u, 0x9c9c5c00u, 0xeeee8e00u, 0x5555c500u, \
    0x8000e880u, 0xc0005cc0u, 0x60008e60u, 0x9000c590u, 0xe8006868u, 0x5c009c9cu, 0x8e00eeeeu, 0xc5005555u, \
    0x80000000u, 0xc0000000u, 0x20000000u, 0x50000000u, 0xf8000000u, 0x74000000u, 0xa2000000u, 0x93000000u, \
    0xd8800000u, 0x25400000u, 0x59e00000u, 0xe6d00000u, 0x78080000u, 0xb40c0000u, 0x82020000u, 0xc3050000u, \
    0x208f8000u, 0x51474000u, 0xfbea2000u, 0x75d93000u, 0xa0858800u, 0x914e5400u, 0xdbe79e00u, 0x25db6d00u, \
    0x58800080u, 0xe54000c0u, 0x79e00020u, 0xb6d00050u, 0x800800f8u, 0xc00c0074u, 0x200200a2u, 0x50050093u

#ifdef __cplusplus
inline constexpr uint SOBOL_MATRICES[128] = {RAYLAB_SOBOL_MATRICES};
#else
const uint SOBOL_MATRICES[128] = uint[128](RAYLAB_SOBOL_MATRICES);
#endif

// Dimension 1's matrix is Pascal's triangle mod 2 read backwards: output digit i is the XOR of
// the index bits b whose bit pattern contains i's (Lucas' theorem: C(b, i) is odd iff i & b == i).
// That XOR over supersets takes one shift-and-mask step per bit of b (a zeta transform over the
// five bits of a bit position) instead of 32 masked XORs.
RL_FN uint sobolDimension1(uint index) {
    uint z = index;
    z ^= (z >> 1u) & 0x55555555u;
    z ^= (z >> 2u) & 0x33333333u;
    z ^= (z >> 4u) & 0x0f0f0f0fu;
    z ^= (z >> 8u) & 0x00ff00ffu;
    z ^= (z >> 16u) & 0x0000ffffu;
    return bitfieldReverse(z);
}

// Written out without a loop: llvmpipe allows an invocation 65535 loop iterations in all
// (path_tracer.glsl), and a loop here would spend 32 of them on every number. Dimension 0's
// matrix is the identity read backwards (van der Corput), so it is the index reversed, and
// dimension 1 has the closed form above: callers pass constant dimensions, so those cases cost a
// few instructions instead of 32 masked XORs (bench/samplers.md).
#define RAYLAB_SOBOL_BIT(b) x ^= SOBOL_MATRICES[base + b] & (0u - ((index >> b) & 1u));
RL_FN uint sobolBits(uint index, uint dim) {
    if (dim == 0u) return bitfieldReverse(index);
    if (dim == 1u) return sobolDimension1(index);
    uint base = dim * 32u;
    uint x = 0u;
    RAYLAB_SOBOL_BIT(0u) RAYLAB_SOBOL_BIT(1u) RAYLAB_SOBOL_BIT(2u) RAYLAB_SOBOL_BIT(3u)
    RAYLAB_SOBOL_BIT(4u) RAYLAB_SOBOL_BIT(5u) RAYLAB_SOBOL_BIT(6u) RAYLAB_SOBOL_BIT(7u)
    RAYLAB_SOBOL_BIT(8u) RAYLAB_SOBOL_BIT(9u) RAYLAB_SOBOL_BIT(10u) RAYLAB_SOBOL_BIT(11u)
    RAYLAB_SOBOL_BIT(12u) RAYLAB_SOBOL_BIT(13u) RAYLAB_SOBOL_BIT(14u) RAYLAB_SOBOL_BIT(15u)
    RAYLAB_SOBOL_BIT(16u) RAYLAB_SOBOL_BIT(17u) RAYLAB_SOBOL_BIT(18u) RAYLAB_SOBOL_BIT(19u)
    RAYLAB_SOBOL_BIT(20u) RAYLAB_SOBOL_BIT(21u) RAYLAB_SOBOL_BIT(22u) RAYLAB_SOBOL_BIT(23u)
    RAYLAB_SOBOL_BIT(24u) RAYLAB_SOBOL_BIT(25u) RAYLAB_SOBOL_BIT(26u) RAYLAB_SOBOL_BIT(27u)
    RAYLAB_SOBOL_BIT(28u) RAYLAB_SOBOL_BIT(29u) RAYLAB_SOBOL_BIT(30u) RAYLAB_SOBOL_BIT(31u)
    return x;
}
#undef RAYLAB_SOBOL_BIT

// Laine & Karras 2011's hash as Burley §4 improves it: each bit depends only on lower bits, so
// applied to reversed bits it is a nested uniform (Owen) scramble.
RL_FN uint laineKarrasPermutation(uint x, uint seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

RL_FN uint nestedUniformScramble(uint x, uint seed) {
    return bitfieldReverse(laineKarrasPermutation(bitfieldReverse(x), seed));
}

RL_FN uint hashCombine(uint seed, uint v) { return seed ^ (v + 0x9e3779b9u + (seed << 6u) + (seed >> 2u)); }

// Burley §5: sample `index` of a pixel's 4D block dim / 4, its index shuffled by a scramble
// seeded per pixel and block, and component dim % 4 Owen-scrambled with its own seed.
RL_FN float sobolSample1D(uvec2 pixel, uint index, uint dim, uint seed) {
    uvec4 h = pcg4d(uvec4(pixel.x, pixel.y, dim >> 2u, seed));
    uint i = nestedUniformScramble(index, h.x);
    return sampleUnitFloat(nestedUniformScramble(sobolBits(i, dim & 3u), hashCombine(h.y, dim & 3u)));
}

// --- zsobol: one Owen-scrambled Sobol sequence over all pixels in Morton order (Ahmed & Wonka
// 2020, "Screen-space blue-noise diffusion of Monte Carlo sampling error via hierarchical ordering
// of pixels", as pbrt-v4's ZSobolSampler), so neighbouring pixels take complementary strata ---

// Permutation p of the 24 permutations of a base-4 digit (pbrt-v4's table), entry k in bits 2k and
// 2k + 1, four a word; picked by selects, as a dynamically indexed constant array is a gather per
// lane on llvmpipe.
RL_FN uint zsobolPermutation(uint p) {
    uint w = p < 12u ? (p < 4u ? 0x78d8b4e4u : p < 8u ? 0xb1e19c6cu : 0x8d2d39c9u)
                     : (p < 16u ? 0x72d236c6u : p < 20u ? 0x87271e4eu : 0x93634b1bu);
    return (w >> (8u * (p & 3u))) & 0xffu;
}

// A pixel's samples are the 2^ZSOBOL_LOG2 consecutive indices after its Morton code; samples past
// that many start a new round with new permutations and scrambles.
RL_FN uint zsobolLog2Samples(uint count) {
    return count <= 1u ? 0u : min(uint(findMSB(count - 1u)) + 1u, 20u);
}

// The bits of x and y, 16 each, interleaved (x in the even bits).
RL_FN uint mortonSpread(uint v) {
    v &= 0xffffu;
    v = (v | (v << 8u)) & 0x00ff00ffu;
    v = (v | (v << 4u)) & 0x0f0f0f0fu;
    v = (v | (v << 2u)) & 0x33333333u;
    return (v | (v << 1u)) & 0x55555555u;
}
RL_FN uint mortonEncode(uvec2 pixel) { return mortonSpread(pixel.x) | (mortonSpread(pixel.y) << 1u); }

// murmur3's finaliser.
RL_FN uint mix32(uint h) {
    h ^= h >> 16u; h *= 0x85ebca6bu; h ^= h >> 13u; h *= 0xc2b2ae35u;
    return h ^ (h >> 16u);
}

// (lo, hi) >> shift for a 64-bit value as two words, shift < 64.
RL_FN uvec2 shiftRight64(uvec2 v, uint shift) {
    if (shift == 0u) return v;
    if (shift >= 32u) return uvec2(v.y >> (shift - 32u), 0u);
    return uvec2((v.x >> shift) | (v.y << (32u - shift)), v.y >> shift);
}

// A hash of the digits above one of the Morton index (a 64-bit value as (lo, hi)); the words are
// folded before one mix, as two nodes of the quadtree sharing a permutation costs nothing.
RL_FN uint zsobolDigitHash(uvec2 higherDigits, uint salt) {
    return mix32(higherDigits.x ^ (higherDigits.y * 0x9e3779b9u) ^ salt);
}

// The global Sobol index of sample `index` of `pixel` (pbrt-v4 ZSobolSampler::GetSampleIndex):
// each base-4 digit of (Morton code, sample) is permuted by a hash of the digits above it, so
// the order of pixels is random at every level of the quadtree but each level stays a Sobol block.
// Index bits from 24 up move a sample only below float precision, so only digits below bit 24 are
// made.
const uint ZSOBOL_INDEX_BITS = 24u;   // the digits made; a loop step per base-4 digit (PathTracer sizes its draws by it)
RL_FN uint zsobolIndex(uvec2 pixel, uint index, uint log2Samples, uint salt) {
    uint m = mortonEncode(pixel);
    uint s = index & ((1u << log2Samples) - 1u);
    uvec2 mortonIndex = log2Samples == 0u ? uvec2(m, 0u) : uvec2((m << log2Samples) | s, m >> (32u - log2Samples));
    uint odd = log2Samples & 1u;   // an odd power of two ends in a single base-2 digit
    uint result = 0u;
    for (uint shift = odd; shift < ZSOBOL_INDEX_BITS; shift += 2u) {
        uint digit = shiftRight64(mortonIndex, shift).x & 3u;
        uint p = zsobolDigitHash(shiftRight64(mortonIndex, shift + 2u), salt) % 24u;
        result |= ((zsobolPermutation(p) >> (2u * digit)) & 3u) << shift;
    }
    if (odd != 0u) result |= (mortonIndex.x & 1u) ^ (zsobolDigitHash(shiftRight64(mortonIndex, 1u), salt) & 1u);
    return result;
}

// Hash words for (dimension, round, seed): .x the digit permutations' salt, .y and .z the Owen
// scrambles of the two components; the same for every pixel, so the pixels share one sequence.
RL_FN uvec4 zsobolHash(uint index, uint dim, uint seed, uint log2Samples) {
    return pcg4d(uvec4(dim, index >> log2Samples, seed, 0x2b50b01u));
}

RL_FN float zsobolSample1D(uvec2 pixel, uint index, uint dim, uint seed, uint count) {
    uint l = zsobolLog2Samples(count);
    uvec4 h = zsobolHash(index, dim, seed, l);
    uint i = zsobolIndex(pixel, index, l, h.x);
    return sampleUnitFloat(nestedUniformScramble(sobolBits(i, 0u), h.y));
}

// Dimensions dim and dim + 1 as Sobol dimensions 0 and 1 of one index: a (0,2)-sequence.
RL_FN vec2 zsobolSample2D(uvec2 pixel, uint index, uint dim, uint seed, uint count) {
    uint l = zsobolLog2Samples(count);
    uvec4 h = zsobolHash(index, dim, seed, l);
    uint i = zsobolIndex(pixel, index, l, h.x);
    return vec2(sampleUnitFloat(nestedUniformScramble(sobolBits(i, 0u), h.y)),
                sampleUnitFloat(nestedUniformScramble(sobolBits(i, 1u), h.z)));
}

// --- the sampler the tracer was compiled with ---

struct Sampler {
    Rng rng;       // independent: every number, in call order; the others: the coins only
    uvec2 pixel;
    uint index;    // sample index of the pixel, across passes
    uint seed;
    uint count;    // samples per pixel of the whole render (stratified's strata, zsobol's block)
};

RL_FN Sampler samplerCreate(uvec2 pixel, uint index, uint seed, uint count) {
    return Sampler(rngCreate(pixel, index, seed), pixel, index, seed, count);
}

// independent ignores `dim`: it is the PCG stream of random.glsl, taken in call order.
RL_FN float sample1D(RL_INOUT(Sampler) s, uint dim) {
#if RAYLAB_SAMPLER == RAYLAB_SAMPLER_ZSOBOL
    return zsobolSample1D(s.pixel, s.index, dim, s.seed, s.count);
#elif RAYLAB_SAMPLER == RAYLAB_SAMPLER_SOBOL
    return sobolSample1D(s.pixel, s.index, dim, s.seed);
#elif RAYLAB_SAMPLER == RAYLAB_SAMPLER_STRATIFIED
    return stratifiedSample1D(s.pixel, s.index, dim, s.seed, s.count);
#else
#ifdef __cplusplus
    (void)dim;
#endif
    return rngNextFloat(s.rng);
#endif
}

// Dimensions dim and dim + 1; stratified's cells and zsobol's pairs are 2D, the others' pairs
// are two 1D numbers.
RL_FN vec2 sample2D(RL_INOUT(Sampler) s, uint dim) {
#if RAYLAB_SAMPLER == RAYLAB_SAMPLER_STRATIFIED
    return stratifiedSample2D(s.pixel, s.index, dim, s.seed, s.count);
#elif RAYLAB_SAMPLER == RAYLAB_SAMPLER_ZSOBOL
    return zsobolSample2D(s.pixel, s.index, dim, s.seed, s.count);
#else
    float a = sample1D(s, dim);
    float b = sample1D(s, dim + 1u);
    return vec2(a, b);
#endif
}

// A further uniform number for a choice already stratified by its dimension (an alias table's
// coin): the next PCG number, without a dimension of its own.
RL_FN float sampleCoin(RL_INOUT(Sampler) s) { return rngNextFloat(s.rng); }

RL_NAMESPACE_END
#endif
