#pragma once
// Owen-scrambled Sobol points for stratified pixel sampling (sampler.hpp).
//
// Sources (docs/references.md):
// - Sobol' 1967, "On the distribution of points in a cube and the approximate evaluation of
//   integrals": the sequence; Joe & Kuo 2008, "Constructing Sobol sequences with better
//   two-dimensional projections": the polynomials and initial direction numbers of its first four
//   dimensions (the few numbers below; the whole table is not needed). The first two dimensions
//   form a (0,2)-sequence in base 2: every 2^m consecutive points aligned on a multiple of 2^m are
//   a (0,m,2)-net (one point in each elementary interval of area 2^-m).
// - Bratley & Fox 1988, "Algorithm 659: Implementing Sobol's quasirandom sequence generator": the
//   recurrence of the direction numbers.
// - Owen 1995, "Randomly permuted (t,m,s)-nets and (t,s)-sequences": nested uniform scrambling,
//   which keeps the net property and makes the points an unbiased randomisation.
// - Burley 2020, "Practical Hash-based Owen Scrambling" (JCGT 9(4)), Listing 2 and sec. 3: Owen
//   scrambling approximated by a hash in bit-reversed order (after Laine & Karras 2011); the
//   multiply/xor constants are those of pbrt-v4's FastOwenScrambler (Pharr, Jakob & Humphreys 2023).
// - Kensler 2013, "Correlated Multi-Jittered Sampling" (Pixar Technical Memo 13-01), permute():
//   a random permutation of [0, n) from a hash, used to shuffle the sample index per block of
//   dimensions so that blocks are not correlated with each other ("padding": Burley 2020, sec. 4,
//   4D blocks of shuffled scrambled Sobol points; pbrt-v4's PaddedSobolSampler pads 2D blocks).
#include <cstdint>

namespace lacrima {

// The bytes reversed by one instruction, then the bits within each byte.
inline uint32_t reverseBits32(uint32_t v) {
  v = __builtin_bswap32(v);
  v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
  v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
  return ((v >> 4) & 0x0F0F0F0Fu) | ((v & 0x0F0F0F0Fu) << 4);
}

// The direction numbers of the Sobol sequence's first four dimensions, as 32-bit fractions:
// dimension 0 is the base-2 radical inverse (the identity matrix, reversed); dimensions 1-3 use
// Joe & Kuo 2008's primitive polynomials and initial numbers m_i (their table's d = 2, 3, 4:
// x + 1 with m = 1; x^2 + x + 1 with m = 1, 3; x^3 + x + 1 with m = 1, 3, 1), extended by the
// recurrence of Bratley & Fox 1988 (eq. 2 of Joe & Kuo 2008):
//   v_k = a_1 v_{k-1} ^ ... ^ a_{s-1} v_{k-s+1} ^ v_{k-s} ^ (v_{k-s} >> s).
struct SobolDirections {
  uint32_t v[4][32];
};

constexpr SobolDirections makeSobolDirections() {
  struct Polynomial {
    int degree;
    uint32_t a;  // the inner coefficients a_1 ... a_{s-1}, a_1 the most significant bit
    uint32_t m[3];
  };
  constexpr Polynomial polynomials[3] = {{1, 0, {1, 0, 0}}, {2, 1, {1, 3, 0}}, {3, 1, {1, 3, 1}}};
  SobolDirections d{};
  for (int k = 0; k < 32; ++k) d.v[0][k] = 1u << (31 - k);
  for (int dim = 1; dim < 4; ++dim) {
    const Polynomial& p = polynomials[dim - 1];
    const int s = p.degree;
    for (int k = 0; k < s; ++k) d.v[dim][k] = p.m[k] << (31 - k);
    for (int k = s; k < 32; ++k) {
      uint32_t v = d.v[dim][k - s] ^ (d.v[dim][k - s] >> s);
      for (int j = 1; j < s; ++j)
        if ((p.a >> (s - 1 - j)) & 1u) v ^= d.v[dim][k - j];
      d.v[dim][k] = v;
    }
  }
  return d;
}

inline constexpr SobolDirections kSobolDirections = makeSobolDirections();

constexpr uint32_t reverseBits32Constexpr(uint32_t v) {
  uint32_t r = 0;
  for (int k = 0; k < 32; ++k) r |= ((v >> k) & 1u) << (31 - k);
  return r;
}

// The same direction numbers with their bits reversed (least significant = first fraction bit):
// the order Owen scrambling works in (owenScrambleReversed), so the sampler's hot path skips a
// reversal. Bit reversal commutes with xor, so a point built from these is the reversed point.
constexpr SobolDirections makeReversedSobolDirections() {
  SobolDirections d = kSobolDirections;
  for (auto& dimension : d.v)
    for (uint32_t& v : dimension) v = reverseBits32Constexpr(v);
  return d;
}

inline constexpr SobolDirections kReversedSobolDirections = makeReversedSobolDirections();

// The xor of the direction numbers of index's set bits (natural order, not Gray code), without
// a branch per bit (the bits of a shuffled index are unpredictable).
inline uint32_t xorOfDirections(const uint32_t (&directions)[32], uint32_t index) {
  uint32_t result = 0;
  for (int k = 0; index != 0; index >>= 1, ++k) result ^= directions[k] & (0u - (index & 1u));
  return result;
}

// Point `index` of Sobol dimension `dimension` (0-3), as 32 fraction bits.
inline uint32_t sobolSample(uint32_t index, int dimension) {
  return xorOfDirections(kSobolDirections.v[dimension], index);
}

// The same point with its bits reversed: reverseBits32(sobolSample(index, dimension)).
inline uint32_t sobolSampleReversed(uint32_t index, int dimension) {
  return xorOfDirections(kReversedSobolDirections.v[dimension], index);
}

// Dimension 0 directly: the base-2 radical inverse of index.
inline uint32_t sobolDimension0(uint32_t index) { return reverseBits32(index); }

// Nested uniform scramble of 32 fraction bits (Burley 2020): each output bit is its input bit
// flipped by a hash of the bits above it (more significant), so the scramble keeps nets nets.
// owenScrambleReversed works on the bits in reversed order (the first fraction bit least
// significant), where a multiply carries each bit's influence to the bits after it.
inline uint32_t owenScrambleReversed(uint32_t v, uint32_t seed) {
  v ^= v * 0x3d20adeau;
  v += seed;
  v *= (seed >> 16) | 1u;
  v ^= v * 0x05526c56u;
  v ^= v * 0x53a22864u;
  return v;
}

inline uint32_t owenScramble(uint32_t bits, uint32_t seed) {
  return reverseBits32(owenScrambleReversed(reverseBits32(bits), seed));
}

// Element i of a random permutation of [0, n) chosen by seed (Kensler 2013, Listing 3; cycle
// walking over the next power of two keeps it a bijection for any n).
inline uint32_t permutationElement(uint32_t i, uint32_t n, uint32_t seed) {
  if (n <= 1) return 0;
  uint32_t w = n - 1;
  w |= w >> 1;
  w |= w >> 2;
  w |= w >> 4;
  w |= w >> 8;
  w |= w >> 16;
  do {
    i ^= seed;
    i *= 0xe170893du;
    i ^= seed >> 16;
    i ^= (i & w) >> 4;
    i ^= seed >> 8;
    i *= 0x0929eb3fu;
    i ^= seed >> 23;
    i ^= (i & w) >> 1;
    i *= 1u | seed >> 27;
    i *= 0x6935fa69u;
    i ^= (i & w) >> 11;
    i *= 0x74dcb303u;
    i ^= (i & w) >> 2;
    i *= 0x9e501cc3u;
    i ^= (i & w) >> 2;
    i *= 0xc860a3dfu;
    i &= w;
    i ^= i >> 5;
  } while (i >= n);
  return (i + seed) % n;
}

// Element i of a permutation of [0, 2^m) (m the bits that hold n - 1) by a nested uniform scramble
// of the index's m bits (Owen 1995 applied to the index, as Burley 2020 sec. 4 shuffles with the
// scrambling hash): each bit flips by a hash of the bits above it, so the first 2^k indices map onto
// one aligned block of 2^k. Sobol points of an aligned block are a net, so every power-of-two prefix
// of a pixel's samples stays stratified: what adaptive sampling needs when a pixel stops early.
inline uint32_t progressiveElement(uint32_t i, uint32_t n, uint32_t seed) {
  if (n <= 1) return 0;
  int bits = 0;
  while (bits < 32 && (uint64_t(1) << bits) < n) ++bits;
  const int shift = 32 - bits;
  return owenScramble(i << shift, seed) >> shift;
}

// The top 24 of 32 fraction bits as a float in [0, 1) (24 bits: exact, never rounds up to 1).
inline float fractionBitsToUnitFloat(uint32_t bits) { return float(bits >> 8) * 0x1p-24f; }

}  // namespace lacrima
