/*
 * exact.h: the exact arithmetic of arcs, for arc.c and arccheck.c:
 * intervals, inline here, and big integers (bigint.c) for when an
 * interval holds 0.  lib/arc.c's first comment says why they suffice.
 */

/*
 * Intervals.  Each operation's result is widened by 2^-50 of its
 * magnitude and 2^-1060: more than the rounding of the operation and of
 * the widening itself, in the subnormal range too.  An overflow gives an
 * infinite bound, a 0 times infinity NaN: both leave the sign undecided.
 */

static inline struct interval
iv_widen(double lo, double hi)
{
	struct interval r;

	r.lo = lo - (fabs(lo) * 0x1p-50 + 0x1p-1060);
	r.hi = hi + (fabs(hi) * 0x1p-50 + 0x1p-1060);
	return r;
}

static inline struct interval
iv_diff(double a, double b)
{
	double d = a - b;

	return iv_widen(d, d);
}

static inline struct interval
iv_add(struct interval a, struct interval b)
{
	return iv_widen(a.lo + b.lo, a.hi + b.hi);
}

static inline struct interval
iv_sub(struct interval a, struct interval b)
{
	return iv_widen(a.lo - b.hi, a.hi - b.lo);
}

static inline struct interval
iv_mul(struct interval a, struct interval b)
{
	double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo,
	    p4 = a.hi * b.hi;

	if (p1 != p1 || p2 != p2 || p3 != p3 || p4 != p4)	/* NaN */
		return iv_widen(-INFINITY, INFINITY);
	return iv_widen(fmin(fmin(p1, p2), fmin(p3, p4)),
	    fmax(fmax(p1, p2), fmax(p3, p4)));
}

static inline struct interval
iv_scale(struct interval a, double s)	/* s a power of two, positive */
{
	struct interval r = { a.lo * s, a.hi * s };

	return iv_widen(r.lo, r.hi);
}

/* a / b, b not holding 0 */
static inline struct interval
iv_div(struct interval a, struct interval b)
{
	double p1 = a.lo / b.lo, p2 = a.lo / b.hi, p3 = a.hi / b.lo,
	    p4 = a.hi / b.hi;

	if (!(b.lo > 0 || b.hi < 0) || p1 != p1 || p2 != p2 || p3 != p3 ||
	    p4 != p4)
		return iv_widen(-INFINITY, INFINITY);
	return iv_widen(fmin(fmin(p1, p2), fmin(p3, p4)),
	    fmax(fmax(p1, p2), fmax(p3, p4)));
}

/* 1, -1, or 0 when the interval cannot tell. */
static inline int
iv_sign(struct interval a)
{
	return a.lo > 0 ? 1 : a.hi < 0 ? -1 : 0;
}

/*
 * Big integers, bigint: at most BIGN 32-bit limbs, sign and magnitude
 * (lib/parse.c has naturals of its own, bignat, for decimals).
 */
#define BIGSHIFT	400
#define BIGN		384

struct bigint {
	int		 neg, n;	/* n limbs, the top one nonzero */
	uint32_t	 d[BIGN];
};

/* The arc's quantities in integers, for the exact fallback. */
struct bigarc {
	struct bigint	 bx, by, mx, my, d, ux, uy;
};


void	 bigint_fromdouble(struct bigint *, double);
void	 bigint_diff(struct bigint *, double, double);
void	 bigint_addsub(struct bigint *, const struct bigint *,
	    const struct bigint *, int);
void	 bigint_mul(struct bigint *, const struct bigint *,
	    const struct bigint *);
void	 bigint_dot(struct bigint *, const struct bigint *,
	    const struct bigint *, const struct bigint *, const struct bigint *,
	    int);
void	 bigint_neg(struct bigint *);
void	 bigint_shr(struct bigint *, int);
int	 bigint_sign(const struct bigint *);
int	 bigint_lowbit(double);
void	 bigint_arc(const struct arc *, struct bigarc *);
void	 bigint_arcshift(const struct arc *, struct bigarc *, int);
