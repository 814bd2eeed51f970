#pragma once
// Function multiversioning for the hot loops of sim/ (lattice RHS, stepper stage updates): each
// marked function is compiled for AVX-512, AVX2 and baseline x86-64 and the best one is chosen at
// load time (GCC target_clones), so no -march flag is needed.
//   LRCHAIN_VECTOR_CLONES       plain loops; FMA contraction off, so all clones give the same bits
//   LRCHAIN_SQRT_VECTOR_CLONES  loops with sqrt: errno-free sqrt so that GCC emits packed sqrtpd;
//                               associativity, reciprocals and FMA contraction stay off, so every
//                               clone computes the same IEEE results (max, -, *, sqrt).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define LRCHAIN_VECTOR_CLONES \
  __attribute__((target_clones("avx512f", "avx2", "default"), optimize("fp-contract=off")))
#define LRCHAIN_SQRT_VECTOR_CLONES                                                  \
  __attribute__((target_clones("avx512f", "avx2", "default"),                        \
                 optimize("fast-math", "no-associative-math", "no-reciprocal-math", \
                          "fp-contract=off")))
#else
#define LRCHAIN_VECTOR_CLONES
#define LRCHAIN_SQRT_VECTOR_CLONES
#endif
