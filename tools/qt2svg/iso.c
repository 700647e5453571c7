/*
 * iso.c: a 3D stream without -z, as an isometric view of its full and
 * partial cubes, seen from the corner where x, y and z are largest: the
 * faces toward +x, +y and +z, each shaded by its direction.  Leaves deeper
 * than the level whose cubes' edges are still a pixel long are merged into
 * their ancestor at that level, as 2D leaves into blocks, so that the
 * picture, not the tree, bounds the file.  The cubes are kept in stream
 * order, preorder, which is a back-to-front order for this view.  A face
 * is left out when the kept cubes across it cover it whole, or when it
 * shows in no triangle of the picture's lattice (faces()); the others are
 * drawn in that order, in batches of faces that do not overlap.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qt2svg.h"

#define MAXISO	10	/* the deepest merging level: 34 MB of lattice */

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

/*
 * The deepest level whose cubes' edges are 1 pixel or more, at least 0
 * and at most MAXISO, which bounds the picture's lattice (faces()).
 */
static int
mergelevel(void)
{
	int l = 0;

	while (l < MAXISO && edgepixels(l + 1) >= 1)
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

/*
 * A number of a path's data, as short as SVG reads it: no space before a
 * minus sign or after a command letter, no 0 before a point.
 */
static char *
putnum(char *p, long long v, int sep)
{
	char tmp[32], *t = tmp;

	fmthund(tmp, v);
	if (t[0] == '-')
		*p++ = *t++;
	else if (sep)
		*p++ = ' ';
	if (t[0] == '0' && t[1] == '.')
		t++;
	while (*t != '\0')
		*p++ = *t++;
	return p;
}

/*
 * A face: its corners from the one nearest the origin, round.  The first
 * face of a path element starts at its corner, the next ones relative to
 * the corner the one before started at, where its z left the pen.
 */
static void
face(struct layer *ly, const struct cube *c, int axis)
{
	static const int step[4][2] = {	/* along the other two axes */
		{ 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 }
	};
	static long long px, py;
	double s = ldexp(1, -c->level), q[3];
	long long x[4], y[4];
	char buf[256], *p = buf;
	int k, a, b;

	a = axis == 0 ? 1 : 0;
	b = axis == 2 ? 1 : 2;
	for (k = 0; k < 4; k++) {
		q[axis] = (double)(c->i[axis] + 1) * s;
		q[a] = (double)(c->i[a] + step[k][0]) * s;
		q[b] = (double)(c->i[b] + step[k][1]) * s;
		x[k] = isox(q[0], q[1]);
		y[k] = isoy(q[0], q[1], q[2]);
	}
	subpath(ly);
	if ((ly->n - 1) % CHUNK == 0) {
		*p++ = 'M';
		p = putnum(p, x[0], 0);
		p = putnum(p, y[0], 1);
		*p++ = 'l';
		k = 0;
	} else {
		*p++ = 'm';
		p = putnum(p, x[0] - px, 0);
		p = putnum(p, y[0] - py, 1);
		k = 1;
	}
	for (a = 1; a < 4; a++, k = 1) {
		p = putnum(p, x[a] - x[a - 1], k);
		p = putnum(p, y[a] - y[a - 1], 1);
	}
	*p++ = 'z';
	out(buf, p - buf);
	px = x[0];
	py = y[0];
}

/*
 * A face waiting in a batch: its cube, its direction, and the ranges of
 * x - z, y - z and x - y over it, in cubes of the merging level.  Those
 * three are constant along the view, and a face's edges run along the
 * lines where one of them is, so two faces overlap in the picture exactly
 * when all three ranges overlap.
 */
struct face {
	const struct cube *c;
	int		 axis;
	int64_t		 lo[3], hi[3];
};

#define BATCH	256

static struct {
	struct face	 f[BATCH];
	int		 n;
	struct layer	 ly;
	const char	*last;
} fb = { .ly = { "<g id=\"faces\" stroke=\"#000000\" stroke-opacity="
    "\"0.35\" stroke-linejoin=\"round\">\n", 0, "", 0 } };

static void
faceranges(struct face *f)
{
	int sh = iso.lb - f->c->level;
	int64_t a = (int64_t)f->c->i[0] << sh, b = (int64_t)f->c->i[1] << sh;
	int64_t c = (int64_t)f->c->i[2] << sh, s = (int64_t)1 << sh;
	int64_t mid[3] = { a - c, b - c, a - b };
	int k;

	/* the cube's own ranges, then the face's part of them */
	for (k = 0; k < 3; k++) {
		f->lo[k] = mid[k] - s;
		f->hi[k] = mid[k] + s;
	}
	switch (f->axis) {
	case 0:		/* x = a + s: x - z from a - c up, x - y from a - b */
		f->lo[0] = mid[0];
		f->lo[2] = mid[2];
		break;
	case 1:		/* y = b + s */
		f->lo[1] = mid[1];
		f->hi[2] = mid[2];
		break;
	default:	/* z = c + s */
		f->hi[0] = mid[0];
		f->hi[1] = mid[1];
		break;
	}
}

static int
overlap(const struct face *f, const struct face *g)
{
	int k;

	for (k = 0; k < 3; k++)
		if (f->lo[k] >= g->hi[k] || g->lo[k] >= f->hi[k])
			return 0;
	return 1;
}

static const char *
faceattrs(const struct cube *c, int axis)
{
	static char attrs[NCLASS][3][QT_MAXLEVEL + 1][96];
	char *at = attrs[c->k][axis][c->level], w[32];
	double e = edgepixels(c->level);

	if (at[0] == '\0') {
		if (e >= 2)
			fmthund(w, hund(e / 8 < 1 ? e / 8 : 1));
		snprintf(at, sizeof(attrs[0][0][0]), "fill=\"%s\" %s%s%s",
		    facecolour[c->k][axis], e >= 2 ? "stroke-width=\"" :
		    "stroke=\"none", e >= 2 ? w : "", "\" ");
	}
	return at;
}

/*
 * The batch's faces, which do not overlap one another, so that any order
 * of them is as good as the stream's: a colour and level at a time, each
 * one path element.
 */
static void
flushfaces(void)
{
	int j, m;

	for (j = 0; j < fb.n; j++) {
		const char *at;

		if (fb.f[j].c == NULL)
			continue;
		at = faceattrs(fb.f[j].c, fb.f[j].axis);
		if (at != fb.last)
			pathattrs(&fb.ly, at);
		fb.last = at;
		for (m = j; m < fb.n; m++)
			if (fb.f[m].c != NULL &&
			    faceattrs(fb.f[m].c, fb.f[m].axis) == at) {
				face(&fb.ly, fb.f[m].c, fb.f[m].axis);
				fb.f[m].c = NULL;
			}
	}
	fb.n = 0;
}

/*
 * The picture's lattice: in cubes of the merging level, a point's x - z
 * and y - z are its coordinates p, q on the picture, and the lines where
 * p, q or p - q is whole cut the picture into triangles, two a unit cell
 * of p and q, 0 below its diagonal and 1 above.  A face of the merging
 * level covers two of them, and a larger face those of the faces of that
 * level it is made of.  Faces come back to front, so a triangle shows the
 * last face that covers it; a face that shows in none is left out.
 */
static void
showface(uint32_t *own, uint32_t id, const struct cube *c, int axis)
{
	static const int tri[3][2][3] = {	/* p, q offsets, triangle */
		{ { 0, -1, 1 }, { 0, 0, 0 } },
		{ { -1, 0, 0 }, { 0, 0, 1 } },
		{ { -1, -1, 0 }, { -1, -1, 1 } },
	};
	int sh = iso.lb - c->level, a, b, k;
	int64_t side = (int64_t)1 << iso.lb, w = 2 * side + 1, s = 1 << sh;
	int64_t o[3], u[3], j, m;

	a = axis == 0 ? 1 : 0;
	b = axis == 2 ? 1 : 2;
	for (k = 0; k < 3; k++)
		o[k] = (int64_t)c->i[k] << sh;
	o[axis] += s - 1;
	memcpy(u, o, sizeof(u));
	for (j = 0; j < s; j++)
		for (m = 0; m < s; m++) {
			u[a] = o[a] + j;
			u[b] = o[b] + m;
			for (k = 0; k < 2; k++) {
				const int *t = tri[axis][k];
				int64_t p = u[0] - u[2] + t[0] + side;
				int64_t q = u[1] - u[2] + t[1] + side;

				own[2 * (p * w + q) + t[2]] = id;
			}
		}
}

/*
 * The faces, cube by cube in stream order: those that no kept cube
 * covers, then of those the ones that show.  They are drawn in that
 * order, gathered into batches of faces that do not overlap one
 * another, so that few path elements hold them; a face that overlaps one
 * of the batch starts the next batch.
 */
static void
faces(void)
{
	struct face *cand = NULL;
	size_t n = 0, cap = 0, m, w = ((size_t)2 << iso.lb) + 1;
	uint32_t *own = xcalloc(2 * w * w, sizeof(*own));
	unsigned char *shown;
	int axis, j;

	for (m = 0; m < iso.n; m++)
		for (axis = 0; axis < 3; axis++) {
			if (covered(&iso.c[m], axis))
				continue;
			cand = xgrow(cand, &cap, n + 1, sizeof(*cand));
			cand[n].c = &iso.c[m];
			cand[n].axis = axis;
			if (n == UINT32_MAX - 1)
				die(1, "more than 2^32 faces to draw");
			showface(own, (uint32_t)++n, &iso.c[m], axis);
		}
	shown = xcalloc(n + 1, 1);
	for (m = 0; m < 2 * w * w; m++)
		shown[own[m]] = 1;
	free(own);
	for (m = 0; m < n; m++) {
		struct face f = cand[m];

		if (!shown[m + 1])
			continue;
		faceranges(&f);
		for (j = 0; j < fb.n && !overlap(&f, &fb.f[j]); j++)
			;
		if (j < fb.n || fb.n == BATCH)
			flushfaces();
		fb.f[fb.n++] = f;
		iso.faces[f.c->k]++;
	}
	flushfaces();
	layerend(&fb.ly);
	free(shown);
	free(cand);
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
	snprintf(text, sizeof(text), "level %s, merged below level %d", num,
	    iso.lb);
	legendtext((long long)opt.margin * 100, mapbottom() +
	    (long long)(ROW * row++ + 2) * 100, NULL, text);
	legendtext((long long)opt.margin * 100, mapbottom() +
	    (long long)(ROW * row + 2) * 100, NULL,
	    "x down left, y down right, z up");
	outs("</g>\n");
}

void
isodraw(double z0)
{
	char x0[32], y0[32], zz[32], size[32];
	long long height;
	int rows = 2 + opt.drawn[CF] + opt.drawn[CP];

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
