/*
 * qtsplit: decompose the region of a qtree(5) stream into a quadtree.
 *
 * A cell is partial when an edge meets its open interior.  Each cell gets
 * the edges of its parent that meet it (exact orientation of the edge
 * against the cell's corners), so a cell costs in proportion to the edges
 * near it.  A cell without edges is full or empty by the even-odd parity of
 * a point just inside its lower-left corner, carried from the parent: the
 * parity changes once for every parent edge that crosses the short path
 * between the two points, and only the parent's edges can.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qtree.h"

struct edge {
	double	ax, ay, bx, by;
	double	xmin, ymin, xmax, ymax;
};

static struct edge *edges;
static size_t nedges;
static struct universe u;
static int maxlevel = -1, minlevel = 0, verbose;
static char path[QT_MAXLEVEL + 2];

/* Per level: the cell's edges and, per edge, the children it meets. */
static uint32_t *lists[QT_MAXLEVEL + 2];
static size_t listcap[QT_MAXLEVEL + 2];
static unsigned char *masks[QT_MAXLEVEL + 2];

static unsigned long long ncells;
static int deepest;

static void
usage(void)
{
	fprintf(stderr, "usage: qtsplit [-v] [-l level] [-m level] [-r path] "
	    "[file]\n");
	exit(2);
}

static int
orient(const struct edge *e, double x, double y)
{
	return orient2d(e->ax, e->ay, e->bx, e->by, x, y);
}

/* The side of e on which (x, y) + (d, d^2) lies, d > 0 infinitesimal. */
static int
nudged(const struct edge *e, int o)
{
	if (o != 0)
		return o;
	if (e->ay != e->by)
		return e->by > e->ay ? -1 : 1;
	return e->bx > e->ax ? 1 : -1;
}

static void
reserve(int level, size_t n)
{
	if (n <= listcap[level])
		return;
	listcap[level] = n + n / 2 + 16;
	lists[level] = xreallocarray(lists[level], listcap[level],
	    sizeof(*lists[level]));
	masks[level] = xreallocarray(masks[level], listcap[level],
	    sizeof(*masks[level]));
}

static void
report(int force)
{
	if (verbose)
		progress(force, "%llu cells, deepest level %d", ncells,
		    deepest);
}

/*
 * Formatting numbers is the costliest part of the output.  A cell's texts
 * are kept while its subtree is written: the children in column 2ix share
 * the parent's x (2ix * h/2 is ix * h exactly), those in row 2iy its y,
 * so a split formats only the odd column's x and the odd row's y.  Column
 * 2ix + 1 is column 2ix with its last digit, which is even, plus one.
 */
struct text {
	char	s[32];
	size_t	len;
};

struct childtext {
	struct text	num[2];	/* 2i and 2i + 1 */
	struct text	odd;	/* the coordinate of 2i + 1 */
};

static struct text leveltext[QT_MAXLEVEL + 1], sizetext[QT_MAXLEVEL + 1];
static struct childtext childx[QT_MAXLEVEL + 1], childy[QT_MAXLEVEL + 1];
static double step[QT_MAXLEVEL + 1];	/* the cell size at each level */

static void
settext(struct text *t, double v)
{
	t->len = fmtreal(t->s, v) - t->s;
}

static void
setnum(struct text *t, uint64_t v)
{
	t->len = fmtint(t->s, (long long)v) - t->s;
}

/* Copies all of the text's buffer, a fixed size that compiles to a few
 * moves; the bytes past its length are overwritten by what follows. */
static char *
puttext(char *p, const struct text *t)
{
	memcpy(p, t->s, sizeof(t->s));
	return p + t->len;
}

/* Texts of the children's columns (or rows) 2i and 2i + 1 at level. */
static void
setchildren(struct childtext *c, double origin, int level, uint64_t i)
{
	setnum(&c->num[0], 2 * i);
	c->num[1] = c->num[0];
	c->num[1].s[c->num[1].len - 1]++;
	settext(&c->odd, origin + (double)(2 * i + 1) * step[level]);
}

static void
emit(int level, const struct text *ix, const struct text *iy,
    const struct text *x, const struct text *y, char class)
{
	char *p = qt_record(512);

	memcpy(p, class ? "leaf " : "node ", 5);
	p += 5;
	if (level == 0)
		*p++ = '.';
	else {
		memcpy(p, path, level);
		p += level;
	}
	*p++ = ' ';
	p = puttext(p, &leveltext[level]);
	*p++ = ' ';
	p = puttext(p, ix);
	*p++ = ' ';
	p = puttext(p, iy);
	*p++ = ' ';
	p = puttext(p, x);
	*p++ = ' ';
	p = puttext(p, y);
	*p++ = ' ';
	p = puttext(p, &sizetext[level]);
	if (class) {
		*p++ = ' ';
		*p++ = class;
	}
	*p++ = '\n';
	qt_recorded(p);
	if (level > deepest)
		deepest = level;
	if ((++ncells & 0xfffff) == 0)
		report(0);
}

/*
 * Sorts the edges of cell (level, ix, iy) into its children: masks[level]
 * gets, per edge, a bit for each child whose open interior it meets.  The
 * parities of the children's reference points go to parity[0..3].
 */
static void
children(int level, uint64_t ix, uint64_t iy, size_t n, int inside,
    int parity[4])
{
	const uint32_t *list = lists[level];
	unsigned char *mask = masks[level];
	double gx[3], gy[3];
	int bottom = 0, left = 0, middle = 0;
	size_t k;

	for (k = 0; k < 3; k++) {
		gx[k] = u.x0 + (double)(2 * ix + k) * step[level + 1];
		gy[k] = u.y0 + (double)(2 * iy + k) * step[level + 1];
	}
	for (k = 0; k < n; k++) {
		const struct edge *e = &edges[list[k]];
		/* orientation at grid point (i, j) in s[3 * j + i]; 2: unknown */
		signed char s[9] = { 2, 2, 2, 2, 2, 2, 2, 2, 2 };
		int inx[2], iny[2], q, m = 0;

		inx[0] = e->xmin < gx[1] && e->xmax > gx[0];
		inx[1] = e->xmin < gx[2] && e->xmax > gx[1];
		iny[0] = e->ymin < gy[1] && e->ymax > gy[0];
		iny[1] = e->ymin < gy[2] && e->ymax > gy[1];
		/*
		 * Most edges, once cells are larger than they are, lie
		 * strictly inside one child: they meet it and no other, and
		 * cross none of the parity paths, which run along the
		 * children's sides.
		 */
		if (inx[0] != inx[1] && iny[0] != iny[1]) {
			int i = inx[1], j = iny[1];

			if (e->xmin > gx[i] && e->xmax < gx[i + 1] &&
			    e->ymin > gy[j] && e->ymax < gy[j + 1]) {
				mask[k] = 1 << (2 * j + i);
				continue;
			}
		}
		for (q = 0; q < 4; q++) {
			int i = q & 1, j = q >> 1, pos = 0, neg = 0, c;

			if (!inx[i] || !iny[j])
				continue;
			for (c = 0; c < 4; c++) {
				int gi = i + (c & 1), gj = j + (c >> 1);
				signed char *o = &s[3 * gj + gi];

				if (*o == 2)
					*o = orient(e, gx[gi], gy[gj]);
				pos |= *o > 0;
				neg |= *o < 0;
			}
			if (pos && neg)
				m |= 1 << q;
		}
		mask[k] = m;
		/*
		 * Crossings of the paths from the parent's point to the
		 * children's: along the bottom to the middle, up the left
		 * side, and up the middle line.
		 */
		if ((e->ay > gy[0]) != (e->by > gy[0])) {
			if (s[0] == 2)
				s[0] = orient(e, gx[0], gy[0]);
			if (s[1] == 2)
				s[1] = orient(e, gx[1], gy[0]);
			bottom ^= nudged(e, s[0]) != nudged(e, s[1]);
		}
		if ((e->ax > gx[0]) != (e->bx > gx[0])) {
			if (s[0] == 2)
				s[0] = orient(e, gx[0], gy[0]);
			if (s[3] == 2)
				s[3] = orient(e, gx[0], gy[1]);
			left ^= nudged(e, s[0]) != nudged(e, s[3]);
		}
		if ((e->ax > gx[1]) != (e->bx > gx[1])) {
			if (s[1] == 2)
				s[1] = orient(e, gx[1], gy[0]);
			if (s[4] == 2)
				s[4] = orient(e, gx[1], gy[1]);
			middle ^= nudged(e, s[1]) != nudged(e, s[4]);
		}
	}
	parity[0] = inside;
	parity[1] = inside ^ bottom;
	parity[2] = inside ^ left;
	parity[3] = parity[1] ^ middle;
}

/* Moves the edges of child q from lists[level] to lists[level + 1]. */
static size_t
childlist(int level, size_t n, int q)
{
	const uint32_t *list = lists[level];
	const unsigned char *mask = masks[level];
	uint32_t *out;
	size_t k, m = 0;

	reserve(level + 1, n);
	out = lists[level + 1];
	for (k = 0; k < n; k++)
		if (mask[k] >> q & 1)
			out[m++] = list[k];
	return m;
}

static int
splits(int level, size_t n)
{
	return level < minlevel || (n > 0 && level < maxlevel);
}

/* Writes the cell and its subtree; its edges are lists[level][0..n-1]. */
static void
visit(int level, uint64_t ix, uint64_t iy, const struct text *tix,
    const struct text *tiy, const struct text *x, const struct text *y,
    size_t n, int inside)
{
	struct childtext *cx = &childx[level + 1], *cy = &childy[level + 1];
	int parity[4], q;

	if (!splits(level, n)) {
		emit(level, tix, tiy, x, y, n > 0 ? 'P' : inside ? 'F' : 'E');
		return;
	}
	emit(level, tix, tiy, x, y, 0);
	if (n > 0)
		children(level, ix, iy, n, inside, parity);
	else
		parity[0] = parity[1] = parity[2] = parity[3] = inside;
	setchildren(cx, u.x0, level + 1, ix);
	setchildren(cy, u.y0, level + 1, iy);
	for (q = 0; q < 4; q++) {
		size_t m = n > 0 ? childlist(level, n, q) : 0;
		int i = q & 1, j = q >> 1;

		path[level] = '0' + q;
		path[level + 1] = '\0';
		visit(level + 1, 2 * ix + i, 2 * iy + j, &cx->num[i],
		    &cy->num[j], i ? &cx->odd : x, j ? &cy->odd : y, m,
		    parity[q]);
	}
	path[level] = '\0';
}

/* Even-odd parity of the universe's reference point, by a ray to +x. */
static int
rootparity(void)
{
	size_t i;
	int inside = 0;

	for (i = 0; i < nedges; i++) {
		const struct edge *e = &edges[i];
		int s;

		if ((e->ay > u.y0) == (e->by > u.y0))
			continue;
		s = nudged(e, orient(e, u.x0, u.y0));
		if (e->by > e->ay ? s > 0 : s < 0)
			inside ^= 1;
	}
	return inside;
}

/* The edges that meet the universe's open interior. */
static size_t
rootlist(void)
{
	double x1 = u.x0 + u.size, y1 = u.y0 + u.size;
	size_t i, n = 0;

	reserve(0, nedges);
	for (i = 0; i < nedges; i++) {
		const struct edge *e = &edges[i];
		int o[4], c, pos = 0, neg = 0;

		if (!(e->xmin < x1 && e->xmax > u.x0 && e->ymin < y1 &&
		    e->ymax > u.y0))
			continue;
		o[0] = orient(e, u.x0, u.y0);
		o[1] = orient(e, x1, u.y0);
		o[2] = orient(e, u.x0, y1);
		o[3] = orient(e, x1, y1);
		for (c = 0; c < 4; c++) {
			pos |= o[c] > 0;
			neg |= o[c] < 0;
		}
		if (pos && neg)
			lists[0][n++] = i;
	}
	return n;
}

struct text_buffer {
	char	*s;
	size_t	 len, cap;
};

/* Keeps a record's text, its fields joined again, newline-terminated. */
static void
keeptext(struct text_buffer *b, const struct qtrec *rec)
{
	size_t i;

	if (b->len + rec->len + 2 > b->cap) {
		b->cap = 2 * (b->len + rec->len + 2);
		b->s = xreallocarray(b->s, b->cap, 1);
	}
	for (i = 0; i < rec->len; i++)
		b->s[b->len + i] = rec->line[i] ? rec->line[i] : ' ';
	b->len += rec->len;
	b->s[b->len++] = '\n';
	b->s[b->len] = '\0';
}

static void
addring(struct point *v, size_t nv)
{
	size_t i;

	edges = xreallocarray(edges, nedges + nv, sizeof(*edges));
	for (i = 0; i < nv; i++) {
		struct edge *e = &edges[nedges++];
		struct point a = v[i], b = v[(i + 1) % nv];

		e->ax = a.x, e->ay = a.y, e->bx = b.x, e->by = b.y;
		e->xmin = fmin(a.x, b.x), e->xmax = fmax(a.x, b.x);
		e->ymin = fmin(a.y, b.y), e->ymax = fmax(a.y, b.y);
	}
}

int
main(int argc, char *argv[])
{
	struct qtreader r;
	struct qtrec rec;
	enum qtkind kind;
	const char *end, *name, *subtree = NULL;
	struct text_buffer ringtext = { NULL, 0, 0 };
	struct point *v = NULL;
	size_t nv = 0, vcap = 0, n;
	long long val;
	uint64_t ix, iy;
	int ch, streamlevel = -1, inside, level, i;
	char **kept = NULL;
	size_t nkept = 0;
	FILE *fp;

	setprogname_(argv[0]);
	while ((ch = getopt(argc, argv, "l:m:r:v")) != -1)
		switch (ch) {
		case 'l':
		case 'm':
			if (parselong(optarg, &end, &val) < 0 || *end != '\0' ||
			    val < 0 || val > QT_MAXLEVEL)
				die(2, "-%c: level must be an integer from 0 "
				    "to %d: %s", ch, QT_MAXLEVEL, optarg);
			if (ch == 'l')
				maxlevel = val;
			else
				minlevel = val;
			break;
		case 'r':
			subtree = optarg;
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

	fp = openin(argc == 1 ? argv[0] : "-", &name);
	qt_open(&r, fp, name);
	while ((kind = qt_read(&r, &rec)) != QT_EOF) {
		switch (kind) {
		case QT_UNIVERSE:
			u = rec.u;
			break;
		case QT_LEVEL:
			streamlevel = rec.level;
			break;
		case QT_RING:
			if (nv > 0)
				addring(v, nv);
			nv = 0;
			keeptext(&ringtext, &rec);
			break;
		case QT_VERTEX:
			if (nv == vcap) {
				vcap = vcap ? 2 * vcap : 64;
				v = xreallocarray(v, vcap, sizeof(*v));
			}
			v[nv++] = rec.v;
			keeptext(&ringtext, &rec);
			break;
		case QT_NODE:
		case QT_LEAF:
			qt_fail(&r, "the input already holds cells: qtsplit "
			    "takes rings");
			break;
		default:
			kept = xreallocarray(kept, nkept + 1, sizeof(*kept));
			kept[nkept++] = xstrdup(rec.line);
			break;
		}
	}
	if (!r.haveuniverse)
		qt_fail(&r, "no universe record");
	qt_close(&r);
	if (nv > 0)
		addring(v, nv);
	free(v);
	if (nedges > UINT32_MAX)
		die(1, "too many edges: %zu", nedges);
	if (maxlevel < 0)
		maxlevel = streamlevel >= 0 ? streamlevel : 6;
	if (minlevel > maxlevel)
		die(2, "-m %d is deeper than the maximum level %d", minlevel,
		    maxlevel);

	for (i = 0; i <= QT_MAXLEVEL; i++) {
		step[i] = ldexp(u.size, -i);
		settext(&sizetext[i], step[i]);
		setnum(&leveltext[i], i);
	}
	qt_header();
	qt_universe(&u);
	qt_level(maxlevel);
	/* the rings as read: the reader checked them */
	for (n = 0; n < ringtext.len; ) {
		size_t eol = n + strcspn(ringtext.s + n, "\n");

		qt_raw(ringtext.s + n, eol - n);
		n = eol + 1;
	}
	free(ringtext.s);
	for (n = 0; n < nkept; n++) {
		qt_raw(kept[n], strlen(kept[n]));
		free(kept[n]);
	}
	free(kept);

	inside = rootparity();
	n = rootlist();
	level = 0;
	ix = iy = 0;
	if (subtree != NULL && strcmp(subtree, ".") != 0) {
		int depth = strlen(subtree);

		if (depth > QT_MAXLEVEL || pathcell(subtree, depth, &ix, &iy) < 0)
			die(2, "-r: not a cell path: %s", subtree);
		for (i = 0; i < depth; i++) {
			int parity[4], q = subtree[i] - '0';

			if (!splits(i, n))
				die(1, "-r: no cell %s in the tree: cell %.*s "
				    "is a leaf", subtree, i > 0 ? i : 1,
				    i > 0 ? subtree : ".");
			if (n > 0)
				children(i, ix >> (depth - i), iy >> (depth - i),
				    n, inside, parity);
			else
				parity[q] = inside;
			n = n > 0 ? childlist(i, n, q) : 0;
			inside = parity[q];
			path[i] = subtree[i];
		}
		path[depth] = '\0';
		level = depth;
	}
	{
		struct text tix, tiy, x, y;

		setnum(&tix, ix);
		setnum(&tiy, iy);
		settext(&x, cellcoord(u.x0, u.size, level, ix));
		settext(&y, cellcoord(u.y0, u.size, level, iy));
		visit(level, ix, iy, &tix, &tiy, &x, &y, n, inside);
	}
	qt_end();
	report(1);
	closeout();
	return 0;
}
