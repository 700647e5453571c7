/*
 * iso.c: a 3D stream without -z, as an isometric view of its full and
 * partial cubes, seen from the corner where x, y and z are largest: the
 * faces toward +x, +y and +z, each shaded by its direction.  Leaves deeper
 * than the level whose cubes' edges are still a pixel long are merged into
 * their ancestor at that level, as 2D leaves into blocks, so that the
 * picture, not the tree, bounds the file.  The cubes are kept in stream
 * order, preorder, which is a back-to-front order for this view, and a
 * face is left out when the kept cubes across it cover it whole.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qt2svg.h"

struct cube {
	uint64_t	 i[3];
	unsigned char	 level, k;
};

static struct {
	int		 lb;		/* the merging level, -1 until known */
	struct cube	*c;
	size_t		 n, cap;
	size_t		*hash;		/* indices + 1 into c, 0 for none */
	size_t		 mask;
	int		 pend;		/* a merged cube being gathered */
	uint64_t	 pi[3];
	unsigned	 pbits;
	unsigned long long faces[NCLASS];
} iso = { .lb = -1 };

/*
 * The face colours: the class's for +z, the top, then 80% and 60% of it
 * for +y and +x, channel by channel, rounded: #0072B2 and #E69F00.
 */
static const char *facecolour[NCLASS][3] = {
	{ "#00446B", "#005B8E", "#0072B2" },
	{ "#346C8C", "#4590BA", "#56B4E9" },
	{ "#8A5F00", "#B87F00", "#E69F00" },
};

/* The map's width in pixels; its height is 2 / sqrt(3) of it. */
static double
isowidth(void)
{
	return mapside();
}

/* A cube edge of this level, in pixels: sqrt(2/3) of the side's share. */
static double
edgepixels(int level)
{
	return ldexp(isowidth() / sqrt(3), -level);
}

/* The deepest level whose cubes' edges are 1 pixel or more, at least 0. */
static int
mergelevel(void)
{
	int l = 0;

	while (l < QT_MAXLEVEL && edgepixels(l + 1) >= 1)
		l++;
	return l;
}

static size_t
hashof(int level, const uint64_t i[3])
{
	uint64_t h = (uint64_t)level * 0x9E3779B97F4A7C15u;

	h ^= i[0] * 0xC2B2AE3D27D4EB4Fu;
	h = (h ^ h >> 29) * 0xBF58476D1CE4E5B9u;
	h ^= i[1] * 0x165667B19E3779F9u;
	h = (h ^ h >> 31) * 0x94D049BB133111EBu;
	h ^= i[2] * 0x27D4EB2F165667C5u;
	return (size_t)(h ^ h >> 32);
}

static int
found(int level, const uint64_t i[3])
{
	size_t j = hashof(level, i) & iso.mask, x;

	while ((x = iso.hash[j]) != 0) {
		const struct cube *c = &iso.c[x - 1];

		if (c->level == level && c->i[0] == i[0] && c->i[1] == i[1] &&
		    c->i[2] == i[2])
			return 1;
		j = (j + 1) & iso.mask;
	}
	return 0;
}

static void
makehash(void)
{
	size_t size = 1, k;

	while (size < 2 * iso.n + 1)
		size *= 2;
	iso.hash = xcalloc(size, sizeof(*iso.hash));
	iso.mask = size - 1;
	for (k = 0; k < iso.n; k++) {
		size_t j = hashof(iso.c[k].level, iso.c[k].i) & iso.mask;

		while (iso.hash[j] != 0)
			j = (j + 1) & iso.mask;
		iso.hash[j] = k + 1;
	}
}

static void
keep(int level, const uint64_t i[3], int k)
{
	struct cube *c;

	if (!opt.drawn[k] || k == CE)
		return;
	iso.c = xgrow(iso.c, &iso.cap, iso.n + 1, sizeof(*iso.c));
	c = &iso.c[iso.n++];
	memcpy(c->i, i, sizeof(c->i));
	c->level = level;
	c->k = k;
}

/*
 * The merged cube's class, by 2D blocks' rule (leaves.c): partial when it
 * holds a partial leaf or both full and empty ones, full when P is not
 * drawn.
 */
static void
flush(void)
{
	unsigned b = iso.pbits;

	if (!iso.pend)
		return;
	iso.pend = 0;
	if ((b & CELL_CLASSBIT('P')) ||
	    (b & CELL_CLASSBIT('F') && b & CELL_CLASSBIT('E')))
		keep(iso.lb, iso.pi, opt.drawn[CP] ? CP : CF);
	else if (b & CELL_CLASSBIT('F'))
		keep(iso.lb, iso.pi, CF);
}

void
isocell(const struct cell3 *c)
{
	uint64_t i[3] = { c->ix, c->iy, c->iz };
	int a, k;

	if (c->class == 0)
		return;
	if (iso.lb < 0)
		iso.lb = mergelevel();
	k = c->class == 'F' ? CF : c->class == 'E' ? CE : CP;
	pic.n[k]++;
	if (c->level > pic.deepest)
		pic.deepest = c->level;
	if (c->level <= iso.lb) {
		flush();
		keep(c->level, i, k);
		return;
	}
	for (a = 0; a < 3; a++)
		i[a] >>= c->level - iso.lb;
	if (iso.pend && memcmp(i, iso.pi, sizeof(i)) == 0) {
		iso.pbits |= CELL_CLASSBIT(c->class);
		return;
	}
	flush();
	iso.pend = 1;
	memcpy(iso.pi, i, sizeof(i));
	iso.pbits = CELL_CLASSBIT(c->class);
}

/*
 * Whether kept cubes cover the side toward -axis of the cell at level,
 * i: no ancestor of it is kept (the caller looked), so it must be its
 * four children on that side, each kept or covered by its own.
 */
static int
coveredbelow(int level, const uint64_t i[3], int axis)
{
	int q, a;

	if (level >= iso.lb)
		return 0;
	for (q = 0; q < 8; q++) {
		uint64_t j[3];

		if (q >> axis & 1)
			continue;
		for (a = 0; a < 3; a++)
			j[a] = 2 * i[a] + (q >> a & 1);
		if (!found(level + 1, j) && !coveredbelow(level + 1, j, axis))
			return 0;
	}
	return 1;
}

/* Whether kept cubes cover a cube's face toward +axis whole. */
static int
covered(const struct cube *c, int axis)
{
	uint64_t n[3], j[3];
	int l, a;

	memcpy(n, c->i, sizeof(n));
	n[axis]++;
	if (n[axis] >> c->level != 0)
		return 0;	/* the universe's side */
	for (l = c->level; l >= 0; l--) {
		for (a = 0; a < 3; a++)
			j[a] = n[a] >> (c->level - l);
		if (found(l, j))
			return 1;
	}
	return coveredbelow(c->level, n, axis);
}

/*
 * The picture's point of the universe's point (u, v, w), each coordinate
 * from 0 to 1: x runs down to the left, y down to the right, z up.
 */
static long long
isox(double u, double v)
{
	return hund(opt.margin + isowidth() * (v - u + 1) / 2);
}

static long long
isoy(double u, double v, double w)
{
	return hund(opt.margin + isowidth() * (2 - 2 * w + u + v) /
	    sqrt(12));
}

/* A face: its corners from the one nearest the origin, round. */
static void
face(struct layer *ly, const struct cube *c, int axis)
{
	static const int step[4][2] = {	/* along the other two axes */
		{ 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 }
	};
	double s = ldexp(1, -c->level), p[3];
	long long x[4], y[4];
	int k, a, b;

	a = axis == 0 ? 1 : 0;
	b = axis == 2 ? 1 : 2;
	for (k = 0; k < 4; k++) {
		p[axis] = (double)(c->i[axis] + 1) * s;
		p[a] = (double)(c->i[a] + step[k][0]) * s;
		p[b] = (double)(c->i[b] + step[k][1]) * s;
		x[k] = isox(p[0], p[1]);
		y[k] = isoy(p[0], p[1], p[2]);
	}
	subpath(ly);
	out("M", 1);
	outxy(x[0], y[0]);
	out("l", 1);
	for (k = 1; k < 4; k++) {
		if (k > 1)
			out(" ", 1);
		outxy(x[k] - x[k - 1], y[k] - y[k - 1]);
	}
	out("z", 1);
}

/*
 * The faces, cube by cube in stream order; a path element holds the
 * faces of one colour and level that come one after another.
 */
static void
faces(void)
{
	static char attrs[NCLASS][3][QT_MAXLEVEL + 1][96];
	struct layer ly = { "<g id=\"faces\" stroke=\"#000000\" "
	    "stroke-opacity=\"0.35\" stroke-linejoin=\"round\">\n", 0, "", 0 };
	const char *last = NULL;
	size_t m;
	int axis;

	for (m = 0; m < iso.n; m++) {
		const struct cube *c = &iso.c[m];

		for (axis = 0; axis < 3; axis++) {
			char *at = attrs[c->k][axis][c->level], w[32];
			double e = edgepixels(c->level);

			if (covered(c, axis))
				continue;
			if (at[0] == '\0') {
				if (e >= 2)
					fmthund(w, hund(e / 8 < 1 ? e / 8 : 1));
				snprintf(at, sizeof(attrs[0][0][0]),
				    "fill=\"%s\" %s%s%s", facecolour[c->k][axis],
				    e >= 2 ? "stroke-width=\"" : "stroke=\"none",
				    e >= 2 ? w : "", "\" ");
			}
			if (at != last)
				pathattrs(&ly, at);
			last = at;
			face(&ly, c, axis);
			iso.faces[c->k]++;
		}
	}
	layerend(&ly);
}

static void
isolegend(void)
{
	char swatch[128], text[160], num[32];
	int k, row = 0;

	outs("<g id=\"legend\" font-family=\"sans-serif\" font-size=\"12\">\n");
	for (k = 0; k < NCLASS; k++) {
		if (!opt.drawn[k] || k == CE)
			continue;
		snprintf(swatch, sizeof(swatch), "<rect fill=\"%s\" "
		    "stroke=\"#000000\" stroke-opacity=\"0.35\"",
		    classcolour[k]);
		snprintf(text, sizeof(text), "%c %s: faces", classletter[k],
		    classname[k]);
		legendrow(row++, swatch, text, iso.faces[k]);
	}
	fmtint(num, pic.level >= 0 ? pic.level : pic.deepest);
	snprintf(text, sizeof(text), "level %s, leaves below level %d "
	    "merged; x down left, y down right, z up", num, iso.lb);
	legendtext((long long)opt.margin * 100, mapbottom() +
	    (long long)(ROW * row + 2) * 100, NULL, text);
	outs("</g>\n");
}

void
isodraw(double z0)
{
	char x0[32], y0[32], zz[32], size[32];
	long long height;
	int rows = 1 + opt.drawn[CF] + opt.drawn[CP];

	if (iso.lb < 0)
		iso.lb = mergelevel();
	flush();
	makehash();
	pic.win.maph = (long long)ceil(isowidth() * 2 / sqrt(3));
	height = mapbottom() / 100 + (long long)ROW * rows + opt.margin;
	printf("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
	    "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" "
	    "width=\"%d\" height=\"%lld\" viewBox=\"0 0 %d %lld\">\n"
	    "<title>qtree</title>\n", opt.width, height, opt.width, height);
	fmtreal(x0, pic.u.x0);
	fmtreal(y0, pic.u.y0);
	fmtreal(zz, z0);
	fmtreal(size, pic.u.size);
	printf("<desc>universe %s %s %s %s, isometric view, drawn by "
	    "qt2svg</desc>\n", x0, y0, zz, size);
	outs("<rect width=\"100%\" height=\"100%\" fill=\"#FFFFFF\"/>\n");
	faces();
	isolegend();
	outs("</svg>\n");
	free(iso.hash);
	free(iso.c);
}
