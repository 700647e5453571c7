/*
 * inline.h: what the library tells the compiler about inlining.
 */

/*
 * A rarely taken path kept out of line, so that the common one it leaves
 * needs no registers saved (GCC and Clang inline a static function called
 * once otherwise); NOINLINE for one that is not rare, only longer.
 */
/*
 * INLINE: a short function inlined at every call, so that each caller
 * gets a copy specialised to its constant arguments.
 */
#if defined(__GNUC__)
#define OUTOFLINE	__attribute__((noinline, cold))
#define NOINLINE	__attribute__((noinline))
#define INLINE		inline __attribute__((always_inline))
#else
#define OUTOFLINE
#define NOINLINE
#define INLINE		inline
#endif
