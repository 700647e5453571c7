/*
 * qtstats: figures about a qtree(5) stream (its polygon, its cells, its
 * mesh) as "key value" lines, one space between, for awk.  The keys are an
 * interface: qtstats(1) lists them, and they keep their names and meaning.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qtree.h"

#define GRID		QT_MAXLEVEL	/* leaves are kept on this grid */
#define LEVELSHIFT	58		/* level bits above the coordinate */
#define COORDMASK	((UINT64_C(1) << LEVELSHIFT) - 1)

enum { F, E, P };

static struct universe u;

/* The polygon, summed ring by ring as its records stream past. */
static struct moments region, ringmo;
static struct point first, prev;
static int ringhole, ringstarted;
static unsigned long long nrings, nholes;
static double perim, perimlow;	/* a compensated sum */

/* Cells per level; sums of 2 IX + 1 and 2 IY + 1 for the centroids. */
struct u128 {
	uint64_t	hi, lo;
};

struct levelstat {
	unsigned long long	nodes, leaves[3];
	struct u128		sx[3], sy[3];
};

static struct levelstat lev[QT_MAXLEVEL + 1];
static int deepest = -1;

/*
 * Leaves on the level-GRID grid, for the level jumps: x is the lower left
 * column, y the row with the level in its top bits.
 */
struct lrec {
	uint64_t	x, y;
};

static struct lrec *leaves;
static size_t nleaves, leafcap;

/* The mesh records. */
struct etype {
	char			*name;
	unsigned long long	 n;
};

static struct point *verts;
static size_t nverts, vertcap;
static uint32_t *refs;		/* vertex numbers, from 0 */
static size_t nrefs, refcap;
static size_t *eoff;		/* element i: refs[eoff[i]..eoff[i+1]-1] */
static size_t nelems, elemcap;
static struct etype *types;
static size_t ntypes;
static int havemesh;

static void
usage(void)
{
	fprintf(stderr, "usage: qtstats [-lv] [file]\n");
	exit(2);
}

static void
add128(struct u128 *s, uint64_t v)
{
	s->lo += v;
	if (s->lo < v)
		s->hi++;
}

static double
u128real(const struct u128 *s)
{
	return ldexp((double)s->hi, 64) + (double)s->lo;
}

static void
addperim(double len)
{
	double t = perim + len;

	/* Neumaier: keep what the larger addend rounds away */
	if (fabs(perim) >= fabs(len))
		perimlow += (perim - t) + len;
	else
		perimlow += (len - t) + perim;
	perim = t;
}

static void
edge(struct point a, struct point b)
{
	mo_edge(&ringmo, a, b);
	addperim(hypot(b.x - a.x, b.y - a.y));
}

/*
 * A ring adds its area and moments with the sign its kind gives it,
 * outer +, hole -, whatever way it runs.
 */
static void
endring(void)
{
	int want = ringhole ? -1 : 1, sign;

	edge(prev, first);
	sign = xs_sign(&ringmo.a2);
	mo_addmo(&region, &ringmo, sign == want || sign == 0 ? 1 : -1);
	mo_zero(&ringmo);
}

static void
ringvertex(struct qtreader *r, struct point v)
{
	if (!ringstarted) {
		first = v;
		ringstarted = 1;
	} else
		edge(prev, v);
	prev = v;
	if (r->vleft == 0) {
		endring();
		ringstarted = 0;
	}
}

static void
addcell(const struct cell *c)
{
	struct levelstat *s = &lev[c->level];
	int k, shift = GRID - c->level;

	if (c->level > deepest)
		deepest = c->level;
	if (c->class == 0) {
		s->nodes++;
		return;
	}
	k = c->class == 'F' ? F : c->class == 'E' ? E : P;
	s->leaves[k]++;
	add128(&s->sx[k], 2 * c->ix + 1);
	add128(&s->sy[k], 2 * c->iy + 1);
	if (nleaves == leafcap) {
		leafcap = leafcap ? 2 * leafcap : 1024;
		leaves = xreallocarray(leaves, leafcap, sizeof(*leaves));
	}
	leaves[nleaves].x = c->ix << shift;
	leaves[nleaves++].y = c->iy << shift |
	    (uint64_t)c->level << LEVELSHIFT;
}

static unsigned long long
number(struct qtreader *r, const char *s, const char *what,
    unsigned long long hi)
{
	const char *end;
	long long v;

	if (parselong(s, &end, &v) < 0 || *end != '\0' || v < 1 ||
	    (unsigned long long)v > hi)
		qt_fail(r, "%s is not a number from 1 to %llu: %s", what, hi, s);
	return v;
}

static double
coord(struct qtreader *r, const char *s)
{
	const char *end;
	double v;

	if (parsereal(s, &end, &v) < 0 || *end != '\0')
		qt_fail(r, "vertex coordinate is not a number: %s", s);
	if (!coordok(v))
		qt_fail(r, "vertex coordinate outside the supported range: %s",
		    s);
	return v;
}

static void
vertexrec(struct qtreader *r, char *line)
{
	char *f[5];

	if (qt_split(r, line, f, 5) != 4)
		qt_fail(r, "vertex record needs 4 fields: vertex ID X Y");
	if (number(r, f[1], "vertex ID", UINT32_MAX) != nverts + 1)
		qt_fail(r, "vertex %s follows vertex %zu", f[1], nverts);
	if (nverts == vertcap) {
		vertcap = vertcap ? 2 * vertcap : 1024;
		verts = xreallocarray(verts, vertcap, sizeof(*verts));
	}
	verts[nverts].x = coord(r, f[2]);
	verts[nverts++].y = coord(r, f[3]);
}

static size_t
typeindex(struct qtreader *r, const char *name)
{
	const char *p;
	size_t i;

	for (i = 0; i < ntypes; i++)
		if (strcmp(types[i].name, name) == 0)
			return i;
	for (p = name; *p >= 'a' && *p <= 'z'; p++)
		;
	if (*p != '\0')
		qt_fail(r, "element type is not a lowercase word: %s", name);
	types = xreallocarray(types, ntypes + 1, sizeof(*types));
	types[ntypes].name = xstrdup(name);
	types[ntypes].n = 0;
	return ntypes++;
}

static void
elemrec(struct qtreader *r, char *line)
{
	char *f[64];
	int n = qt_split(r, line, f, 64), k;
	size_t t;

	if (n < 6)
		qt_fail(r, "elem record needs at least 6 fields: elem ID TYPE "
		    "V1 V2 V3 ...");
	if (number(r, f[1], "element ID", SIZE_MAX - 1) != nelems + 1)
		qt_fail(r, "elem %s follows elem %zu", f[1], nelems);
	t = typeindex(r, f[2]);
	if (strcmp(f[2], "quad") == 0 && n != 7)
		qt_fail(r, "a quad element has 4 vertices, not %d", n - 3);
	types[t].n++;
	if (nrefs + n > refcap) {
		refcap = 2 * (nrefs + n);
		refs = xreallocarray(refs, refcap, sizeof(*refs));
	}
	if (nelems + 2 > elemcap) {
		elemcap = elemcap ? 2 * elemcap : 1024;
		eoff = xreallocarray(eoff, elemcap, sizeof(*eoff));
	}
	eoff[nelems] = nrefs;
	for (k = 3; k < n; k++) {
		unsigned long long v = number(r, f[k], "vertex number",
		    UINT32_MAX);

		if (v > nverts)
			qt_fail(r, "elem %s refers to vertex %llu, which no "
			    "vertex record before it defines", f[1], v);
		refs[nrefs++] = v - 1;
	}
	eoff[++nelems] = nrefs;
}

static int
istag(const char *line, const char *tag)
{
	size_t n = strlen(tag);

	return strncmp(line, tag, n) == 0 &&
	    (line[n] == ' ' || line[n] == '\0');
}

static void
readstream(struct qtreader *r)
{
	struct qtrec rec;
	enum qtkind kind;

	while ((kind = qt_read(r, &rec)) != QT_EOF) {
		switch (kind) {
		case QT_UNIVERSE:
			u = rec.u;
			break;
		case QT_RING:
			nrings++;
			nholes += rec.hole;
			ringhole = rec.hole;
			break;
		case QT_VERTEX:
			ringvertex(r, rec.v);
			break;
		case QT_NODE:
		case QT_LEAF:
			addcell(&rec.c);
			break;
		case QT_OTHER:
			if (istag(rec.line, "vertex")) {
				vertexrec(r, rec.line);
				havemesh = 1;
			} else if (istag(rec.line, "elem")) {
				elemrec(r, rec.line);
				havemesh = 1;
			}
			break;
		default:
			break;
		}
	}
}

/*
 * Sorts by x, stably, least significant digit first.  That sorts by
 * (x, y): the leaves come in preorder, and preorder puts the cells whose
 * left sides, or right sides, lie on one line in the order of their y
 * (the first cell to differ between two of them is south of the other's,
 * the line being no further west than their split); and the second axis
 * starts from an array sorted by (y, x).  The keys are multiples of
 * 2^(GRID - deepest) up to 2^GRID, so only their deepest + 1 bits above
 * those are sorted on, in the fewest digits of at most 16 bits; the counts
 * of every digit come from one pass, and a digit that is the same for all
 * takes none.
 */
#define MAXDIGITS	((GRID + 16) / 16)

static void
sortrecs(struct lrec *a, struct lrec *tmp, size_t n)
{
	static size_t count[MAXDIGITS][1 << 16];
	struct lrec *src = a, *dst = tmp, *t;
	int low = GRID - deepest, ndigit = (deepest + 16) / 16;
	int width = (deepest + ndigit) / ndigit, d;
	uint64_t mask = ((uint64_t)1 << width) - 1;
	size_t i, sum;

	if (n == 0)
		return;
	memset(count, 0, ndigit * sizeof(count[0]));
	for (i = 0; i < n; i++)
		for (d = 0; d < ndigit; d++)
			count[d][a[i].x >> (low + width * d) & mask]++;
	for (d = 0; d < ndigit; d++) {
		int shift = low + width * d;
		size_t *c = count[d];

		if (c[src[0].x >> shift & mask] == n)
			continue;
		for (i = 0, sum = 0; i <= mask; i++) {
			size_t k = c[i];

			c[i] = sum;
			sum += k;
		}
		for (i = 0; i < n; i++)
			dst[c[src[i].x >> shift & mask]++] = src[i];
		t = src, src = dst, dst = t;
	}
	if (src != a)
		memcpy(a, src, n * sizeof(*a));
}

static uint64_t
span(const struct lrec *r)
{
	return (uint64_t)1 << (GRID - (int)(r->y >> LEVELSHIFT));
}

/*
 * lo holds the cells' sides at their low x, hi at their high x, both
 * sorted by x then y.  On each line x the sides of the cells to its left
 * and to its right are disjoint runs in y: a merge finds the pairs that
 * overlap over a positive length, side neighbours.
 */
static int
sweep(const struct lrec *lo, const struct lrec *hi, size_t n)
{
	size_t i = 0, j = 0;
	int best = 0;

	while (i < n && j < n) {
		uint64_t a0, a1, b0, b1;
		int jump;

		if (hi[j].x < lo[i].x) {
			j++;
			continue;
		}
		if (lo[i].x < hi[j].x) {
			i++;
			continue;
		}
		a0 = lo[i].y & COORDMASK;
		a1 = a0 + span(&lo[i]);
		b0 = hi[j].y & COORDMASK;
		b1 = b0 + span(&hi[j]);
		if (a0 < b1 && b0 < a1) {
			jump = (int)(lo[i].y >> LEVELSHIFT) -
			    (int)(hi[j].y >> LEVELSHIFT);
			if (abs(jump) > best)
				best = abs(jump);
		}
		if (a1 <= b1)
			i++;
		if (b1 <= a1)
			j++;
	}
	return best;
}

/* Builds the high sides from the low ones, then sweeps. */
static int
sweepaxis(struct lrec *lo, struct lrec *hi, struct lrec *tmp, size_t n)
{
	size_t i;

	for (i = 0; i < n; i++) {
		hi[i].x = lo[i].x + span(&lo[i]);
		hi[i].y = lo[i].y;
	}
	sortrecs(lo, tmp, n);
	sortrecs(hi, tmp, n);
	return sweep(lo, hi, n);
}

static int
maxjump(void)
{
	struct lrec *hi, *tmp;
	size_t i;
	int best, across;

	if (nleaves < 2)
		return 0;
	hi = xreallocarray(NULL, nleaves, sizeof(*hi));
	tmp = xreallocarray(NULL, nleaves, sizeof(*tmp));
	best = sweepaxis(leaves, hi, tmp, nleaves);
	/* the same again across rows: swap x and y, keeping the level */
	for (i = 0; i < nleaves; i++) {
		uint64_t x = leaves[i].x, y = leaves[i].y;

		leaves[i].x = y & COORDMASK;
		leaves[i].y = x | (y & ~COORDMASK);
	}
	across = sweepaxis(leaves, hi, tmp, nleaves);
	if (across > best)
		best = across;
	free(hi);
	free(tmp);
	return best;
}

/* Vertex numbers sorted by (x, y) or by (y, x); then ties by number. */
static int byaxis;

static int
cmpvert(const void *pa, const void *pb)
{
	const struct point *a = &verts[*(const uint32_t *)pa];
	const struct point *b = &verts[*(const uint32_t *)pb];
	double a1 = byaxis ? a->y : a->x, b1 = byaxis ? b->y : b->x;
	double a2 = byaxis ? a->x : a->y, b2 = byaxis ? b->x : b->y;
	uint32_t ia = *(const uint32_t *)pa, ib = *(const uint32_t *)pb;

	if (a1 != b1)
		return a1 < b1 ? -1 : 1;
	if (a2 != b2)
		return a2 < b2 ? -1 : 1;
	return (ia > ib) - (ia < ib);
}

static uint32_t *
sortverts(int axis, uint32_t **rank)
{
	uint32_t *order = xreallocarray(NULL, nverts, sizeof(*order));
	size_t i;

	*rank = xreallocarray(NULL, nverts, sizeof(**rank));
	for (i = 0; i < nverts; i++)
		order[i] = i;
	byaxis = axis;
	qsort(order, nverts, sizeof(*order), cmpvert);
	for (i = 0; i < nverts; i++)
		(*rank)[order[i]] = i;
	return order;
}

static int
between(double v, double a, double b)
{
	return a < b ? a < v && v < b : b < v && v < a;
}

/*
 * The vertices on the open segment a-b of a slanted side: column by
 * column of the vertices sorted by x, the rows within its y range, each
 * tested exactly for lying on the line.
 */
static void
slanted(const uint32_t *byx, uint32_t a, uint32_t b, char *hanging)
{
	struct point pa = verts[a], pb = verts[b];
	double xlo = fmin(pa.x, pb.x), xhi = fmax(pa.x, pb.x);
	double ylo = fmin(pa.y, pb.y), yhi = fmax(pa.y, pb.y);
	size_t lo = 0, hi = nverts, k;

	while (lo < hi) {	/* first vertex with x > xlo */
		size_t mid = lo + (hi - lo) / 2;

		if (verts[byx[mid]].x <= xlo)
			lo = mid + 1;
		else
			hi = mid;
	}
	for (k = lo; k < nverts && verts[byx[k]].x < xhi; k++) {
		struct point v = verts[byx[k]];

		if (v.y > ylo && v.y < yhi &&
		    orient2d(pa.x, pa.y, pb.x, pb.y, v.x, v.y) == 0)
			hanging[byx[k]] = 1;
	}
}

/*
 * A vertex hangs when it lies in the open interior of a side of some
 * element.  On a side along x or y those vertices are exactly the ones
 * between its two ends in the order sorted along that line.
 */
static unsigned long long
counthanging(void)
{
	uint32_t *byx, *byy, *rankx, *ranky;
	char *hanging;
	unsigned long long n = 0;
	size_t e, i, k;

	if (nverts == 0)
		return 0;
	byx = sortverts(0, &rankx);
	byy = sortverts(1, &ranky);
	hanging = xmalloc(nverts);
	memset(hanging, 0, nverts);
	for (e = 0; e < nelems; e++) {
		size_t start = eoff[e], stop = eoff[e + 1];

		for (i = start; i < stop; i++) {
			uint32_t a = refs[i];
			uint32_t b = refs[i + 1 < stop ? i + 1 : start];
			struct point pa = verts[a], pb = verts[b];
			const uint32_t *order;
			uint32_t r0, r1;

			if (pa.x == pb.x && pa.y == pb.y)
				continue;
			if (pa.x != pb.x && pa.y != pb.y) {
				slanted(byx, a, b, hanging);
				continue;
			}
			order = pa.x == pb.x ? byx : byy;
			r0 = pa.x == pb.x ? rankx[a] : ranky[a];
			r1 = pa.x == pb.x ? rankx[b] : ranky[b];
			if (r0 > r1) {
				uint32_t t = r0;

				r0 = r1;
				r1 = t;
			}
			for (k = r0 + 1; k < r1; k++) {
				struct point v = verts[order[k]];

				/* not a copy of an end */
				if (pa.x == pb.x ? between(v.y, pa.y, pb.y) :
				    between(v.x, pa.x, pb.x))
					hanging[order[k]] = 1;
			}
		}
	}
	for (i = 0; i < nverts; i++)
		n += hanging[i];
	free(hanging);
	free(byx);
	free(byy);
	free(rankx);
	free(ranky);
	return n;
}

static void
putkey(const char *key, const char *value)
{
	printf("%s %s\n", key, value);
}

static void
putcount(const char *key, unsigned long long v)
{
	char buf[32];

	fmtint(buf, (long long)v);
	putkey(key, buf);
}

static void
putreal(const char *key, double v)
{
	char buf[32];

	fmtreal(buf, v);
	putkey(key, buf);
}

/* Area of the leaves of the given classes, exactly, as an expansion. */
static void
leafarea(struct xsum *s, int withpartial)
{
	int l;

	for (l = 0; l <= deepest; l++) {
		unsigned long long n = lev[l].leaves[F];

		if (withpartial)
			n += lev[l].leaves[P];
		if (n > 0)
			xs_addprod3(s, ldexp((double)n, -2 * l), u.size,
			    u.size);
	}
}

/*
 * The centroid of the leaves, from the exact sums of 2 IX + 1: a leaf at
 * level l has its centre at X0 + (2 IX + 1) SIZE / 2^(l+1) and weight
 * 4^-l.
 */
static void
leafcentroid(const char *kx, const char *ky, int withpartial)
{
	struct xsum w, mx, my;
	double sw;
	int l;

	xs_init(&w);
	xs_init(&mx);
	xs_init(&my);
	for (l = 0; l <= deepest; l++) {
		const struct levelstat *s = &lev[l];
		double n = (double)s->leaves[F];
		double sx = u128real(&s->sx[F]), sy = u128real(&s->sy[F]);

		if (withpartial) {
			n += (double)s->leaves[P];
			sx += u128real(&s->sx[P]);
			sy += u128real(&s->sy[P]);
		}
		xs_add(&w, ldexp(n, -2 * l));
		xs_add(&mx, ldexp(sx, -3 * l - 1));
		xs_add(&my, ldexp(sy, -3 * l - 1));
	}
	sw = xs_round(&w);
	putreal(kx, u.x0 + u.size * (xs_round(&mx) / sw));
	putreal(ky, u.y0 + u.size * (xs_round(&my) / sw));
	xs_free(&w);
	xs_free(&mx);
	xs_free(&my);
}

/* |approximation - polygon| / polygon, the difference taken exactly. */
static double
relerr(const struct xsum *approx, double area)
{
	struct xsum d;
	double v;

	xs_init(&d);
	xs_addxs(&d, approx, 1);
	xs_addxs(&d, &region.a2, -0.5);
	v = fabs(xs_round(&d)) / area;
	xs_free(&d);
	return v;
}

static int
cmptype(const void *a, const void *b)
{
	return strcmp(((const struct etype *)a)->name,
	    ((const struct etype *)b)->name);
}

static void
report(int table)
{
	unsigned long long cells = 0, nodes = 0, leafn[3] = { 0, 0, 0 };
	double area = 0, cx, cy;
	char key[64];
	size_t i;
	int l, k;

	putcount("rings", nrings);
	putcount("holes", nholes);
	if (nrings > 0) {
		mo_result(&region, &area, &cx, &cy);
		putreal("polygon_area", area);
		putreal("perimeter", perim + perimlow);
		putreal("centroid_x", cx);
		putreal("centroid_y", cy);
	}
	for (l = 0; l <= deepest; l++) {
		nodes += lev[l].nodes;
		for (k = 0; k < 3; k++)
			leafn[k] += lev[l].leaves[k];
	}
	cells = nodes + leafn[F] + leafn[E] + leafn[P];
	putcount("cells", cells);
	putcount("nodes", nodes);
	putcount("leaves", leafn[F] + leafn[E] + leafn[P]);
	putcount("leaves_F", leafn[F]);
	putcount("leaves_E", leafn[E]);
	putcount("leaves_P", leafn[P]);
	if (cells > 0) {
		struct xsum full, fullpart;
		double af, afp, uniform = ldexp(1, 2 * deepest);

		putcount("deepest_level", deepest);
		if (deepest <= 31)
			putcount("uniform_cells", 1ULL << 2 * deepest);
		else
			putreal("uniform_cells", uniform);
		putreal("saving", (double)nleaves / uniform);
		putcount("max_level_jump", maxjump());
		xs_init(&full);
		xs_init(&fullpart);
		leafarea(&full, 0);
		leafarea(&fullpart, 1);
		af = xs_round(&full);
		afp = xs_round(&fullpart);
		putreal("area_full", af);
		putreal("area_full_partial", afp);
		if (area > 0) {
			putreal("area_full_relerr", relerr(&full, area));
			putreal("area_full_partial_relerr",
			    relerr(&fullpart, area));
		}
		if (af > 0)
			leafcentroid("centroid_full_x", "centroid_full_y", 0);
		if (afp > 0)
			leafcentroid("centroid_full_partial_x",
			    "centroid_full_partial_y", 1);
		xs_free(&full);
		xs_free(&fullpart);
	}
	if (havemesh) {
		unsigned long long quads = 0;

		putcount("vertices", nverts);
		putcount("elements", nelems);
		qsort(types, ntypes, sizeof(*types), cmptype);
		for (i = 0; i < ntypes; i++)
			if (strcmp(types[i].name, "quad") == 0)
				quads = types[i].n;
		putcount("elements_quad", quads);
		for (i = 0; i < ntypes; i++) {
			if (strcmp(types[i].name, "quad") == 0)
				continue;
			snprintf(key, sizeof(key), "elements_%s",
			    types[i].name);
			putcount(key, types[i].n);
		}
		putcount("hanging_vertices", counthanging());
	}
	if (!table)
		return;
	printf("# level cells nodes leaves leaves_F leaves_E leaves_P\n");
	for (l = 0; l <= deepest; l++) {
		const struct levelstat *s = &lev[l];
		unsigned long long n = s->leaves[F] + s->leaves[E] +
		    s->leaves[P];

		printf("level %d %llu %llu %llu %llu %llu %llu\n", l,
		    s->nodes + n, s->nodes, n, s->leaves[F], s->leaves[E],
		    s->leaves[P]);
	}
}

int
main(int argc, char *argv[])
{
	struct qtreader r;
	const char *name;
	int ch, table = 0, verbose = 0;
	FILE *fp;

	setprogname_(argv[0]);
	while ((ch = getopt(argc, argv, "lv")) != -1)
		switch (ch) {
		case 'l':
			table = 1;
			break;
		case 'v':
			verbose = 1;
			break;
		default:
			usage();
		}
	argc -= optind;
	argv += optind;
	if (argc > 1)
		usage();

	mo_init(&region);
	mo_init(&ringmo);
	fp = openin(argc == 1 ? argv[0] : "-", &name);
	qt_open(&r, fp, name);
	r.verbose = verbose;
	readstream(&r);
	qt_close(&r);
	report(table);
	closeout();
	return 0;
}
