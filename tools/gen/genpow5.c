/*
 * genpow5: writes lib/pow5.c, the table of powers of five that parsereal
 * (lib/parse.c) multiplies by and fmtreal (lib/fmt.c) scales by, on
 * standard output.
 *
 *	genpow5 > lib/pow5.c
 *
 * The table is committed; tests/lib-numbers.bats runs this program and
 * compares.  Each 5^q, q = POW5MIN .. POW5MAX, is kept as its top 128 bits,
 * truncated, with exact integer arithmetic: for q >= 0 the bits of 5^q
 * itself, for q < 0 those of floor(2^k / 5^-q), k making 128 bits.
 * POW5MIN is the least q for which a 19-digit decimal w 10^q can be a
 * double (see lib/parse.c); POW5MAX the greatest power of ten that
 * fmtreal scales by (10^-k for the least binary exponent q, k =
 * floor(q log10 2), and one more digit).  lib/num.h has both.
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#define POW5MIN	(-342)
#define POW5MAX	325
#define LIMBS	32	/* 1024 bits: above 5^342 and twice it */

/* Naturals as little-endian 32-bit limbs. */
struct big {
	uint32_t	 d[LIMBS];
};

static int
bitlen(const struct big *x)
{
	int i, n;

	for (i = LIMBS - 1; i > 0 && x->d[i] == 0; i--)
		;
	for (n = 0; n < 32 && x->d[i] >> n != 0; n++)
		;
	return 32 * i + n;
}

static int
bit(const struct big *x, int i)
{
	return i >= 0 && x->d[i / 32] >> (i % 32) & 1;
}

static void
mul5(struct big *x)
{
	uint64_t c = 0;
	int i;

	for (i = 0; i < LIMBS; i++) {
		c += (uint64_t)x->d[i] * 5;
		x->d[i] = (uint32_t)c;
		c >>= 32;
	}
}

/* x = 2x + b */
static void
shl1(struct big *x, int b)
{
	int i;

	for (i = LIMBS - 1; i > 0; i--)
		x->d[i] = x->d[i] << 1 | x->d[i - 1] >> 31;
	x->d[0] = x->d[0] << 1 | (uint32_t)b;
}

static int
geq(const struct big *x, const struct big *y)
{
	int i;

	for (i = LIMBS - 1; i >= 0; i--)
		if (x->d[i] != y->d[i])
			return x->d[i] > y->d[i];
	return 1;
}

static void
sub(struct big *x, const struct big *y)
{
	uint64_t borrow = 0;
	int i;

	for (i = 0; i < LIMBS; i++) {
		uint64_t t = (uint64_t)x->d[i] - y->d[i] - borrow;

		x->d[i] = (uint32_t)t;
		borrow = t >> 63;
	}
}

/* Bits from .. from + 127 of x. */
static void
top128(const struct big *x, int from, uint64_t *hi, uint64_t *lo)
{
	int i;

	*hi = *lo = 0;
	for (i = 127; i >= 64; i--)
		*hi = *hi << 1 | (uint64_t)bit(x, from + i);
	for (; i >= 0; i--)
		*lo = *lo << 1 | (uint64_t)bit(x, from + i);
}

/* floor(2^k / d), known to be below 2^128, by long division. */
static void
recip(const struct big *d, int k, uint64_t *hi, uint64_t *lo)
{
	struct big r;
	int i;

	memset(&r, 0, sizeof(r));
	*hi = *lo = 0;
	for (i = k; i >= 0; i--) {
		int q;

		shl1(&r, i == k);
		if ((q = geq(&r, d)) != 0)
			sub(&r, d);
		*hi = *hi << 1 | *lo >> 63;
		*lo = *lo << 1 | (uint64_t)q;
	}
}

int
main(void)
{
	static uint64_t hi[POW5MAX - POW5MIN + 1], lo[POW5MAX - POW5MIN + 1];
	static int e[POW5MAX - POW5MIN + 1];
	struct big p;
	int q, n;

	memset(&p, 0, sizeof(p));
	p.d[0] = 1;
	for (n = 0; n <= -POW5MIN || n <= POW5MAX; n++) {
		int len = bitlen(&p);

		if (n <= POW5MAX) {
			top128(&p, len - 128, &hi[n - POW5MIN], &lo[n - POW5MIN]);
			e[n - POW5MIN] = len - 128;
		}
		if (n >= 1 && -n >= POW5MIN) {
			/* 2^(len-1) < 5^n < 2^len: 2^(127+len) / 5^n has 128 bits */
			recip(&p, 127 + len, &hi[-n - POW5MIN], &lo[-n - POW5MIN]);
			e[-n - POW5MIN] = -127 - len;
		}
		mul5(&p);
	}

	printf("/*\n"
	    " * pow5.c: written by tools/gen/genpow5.c, not by hand; tests/lib-numbers.bats\n"
	    " * checks that the two agree.  5^q for q = POW5MIN .. POW5MAX is\n"
	    " * (hi 2^64 + lo) 2^e, 2^127 <= hi 2^64 + lo < 2^128, truncated: exact\n"
	    " * for 0 <= q <= 55, below 5^q by less than 2^e for the others.\n"
	    " */\n"
	    "#include <stdint.h>\n"
	    "\n"
	    "#include \"qtree.h\"\n"
	    "#include \"num.h\"\n"
	    "\n"
	    "#if POW5MIN != %d || POW5MAX != %d\n"
	    "#error \"lib/num.h and tools/gen/genpow5.c disagree\"\n"
	    "#endif\n"
	    "\n"
	    "const struct pow5 pow5tab[POW5MAX - POW5MIN + 1] = {\n",
	    POW5MIN, POW5MAX);
	for (q = POW5MIN; q <= POW5MAX; q++)
		printf("\t{ 0x%016llx, 0x%016llx, %d },\t/* 5^%d */\n",
		    (unsigned long long)hi[q - POW5MIN],
		    (unsigned long long)lo[q - POW5MIN], e[q - POW5MIN], q);
	printf("};\n");
	return ferror(stdout) || fclose(stdout) != 0;
}
