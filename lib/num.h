/*
 * num.h: the numbers' internals the library's files share and no program
 * calls: the 128-bit product and the powers of five and ten of parsereal
 * and fmtreal, and the error-free transformations of the exact sums.
 */

/* fmt.c, parse.c: the 128-bit product of two 64-bit numbers. */
static inline void
mul64(uint64_t a, uint64_t b, uint64_t *hi, uint64_t *lo)
{
#ifdef __SIZEOF_INT128__
	__extension__ unsigned __int128 p = (unsigned __int128)a * b;

	*hi = (uint64_t)(p >> 64);
	*lo = (uint64_t)p;
#else
	uint64_t a1 = a >> 32, a0 = a & 0xffffffff;
	uint64_t b1 = b >> 32, b0 = b & 0xffffffff;
	uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
	uint64_t mid = (p00 >> 32) + (p01 & 0xffffffff) + (p10 & 0xffffffff);

	*hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
	*lo = mid << 32 | (p00 & 0xffffffff);
#endif
}

/* parse.c, for fmt.c: 10^0 to 10^22, the powers of ten a double holds. */
extern const double exact10[23];

/* geom.c: error-free transformations, for area.c's exact sums */
void	 two_sum(double, double, double *, double *);
void	 two_product(double, double, double *, double *);

/*
 * pow5.c: 5^q for q = POW5MIN .. POW5MAX as (hi 2^64 + lo) 2^e, 2^127 <=
 * hi 2^64 + lo < 2^128, truncated (exact for 0 <= q <= 55), written by
 * tools/gen/genpow5.c: what parsereal multiplies by and fmtreal scales by.
 */
#define POW5MIN	(-342)
#define POW5MAX	325

struct pow5 {
	uint64_t	 hi, lo;
	int		 e;
};

extern const struct pow5 pow5tab[POW5MAX - POW5MIN + 1];
