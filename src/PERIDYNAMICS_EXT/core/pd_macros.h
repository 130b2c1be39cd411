/* Portability macros for the core, which is plain C11 (no GNU extensions):
 * ISO C has neither M_PI nor a way to force inlining. */
#ifndef PD_MACROS_H
#define PD_MACROS_H

/* pi to more digits than a double holds; M_PI is POSIX, not ISO C. */
#define PD_PI 3.14159265358979323846

/* The specialized kernel copies rely on their loop body being inlined so that
 * constant flags fold away; always_inline insists where the compiler can.
 * Other compilers get a plain hint. */
#if defined(__GNUC__) || defined(__clang__)
#define PD_INLINE static inline __attribute__((always_inline))
#else
#define PD_INLINE static inline
#endif

/* A kernel's rarely taken branch kept out of line: the kernel carries a
 * call, not a copy of its loop. */
#if defined(__GNUC__) || defined(__clang__)
#define PD_NOINLINE static __attribute__((noinline, unused))
#else
#define PD_NOINLINE static
#endif

#endif
